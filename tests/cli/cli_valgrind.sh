#!/bin/sh
# cli_valgrind.sh BUILD - the silk command under Valgrind's memcheck on the
# demo meshes (those of `make demo`): every `silk gen` shape (generated
# under memcheck too) and bunny-500 and fandisk-128 from the shared meshes,
# each rendered flat and smooth at 64x48 and described by `silk info`;
# contact sheets, a close-up and --compare as the demo makes them.  Every run must end with 0 errors and 0 bytes
# leaked of any kind (definite, indirect, possible, still reachable).
#
# Valgrind cannot run the AddressSanitizer build, so with BUILD = build-san
# (the second pass of `make test`) this test only says so; the plain
# build's pass runs it.  Without valgrind it is skipped, except in CI
# (CI=true, .ci/run installs valgrind), where that is a failure.
. "$(dirname "$0")/../shlib.sh"

case "$build" in
*san*)
    echo "skip: valgrind does not run sanitizer builds (the $build pass covers memory with ASan)"
    done_testing
    exit $?
    ;;
esac
if ! command -v valgrind >/dev/null 2>&1; then
    if [ -n "${CI:-}" ]; then
        fail "valgrind" "not installed (CI installs it: .ci/run)"
    else
        echo "skip: valgrind is not installed"
    fi
    done_testing
    exit $?
fi

meshes=${SILK_MESHES:-../shared/meshes}
vg="valgrind --tool=memcheck --leak-check=full --show-leak-kinds=all --errors-for-leak-kinds=all
    --error-exitcode=99 --track-origins=yes --quiet"

# memcheck NAME ARGS...: silk ARGS under memcheck; passes on exit 0 with an
# empty Valgrind report (the report and the command's stderr share $err)
memcheck() {
    name=$1
    shift
    $vg --log-file="$tmp/vg.log" "$SILK" "$@" >"$out" 2>"$err"
    rc=$?
    if [ "$rc" -eq 0 ] && [ ! -s "$tmp/vg.log" ]; then
        pass "$name"
    else
        fail "$name" "exit $rc; $(head -c 600 "$tmp/vg.log") $(head -c 200 "$err")"
    fi
}

for shape in sphere torus cone cylinder knot; do
    memcheck "gen $shape" gen "$shape" -o "$tmp/$shape.obj"
done
list="$tmp/sphere.obj $tmp/torus.obj $tmp/cone.obj $tmp/cylinder.obj $tmp/knot.obj"
want=5
if [ -d "$meshes" ]; then
    want=6
    for m in bunny-500 fandisk-128; do
        [ -f "$meshes/$m.obj" ] && list="$list $meshes/$m.obj"
    done
else
    echo "skip: $meshes is missing, so bunny-500 and fandisk-128 are not checked"
fi

n=0
for m in $list; do
    [ -f "$m" ] || continue
    n=$((n + 1))
    b=$(basename "$m" .obj)
    for mode in flat smooth; do
        memcheck "render $b $mode" render "$m" --size 64x48 --mode "$mode" -o "$tmp/$b-$mode.png"
    done
    memcheck "info $b" info "$m" --size 64x48
done
check "at least $want meshes ($n)" test "$n" -ge "$want"
# what `make demo` does besides: contact sheets of all modes with edges,
# a close-up, flat | smooth side by side
for b in sphere knot; do
    memcheck "sheet $b" render "$tmp/$b.obj" --size 64x48 --modes flat,smooth,blend,pn --sheet --wire \
        -o "$tmp/$b-sheet.png"
    memcheck "close-up $b" render "$tmp/$b.obj" --size 64x48 --modes flat,smooth --sheet --zoom 6 \
        -o "$tmp/$b-zoom.png"
    memcheck "compare $b" render "$tmp/$b.obj" --size 64x48 --compare -o "$tmp/$b-compare.ppm"
done

# the error paths free what they took: a malformed file, an arena too
# small for loading and for the frame, a fall-back frame
memcheck_fails() {
    name=$1
    shift
    $vg --log-file="$tmp/vg.log" "$SILK" "$@" >"$out" 2>"$err"
    rc=$?
    if [ "$rc" -ne 99 ] && [ "$rc" -ne 0 ] && [ ! -s "$tmp/vg.log" ]; then
        pass "$name"
    else
        fail "$name" "exit $rc; $(head -c 600 "$tmp/vg.log")"
    fi
}
memcheck_fails "render a malformed file" render "$here/bad/face-index-beyond.obj" -o "$tmp/bad.png"
memcheck_fails "arena too small to load" render "$tmp/sphere.obj" --arena 4K -o "$tmp/small.png"
memcheck "arena too small to smooth" render "$tmp/sphere.obj" --arena 60K --size 32x32 -o "$tmp/fall.png"

done_testing
