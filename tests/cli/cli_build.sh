#!/bin/sh
# cli_build.sh - the build follows its own configuration: a build directory
# made with SDL2 and built again without it (SDL2_OK= stands for a machine
# without libsdl2-dev), then with it again, links each time without `make
# clean`, and `silk view` has the window exactly when SDL2 was there.  The
# normal build's objects are copied into a directory of the test's own, so
# only what the configuration changes is compiled.
. "$(dirname "$0")/../shlib.sh"

root=$(cd "$here/.." && pwd)
if [ -n "${SILK_SAN:-}" ]; then
    echo "skip: the build's configuration is checked in the normal pass"
    done_testing
    exit 0
fi
case "$build" in /*) src=$build ;; *) src=$root/$build ;; esac
b=$tmp/b
mkdir -p "$b"
cp -pr "$src/obj" "$src/libsilk.a" "$src/libsilk_platform.a" "$b/"
[ -e "$src/sdl2.stamp" ] && cp -p "$src/sdl2.stamp" "$b/"
mk() { env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make -s -C "$root" BUILD="$b" "$@" "$b/silk" >"$tmp/make.log" 2>&1; }

mk SDL2_OK=
check "without SDL2: make links ($(grep -m 1 -iE 'error|multiple|undefined' "$tmp/make.log"))" test $? -eq 0
check "without SDL2: view has no window" sh -c "'$b/silk' view --help | grep -q 'not in this build'"
if pkg-config --exists sdl2 2>/dev/null; then
    mk
    check "SDL2 installed since: make links ($(grep -m 1 -iE 'error|multiple|undefined' "$tmp/make.log"))" test $? -eq 0
    check "SDL2 installed since: view has its window" sh -c "! '$b/silk' view --help | grep -q 'not in this build'"
    mk SDL2_OK=
    check "and without it again: make links" test $? -eq 0
else
    echo "skip: SDL2 is not installed, so building with it is not tried"
fi

done_testing
