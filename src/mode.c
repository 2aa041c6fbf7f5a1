/*
 * mode.c - render modes by name: the parser every front end shares, the
 * inverse of silk_mode_name (src/render.c) plus PN's level suffix.
 *
 * No paper equation lives here; "pnL" names PN triangles (Vlachos et al.
 * 2001) at level L, docs/methods.md.
 */
#include <string.h>
#include "silk/render.h"

int silk_mode_parse(const char *name, silk_mode *mode, uint32_t *level)
{
    static const silk_mode all[] = { SILK_MODE_FLAT, SILK_MODE_SMOOTH, SILK_MODE_BLEND, SILK_MODE_PN, SILK_MODE_CLIP,
                                     SILK_MODE_SILTEX };
    if (!name) return -1;
    for (size_t i = 0; i < sizeof all / sizeof all[0]; i++)
        if (strcmp(name, silk_mode_name(all[i])) == 0) {
            *mode = all[i];
            *level = 0;
            return 0;
        }
    /* "pnL": decimal digits, no sign, no leading zero, 1..SILK_PN_MAX_LEVEL */
    if (strncmp(name, "pn", 2) != 0 || name[2] < '1' || name[2] > '9') return -1;
    uint32_t l = 0;
    for (const char *p = name + 2; *p; p++) {
        if (*p < '0' || *p > '9') return -1;
        l = l * 10 + (uint32_t)(*p - '0');
        if (l > SILK_PN_MAX_LEVEL) return -1;
    }
    *mode = SILK_MODE_PN;
    *level = l;
    return 0;
}
