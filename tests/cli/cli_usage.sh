#!/bin/sh
# cli_usage.sh - the command line itself: --help for the command and each
# subcommand lists every option; every bad option or value is one line
# "silk: ..." on stderr with exit 2, bad input exit 1, and no output file.
. "$(dirname "$0")/../shlib.sh"

sphere=$tmp/sphere.obj
"$SILK" gen sphere -o "$sphere" || { fail "gen sphere" "exit $?"; done_testing; exit 1; }

# ---- help --------------------------------------------------------------------------
# help_has NAME ARGS... -- WORDS...: exit 0 and stdout mentions every word.
help_has() {
    name=$1; shift
    args=
    while [ "$1" != "--" ]; do args="$args $1"; shift; done
    shift
    run_silk $args
    missing=
    for w in "$@"; do grep -q -- "$w" "$out" || missing="$missing $w"; done
    if [ "$rc" -eq 0 ] && [ -z "$missing" ] && [ ! -s "$err" ]; then pass "$name"
    else fail "$name" "exit $rc, missing:$missing"; fi
}
scene="--scale --crease --normals --arena --eye --target --up --fov --ortho --size --format --mode --tolerance --bg --wire"
help_has "silk --help" --help -- render info gen "Exit status" "help"
help_has "silk help" help -- render info gen
help_has "silk render --help" render --help -- --output --compare $scene rgb565 smooth
help_has "silk help render" help render -- --output $scene
help_has "silk info --help" info --help -- ${scene% --bg --wire}
help_has "silk gen --help" gen --help -- sphere torus cone cylinder knot --segments --bands
# options a command would ignore are refused, not swallowed
for opt in --wire "--bg 000000" "--lines over" "--color ff0000"; do
    want="unknown option ${opt% *}" expect_usage "info refuses $opt" info "$sphere" $opt
    want="unknown option ${opt% *}" expect_usage "pack refuses $opt" pack "$sphere" -o "$tmp/x.h" $opt
done
want='unknown option --mode' expect_usage "pack refuses --mode" pack "$sphere" -o "$tmp/x.h" --mode flat
run_silk --version
check "silk --version" grep -q '^silk [0-9]' "$out"

run_silk
check "no command: usage on stderr, exit 2" test "$rc" -eq 2 -a -s "$err" -a ! -s "$out"
want='unknown command' expect_usage "unknown command" frobnicate
want='unknown command' expect_usage "help for an unknown command" help frobnicate

# ---- bad options: exit 2, one line, no output ---------------------------------------
o=$tmp/out.png
bad() {
    name=$1; shift
    expect_usage "$name" render "$sphere" -o "$o" "$@"
    [ -e "$o" ] && { fail "$name leaves no output" "$o exists"; rm -f "$o"; }
}
want='size' bad "--size 0x5" --size 0x5
want='size' bad "--size abc" --size abc
want='size' bad "--size 100000x2" --size 100000x2
want='size' bad "--size 10x" --size 10x
want='size' bad "--size x10" --size x10
want='size' bad "--size -5x5" --size -5x5
want='size' bad "--size 10x10x10" --size 10x10x10
want='size' bad "--size 8193x10" --size 8193x10
want='size' bad "--size 99999999999999999999x1" --size 99999999999999999999x1
want='fov' bad "--fov 200" --fov 200
want='fov' bad "--fov 0" --fov 0
want='fov' bad "--fov 180" --fov 180
want='fov' bad "--fov -30" --fov -30
want='fov' bad "--fov abc" --fov abc
want='fov' bad "--fov nan" --fov nan
want='fov' bad "--fov inf" --fov inf
want='fov' bad "--fov 0x10" --fov 0x10
want='fov' bad "--fov '' " --fov ''
want='tolerance' bad "--tolerance 10" --tolerance 10
want='tolerance' bad "--tolerance 0.1" --tolerance 0.1
want='tolerance' bad "--tolerance 1e400" --tolerance 1e400
want='bg' bad "--bg 12345" --bg 12345
want='bg' bad "--bg zzzzzz" --bg zzzzzz
want='bg' bad "--bg 1234567" --bg 1234567
want='mode' bad "--mode wobbly" --mode wobbly
want='format' bad "--format rgb" --format rgb
want='normals' bad "--normals maybe" --normals maybe
want='crease' bad "--crease 200" --crease 200
want='crease' bad "--crease -1" --crease -1
want='scale' bad "--scale 0" --scale 0
want='scale' bad "--scale -1" --scale -1
want='scale' bad "--scale abc" --scale abc
want='scale' bad "--scale 1e999" --scale 1e999
want='eye' bad "--eye 1,2" --eye 1,2
want='eye' bad "--eye 1,2,3,4" --eye 1,2,3,4
want='eye' bad "--eye a,b,c" --eye a,b,c
want='eye' bad "--eye 1e9,0,0" --eye 1e9,0,0
want='eye' bad "--eye ,," --eye ,,
want='target' bad "--target 1,,2" --target 1,,2
want='up' bad "--up 0,0,0" --up 0,0,0
want='ortho' bad "--ortho 0" --ortho 0
want='ortho' bad "--ortho -1" --ortho -1
want='ortho' bad "--ortho fit" --ortho fit
want='arena' bad "--arena 12" --arena 12
want='arena' bad "--arena lots" --arena lots
want='arena' bad "--arena 5T" --arena 5T
want='arena' bad "--arena 99G" --arena 99G
want='unknown option' bad "unknown option" --bogus
want='unknown option' bad "unknown short option" -x
want='needs a value' bad "missing value at the end" --size
want='needs a value' expect_usage "-o without a value" render "$sphere" -o
want='no output' expect_usage "no -o" render "$sphere"
want='no mesh' expect_usage "no mesh" render -o "$o"
want='one mesh' expect_usage "two meshes to info" info "$sphere" "$sphere"
want='names mesh 3' expect_usage "two meshes, an option for a third" render "$sphere" "$sphere" -o "$o" --place 3:0,0,0
want='unknown image format' expect_usage "unknown output extension" render "$sphere" -o "$tmp/x.gif"
# the camera options agree with each other only if the view exists
want='camera' expect_usage "eye at the target" render "$sphere" -o "$o" --eye 1,1,1 --target 1,1,1
want='camera' expect_usage "up along the view" render "$sphere" -o "$o" --eye 0,5,0 --target 0,0,0 --up 0,1,0
want='cannot be framed' expect_usage "default camera for an extreme aspect" render "$sphere" -o "$o" --size 1x8192
check "no output after all that" test ! -e "$o"

# what a mode does not draw is refused as usage, in the command's words
# (not the library's "silk_render:")
for c in "pn --lines over" "blend --lines only" "clip --lines over" "clip --lines-polygonal"; do
    want="^silk: render: ${c%% *} mode draws" expect_usage "--mode $c: exit 2 in render's words" render "$sphere" -o "$o" --mode $c
    check "--mode $c: no silk_render: in the message" test -z "$(grep silk_render "$err")"
done
want="^silk: render: pn mode draws" expect_usage "--modes flat,pn --lines over" render "$sphere" -o "$o" --modes flat,pn --sheet --lines over
# every mode is named in the help
"$SILK" help render >"$tmp/help-render"
for m in flat smooth pn blend clip siltex; do
    check "help render names mode $m" grep -qE -- "--mode [a-zL|]*\\b$m\\b" "$tmp/help-render"
done

# info takes the same options and fails the same way
want='size' expect_usage "info --size abc" info "$sphere" --size abc
want='unknown option' expect_usage "info -o" info "$sphere" -o x.png
want='no mesh' expect_usage "info without a mesh" info

# ---- bad input: exit 1 ---------------------------------------------------------------
want='cannot open: No such file or directory' expect_input "missing file" render "$tmp/none.obj" -o "$o"
want='Is a directory' expect_input "directory as mesh" info "$tmp"
printf 'v 0 0 0\nv 1 0 0\n' >"$tmp/notri.obj"
expect_input "mesh without triangles" render "$tmp/notri.obj" -o "$o"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n' >"$tmp/badidx.obj"
want='badidx.obj:4' expect_input "bad index names file and line" info "$tmp/badidx.obj"
check "no output after input errors" test ! -e "$o"
check "no temporary files" no_tmp_files "$tmp"

# options in any order, and --opt=value
run_silk render --size=24x16 -o "$tmp/order.png" --mode=flat "$sphere"
check "options before the mesh and --opt=value" test "$rc" -eq 0 -a "$(png_size "$tmp/order.png")" = 24x16

done_testing
