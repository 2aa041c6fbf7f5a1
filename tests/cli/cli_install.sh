#!/bin/sh
# cli_install.sh - what `make install` gives a user: into a temporary
# PREFIX, the libraries (libsilk.a, libsilk_platform.a), the headers
# (silk/platform.h among them), silk.pc and silk-platform.pc, the command,
# its manual page, the README, docs/ and the licence; `make uninstall`
# removes all of it again.  A small program (tests/core/test_cxx.cpp)
# built with
#   c++ test_cxx.cpp $(pkg-config --cflags --libs silk-platform)
# renders a frame and writes it as PNG and PPM with the installed writers,
# and reads the PNG back; the installed `silk` works
# from another directory (gen, render, info, profile, help --man).
. "$(dirname "$0")/../shlib.sh"

root=$(cd "$here/.." && pwd)
if [ -n "${SILK_SAN:-}" ]; then
    echo "skip: make install is checked in the normal pass (a sanitizer build is not installed)"
    done_testing
    exit 0
fi
command -v pkg-config >/dev/null 2>&1 || { echo "skip: pkg-config is not installed"; done_testing; exit 0; }

prefix=$tmp/prefix
case "$build" in /*) b=$build ;; *) b=$root/$build ;; esac
make -s -C "$root" BUILD="$b" PREFIX="$prefix" install >"$tmp/install.log" 2>&1
check "make install PREFIX=... succeeds ($(tail -n 3 "$tmp/install.log"))" test $? -eq 0
for f in lib/libsilk.a lib/libsilk_platform.a lib/pkgconfig/silk.pc lib/pkgconfig/silk-platform.pc \
         include/silk/silk.h include/silk/platform.h include/silk/validate.h bin/silk \
         share/man/man1/silk.1 share/doc/silk/LICENSE share/doc/silk/README.md share/doc/silk/docs/architecture.md \
         share/doc/silk/docs/img/bunny-modes.png include/silk/silmap.h; do
    check "installed $f" test -s "$prefix/$f"
done
n=$(ls "$root"/docs/*.md | wc -l)
check "installed every page of docs/ ($n)" test "$(ls "$prefix"/share/doc/silk/docs/*.md | wc -l)" -eq "$n"
check "the manual page points at the installed docs" grep -q 'share/doc/silk' "$prefix/share/man/man1/silk.1"
check "the installed page is silk help --man" sh -c "'$prefix/bin/silk' help --man | cmp -s - '$prefix/share/man/man1/silk.1'"

PKG_CONFIG_PATH=$prefix/lib/pkgconfig
export PKG_CONFIG_PATH
flags=$(pkg-config --cflags --libs silk-platform 2>"$err")
check "pkg-config silk-platform ($flags$(head -c 200 "$err"))" test -n "$flags"
# The C++ test of the headers (it renders and writes PNG and PPM) is the program.
${CXX:-c++} -std=c++11 -Wall -Wextra -Wpedantic -Werror "$here/core/test_cxx.cpp" -o "$tmp/prog" $flags 2>"$err"
check "a program builds against the installed library ($(head -c 300 "$err"))" test $? -eq 0

# From a directory with no silk sources in sight, with the installed tools only.
mkdir -p "$tmp/elsewhere"
cd "$tmp/elsewhere" || exit 1
PATH=$prefix/bin:$PATH
"$prefix/bin/silk" gen sphere -o sphere.obj >"$out" 2>"$err"
check "silk gen from another directory" test $? -eq 0 -a -s sphere.obj
"$tmp/prog" prog >"$out" 2>"$err"
check "the program renders and writes PNG and PPM ($(grep FAIL "$out" | head -c 200))" \
    test $? -eq 0 -a -s prog.png -a -s prog.ppm
check "its PNG is a PNG" is_png prog.png
check "its PPM is 64x48" test "$(ppm_size prog.ppm)" = 64x48
"$prefix/bin/silk" render sphere.obj -o r.png --size 96x72 >"$out" 2>"$err"
check "silk render from another directory" test $? -eq 0 -a -s r.png
"$prefix/bin/silk" info sphere.obj >"$out" 2>"$err"
check "silk info from another directory" test $? -eq 0 -a -s "$out"
"$prefix/bin/silk" profile sphere.obj --board host --csv p.csv >"$out" 2>"$err"
check "silk profile --board host from another directory ($(head -c 200 "$err"))" \
    grep -qE '^footprint host sphere ram_total_bytes=[0-9]+ model_bytes=[0-9]+ fell_back_frames=0$' "$out"
check "silk profile writes its CSV" grep -q '^ram,ram total,' p.csv
"$prefix/bin/silk" profile sphere.obj --board mps2-an385 >"$out" 2>"$err"
check "silk profile of a firmware board points at make profile ($(head -c 200 "$err"))" \
    test $? -eq 2 -a "$(wc -l <"$err")" -eq 1 && grep -q 'make profile PROFILE_BOARD=mps2-an385' "$err"
if command -v man >/dev/null 2>&1; then
    MANPATH=$prefix/share/man LC_ALL=C MANWIDTH=80 man silk >"$out" 2>"$err"
    check "man silk reads the installed page" grep -q 'silk render' "$out"
fi
cd "$root" || exit 1

# make uninstall: every file install wrote is gone, and the directories of silk's own
touch "$prefix/lib/other.a"
make -s -C "$root" BUILD="$b" PREFIX="$prefix" uninstall >"$tmp/uninstall.log" 2>&1
check "make uninstall succeeds ($(tail -n 3 "$tmp/uninstall.log"))" test $? -eq 0
left=$(cd "$prefix" && find . -type f ! -name other.a | head -n 5 | tr '\n' ' ')
check "make uninstall leaves none of silk's files (${left:-none})" test -z "$left"
check "make uninstall leaves what is not silk's" test -e "$prefix/lib/other.a"
check "make uninstall removes silk's directories" test ! -e "$prefix/include/silk" -a ! -e "$prefix/share/doc/silk"

done_testing
