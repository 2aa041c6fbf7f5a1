#!/bin/sh
# profile_fw.sh - where every byte of flash and RAM goes on a firmware board
# (mps2-an385, microbit): the second half of `make profile`, after make has
# built the firmware for the mesh.
#
#   sh tools/scripts/profile_fw.sh MESH [--check]
#
# The board's settings come from the Makefile, which read them from
# boards/$(BOARD)/board.mk, as environment variables: BOARD, FW_DIR (where
# the firmware of each model is: FW_DIR/NAME/fw.elf and fw.map), BOARD_RUN
# (the emulator command line, QEMU), BOARD_CROSS, BOARD_FLASH_BYTES,
# BOARD_WIDTH, BOARD_HEIGHT, BOARD_BAND_ROWS, BOARD_INSTR_PER_TICK (the
# instructions a tick of the board's timer is, 40 or 62.5) and PROFILE_CSV
# (the CSV to write).
#
# It runs the firmware, which renders its views flat and smooth in bands and
# reports its own arena high-water marks by purpose and its stack high-water
# mark from stack painting (saved as FW_DIR/NAME/report.txt); flash and
# static RAM come from the linker's map file, input section by input
# section: the core's code by module, the scene, platform code, libc,
# libgcc, and the packed model by kind.  The last line is
#   footprint BOARD MESH ram_total_bytes=N code_bytes=N model_bytes=N fell_back_frames=N
# with ram_total = static RAM + arena high-water +
# stack high-water (the band buffers are in the arena) and code = flash
# other than the model.  Frames that fell back to flat for lack of RAM are
# said at the top, marked in the speed table, left out of the speed line's
# figures and counted on the last lines.  --check
# exits 1 when the board's budget is not met (a frame fell back, RAM over
# budget, core code over 40 KiB).
#
# Speed: the firmware reads a timer around each frame, around each piece of
# the renderer's stages (its stage clock) and each fragment stage call
# (platform/mps2/fw_main.c); under QEMU with `-icount shift=0` in BOARD_RUN
# a tick is a fixed number of instructions, BOARD_INSTR_PER_TICK, which the
# firmware's loop of known length checks ("fw timer").  It prints
# instructions per frame (the renderer's, without the sink's output work),
# per stage (visibility, silhouette plan, emission, vertex stage,
# rasterizer, fragment stage; each piece's measured timing overhead taken
# off; "other" is the frame less the stages), and frames per second at
# BOARD_CLOCK_HZ for each cycles-per-instruction figure of BOARD_CPI; then
# a line
#   speed BOARD MESH flat_instructions=N smooth_instructions=N smooth_fell_back=N
# with the largest frame of each mode (of the frames drawn in it).
set -u
mesh=${1:?usage: profile_fw.sh MESH [--check]}
check=0
[ "${2:-}" = --check ] && check=1
for v in BOARD FW_DIR BOARD_RUN BOARD_FLASH_BYTES BOARD_WIDTH BOARD_HEIGHT BOARD_BAND_ROWS PROFILE_CSV; do
    eval "[ -n \"\${$v:-}\" ]" || { echo "profile_fw.sh: $v is not set (run it through make profile)" >&2; exit 2; }
done
name=$(basename "$mesh")
name=${name%.*}
dir=$FW_DIR/$name
[ -e "$dir/fw.elf" ] || { echo "silk: profile: $dir/fw.elf is missing (make BOARD=$BOARD BOARD_MESHES=$mesh firmware)" >&2; exit 1; }

# The firmware under the emulator, 300 s at most.  Exit 2 with "fw result=
# fell_back ..." is a run to the end whose smooth frames did not all fit:
# it is profiled, and the fall-back is said at the top, in the speed table
# and on the last lines.
timeout 300 $BOARD_RUN "$dir/fw.elf" -append "$dir/frame" >"$dir/report.txt" 2>&1
st=$?
if [ "$st" -eq 2 ] && grep -q '^fw result=fell_back ' "$dir/report.txt"; then
    st=0
elif [ "$st" -ne 0 ] || ! grep -qx 'fw result=ok' "$dir/report.txt"; then
    cat "$dir/report.txt" >&2
    echo "silk: profile: the firmware did not run to the end (exit $st, $BOARD_RUN $dir/fw.elf)" >&2
    exit 1
fi
# .text of the whole core library for the board, linked or not.
lib_text=$("${BOARD_CROSS:-}size" -t "$FW_DIR/libsilk.a" 2>/dev/null | awk '/\(TOTALS\)/ { print $1 }')

awk -v board="$BOARD" -v mesh="$mesh" -v name="$name" -v dir="$dir" -v csv="$PROFILE_CSV" -v check="$check" \
    -v flash_budget="$BOARD_FLASH_BYTES" -v width="$BOARD_WIDTH" -v height="$BOARD_HEIGHT" \
    -v band_rows="$BOARD_BAND_ROWS" -v lib_text="${lib_text:-0}" -v runner="${BOARD_RUN%% *}" \
    -v clock_hz="${BOARD_CLOCK_HZ:-0}" -v cpis="${BOARD_CPI:-}" -v ipt="${BOARD_INSTR_PER_TICK:-40}" -v code_limit="${BOARD_CODE_BYTES:-40960}" '
function hex(s,    i, n, c) {
    n = 0
    s = tolower(s)
    sub(/^0x/, "", s)
    for (i = 1; i <= length(s); i++) {
        c = index("0123456789abcdef", substr(s, i, 1))
        if (!c) break
        n = n * 16 + c - 1
    }
    return n
}
function field(key,    i) {               # "key=N" on the current report line
    for (i = 1; i <= NF; i++) if (index($i, key "=") == 1) return substr($i, length(key) + 2) + 0
    return -1
}
function row(area, item, bytes, note) {
    printf "  %-34s %9d  %s\n", item, bytes, note
    if (csv != "") printf "%s,%s,%d\n", area, item, bytes >csv
}
# "…/libsilk.a(raster.o)" -> "core raster", and so on.
function module_of(file,    base, member) {
    base = file
    sub(/.*\//, "", base)
    member = ""
    if (index(file, "(")) {
        member = substr(file, index(file, "(") + 1)
        sub(/\).*/, "", member)
        sub(/\.[^.]*$/, "", member)
    }
    if (index(file, "libsilk.a(")) return "core " member
    if (index(file, "libc_nano.a(") || index(file, "libc.a(")) return "libc"
    if (index(file, "libgcc.a(")) return "libgcc"
    if (index(file, "libnosys.a(")) return "libnosys"
    if (index(base, "fw_main")) return "scene fw_main"
    sub(/\.[^.]*$/, "", base)
    return "platform " base
}
function account(out_sec, in_sec, size, file,    kind, p, m) {
    if (out_sec == ".bss") kind = "bss"
    else if (out_sec == ".data") kind = "data"
    else if (substr(in_sec, 1, 5) == ".text") kind = "text"
    else kind = "ro"                       # .rodata, .vectors, .ARM.exidx
    p = index(in_sec, "fwmodel_")
    if (p && substr(in_sec, 1, 7) == ".rodata" && (substr(in_sec, p + 8) in model_kind)) {
        model[model_kind[substr(in_sec, p + 8)]] += size
        return
    }
    m = module_of(file)
    if (!(m in seen)) { seen[m] = 1; mods[++nmod] = m }
    bytes[m, kind] += size
}
BEGIN {
    # packed array (fwmodel_X) -> kind, as `silk pack` names them; kinds in print order
    split("model compact|pos positions|normal normals|normal_vertex normals|tri_normal normals|uv uvs|tri_uv uvs|color colours|" \
          "tri triangles|tri_edge edges|edge edges|vert_edge_start vertex_edges|vert_edge vertex_edges|" \
          "edge_feature features|feature features|vis_node visibility|vis visibility|texels texture|texture texture|" \
          "cameras cameras", pairs, "|")
    for (i = 1; pairs[i] != ""; i++) {
        split(pairs[i], kv, " ")
        k = kv[2]
        gsub(/_/, " ", k)
        model_kind[kv[1]] = k
        if (!(k in kind_seen)) { kind_seen[k] = 1; kinds[++nkinds] = k }
    }
    nmod = 0
}
# ---- the firmware report
FILENAME ~ /report\.txt$/ {
    if ($0 ~ /^fw frame=/) {
        frames++
        ffell[field("frame")] = field("fell_back") == 1
        if (field("frame_bytes") + 0 > frame_need) frame_need = field("frame_bytes") + 0
        if (field("fell_back") == 1) { fell++; if ($0 ~ / mode=smooth /) smooth_fell++ }
    } else if ($0 ~ /^fw arena size=/) {
        arena_size = field("size"); arena_peak = field("peak")
    } else if ($0 ~ /^fw arena_purpose /) {
        pname[++npurpose] = substr($3, 6); ppeak[npurpose] = field("peak")
    } else if ($0 ~ /^fw stack /) {
        stack_size = field("size"); stack_used = field("used")
    } else if ($0 ~ /^fw static /) {
        data = field("data"); bss = field("bss")
    } else if ($0 ~ /^fw timer /) {
        loop_instr = field("loop_instructions"); loop_ticks = field("ticks")
    } else if ($0 ~ /^fw time /) {
        tf = field("frame"); tmode[tf] = $0 ~ / mode=smooth / ? "smooth" : "flat"; tcam[tf] = field("camera")
        tticks[tf] = field("render_ticks"); ntime++
    } else if ($0 ~ /^fw stages /) {
        tf = field("frame"); ov = field("overhead_ticks_per_1000_calls") / 1000
        fticks[tf] = field("fragment_ticks") - ov * field("fragment_calls"); fcalls[tf] = field("fragment_calls")
    } else if ($0 ~ /^fw stage /) {
        tf = field("frame"); sname = $6; sub(/^stage=/, "", sname)
        sticks[tf, sname] = field("ticks") - field("overhead_ticks_per_1000_pieces") / 1000 * field("pieces")
        nstage[tf]++
    } else if ($0 ~ /^fw ram /) {
        ram_total = field("total"); ram_budget = field("budget")
    }
    next
}
# ---- the map file: input sections of the loaded output sections (GNU ld -Map)
!in_map { if (index($0, "Linker script and memory map") == 1) in_map = 1; next }
/^\./ { out_sec = $1; pending = ""; next }
!/^ / { pending = ""; next }
{
    wanted = out_sec == ".text" || out_sec == ".ARM.exidx" || out_sec == ".data" || out_sec == ".bss"
    if ($1 == "*fill*") {
        if (NF >= 3 && wanted && out_sec != ".bss") fill += hex($3)
        next
    }
    if (NF == 1 && substr($1, 1, 1) == ".") { pending = $1; next }   # long name: the rest is on the next line
    if (pending != "" && NF == 3 && $1 ~ /^0x/ && $2 ~ /^0x/) {
        if (wanted) account(out_sec, pending, hex($2), $3)
        pending = ""
        next
    }
    pending = ""
    if (NF >= 4 && substr($1, 1, 1) == "." && $2 ~ /^0x/ && $3 ~ /^0x/ && wanted) account(out_sec, $1, hex($3), $4)
}
END {
    if (!in_map) { print "silk: profile: cannot read the map file " dir "/fw.map" >"/dev/stderr"; exit 1 }
    if (csv != "") printf "area,item,bytes\n" >csv
    # modules by name
    for (i = 2; i <= nmod; i++) for (j = i; j > 1 && mods[j - 1] > mods[j]; j--) { t = mods[j]; mods[j] = mods[j - 1]; mods[j - 1] = t }
    printf "silk profile: %s on %s (%s)\n", mesh, board, dir
    printf "frame %sx%s, bands of %d rows; %d frames rendered (flat and smooth from %d views)\n",
        width, height, band_rows, frames, int(frames / 2)
    if (fell) printf "FELL BACK: %d of %d frames (%d smooth) were drawn unsmoothed: the arena could not hold their plan\n",
        fell, frames, smooth_fell
    printf "\nFLASH (bytes; from %s/fw.map)\n", dir
    for (i = 1; i <= nmod; i++) {
        m = mods[i]; t = bytes[m, "text"] + 0; ro = bytes[m, "ro"] + 0; d = bytes[m, "data"] + 0
        if (!t && !ro && !d) continue
        row("flash", m, t + ro + d, sprintf("code %d, constants %d%s", t, ro, d ? ", .data image" : ""))
        if (substr(m, 1, 5) == "core ") { core_text += t; core_ro += ro }
        code += t + ro; data_init += d
    }
    row("flash", "alignment padding", fill, "")
    code += fill + data_init
    print "  model (silk pack):"
    for (i = 1; i <= nkinds; i++) { model_total += model[kinds[i]]; if (model[kinds[i]]) row("flash", "model " kinds[i], model[kinds[i]], "") }
    printf "  %-34s %9d  (limit %d: %s)\n", "core code (.text of libsilk)", core_text, code_limit, core_text <= code_limit ? "ok" : "OVER"
    printf "  %-34s %9d\n", "core constants (.rodata)", core_ro
    if (lib_text) printf "  %-34s %9d  (every module, loaders too: `size` of fw/libsilk.a)\n", "core library .text", lib_text
    row("flash", "code total", code, "everything but the model")
    row("flash", "model total", model_total, "")
    row("flash", "flash total", code + model_total, flash_budget ? sprintf("of %d (%s)", flash_budget, code + model_total <= flash_budget ? "fits" : "OVER") : "")

    printf "\nRAM (bytes; measured by the firmware under %s)\n", runner
    row("ram", "static .data", data, "libc state")
    row("ram", "static .bss besides the arena", bss - arena_size, "")
    row("ram", "arena", arena_peak, sprintf("high-water of %d reserved", arena_size))
    for (i = 1; i <= npurpose; i++) if (ppeak[i] > 0) {
        row("ram", "  arena " pname[i], ppeak[i], pname[i] == "raster" ? "band buffers: colour + depth" : pname[i] == "frame" ? "per-frame scratch, peak" : "")
        # the rest of the peak is optional: kept edge tangents (src/render.c, keep_tangents)
        if (pname[i] == "frame" && frame_need < ppeak[i])
            row("ram", "    of it the frames need", frame_need, "the rest: edge tangents kept for speed where there was room")
    }
    row("ram", "stack", stack_used, sprintf("painted high-water of %d reserved", stack_size))
    row("ram", "ram total", ram_total, sprintf("of %d budget (%s)", ram_budget, ram_total <= ram_budget ? "fits" : "OVER"))
    if (fell) printf "\n  %d of %d frames fell back (%d smooth): the arena could not hold their per-frame\n" \
        "  scratch, so part or all of the frame was drawn unsmoothed; see docs/small-devices.md.\n", fell, frames, smooth_fell
    # ---- speed: ticks to instructions, checked on the loop of known length
    # The loop and the reads around it may straddle one more tick boundary
    # than its length fills, so the instructions a tick given are accepted
    # when the ticks of the loop are that within one.
    ipt += 0
    if (ntime && ipt > 0 && loop_ticks > 0 && loop_instr / ipt - loop_ticks <= 1 && loop_ticks - loop_instr / ipt <= 1) {
        ncpi = split(cpis, cpi, " ")
        printf "\nSPEED (instructions per frame; QEMU -icount shift=0, %g instructions a timer tick:\n", ipt
        printf "  a loop of %d instructions took %d ticks)\n", loop_instr, loop_ticks
        split("visibility plan emit vertex raster", snames, " ")
        printf "  %-6s %-6s %11s %10s %10s %10s %10s %10s %10s %8s", "camera", "mode", "frame", "visibility", "plan",
            "emission", "vertex", "raster", "fragment", "other"
        for (c = 1; c <= ncpi; c++) printf "  %11s", sprintf("fps CPI %s", cpi[c])
        printf "\n"
        for (f = 0; f < ntime; f++) {
            n = tticks[f] * ipt; g = fticks[f] * ipt
            printf "  %-6d %-6s %11d", tcam[f], tmode[f], n
            rest = n
            for (s = 1; s <= 5; s++) {
                x = sticks[f, snames[s]] * ipt
                rest -= x
                if (snames[s] == "raster") x -= g          # the fragment stage runs inside the rasterizer
                printf " %10d", x
                if (csv != "" && nstage[f]) printf "speed,camera %d %s %s instructions,%d\n", tcam[f], tmode[f], snames[s], x >csv
            }
            printf " %10d %8d", g, rest
            for (c = 1; c <= ncpi; c++) printf "  %11.2f", clock_hz / (n * cpi[c])
            printf "%s\n", ffell[f] ? "  fell back: drawn flat" : ""
            if (csv != "") {
                printf "speed,camera %d %s instructions,%d\n", tcam[f], tmode[f], n >csv
                if (nstage[f]) printf "speed,camera %d %s fragment instructions,%d\n", tcam[f], tmode[f], g >csv
            }
            if (!ffell[f] && n > worst[tmode[f]]) worst[tmode[f]] = n   # a frame that fell back was drawn flat
        }
        printf "  Stages timed in a second pass (the stage clock of the renderer; the fragment stage, called from\n"
        printf "  the rasterizer, timed call by call in a third: %d calls in the first frame) and taken off the\n", fcalls[0]
        printf "  rasterizer; other: the frame less the stages.  fps at %.0f MHz for each cycles-per-instruction figure.\n", clock_hz / 1e6
        printf "speed %s %s flat_instructions=%d smooth_instructions=%d smooth_fell_back=%d\n", board, name,
            worst["flat"], worst["smooth"], smooth_fell + 0
    } else if (ntime) {
        printf "\nSPEED: not measured (the timer is not counting instructions: run QEMU with -icount shift=0)\n"
    }
    if (csv != "") {
        printf "frames,fell_back,%d\n", fell >csv
        if (close(csv) != 0) { print "silk: profile: " csv ": write failed" >"/dev/stderr"; exit 1 }
        printf "\ncsv: %s\n", csv
    }
    if (fell) printf "silk: profile: %d of %d frames fell back (%d smooth): %s cannot smooth them in this RAM\n",
        fell, frames, smooth_fell, board >"/dev/stderr"
    printf "footprint %s %s ram_total_bytes=%d code_bytes=%d model_bytes=%d fell_back_frames=%d\n", board, name,
        ram_total, code, model_total, fell + 0
    if (check && (fell || ram_total > ram_budget || core_text > code_limit)) {
        printf "silk: profile: %s does not meet its budget (%d frames fell back)\n", board, fell >"/dev/stderr"
        exit 1
    }
}' "$dir/report.txt" "$dir/fw.map"
