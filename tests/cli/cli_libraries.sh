#!/bin/sh
# cli_libraries.sh - the Arduino library (made by `make arduino`) and the
# PlatformIO package (library.json over the tree) build for a Cortex-M4
# (hard float) and a Cortex-M0+, with the example sketch, the way each
# tool builds them.  Neither tool is installed here (they fetch their
# toolchains and cores from the network), so their rules are replicated
# with arm-none-eabi-gcc, and a stand-in for the Arduino core's headers
# (Arduino.h, SPI.h: the declarations the sketch uses, and definitions
# that do nothing, to link):
#   Arduino (arduino-cli, library format 1.5, "recursive" layout): every
#     .c, .cpp and .S file under the library's src/, recursively, with
#     src/ as the library's one include path; the sketch's .ino turned into
#     SKETCH.ino.cpp behind `#include <Arduino.h>`, compiled as C++ with the
#     libraries' include paths and the sketch's folder; all linked with
#     the core, unused sections dropped.
#   PlatformIO (PlatformIOLibBuilder): the files srcFilter selects under
#     srcDir, with includeDir, srcDir and the -I of build.flags (relative to
#     the library) on the include path, which the project inherits; the
#     example folder as the project's src/, its .ino turned into a .cpp
#     the same way.
# Checked too: library.properties has the fields the Library Manager
# requires, the example follows the sketch-folder rule (the folder's name
# is the .ino's), and the example's model is what `make example-model`
# writes.  Without arm-none-eabi-gcc this skips, except in CI.
. "$(dirname "$0")/../shlib.sh"

if [ -n "${SILK_SAN:-}" ]; then
    echo "skip: the packages are built for Cortex-M in the normal pass"
    done_testing
    exit 0
fi

# ---- the layouts ---------------------------------------------------------------

make -s -C "$here/.." arduino ARDUINO_OUT="$tmp/arduino" BUILD="$build" >"$out" 2>"$err"
check "make arduino: exit 0" test $? -eq 0
lib=$tmp/arduino/silk
props=$lib/library.properties
for f in name version author maintainer sentence paragraph category url architectures; do
    check "library.properties: $f" grep -qE "^$f=.+" "$props"
done
check "library.properties: the version is the Makefile's" \
    grep -qx "version=$(sed -n 's/^VERSION  *:= *//p' "$here/../Makefile")" "$props"
check "library.properties: a Library Manager category" \
    grep -qxE 'category=(Display|Communication|Signal Input/Output|Sensors|Device Control|Timing|Data Storage|Data Processing|Other)' "$props"
check "arduino: src/ holds the headers and the sources" test -f "$lib/src/silk.h" -a -f "$lib/src/silk/silk.h" -a \
    -f "$lib/src/core/render.c" -a -f "$lib/src/silk_panel.c"
check "arduino: the example's folder is named for its sketch" test -f "$lib/examples/silk_panel/silk_panel.ino"
check "arduino: no library.properties in the tree (its layout is not the tree's)" test ! -e "$here/../library.properties"
if command -v python3 >/dev/null 2>&1; then
    check "library.json: the version is the Makefile's" python3 -c "
import json, sys
d = json.load(open('$here/../library.json'))
assert d['version'] == sys.argv[1], d['version']
assert d['build']['includeDir'] == 'include' and d['build']['srcDir'] == '.'
" "$(sed -n 's/^VERSION  *:= *//p' "$here/../Makefile")"
fi

# The example's model: what `make example-model` writes now.
mkdir -p "$tmp/model"
(cd "$tmp/model" && "$OLDPWD/$SILK" gen torus --segments 16 --bands 8 -o torus.obj >/dev/null &&
    "$OLDPWD/$SILK" pack torus.obj -o model.h --name model --size 320x240 --format rgb565 --views 12 \
    --visibility brute >/dev/null)
check "examples/silk_panel/model.h is what make example-model writes" cmp -s "$tmp/model/model.h" \
    examples/silk_panel/model.h

if ! command -v arm-none-eabi-gcc >/dev/null 2>&1; then
    if [ -n "${CI:-}" ]; then fail "toolchain" "CI must have arm-none-eabi-gcc"; else
        echo "skip: arm-none-eabi-gcc is not installed (make deps)"; fi
    done_testing
    exit 0
fi

# ---- a stand-in for the Arduino core ---------------------------------------------

core=$tmp/core
mkdir -p "$core"
cat >"$core/Arduino.h" <<'EOF'
#ifndef ARDUINO_H
#define ARDUINO_H
#include <stddef.h>
#include <stdint.h>
#define HIGH 1
#define LOW 0
#define OUTPUT 1
void pinMode(uint8_t pin, uint8_t mode);
void digitalWrite(uint8_t pin, uint8_t value);
void delay(unsigned long ms);
unsigned long millis(void);
#ifdef __cplusplus
class HardwareSerial {
public:
    void begin(unsigned long baud);
    size_t print(const char *s);
    size_t print(int v);
    size_t print(unsigned long v);
    size_t println(const char *s);
};
extern HardwareSerial Serial;
#endif
#endif
EOF
cat >"$core/SPI.h" <<'EOF'
#ifndef SPI_H
#define SPI_H
#include <Arduino.h>
#define MSBFIRST 1
#define SPI_MODE0 0
class SPISettings {
public:
    SPISettings(uint32_t clock, uint8_t order, uint8_t mode) : clock_(clock), order_(order), mode_(mode) {}
    uint32_t clock_;
    uint8_t order_, mode_;
};
class SPIClass {
public:
    void begin();
    void beginTransaction(SPISettings settings);
    void endTransaction();
    uint8_t transfer(uint8_t data);
    void transfer(void *buf, size_t count);
};
extern SPIClass SPI;
#endif
EOF
cat >"$core/core.cpp" <<'EOF'
#include <Arduino.h>
#include <SPI.h>
void pinMode(uint8_t, uint8_t) {}
void digitalWrite(uint8_t, uint8_t) {}
void delay(unsigned long) {}
unsigned long millis(void) { return 0; }
void HardwareSerial::begin(unsigned long) {}
size_t HardwareSerial::print(const char *) { return 0; }
size_t HardwareSerial::print(int) { return 0; }
size_t HardwareSerial::print(unsigned long) { return 0; }
size_t HardwareSerial::println(const char *) { return 0; }
HardwareSerial Serial;
void SPIClass::begin() {}
void SPIClass::beginTransaction(SPISettings) {}
void SPIClass::endTransaction() {}
uint8_t SPIClass::transfer(uint8_t) { return 0; }
void SPIClass::transfer(void *, size_t) {}
SPIClass SPI;
void setup();
void loop();
int main() { setup(); loop(); return 0; }
EOF

# SKETCH.ino as the tools see it: a .cpp behind the core's header (the
# sketch declares its functions before it uses them: no prototypes to add).
ino_to_cpp() {
    { echo '#include <Arduino.h>'; echo "#line 1 \"$(basename "$1")\""; cat "$1"; } >"$2"
}

WARN="-Wall -Wextra -Werror"
# objects DIR FLAGS INCLUDES FILES...: each compiled as its tool would, C
# as gnu11 and C++ as gnu++17 without exceptions and RTTI, into DIR.
objects() {
    d=$1 fl=$2 inc=$3
    shift 3
    mkdir -p "$d"
    for f in "$@"; do
        o=$d/$(echo "$f" | tr '/' '_').o
        case "$f" in
        *.c) arm-none-eabi-gcc -std=gnu11 $fl $WARN $inc -c "$f" -o "$o" ;;
        *.cpp) arm-none-eabi-g++ -std=gnu++17 -fno-exceptions -fno-rtti $fl $WARN $inc -c "$f" -o "$o" ;;
        esac || return 1
    done
}

link_all() {
    # gcc, not g++: the sketch needs no C++ library (no exceptions, no RTTI), and a
    # toolchain may not ship one (Debian's gcc-arm-none-eabi does not)
    arm-none-eabi-gcc $1 -specs=nano.specs -specs=nosys.specs -Wl,--gc-sections -o "$2" "$3"/*.o
}

for cpu in "cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16" "cortex-m0plus -mthumb"; do
    name=${cpu%% *}
    fl="-mcpu=$cpu -Os -ffunction-sections -fdata-sections"

    # Arduino: the library's src/, recursively; the sketch; the core.
    a=$tmp/a-$name
    mkdir -p "$a"
    ino_to_cpp "$lib/examples/silk_panel/silk_panel.ino" "$a/silk_panel.ino.cpp"
    srcs=$(find "$lib/src" -name '*.c' -o -name '*.cpp' -o -name '*.S' | sort)
    if objects "$a/obj" "$fl" "-I$lib/src -I$core" $srcs 2>"$err" &&
        objects "$a/obj" "$fl" "-I$core -I$lib/src -I$lib/examples/silk_panel" "$a/silk_panel.ino.cpp" \
            "$core/core.cpp" 2>>"$err" && link_all "$fl" "$a/sketch.elf" "$a/obj" 2>>"$err"; then
        pass "arduino, $name: $(echo "$srcs" | wc -w) library files and the sketch build warning-free and link ($(
            arm-none-eabi-size "$a/sketch.elf" | awk 'NR == 2 { print $1 " bytes of flash" }'))"
    else
        fail "arduino, $name: the library and the sketch build" "$(head -c 400 "$err")"
    fi

    # PlatformIO: library.json's selection and include paths over the tree.
    if ! command -v python3 >/dev/null 2>&1; then
        echo "skip: PlatformIO's rules are read from library.json with python3, which is missing"
        continue
    fi
    p=$tmp/p-$name
    python3 - "$here/.." >"$tmp/pio" <<'EOF'
import fnmatch, json, os, sys
root = sys.argv[1]
b = json.load(open(os.path.join(root, 'library.json')))['build']
src = os.path.normpath(os.path.join(root, b.get('srcDir', 'src')))
filt = b.get('srcFilter', ['+<*>'])
if isinstance(filt, str): filt = filt.split()
files = []
for d, _, fs in os.walk(src):
    for f in fs:
        rel = os.path.relpath(os.path.join(d, f), src)
        keep = False
        for rule in filt:   # in order, the last that matches decides, as PlatformIO applies them
            sign, pat = rule[0], rule[2:-1]
            if fnmatch.fnmatch(rel, pat) or fnmatch.fnmatch(rel, pat + '/*'): keep = sign == '+'
        if keep and f.endswith(('.c', '.cpp', '.S')): files.append(os.path.join(d, f))
inc = [os.path.join(root, b.get('includeDir', 'include')), src]
flags = b.get('flags', [])
if isinstance(flags, str): flags = [flags]
for f in flags:
    if f.startswith('-I'): inc.append(os.path.join(root, f[2:].strip()))
print(' '.join('-I' + os.path.normpath(i) for i in inc))
print(' '.join(sorted(files)))
EOF
    inc=$(sed -n 1p "$tmp/pio")
    srcs=$(sed -n 2p "$tmp/pio")
    mkdir -p "$p"
    ino_to_cpp examples/silk_panel/silk_panel.ino "$p/silk_panel.ino.cpp"
    if [ -n "$srcs" ] && objects "$p/obj" "$fl" "$inc -I$core" $srcs 2>"$err" &&
        objects "$p/obj" "$fl" "-I$core $inc -Iexamples/silk_panel" "$p/silk_panel.ino.cpp" "$core/core.cpp" \
            2>>"$err" && link_all "$fl" "$p/sketch.elf" "$p/obj" 2>>"$err"; then
        pass "platformio, $name: $(echo "$srcs" | wc -w) library files and the example build warning-free and link ($(
            arm-none-eabi-size "$p/sketch.elf" | awk 'NR == 2 { print $1 " bytes of flash" }'))"
    else
        fail "platformio, $name: the library and the example build" "$(head -c 400 "$err")"
    fi
done
check "arduino and platformio build the same files" \
    test "$(find "$lib/src" -name '*.c' | wc -l)" -eq "$(ls src/*.c platform/panel/*.c | wc -l)"

done_testing
