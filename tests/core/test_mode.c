/*
 * test_mode.c - silk_mode_parse (src/mode.c): every name silk_mode_name
 * gives comes back as its mode, "pnL" gives PN at level L for exactly the
 * levels silk renders, and nothing else parses (the command line, the
 * contact sheet and the benchmark all rely on this one parser).
 */
#include <stdio.h>
#include <string.h>
#include "check.h"
#include "silk/silk.h"

TEST(names_round_trip)
{
    const silk_mode all[] = { SILK_MODE_FLAT, SILK_MODE_SMOOTH, SILK_MODE_PN, SILK_MODE_BLEND, SILK_MODE_CLIP };
    for (size_t i = 0; i < sizeof all / sizeof all[0]; i++) {
        silk_mode m = (silk_mode)99;
        uint32_t level = 99;
        CHECKF(silk_mode_parse(silk_mode_name(all[i]), &m, &level) == 0, "%s", silk_mode_name(all[i]));
        CHECKF(m == all[i] && level == 0, "%s -> mode %d level %u", silk_mode_name(all[i]), (int)m, (unsigned)level);
    }
}

TEST(pn_levels)
{
    char name[16];
    for (uint32_t l = 1; l <= SILK_PN_MAX_LEVEL; l++) {
        snprintf(name, sizeof name, "pn%u", (unsigned)l);
        silk_mode m = SILK_MODE_FLAT;
        uint32_t level = 0;
        CHECKF(silk_mode_parse(name, &m, &level) == 0 && m == SILK_MODE_PN && level == l, "%s", name);
    }
}

TEST(refused)
{
    const char *bad[] = { "", "Flat", "flat ", " smooth", "pn0", "pn03", "pn-1", "pn+2", "pn33", "pn999999999999",
                          "pnx", "pn3x", "p", "blendx", "smoothpn", "pn 3" };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        silk_mode m = SILK_MODE_BLEND;
        uint32_t level = 7;
        CHECKF(silk_mode_parse(bad[i], &m, &level) == -1, "\"%s\" parsed", bad[i]);
        CHECKF(m == SILK_MODE_BLEND && level == 7, "\"%s\" changed the outputs", bad[i]);
    }
    silk_mode m;
    uint32_t level;
    CHECK(silk_mode_parse(NULL, &m, &level) == -1);
}

int main(void)
{
    RUN(names_round_trip);
    RUN(pn_levels);
    RUN(refused);
    return check_done();
}
