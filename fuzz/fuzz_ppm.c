/*
 * fuzz_ppm.c - libFuzzer harness for the binary PPM reader `silk diff` uses
 * (platform/ppm_read.c), built with the core alone: the reader is included
 * here rather than linked.  Any input must give either an image whose
 * every byte can be read, of the size the header says and no larger than
 * the data holds, or one clean error line naming the file.
 */
#include "fuzz.h"
#include "../platform/ppm_read.c"

int FUZZ_ENTRY(const uint8_t *data, size_t size)
{
    uint8_t *rgb = NULL;
    int w = -1, h = -1;
    silk_error err;
    memset(&err, 0, sizeof err);
    silk_status st = silk_ppm_parse(data, size, "fuzz.ppm", &rgb, &w, &h, &err);
    if (st != SILK_OK) {
        fuzz_check_error(st, &err, "fuzz.ppm");
        fuzz_expect(rgb == NULL && w == 0 && h == 0, "a failed read left an image");
        return 0;
    }
    fuzz_expect(rgb && w > 0 && h > 0, "an empty image: %dx%d", w, h);
    size_t n = (size_t)w * (size_t)h * 3;
    fuzz_expect(n <= size, "%dx%d pixels from %zu bytes", w, h, size);
    unsigned sum = 0;
    for (size_t i = 0; i < n; i++) sum += rgb[i];   /* ASan: every byte is there */
    fuzz_expect(sum <= 255u * n, "impossible sum");
    free(rgb);
    return 0;
}
