/*
 * fuzz_stl.c - libFuzzer harness for the STL reader (src/stl.c: ascii and
 * binary, the weld of corners into vertices) and the mesh build behind it
 * (orientation, edges, normals, features; paper III-A, III-B).
 *
 * The input is an STL file.  It is loaded twice, as fuzz/fuzz.h describes
 * (fuzz_reader): with the default options into a tight arena and with file
 * normals, a --scale and a crease angle taken from its length into a roomy
 * one.  Besides "no crash", every outcome is checked:
 *   failure: one clean line naming the file, the arena as it was;
 *   success: the mesh passes silk_mesh_validate (every index consistent),
 *            and the visibility hierarchy builds over it (or fails cleanly).
 * `make fuzz` builds it with clang -fsanitize=fuzzer,address,undefined.
 */
#include "fuzz.h"

int FUZZ_ENTRY(const uint8_t *data, size_t size)
{
    fuzz_reader(silk_load_stl, "fuzz.stl", data, size);
    return 0;
}
