/*
 * siltex.c - silhouette textures at run time (Wu, Wei, Wang, Guo,
 * "Silhouette Texture", sections 3.3-3.5; silk/siltex.h): the angles of a
 * texel, stored or reconstructed from the compressed form (sec. 3.5), the
 * single-lobe lookup of eq. 4, and the HAL stages that draw the outer hull
 * through it.
 *
 * Per pixel: C and T (the hull's, interpolated) make the texel frame
 * (C, T', B); the view direction d gives the azimuth theta in that frame
 * and d.C; phi(theta) comes from the four texels around the atlas point
 * and the two azimuth samples around theta (bilinear x linear); the pixel
 * is drawn iff d.C >= cos(phi).  The azimuth is an octant fold and a table
 * of atan, cos(phi) a table and two Taylor terms: no trigonometric
 * function and no floating point.  tests/core/test_siltex.c compares each step
 * with a double-precision reference.
 */
#include <string.h>
#include "silk/siltex.h"
#include "silk/hal.h"
#include "silk/texture.h"

static uint32_t rd16(const uint8_t *p) { return (uint32_t)p[0] | (uint32_t)p[1] << 8; }
static int32_t rd16s(const uint8_t *p) { return (int32_t)(int16_t)rd16(p); }
static int32_t rd32s(const uint8_t *p)
{
    uint32_t u = (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
    return u <= 0x7fffffffu ? (int32_t)u : -(int32_t)(~u) - 1;
}

/* atan(i / 256) in turns, Q0.20 (2^20 = 2 pi) */
static const uint32_t atan_turns[257] = {
    0, 652, 1304, 1956, 2607, 3259, 3911, 4562, 5213, 5865,
    6516, 7166, 7817, 8467, 9117, 9767, 10417, 11066, 11715, 12363,
    13012, 13659, 14307, 14954, 15600, 16246, 16891, 17536, 18181, 18825,
    19468, 20111, 20753, 21395, 22036, 22676, 23315, 23954, 24593, 25230,
    25867, 26503, 27138, 27772, 28406, 29039, 29671, 30302, 30932, 31561,
    32190, 32817, 33444, 34069, 34694, 35318, 35940, 36562, 37182, 37802,
    38420, 39038, 39654, 40269, 40884, 41497, 42108, 42719, 43329, 43937,
    44544, 45150, 45755, 46358, 46960, 47561, 48161, 48760, 49357, 49953,
    50547, 51140, 51732, 52323, 52912, 53500, 54087, 54672, 55255, 55838,
    56419, 56998, 57576, 58153, 58728, 59302, 59874, 60445, 61014, 61582,
    62148, 62713, 63276, 63838, 64398, 64957, 65514, 66070, 66624, 67177,
    67728, 68278, 68826, 69372, 69917, 70460, 71002, 71542, 72080, 72617,
    73152, 73686, 74218, 74748, 75277, 75804, 76330, 76854, 77376, 77897,
    78416, 78934, 79449, 79963, 80476, 80987, 81496, 82004, 82510, 83014,
    83517, 84018, 84517, 85015, 85511, 86005, 86498, 86989, 87478, 87966,
    88452, 88937, 89419, 89901, 90380, 90858, 91334, 91809, 92282, 92753,
    93222, 93690, 94157, 94621, 95084, 95546, 96006, 96464, 96920, 97375,
    97828, 98280, 98730, 99178, 99625, 100070, 100513, 100955, 101395, 101834,
    102271, 102707, 103140, 103573, 104003, 104432, 104860, 105286, 105710, 106133,
    106554, 106973, 107391, 107808, 108223, 108636, 109048, 109458, 109867, 110274,
    110679, 111083, 111486, 111887, 112286, 112684, 113081, 113476, 113869, 114261,
    114651, 115040, 115428, 115814, 116198, 116581, 116963, 117343, 117722, 118099,
    118474, 118849, 119221, 119593, 119963, 120331, 120698, 121064, 121428, 121791,
    122152, 122512, 122871, 123228, 123584, 123939, 124292, 124643, 124994, 125343,
    125690, 126037, 126382, 126725, 127068, 127408, 127748, 128086, 128423, 128759,
    129093, 129426, 129758, 130088, 130418, 130745, 131072,
};

/* cos(q pi / 255) and sin(q pi / 255), Q2.30 */
static const int32_t cos_q[256] = {
    1073741824, 1073660338, 1073415892, 1073008523, 1072438293, 1071705289,
    1070809621, 1069751427, 1068530865, 1067148122, 1065603408, 1063896957,
    1062029028, 1059999904, 1057809893, 1055459329, 1052948567, 1050277989,
    1047448000, 1044459029, 1041311531, 1038005983, 1034542886, 1030922767,
    1027146174, 1023213682, 1019125886, 1014883408, 1010486891, 1005937002,
    1001234432, 996379896, 991374129, 986217891, 980911966, 975457158,
    969854295, 964104228, 958207830, 952165995, 945979640, 939649705,
    933177150, 926562958, 919808132, 912913698, 905880702, 898710212,
    891403316, 883961122, 876384761, 868675383, 860834158, 852862275,
    844760945, 836531397, 828174881, 819692665, 811086035, 802356300,
    793504783, 784532828, 775441796, 766233069, 756908043, 747468133,
    737914773, 728249412, 718473518, 708588574, 698596080, 688497554,
    678294528, 667988551, 657581186, 647074014, 636468629, 625766641,
    614969674, 604079367, 593097374, 582025360, 570865006, 559618007,
    548286069, 536870912, 525374269, 513797885, 502143517, 490412933,
    478607915, 466730254, 454781753, 442764224, 430679494, 418529395,
    406315771, 394040477, 381705376, 369312339, 356863249, 344359993,
    331804471, 319198588, 306544257, 293843398, 281097940, 268309817,
    255480970, 242613347, 229708899, 216769586, 203797372, 190794226,
    177762121, 164703035, 151618951, 138511854, 125383734, 112236583,
    99072397, 85893173, 72700913, 59497618, 46285293, 33065942,
    19841573, 6614192, -6614192, -19841573, -33065942, -46285293,
    -59497618, -72700913, -85893173, -99072397, -112236583, -125383734,
    -138511854, -151618951, -164703035, -177762121, -190794226, -203797372,
    -216769586, -229708899, -242613347, -255480970, -268309817, -281097940,
    -293843398, -306544257, -319198588, -331804471, -344359993, -356863249,
    -369312339, -381705376, -394040477, -406315771, -418529395, -430679494,
    -442764224, -454781753, -466730254, -478607915, -490412933, -502143517,
    -513797885, -525374269, -536870912, -548286069, -559618007, -570865006,
    -582025360, -593097374, -604079367, -614969674, -625766641, -636468629,
    -647074014, -657581186, -667988551, -678294528, -688497554, -698596080,
    -708588574, -718473518, -728249412, -737914773, -747468133, -756908043,
    -766233069, -775441796, -784532828, -793504783, -802356300, -811086035,
    -819692665, -828174881, -836531397, -844760945, -852862275, -860834158,
    -868675383, -876384761, -883961122, -891403316, -898710212, -905880702,
    -912913698, -919808132, -926562958, -933177150, -939649705, -945979640,
    -952165995, -958207830, -964104228, -969854295, -975457158, -980911966,
    -986217891, -991374129, -996379896, -1001234432, -1005937002, -1010486891,
    -1014883408, -1019125886, -1023213682, -1027146174, -1030922767, -1034542886,
    -1038005983, -1041311531, -1044459029, -1047448000, -1050277989, -1052948567,
    -1055459329, -1057809893, -1059999904, -1062029028, -1063896957, -1065603408,
    -1067148122, -1068530865, -1069751427, -1070809621, -1071705289, -1072438293,
    -1073008523, -1073415892, -1073660338, -1073741824,
};
static const int32_t sin_q[256] = {
    0, 13228134, 26454260, 39676370, 52892459, 66100520,
    79298548, 92484540, 105656494, 118812412, 131950297, 145068155,
    158163994, 171235827, 184281670, 197299542, 210287469, 223243478,
    236165603, 249051884, 261900363, 274709091, 287476123, 300199523,
    312877358, 325507705, 338088647, 350618273, 363094683, 375515982,
    387880286, 400185717, 412430408, 424612500, 436730145, 448781503,
    460764745, 472678053, 484519617, 496287641, 507980339, 519595935,
    531132668, 542588785, 553962548, 565252231, 576456120, 587572514,
    598599727, 609536085, 620379928, 631129609, 641783498, 652339976,
    662797443, 673154311, 683409007, 693559976, 703605676, 713544584,
    723375189, 733096001, 742705544, 752202359, 761585005, 770852058,
    780002111, 789033775, 797945680, 806736474, 815404820, 823949405,
    832368931, 840662121, 848827714, 856864473, 864771177, 872546627,
    880189641, 887699061, 895073746, 902312576, 909414454, 916378301,
    923203061, 929887697, 936431194, 942832561, 949090824, 955205035,
    961174265, 966997608, 972674181, 978203121, 983583590, 988814771,
    993895869, 998826114, 1003604758, 1008231075, 1012704363, 1017023942,
    1021189159, 1025199379, 1029053994, 1032752420, 1036294096, 1039678482,
    1042905067, 1045973359, 1048882894, 1051633230, 1054223949, 1056654659,
    1058924989, 1061034596, 1062983160, 1064770384, 1066395998, 1067859754,
    1069161431, 1070300830, 1071277780, 1072092131, 1072743761, 1073232569,
    1073558483, 1073721452, 1073721452, 1073558483, 1073232569, 1072743761,
    1072092131, 1071277780, 1070300830, 1069161431, 1067859754, 1066395998,
    1064770384, 1062983160, 1061034596, 1058924989, 1056654659, 1054223949,
    1051633230, 1048882894, 1045973359, 1042905067, 1039678482, 1036294096,
    1032752420, 1029053994, 1025199379, 1021189159, 1017023942, 1012704363,
    1008231075, 1003604758, 998826114, 993895869, 988814771, 983583590,
    978203121, 972674181, 966997608, 961174265, 955205035, 949090824,
    942832561, 936431194, 929887697, 923203061, 916378301, 909414454,
    902312576, 895073746, 887699061, 880189641, 872546627, 864771177,
    856864473, 848827714, 840662121, 832368931, 823949405, 815404820,
    806736474, 797945680, 789033775, 780002111, 770852058, 761585005,
    752202359, 742705544, 733096001, 723375189, 713544584, 703605676,
    693559976, 683409007, 673154311, 662797443, 652339976, 641783498,
    631129609, 620379928, 609536085, 598599727, 587572514, 576456120,
    565252231, 553962548, 542588785, 531132668, 519595935, 507980339,
    496287641, 484519617, 472678053, 460764745, 448781503, 436730145,
    424612500, 412430408, 400185717, 387880286, 375515982, 363094683,
    350618273, 338088647, 325507705, 312877358, 300199523, 287476123,
    274709091, 261900363, 249051884, 236165603, 223243478, 210287469,
    197299542, 184281670, 171235827, 158163994, 145068155, 131950297,
    118812412, 105656494, 92484540, 79298548, 66100520, 52892459,
    39676370, 26454260, 13228134, 0,
};

uint32_t silk_siltex_q(const silk_siltex *st, uint32_t t, uint32_t i)
{
    if (!(st->flags & SILK_STEX_COMPRESSED)) return st->angles[(size_t)t * st->k + i];
    /* in units of 2^-30 q: |weight| <= 128, |scale| <= 2^31, |basis| <= 2^15,
     * so each term is below 2^53 and the sum of 64 below 2^59 */
    int64_t sum = (int64_t)rd16s(st->mean + 2 * (size_t)i) * ((int64_t)1 << 26);
    const int8_t *w = (const int8_t *)(const void *)(st->weights + (size_t)t * st->e);
    for (uint32_t j = 0; j < st->e; j++)
        sum += (int64_t)w[j] * rd32s(st->scale + 4 * (size_t)j) * rd16s(st->basis + 2 * ((size_t)j * st->k + i));
    int64_t q = (sum + ((int64_t)1 << 29)) >> 30;
    return q < 0 ? 0 : (q > 255 ? 255 : (uint32_t)q);
}

uint32_t silk_siltex_azimuth(int64_t x, int64_t y)
{
    uint64_t ax = silk_abs64(x), ay = silk_abs64(y);
    if (ax == 0 && ay == 0) return 0;
    /* the octant: the smaller over the larger is a ratio in [0, 1] */
    uint64_t lo = ay <= ax ? ay : ax, hi = ay <= ax ? ax : ay;
    while (hi >= ((uint64_t)1 << 38)) {   /* room for the ratio's 24 bits */
        hi >>= 1;
        lo >>= 1;
    }
    uint32_t r = (uint32_t)((lo << 24) / hi);   /* Q24, 0 .. 2^24 */
    uint32_t i = r >> 16, f = r & 0xffff;
    uint32_t a = atan_turns[i] + (i < 256 ? (uint32_t)(((atan_turns[i + 1] - atan_turns[i]) * f + 32768) >> 16) : 0);
    if (ay > ax) a = (1u << 18) - a;                  /* pi/2 - atan(x/y) */
    if (x < 0) a = (1u << 19) - a;                    /* left half: pi - a */
    if (y < 0) a = ((1u << 20) - a) & ((1u << 20) - 1);   /* lower half: 2 pi - a */
    return a;
}

int32_t silk_siltex_cos(uint32_t q16)
{
    uint32_t i = q16 >> 16;
    if (i >= 255) return cos_q[255];
    /* h: the rest of the angle in radians, Q30, below pi / 255 */
    int64_t h = ((int64_t)(q16 & 0xffff) * 13228468 + 32768) >> 16;
    int64_t h2 = (h * h) >> 30, h3 = (h2 * h) >> 30;
    int64_t c = (int64_t)cos_q[i] * (((int64_t)1 << 30) - h2 / 2) - (int64_t)sin_q[i] * (h - h3 / 6);
    return (int32_t)((c + ((int64_t)1 << 29)) >> 30);
}

uint32_t silk_siltex_acos(int64_t c)
{
    if (c >= cos_q[0]) return 0;
    if (c <= cos_q[255]) return 255u << 16;
    uint32_t lo = 0, hi = 255;   /* cos_q[lo] > c >= cos_q[hi] */
    while (hi - lo > 1) {
        uint32_t mid = (lo + hi) / 2;
        if (cos_q[mid] > c) lo = mid;
        else hi = mid;
    }
    int64_t span = (int64_t)cos_q[lo] - cos_q[hi];
    int64_t q = ((int64_t)lo << 16) + (((int64_t)cos_q[lo] - c) * 65536 + span / 2) / span;
    /* then one Newton step on cos(q) = c: the chord is off by up to a
     * twelfth of a step next to the table's ends, where cos bends most
     * against its slope; -dcos/dq is sin(q pi / 255) pi / 255 (Q30 per q) */
    int64_t sn = sin_q[lo] + ((((int64_t)sin_q[hi] - sin_q[lo]) * (q & 0xffff)) >> 16);
    int64_t slope = (sn * 13228468) >> 30;
    if (slope > 0) {
        int64_t dq = ((int64_t)silk_siltex_cos((uint32_t)q) - c) * 65536 / slope;
        q += dq < -65536 ? -65536 : (dq > 65536 ? 65536 : dq);
    }
    return (uint32_t)(q < (int64_t)lo << 16 ? (int64_t)lo << 16 : (q > (int64_t)hi << 16 ? (int64_t)hi << 16 : q));
}

int silk_siltex_frame(const silk_fx c[3], const silk_fx t[3], int64_t C[3], int64_t T[3], int64_t B[3])
{
    if (!silk_unit64(c[0], c[1], c[2], C)) return 0;
    int64_t tc = ((int64_t)t[0] * C[0] + (int64_t)t[1] * C[1] + (int64_t)t[2] * C[2]) >> 16;
    int64_t p[3] = { t[0] - ((tc * C[0]) >> 16), t[1] - ((tc * C[1]) >> 16), t[2] - ((tc * C[2]) >> 16) };
    if (!silk_unit64(p[0], p[1], p[2], T) || (silk_abs64(tc) > SILK_FX_ONE - 64)) {
        /* T along C: any perpendicular will do, from the axis C is least along */
        int k = silk_abs64(C[0]) <= silk_abs64(C[1]) ? (silk_abs64(C[0]) <= silk_abs64(C[2]) ? 0 : 2)
                                                     : (silk_abs64(C[1]) <= silk_abs64(C[2]) ? 1 : 2);
        int64_t e[3] = { 0, 0, 0 };
        e[k] = SILK_FX_ONE;
        p[0] = e[0] - ((C[k] * C[0]) >> 16);
        p[1] = e[1] - ((C[k] * C[1]) >> 16);
        p[2] = e[2] - ((C[k] * C[2]) >> 16);
        silk_unit64(p[0], p[1], p[2], T);
    }
    B[0] = (C[1] * T[2] - C[2] * T[1]) >> 16;
    B[1] = (C[2] * T[0] - C[0] * T[2]) >> 16;
    B[2] = (C[0] * T[1] - C[1] * T[0]) >> 16;
    return 1;
}

/* The four texels around (u, v), clamped, and the weights of the right
 * column and the lower row (Q16). */
typedef struct texels {
    uint32_t t[4];   /* (x0, y0), (x1, y0), (x0, y1), (x1, y1) */
    int64_t wx, wy;
} texels;

static void texels_at(const silk_siltex *st, silk_fx u, silk_fx v, texels *o)
{
    int64_t fx = (int64_t)u - SILK_FX_HALF, fy = (int64_t)v - SILK_FX_HALF;
    int64_t x0 = fx >> 16, y0 = fy >> 16;
    o->wx = fx & 0xffff;
    o->wy = fy & 0xffff;
    int64_t xs[2] = { x0, x0 + 1 }, ys[2] = { y0, y0 + 1 };
    for (int k = 0; k < 2; k++) {
        xs[k] = xs[k] < 0 ? 0 : (xs[k] >= st->w ? st->w - 1 : xs[k]);
        ys[k] = ys[k] < 0 ? 0 : (ys[k] >= st->h ? st->h - 1 : ys[k]);
    }
    for (int k = 0; k < 4; k++) o->t[k] = (uint32_t)(ys[k >> 1] * st->w + xs[k & 1]);
}

static int64_t blend4(const texels *tx, const int64_t p[4])
{
    int64_t top = p[0] * 65536 + (p[1] - p[0]) * tx->wx, bot = p[2] * 65536 + (p[3] - p[2]) * tx->wx;
    return (top * 65536 + (bot - top) * tx->wy + ((int64_t)1 << 31)) >> 32;
}

/* phi at the texels around a point, azimuth az (silk_siltex_phi). */
static uint32_t phi_at(const silk_siltex *st, const texels *tx, uint32_t az)
{
    uint64_t s = (uint64_t)(az & ((1u << 20) - 1)) * st->k;   /* Q20 samples */
    uint32_t i0 = (uint32_t)(s >> 20), i1 = i0 + 1 == st->k ? 0 : i0 + 1;
    int64_t f = (int64_t)((s >> 4) & 0xffff), p[4];
    for (int k = 0; k < 4; k++) {
        int64_t a = silk_siltex_q(st, tx->t[k], i0), b = silk_siltex_q(st, tx->t[k], i1);
        p[k] = a * 65536 + (b - a) * f;   /* Q16 q units */
    }
    int64_t phi = blend4(tx, p);
    return phi < 0 ? 0 : (uint32_t)phi;
}

uint32_t silk_siltex_phi(const silk_siltex *st, silk_fx u, silk_fx v, uint32_t az)
{
    texels tx;
    texels_at(st, u, v, &tx);
    return phi_at(st, &tx, az);
}

/* The lobe at the texels around a point along d: phi (q units, Q16) and
 * d.C (Q2.30); 0 when the interpolated C is zero (nothing is seen). */
static int lobe_at(const silk_siltex *st, const texels *tx, const silk_fx c[3], const silk_fx t[3],
                   const int64_t d[3], uint32_t *phi, int64_t *dc)
{
    int64_t C[3], T[3], B[3];
    if (!silk_siltex_frame(c, t, C, T, B)) return 0;
    int64_t dt = (d[0] * T[0] + d[1] * T[1] + d[2] * T[2]) >> 16;
    int64_t db = (d[0] * B[0] + d[1] * B[1] + d[2] * B[2]) >> 16;
    *dc = (d[0] * C[0] + d[1] * C[1] + d[2] * C[2]) >> 2;   /* Q32 to Q30 */
    *phi = phi_at(st, tx, silk_siltex_azimuth(dt, db));
    return 1;
}

/* Eq. 4 at the texels around a point (silk_siltex_visible). */
static int visible_at(const silk_siltex *st, const texels *tx, const silk_fx c[3], const silk_fx t[3],
                      const int64_t d[3])
{
    uint32_t phi;
    int64_t dc;
    return lobe_at(st, tx, c, t, d, &phi, &dc) && dc >= silk_siltex_cos(phi);
}

int silk_siltex_visible(const silk_siltex *st, silk_fx u, silk_fx v, const silk_fx c[3], const silk_fx t[3],
                        const int64_t d[3])
{
    texels tx;
    texels_at(st, u, v, &tx);
    return visible_at(st, &tx, c, t, d);
}

/* Octahedral normal of texel t, decoded: |x| + |y| + |z| = 127. */
static void normal_of(const silk_siltex *st, uint32_t t, int64_t n[3])
{
    int64_t x = (int8_t)st->normal[2 * (size_t)t], y = (int8_t)st->normal[2 * (size_t)t + 1];
    x = x < -127 ? -127 : x;
    y = y < -127 ? -127 : y;
    int64_t ax = x < 0 ? -x : x, ay = y < 0 ? -y : y, z = 127 - ax - ay;
    if (z < 0) {   /* the lower hemisphere, folded over the diagonals */
        int64_t nx = (127 - ay) * (x < 0 ? -1 : 1), ny = (127 - ax) * (y < 0 ? -1 : 1);
        x = nx;
        y = ny;
    }
    n[0] = x;
    n[1] = y;
    n[2] = z;
}

/* The decoded normals blended, then normalised once: neighbouring texels'
 * codes are of nearly equal length, so this is the blend of the unit
 * normals to well under a level of shading. */
static void normal_at(const silk_siltex *st, const texels *tx, int64_t n[3])
{
    int64_t m[4][3], b[3];
    for (int k = 0; k < 4; k++) normal_of(st, tx->t[k], m[k]);
    for (int i = 0; i < 3; i++) {
        int64_t p[4] = { m[0][i] * 65536, m[1][i] * 65536, m[2][i] * 65536, m[3][i] * 65536 };
        b[i] = blend4(tx, p);
    }
    if (!silk_unit64(b[0], b[1], b[2], n)) n[0] = n[1] = 0, n[2] = SILK_FX_ONE;
}

void silk_siltex_normal(const silk_siltex *st, silk_fx u, silk_fx v, int64_t n[3])
{
    texels tx;
    texels_at(st, u, v, &tx);
    normal_at(st, &tx, n);
}

/* ---- the HAL stages ------------------------------------------------------------- */

enum { VAR_POS = 0, VAR_UV = 3, VAR_C = 5, VAR_T = 8, VAR_COUNT = 11 };

/* The shading stage's vertex stage for the position, then the corner's atlas
 * point and its vertex's C and T.  The mesh builder may have turned a
 * triangle over (orient.c swaps two corners), so the corner is found by
 * its vertex among the HULL section's three. */
static void siltex_vertex(const silk_hal *h, const silk_geom *g, const silk_vrec *r, silk_vertex_out *out)
{
    const silk_siltex_stage *s = (const silk_siltex_stage *)h->uniforms;
    const silk_siltex *st = s->tex;
    s->shade->vertex(s->shade, g, r, out);
    for (int k = VAR_UV; k < VAR_COUNT; k++) out->var[k] = 0;
    uint32_t a = r->a, tri = a / 3;
    if (r->kind != SILK_VREC_CORNER || tri >= st->ntris || tri >= g->mesh->ntris) return;
    uint32_t v = silk_mesh_corner(g->mesh, a), corner = a % 3;
    for (uint32_t k = 0; k < 3; k++) {
        const uint8_t *p = st->hull_tri + 4 * (3 * (size_t)tri + k);
        if (((uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24) == v) corner = k;
    }
    const uint8_t *uv = st->uv + 4 * (3 * (size_t)tri + corner);
    out->var[VAR_UV] = (silk_fx)(rd16(uv) << 12);       /* 1/16 texel to Q16.16 */
    out->var[VAR_UV + 1] = (silk_fx)(rd16(uv + 2) << 12);
    if (v >= st->nverts) return;
    const uint8_t *f = st->frame + 12 * (size_t)v;
    for (int k = 0; k < 3; k++) {
        out->var[VAR_C + k] = rd16s(f + 2 * k) * 4;       /* Q1.14 to Q16.16 */
        out->var[VAR_T + k] = rd16s(f + 6 + 2 * k) * 4;
    }
}

/* The unit view direction d at the point of varyings var, and in
 * perspective the eye-to-point vector e (the line width's depth); 0 where
 * the point is the eye. */
static int view_dir(const silk_view *view, const silk_fx *var, int64_t d[3], silk_vec3 *e)
{
    *e = silk_v3(0, 0, 0);
    if (view->cam.ortho) {
        d[0] = view->forward.x, d[1] = view->forward.y, d[2] = view->forward.z;
        return 1;
    }
    *e = silk_v3_sub(silk_v3(var[VAR_POS], var[VAR_POS + 1], var[VAR_POS + 2]), view->cam.eye);
    return silk_unit64(e->x, e->y, e->z, d);
}

/* Eq. 4, then the shading stage with the normal map's normal and the
 * colour map's colour. */
static uint32_t siltex_fragment(const silk_hal *h, const silk_fx *var)
{
    const silk_siltex_stage *s = (const silk_siltex_stage *)h->uniforms;
    const silk_siltex *st = s->tex;
    int64_t d[3];
    const silk_view *view = s->view;
    silk_vec3 e;
    if (!view_dir(view, var, d, &e)) return SILK_FRAGMENT_DISCARD;
    silk_fx u = var[VAR_UV], v = var[VAR_UV + 1];
    texels tx;
    texels_at(st, u, v, &tx);
    uint32_t phi;
    int64_t dc;
    if (!lobe_at(st, &tx, &var[VAR_C], &var[VAR_T], d, &phi, &dc)) return SILK_FRAGMENT_DISCARD;
    int seen = dc >= silk_siltex_cos(phi);
    if (s->lines) {
        /* eq. 5: a line where |acos(d.C) - phi| <= w, w growing with the
         * eye depth (a pixel's width there) in perspective */
        int64_t w = s->line_q;
        if (!view->cam.ortho) w = (silk_v3_dot64(e, view->forward) >> 16) * w >> 16;
        int64_t lo = (int64_t)phi - w, hi = (int64_t)phi + w, top = (int64_t)255 << 16;
        lo = lo < 0 ? 0 : lo;
        hi = hi > top ? top : hi;
        if (dc <= silk_siltex_cos((uint32_t)lo) && dc >= silk_siltex_cos((uint32_t)hi)) return s->line_rgb;
        if (seen && s->lines == 2) return s->bg_rgb;   /* lines alone: the surface only hides them */
    }
    if (!seen) return SILK_FRAGMENT_DISCARD;
    int64_t n[3];
    normal_at(st, &tx, n);
    silk_fx shade_var[SILK_MAX_VARYINGS + 2];
    memset(shade_var, 0, sizeof shade_var);
    for (int k = 0; k < 3; k++) {
        shade_var[k] = var[VAR_POS + k];
        shade_var[3 + k] = (silk_fx)n[k];
    }
    uint32_t rgb = 0xFFFFFF;
    if (SILK_TEXTURES && st->color)   /* the texture's v runs upwards, the atlas's downwards */
        rgb = silk_texture_sample(&s->color_map, (silk_fx)(u / (int32_t)st->w),
                                  (silk_fx)(SILK_FX_ONE - v / (int32_t)st->h), 0, 0);
    return silk_hal_phong_tinted(s->shade, shade_var, rgb);
}

/* Eq. 4's margin in place of the colour (silk_siltex_margin_hal): the
 * angle acos(d.C) - phi, which crosses 0 where the lobe's edge is and,
 * unlike d.C - cos(phi), grows as evenly as phi does across the lobe's
 * edge (phi is bilinear between texels), as the 24-bit code
 * SILK_SILTEX_MARGIN_ZERO + margin / 4 (q units in Q8.16 to Q8.14),
 * clamped, and at most ZERO exactly where siltex_fragment draws the pixel
 * (its test is the cosines'; the two disagree by a rounding at most, and
 * then the code is the one next to ZERO on the drawn side).  No discard:
 * every front pixel of the hull gets its margin, drawn or not. */
static uint32_t margin_fragment(const silk_hal *h, const silk_fx *var)
{
    const silk_siltex_stage *s = (const silk_siltex_stage *)h->uniforms;
    const int64_t far = SILK_SILTEX_MARGIN_ZERO - 1;
    int64_t d[3];
    silk_vec3 e;
    texels tx;
    uint32_t phi;
    int64_t dc;
    if (!view_dir(s->view, var, d, &e)) return (uint32_t)(SILK_SILTEX_MARGIN_ZERO + far);
    texels_at(s->tex, var[VAR_UV], var[VAR_UV + 1], &tx);
    if (!lobe_at(s->tex, &tx, &var[VAR_C], &var[VAR_T], d, &phi, &dc)) return (uint32_t)(SILK_SILTEX_MARGIN_ZERO + far);
    int seen = dc >= silk_siltex_cos(phi);
    int64_t m = ((int64_t)silk_siltex_acos(dc) - phi) / 4;
    if (seen != (m <= 0)) m = seen ? 0 : 1;
    m = m < -(int64_t)SILK_SILTEX_MARGIN_ZERO ? -(int64_t)SILK_SILTEX_MARGIN_ZERO : (m > far ? far : m);
    return (uint32_t)(SILK_SILTEX_MARGIN_ZERO + m);
}

void silk_siltex_margin_hal(silk_hal *h, silk_siltex_stage *s)
{
    silk_siltex_hal(h, s);
    h->fragment = margin_fragment;
}

void silk_siltex_hal(silk_hal *h, silk_siltex_stage *s)
{
    memset(h, 0, sizeof *h);
    h->vertex = siltex_vertex;
    h->fragment = siltex_fragment;
    h->nvaryings = VAR_COUNT;
    h->uniforms = s;
    h->footprint_var = 0;
    /* the colour map as a texture, described once here rather than per pixel */
    const silk_siltex *st = s->tex;
    if (!SILK_TEXTURES) return;
    memset(&s->color_map, 0, sizeof s->color_map);
    if (st && st->color) {
        s->color_map.pixels = st->color;
        s->color_map.width = (uint16_t)st->w;
        s->color_map.height = (uint16_t)st->h;
        s->color_map.format = SILK_TEX_RGB888;
        s->color_map.levels = 1;
        s->color_map.filter = SILK_TEX_BILINEAR;
        s->color_map.wrap = SILK_TEX_CLAMP;
    }
}

int64_t silk_siltex_line_width(const silk_view *view, silk_fx reach)
{
    /* w (radians) = 1 px / (pixels_per_unit / depth) / reach; in q units
     * times 255 / pi (Q16: 5319493), per unit of eye depth in perspective;
     * at most 2^31, so that times a depth below 2^31 it stays in 64 bits */
    int64_t ppu = view->pixels_per_unit > 0 ? view->pixels_per_unit : 1;
    int64_t r = reach > 64 ? reach : 64;
    int64_t w = ((int64_t)5319493 << 16) / ppu * 65536 / r;
    return w < ((int64_t)1 << 31) ? w : ((int64_t)1 << 31);
}
