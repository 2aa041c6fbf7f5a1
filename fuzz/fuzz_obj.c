/*
 * fuzz_obj.c - libFuzzer harness for the OBJ reader (src/obj.c) and the
 * mesh build behind it (edges, normals, features; paper III-A, III-B).
 *
 * The input is an OBJ file.  It is loaded twice: with the default options
 * into an arena of 64 bytes per input byte (so the out-of-memory paths run
 * for dense files), and with file normals, a --scale and a crease angle
 * taken from its length into a roomy one.  Besides "no crash",
 * every outcome is checked:
 *   failure: one clean line naming the file, the arena as it was;
 *   success: the mesh passes silk_mesh_validate (every index consistent),
 *            and the visibility hierarchy builds over it (or fails cleanly).
 * `make fuzz` builds it with clang -fsanitize=fuzzer,address,undefined.
 */
#include "fuzz.h"

int FUZZ_ENTRY(const uint8_t *data, size_t size)
{
    fuzz_reader(silk_load_obj, "fuzz.obj", data, size);
    return 0;
}
