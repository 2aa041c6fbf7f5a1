/*
 * fuzz_ply.c - libFuzzer harness for the PLY reader (src/ply.c: ASCII and
 * both binary byte orders) and the mesh build behind it (edges, normals,
 * features; paper III-A, III-B).
 *
 * The input is a PLY file.  It is loaded twice: with the default options
 * into an arena of 64 bytes per input byte (binary PLY is dense, so the
 * out-of-memory paths run often), and with file normals, a --scale and a
 * crease angle taken from its length into a roomy one.  Besides "no crash",
 * every outcome is checked:
 *   failure: one clean line naming the file, the arena as it was;
 *   success: the mesh passes silk_mesh_validate (every index consistent),
 *            and the visibility hierarchy builds over it (or fails cleanly).
 * `make fuzz` builds it with clang -fsanitize=fuzzer,address,undefined.
 */
#include "fuzz.h"

int FUZZ_ENTRY(const uint8_t *data, size_t size)
{
    fuzz_reader(silk_load_ply, "fuzz.ply", data, size);
    return 0;
}
