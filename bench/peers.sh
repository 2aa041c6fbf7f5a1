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
# silk flat) do not.
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
cat "$out/bench-peers.md"
