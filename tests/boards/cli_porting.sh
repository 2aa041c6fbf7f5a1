#!/bin/sh
# cli_porting.sh - docs/porting.md holds: its code is the tree's, and it
# builds and draws.
#   - the guide's listings are examples/spi_panel/spi_panel.c and board.h
#     and the band function of platform/panel/silk_panel.c, character for
#     character;
#   - the example, with a model packed by `silk pack`, built for the host
#     with tests/boards/panel_board.c (the bus a model of the ILI9341, and again
#     of the ST7789, its DMA completing only when waited for), draws every
#     packed view: the panel's pictures equal `silk render`'s byte for byte;
#   - libsilk.a built for a Cortex-M4 (hard float) and a Cortex-M0+ as the
#     guide says (make lib with the cross compiler), and the example linked
#     against it with a board of empty functions, warning-free (skipped
#     without arm-none-eabi-gcc, except in CI).
. "$(dirname "$0")/../shlib.sh"

doc=docs/porting.md

# ---- the listings ----------------------------------------------------------

# The fenced block after the line "<!-- listing FILE [FROM TO] -->": FILE
# whole, or its lines from the one starting with FROM to the one after
# that starting with TO.
listing() {
    awk -v want="$1" '
        $0 ~ /^<!-- listing / { split($0, w, " "); on = (w[3] == want); next }
        on && /^```/ { if (inside) exit; inside = 1; next }
        on && inside { print }' "$doc"
}
excerpt() {
    awk -v from="$2" -v to="$3" 'index($0, from) == 1 { on = 1 } on { print } on && index($0, to) == 1 && NR > 1 && seen { exit } on { seen = 1 }' "$1"
}
for f in examples/spi_panel/spi_panel.c examples/spi_panel/board.h; do
    listing "$f" >"$tmp/listed"
    check "porting.md lists $f as it is" cmp -s "$tmp/listed" "$f"
done
listing platform/panel/silk_panel.c >"$tmp/listed"
excerpt platform/panel/silk_panel.c "/* silk_sink.band: the band's window" "}" >"$tmp/band"
check "porting.md lists the panel sink's band function as it is" cmp -s "$tmp/listed" "$tmp/band"

# ---- the example on the host ------------------------------------------------

meshes=${SILK_MESHES:-../shared/meshes}
mesh=$meshes/bunny-500.obj
if [ ! -e "$mesh" ]; then
    echo "note: $mesh is missing; the generated torus stands in for it"
    mesh=$tmp/torus.obj
    "$SILK" gen torus -o "$mesh" >/dev/null
fi
run_silk pack "$mesh" -o "$tmp/model.h" --name model --size 320x240 --format rgb565 --views 4
check "pack: the example's model" [ "$rc" -eq 0 ]
CC=${CC:-cc}
SANFLAGS=
[ -n "${SILK_SAN:-}" ] && SANFLAGS="-fsanitize=address,undefined"
grep -o 'camera [0-9]*: --eye [^ ]*' "$tmp/model.h" >"$tmp/eyes"
drawn=$mesh   # what the panel draws: the header's compact model, or the mesh
header_model "$tmp/model.h" "$tmp/model.slkc" && drawn=$tmp/model.slkc
for panel in ILI9341 ST7789; do
    if "$CC" -std=c11 -Wall -Wextra -Wpedantic -Werror -O2 $SANFLAGS -DPANEL=SILK_PANEL_$panel -Iinclude \
        -Iplatform/panel -Iexamples/spi_panel -Itests -I"$tmp" -o "$tmp/panel_board" examples/spi_panel/spi_panel.c \
        tests/boards/panel_board.c tests/support/panel_model.c platform/panel/silk_panel.c "$build/libsilk.a" 2>"$err"; then
        pass "$panel: the example builds for the host, warning-free"
        "$tmp/panel_board" "$tmp/panel" >"$out" 2>"$err"
        status=$?
        check "$panel: the example draws on the panel model ($(head -c 200 "$err"))" test "$status" -eq 0
        check "$panel: ... 4 frames, a memory write a band" \
            grep -q 'panel_board: 4 frames shown, 60 memory writes of 307200 pixels' "$out"
        n=0
        while read -r _ k _ eye; do
            k=${k%:}
            [ -e "$tmp/ref-$k.ppm" ] ||
                "$SILK" render "$drawn" --size 320x240 --format rgb565 --eye "$eye" --aa off -o "$tmp/ref-$k.ppm"
            if cmp -s "$tmp/ref-$k.ppm" "$tmp/panel-c$k.ppm"; then n=$((n + 1)); else
                fail "$panel: the panel's frame $k equals silk render" "$(cmp "$tmp/ref-$k.ppm" "$tmp/panel-c$k.ppm" 2>&1)"
            fi
        done <"$tmp/eyes"
        check "$panel: the panel's 4 frames equal silk render byte for byte ($n)" [ "$n" -eq 4 ]
    else
        fail "$panel: the example builds for the host" "$(head -c 300 "$err")"
    fi
done

# ---- the example on Cortex-M parts ---------------------------------------------

if [ -n "${SILK_SAN:-}" ]; then
    echo "skip: the Cortex-M builds are checked in the normal pass"
elif ! command -v arm-none-eabi-gcc >/dev/null 2>&1; then
    if [ -n "${CI:-}" ]; then fail "toolchain" "CI must have arm-none-eabi-gcc"; else
        echo "skip: arm-none-eabi-gcc is not installed (make deps)"; fi
else
    cat >"$tmp/board_none.c" <<'EOF'
#include "board.h"
int spi_panel_run(void);
int board_spi_write(int dc, const uint8_t *data, size_t n) { (void)dc; (void)data; (void)n; return 0; }
int board_spi_start(const uint8_t *data, size_t n) { (void)data; (void)n; return 0; }
int board_spi_wait(void) { return 0; }
void board_delay_ms(uint32_t ms) { (void)ms; }
void board_log(const char *msg) { (void)msg; }
void board_frame_shown(int k) { (void)k; }
int main(void) { return spi_panel_run(); }
EOF
    for cpu in "cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16" "cortex-m0plus -mthumb"; do
        name=${cpu%% *}
        arch="-mcpu=$cpu"
        lib=$tmp/build-$name
        # as docs/porting.md builds it
        if make -s -C "$here/.." lib BUILD="$lib" CC=arm-none-eabi-gcc AR=arm-none-eabi-ar OPT=-Os \
            CFLAGS="$arch -ffunction-sections -fdata-sections -Werror" >"$tmp/make.out" 2>&1 &&
            arm-none-eabi-gcc -std=c11 -Wall -Wextra -Wpedantic -Werror -Os $arch -ffunction-sections \
                -fdata-sections -Iinclude -Iplatform/panel -Iexamples/spi_panel -I"$tmp" \
                -specs=nano.specs -specs=nosys.specs -Wl,--gc-sections -o "$tmp/$name.elf" \
                examples/spi_panel/spi_panel.c platform/panel/silk_panel.c "$tmp/board_none.c" "$lib/libsilk.a" \
                2>"$err"; then
            pass "$name: libsilk.a and the example build and link, warning-free ($(arm-none-eabi-size "$tmp/$name.elf" |
                awk 'NR == 2 { print $1 " bytes of flash, " $2 + $3 " of static RAM" }'))"
        else
            fail "$name: libsilk.a and the example build and link" "$(tail -c 300 "$tmp/make.out") $(head -c 300 "$err")"
        fi
    done
fi

done_testing
