#!/bin/sh
# bench/peers.sh OUTDIR - silk against two software rasterizers that shade
# per pixel (small3dlib, PortableGL), frame-interleaved in one process by
# ../shared/peers/run.sh (same mesh, camera, size and Phong shading; see its
# harness/README.md).  Writes OUTDIR/bench-peers.md: per mesh and size, silk
# flat's time per frame over each peer's, and silk smooth's over silk flat's
# (below 1: silk flat is faster), each the median over the views of the
# ratio of frames timed a few milliseconds apart (pair.c's
# silk_flat_over_this), so that a change of load hits both.  The machine
# may be loaded: the ratios hold, the absolute times (the median frame of
# silk flat) do not.  With CALLGRIND=1 it adds instructions per frame (12
# views, callgrind over the harness's frame function) of silk flat, silk
# smooth and small3dlib, which do not depend on the load (slow: minutes).
set -eu
out=${1:-out}
peers=${SILK_PEERS:-../shared/peers}
[ -f "$peers/run.sh" ] || { echo "bench/peers.sh: skipping ($peers/run.sh not found)"; exit 0; }
mkdir -p "$out/peers"
out=$(cd "$out" && pwd)     # run.sh builds in the peers' folder: absolute paths
sh "$peers/run.sh" . "$out/peers" 2> "$out/peers/pair.log" > /dev/null
grep -q '^PAIR' "$out/peers/pair.txt" || { echo "bench/peers.sh: no results (see $out/peers/pair.log)" >&2; exit 1; }
awk '
/^PAIR/ {
    for (i = 2; i <= NF; i++) { split($i, kv, "="); f[kv[1]] = kv[2] }
    n = f["mesh"]; sub(/.*\//, "", n); sub(/\.obj$/, "", n)
    key = n " " f["size"]
    if (!(key in seen)) { seen[key] = 1; order[++k] = key }
    ms[key, f["prog"]] = f["median_ms"]
    r[key, f["prog"]] = f["silk_flat_over_this"]
}
END {
    print "| mesh, size | silk flat ms | ÷ small3dlib | ÷ PortableGL | silk smooth ÷ silk flat |"
    print "|---|---:|---:|---:|---:|"
    for (i = 1; i <= k; i++) {
        key = order[i]
        printf "| %s | %.2f | %.2f | %.2f | %.2f |\n", key, ms[key, "silk-flat"], r[key, "small3dlib"],
               r[key, "portablegl"], 1 / r[key, "silk-smooth"]
    }
}' "$out/peers/pair.txt" > "$out/bench-peers.md"

if [ "${CALLGRIND:-0}" = 1 ] && command -v valgrind >/dev/null; then
    silk=$(pwd)
    meshes=$(cd "${SILK_MESHES:-$peers/../meshes}" && pwd)
    bin="$out/peers/bin"
    # instructions of the frames alone: h_bench_frame, 12 views, divided by 12
    ipf() {
        valgrind --tool=callgrind --dump-instr=no --callgrind-out-file="$bin/cg.out" \
            --toggle-collect=h_bench_frame "$@" --frames 12 --count 0 >/dev/null 2>&1
        callgrind_annotate "$bin/cg.out" 2>/dev/null |
            awk '/PROGRAM TOTALS/ { gsub(",", "", $1); printf "%.1f M", $1 / 12e6; exit }'
        rm -f "$bin/cg.out"
    }
    {
        echo
        echo "Instructions per frame (callgrind, 12 views):"
        echo
        echo "| mesh, size | silk flat | silk smooth | small3dlib |"
        echo "|---|---:|---:|---:|"
        for size in 320x240 640x480; do
            make -s -C "$peers/harness" SILK="$silk" S3L="$(cd "$peers/small3dlib" && pwd)" BIN="$bin" \
                "$bin/h_silk" "$bin/h_s3l_$size" >&2
            for m in bunny-500 sphere-200 bunny-fine; do
                [ -f "$meshes/$m.obj" ] || continue
                echo "| $m $size | $(ipf "$bin/h_silk" "$meshes/$m.obj" --size "$size" --mode flat) |" \
                     "$(ipf "$bin/h_silk" "$meshes/$m.obj" --size "$size" --mode smooth) |" \
                     "$(ipf "$bin/h_s3l_$size" "$meshes/$m.obj" --size "$size") |"
            done
        done
    } >> "$out/bench-peers.md"
fi
cat "$out/bench-peers.md"
