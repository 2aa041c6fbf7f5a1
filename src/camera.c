/*
 * camera.c - the view: lookAt, perspective or orthographic projection, and
 * world -> clip -> pixel transforms in Q16.16.
 *
 * Not a paper equation: the standard OpenGL lookAt / frustum / ortho
 * matrices, with two changes for fixed point (docs/raster.md):
 *  - the perspective frustum has its far plane at infinity, so clip z is
 *    exactly w - 2 znear and the rasterizer's depth (w - z) / w = 2 znear / w
 *    carries only the rounding of w (a finite far plane would mix in the
 *    rounding of z, 30x coarser at ordinary settings);
 *  - silk_view_clip subtracts the eye before rotating, in 64 bits, instead of
 *    going through a matrix with the translation rounded into it.
 */
#include "silk/camera.h"

/* ---- 4x4 matrices ------------------------------------------------------- */

/* Sum of n 64-bit products of silk_fx values, shifted back to Q16.16 with
 * rounding and saturated.  Each product is below 2^62 but four of them can
 * exceed int64, so positive and negative parts are summed apart, unsigned. */
static silk_fx sum_q16(const int64_t *prod, int n)
{
    uint64_t pos = 0, neg = 0;
    for (int i = 0; i < n; i++) {
        if (prod[i] >= 0) pos += (uint64_t)prod[i];
        else neg += (uint64_t)0 - (uint64_t)prod[i];
    }
    int negative = neg > pos;
    uint64_t mag = negative ? neg - pos : pos - neg;
    mag = (mag >> 16) + ((mag >> 15) & 1);            /* round half away from zero */
    if (mag > (uint64_t)SILK_FX_MAX) mag = (uint64_t)SILK_FX_MAX;
    return negative ? -(silk_fx)mag : (silk_fx)mag;
}

silk_mat4 silk_mat4_identity(void)
{
    silk_mat4 r = { { { 0 } } };
    for (int i = 0; i < 4; i++) r.m[i][i] = SILK_FX_ONE;
    return r;
}

silk_mat4 silk_mat4_mul(const silk_mat4 *a, const silk_mat4 *b)
{
    silk_mat4 r;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            int64_t p[4];
            for (int k = 0; k < 4; k++) p[k] = (int64_t)a->m[i][k] * b->m[k][j];
            r.m[i][j] = sum_q16(p, 4);
        }
    return r;
}

silk_vec4 silk_mat4_apply_point(const silk_mat4 *m, silk_vec3 p)
{
    silk_fx out[4];
    for (int i = 0; i < 4; i++) {
        int64_t q[4] = { (int64_t)m->m[i][0] * p.x, (int64_t)m->m[i][1] * p.y,
                         (int64_t)m->m[i][2] * p.z, (int64_t)m->m[i][3] * SILK_FX_ONE };
        out[i] = sum_q16(q, 4);
    }
    silk_vec4 r = { out[0], out[1], out[2], out[3] };
    return r;
}

silk_vec3 silk_mat4_apply_dir(const silk_mat4 *m, silk_vec3 d)
{
    silk_fx out[3];
    for (int i = 0; i < 3; i++) {
        int64_t q[3] = { (int64_t)m->m[i][0] * d.x, (int64_t)m->m[i][1] * d.y,
                         (int64_t)m->m[i][2] * d.z };
        out[i] = sum_q16(q, 3);
    }
    return silk_v3(out[0], out[1], out[2]);
}

/* ---- helpers -------------------------------------------------------------- */

/* Unit vector along a 64-bit vector, in Q8.24: 256 times finer than Q16.16,
 * so the camera's rotation does not limit narrow fields of view.  Returns 0
 * for the zero vector. */
static int unit24(int64_t x, int64_t y, int64_t z, int32_t out[3])
{
    int64_t v[3] = { x, y, z }, m = 0;
    for (int i = 0; i < 3; i++) {
        int64_t a = v[i] < 0 ? -v[i] : v[i];
        if (a > m) m = a;
    }
    if (m == 0) { out[0] = out[1] = out[2] = 0; return 0; }
    /* largest component to [2^29, 2^30]: the squares sum below 2^62 */
    int up = 0, down = 0;
    while ((m >> down) > ((int64_t)1 << 30)) down++;
    while ((m << up) < ((int64_t)1 << 29)) up++;
    uint64_t ss = 0;
    for (int i = 0; i < 3; i++) {
        v[i] = down ? silk_shr_round64(v[i], down) : v[i] * ((int64_t)1 << up);
        ss += (uint64_t)(v[i] * v[i]);
    }
    int64_t len = silk_isqrt64(ss);
    for (int i = 0; i < 3; i++) {
        int64_t n = v[i] * ((int64_t)1 << 24);
        out[i] = (int32_t)(n >= 0 ? (n + len / 2) / len : -((-n + len / 2) / len));
    }
    return 1;
}

static silk_vec3 q24_to_fx(const int32_t v[3])
{
    return silk_v3((silk_fx)silk_shr_round64(v[0], 8), (silk_fx)silk_shr_round64(v[1], 8),
                   (silk_fx)silk_shr_round64(v[2], 8));
}

/* cot(deg / 2) in Q16.16 from a Q2.30 Taylor series: silk_fx_sincos_deg's
 * absolute error would be a large relative error in sin of a narrow field
 * of view. deg in [SILK_FOV_MIN, SILK_FOV_MAX]. */
static silk_fx cot_half_deg(silk_fx deg)
{
    const int64_t pi30 = 3373259426LL;                       /* pi in Q2.30 */
    int64_t x = ((int64_t)deg * pi30) / (360LL * 65536);     /* half angle, radians, Q30 (< 1.57) */
    int64_t x2 = (x * x) >> 30, s = x, c = (int64_t)1 << 30, ts = x, tc = c;
    for (int n = 1; n < 14; n++) {
        ts = -((ts * x2) >> 30) / ((2 * n) * (2 * n + 1));
        tc = -((tc * x2) >> 30) / ((2 * n - 1) * (2 * n));
        s += ts;
        c += tc;
    }
    return silk_fx_sat((c * 65536 + s / 2) / s);
}

/* n / d rounded half away from zero; d > 0. */
static int64_t div_round64(int64_t n, int64_t d)
{
    uint64_t q = silk_udiv64(silk_abs64(n) + (uint64_t)d / 2, (uint64_t)d);
    return n >= 0 ? (int64_t)q : -(int64_t)q;
}

/* The same, saturated to silk_fx. */
static silk_fx div_round(int64_t n, int64_t d) { return silk_fx_sat(div_round64(n, d)); }

/* Eye-space coordinates of p: R * (p - eye), 64-bit, rounded once. */
static void eye_coords(const silk_view *v, silk_vec3 p, silk_fx e[3])
{
    int64_t d[3] = { (int64_t)p.x - v->cam.eye.x, (int64_t)p.y - v->cam.eye.y,
                     (int64_t)p.z - v->cam.eye.z };
    if (!SILK_CPU32) {
        /* the loop below written out on a 64-bit host (once per vertex a
         * frame, where its counting and indexing cost as much as the products) */
        const int32_t(*r)[3] = v->rot24;
        e[0] = silk_fx_sat(silk_shr_round64(r[0][0] * d[0] + r[0][1] * d[1] + r[0][2] * d[2], 24));
        e[1] = silk_fx_sat(silk_shr_round64(r[1][0] * d[0] + r[1][1] * d[1] + r[1][2] * d[2], 24));
        e[2] = silk_fx_sat(silk_shr_round64(r[2][0] * d[0] + r[2][1] * d[1] + r[2][2] * d[2], 24));
        return;
    }
    /* d within 32 bits, as it is for any point nearer the eye than 2^15
     * units: 32-by-32-bit products, one multiply-accumulate instruction each
     * on a 32-bit processor instead of three; the same sums */
    if (d[0] == (int32_t)d[0] && d[1] == (int32_t)d[1] && d[2] == (int32_t)d[2]) {
        int32_t d32[3] = { (int32_t)d[0], (int32_t)d[1], (int32_t)d[2] };
        for (int i = 0; i < 3; i++) {
            int64_t s = (int64_t)v->rot24[i][0] * d32[0] + (int64_t)v->rot24[i][1] * d32[1] +
                        (int64_t)v->rot24[i][2] * d32[2];
            e[i] = silk_fx_sat(silk_shr_round64(s, 24));
        }
        return;
    }
    for (int i = 0; i < 3; i++) {
        /* |R| <= 2^24 and |d| < 2^33: the sum stays below 2^59 */
        int64_t s = (int64_t)v->rot24[i][0] * d[0] + (int64_t)v->rot24[i][1] * d[1] +
                    (int64_t)v->rot24[i][2] * d[2];
        e[i] = silk_fx_sat(silk_shr_round64(s, 24));
    }
}

/* Orthographic clip z: (-2 ez - (far + near)) / (far - near), one rounding. */
static silk_fx ortho_z(const silk_camera *c, silk_fx ez)
{
    int64_t num = -2 * (int64_t)ez - ((int64_t)c->zfar + c->znear);
    return div_round(num * SILK_FX_ONE, (int64_t)c->zfar - c->znear);
}

/* ---- the view ------------------------------------------------------------- */

static silk_status bad(silk_error *err, silk_status code, const char *what)
{
    return silk_fail(err, code, "camera", 0, "%s", what);
}

/* v's view matrix from its axes (rot24) and the eye, and its projection:
 * the far plane at infinity, or an orthographic box. */
static void view_matrices(silk_view *v, const silk_camera *cam, silk_fx sx, silk_fx sy)
{
    silk_mat4 V = silk_mat4_identity();
    silk_vec3 rows[3] = { v->right, v->upv, silk_v3_neg(v->forward) };
    for (int i = 0; i < 3; i++) {
        V.m[i][0] = rows[i].x;
        V.m[i][1] = rows[i].y;
        V.m[i][2] = rows[i].z;
        int64_t t = (int64_t)v->rot24[i][0] * cam->eye.x + (int64_t)v->rot24[i][1] * cam->eye.y +
                    (int64_t)v->rot24[i][2] * cam->eye.z;
        V.m[i][3] = silk_fx_sat(-silk_shr_round64(t, 24));
    }
    v->view = V;

    silk_mat4 P = { { { 0 } } };
    P.m[0][0] = sx;
    P.m[1][1] = sy;
    if (cam->ortho) {
        int64_t range = (int64_t)cam->zfar - cam->znear;
        P.m[2][2] = div_round(-2 * (int64_t)SILK_FX_ONE * SILK_FX_ONE, range);
        P.m[2][3] = div_round(-((int64_t)cam->zfar + cam->znear) * SILK_FX_ONE, range);
        P.m[3][3] = SILK_FX_ONE;
    } else {
        P.m[2][2] = -SILK_FX_ONE;                    /* far plane at infinity */
        P.m[2][3] = -2 * cam->znear;
        P.m[3][2] = -SILK_FX_ONE;
    }
    v->proj = P;
    v->viewproj = silk_mat4_mul(&P, &V);
}

silk_status silk_view_init(silk_view *v, const silk_camera *cam, silk_error *err)
{
    if (!v || !cam) return bad(err, SILK_ERR_ARG, "no camera given");
    if (cam->width < 1 || cam->height < 1)
        return silk_fail(err, SILK_ERR_ARG, "camera", 0, "image size %dx%d is smaller than 1x1",
                         cam->width, cam->height);
    if (cam->width > SILK_MAX_DIM || cam->height > SILK_MAX_DIM)
        return silk_fail(err, SILK_ERR_RANGE, "camera", 0,
                         "image size %dx%d is larger than %dx%d", cam->width, cam->height,
                         SILK_MAX_DIM, SILK_MAX_DIM);
    if (cam->znear <= 0 || cam->zfar <= cam->znear)
        return bad(err, SILK_ERR_ARG, "need 0 < znear < zfar");
    if (cam->znear < SILK_ZNEAR_MIN)
        return bad(err, SILK_ERR_RANGE, "znear is below 1/1024, too small for fixed point");
    if (cam->znear > SILK_ZNEAR_MAX)
        return bad(err, SILK_ERR_RANGE, "znear is above 16383, too large for fixed point (2 znear must fit)");

    int32_t fwd[3], up[3], right[3], upv[3];
    if (!unit24((int64_t)cam->target.x - cam->eye.x, (int64_t)cam->target.y - cam->eye.y,
                (int64_t)cam->target.z - cam->eye.z, fwd))
        return bad(err, SILK_ERR_ARG, "eye and target are the same point");
    if (!unit24(cam->up.x, cam->up.y, cam->up.z, up)) return bad(err, SILK_ERR_ARG, "up vector is zero");
    /* right = fwd x up, exact in Q48: its length is sin(angle(fwd, up)) */
    int64_t rx = (int64_t)fwd[1] * up[2] - (int64_t)fwd[2] * up[1];
    int64_t ry = (int64_t)fwd[2] * up[0] - (int64_t)fwd[0] * up[2];
    int64_t rz = (int64_t)fwd[0] * up[1] - (int64_t)fwd[1] * up[0];
    /* sin < 1/256 (0.22 degrees): the camera's roll would be noise */
    int64_t qx = rx >> 24, qy = ry >> 24, qz = rz >> 24;     /* Q24 */
    if (qx * qx + qy * qy + qz * qz < ((int64_t)1 << 32))
        return bad(err, SILK_ERR_ARG, "up vector is parallel to the view direction");
    unit24(rx, ry, rz, right);
    unit24((int64_t)right[1] * fwd[2] - (int64_t)right[2] * fwd[1],
           (int64_t)right[2] * fwd[0] - (int64_t)right[0] * fwd[2],
           (int64_t)right[0] * fwd[1] - (int64_t)right[1] * fwd[0], upv);

    silk_fx sx, sy;   /* clip x, y per eye-space unit (perspective: at depth 1) */
    if (cam->ortho) {
        if (cam->ortho_half_height < SILK_ZNEAR_MIN)
            return bad(err, SILK_ERR_RANGE, "orthographic half height must be at least 1/1024");
        sy = silk_fx_div(SILK_FX_ONE, cam->ortho_half_height);
    } else {
        if (cam->fov_deg <= 0 || cam->fov_deg >= SILK_FX_C(180, 1))
            return bad(err, SILK_ERR_ARG, "field of view must be in (0, 180) degrees");
        if (cam->fov_deg < SILK_FOV_MIN || cam->fov_deg > SILK_FOV_MAX)
            return bad(err, SILK_ERR_RANGE, "field of view must be in [1, 179] degrees for fixed point");
        sy = cot_half_deg(cam->fov_deg);              /* 0.0087 .. 114.6 */
    }
    int64_t sx64 = ((int64_t)sy * cam->height + cam->width / 2) / cam->width;
    if (sx64 > SILK_FX_MAX / 4 || sx64 < 1)
        return bad(err, SILK_ERR_RANGE, "aspect ratio and field of view give a scale outside Q16.16");
    sx = (silk_fx)sx64;

    v->cam = *cam;
    v->forward = q24_to_fx(fwd);
    v->right = q24_to_fx(right);
    v->upv = q24_to_fx(upv);
    v->pixels_per_unit = cam->ortho
        ? div_round((int64_t)cam->height * SILK_FX_ONE * SILK_FX_ONE, 2 * (int64_t)cam->ortho_half_height)
        : silk_fx_sat(((int64_t)sy * cam->height) / 2);
    for (int k = 0; k < 3; k++) {
        v->rot24[0][k] = right[k];
        v->rot24[1][k] = upv[k];
        v->rot24[2][k] = -fwd[k];
    }

    view_matrices(v, cam, sx, sy);
    return SILK_OK;
}

/* Clip x, y from eye x, y: sy * e and sy * e * H / W, or for orthographic
 * views e / half_height and e * H / (half_height * W), divided exactly
 * rather than through the rounded matrix entries (1 / half_height has few
 * significant bits when the half height is large). */
static void clip_xy(const silk_view *v, const silk_fx e[3], silk_vec4 *c)
{
    const silk_camera *cam = &v->cam;
    if (cam->ortho) {
        c->x = div_round((int64_t)e[0] * cam->height * SILK_FX_ONE, (int64_t)cam->ortho_half_height * cam->width);
        c->y = div_round((int64_t)e[1] * SILK_FX_ONE, cam->ortho_half_height);
    } else {
        silk_fx sy = v->proj.m[1][1];
        c->x = silk_fx_muldiv(silk_fx_mul(sy, e[0]), cam->height, cam->width);
        c->y = silk_fx_mul(sy, e[1]);
    }
}

silk_vec4 silk_view_clip(const silk_view *v, silk_vec3 p)
{
    silk_fx e[3];
    eye_coords(v, p, e);
    silk_vec4 c;
    clip_xy(v, e, &c);
    if (v->cam.ortho) {
        c.z = ortho_z(&v->cam, e[2]);
        c.w = SILK_FX_ONE;
    } else {
        c.w = -e[2];
        c.z = silk_fx_sub(c.w, 2 * v->cam.znear);
    }
    return c;
}

/* num / (2 w) * size, rounded: num may be up to 2^55 and size 2^13, so the
 * division is split into quotient and remainder to stay in 64 bits.  Not
 * saturated here: the caller adds the image centre first and saturates the
 * sum once, so that both sides clamp at the same distance (< 2^61 here). */
static int64_t scale_div(int64_t num, int size, int64_t w2)
{
    int64_t q = num / w2, r = num % w2;
    return q * size + div_round(r * size, w2);
}

int silk_view_project(const silk_view *v, silk_vec3 p, silk_vec2 *px)
{
    const silk_camera *c = &v->cam;
    silk_fx e[3];
    eye_coords(v, p, e);
    if (-(int64_t)e[2] < c->znear) return 0;
    /* pixel = (ndc + 1) / 2 * size, y flipped (row 0 at the top), straight
     * from eye space so no clip-space rounding is added */
    int64_t cx = (int64_t)c->width * SILK_FX_HALF, cy = (int64_t)c->height * SILK_FX_HALF;
    if (c->ortho) {
        int64_t h2 = 2 * (int64_t)c->ortho_half_height;
        px->x = silk_fx_sat(cx + div_round64((int64_t)e[0] * c->height * SILK_FX_ONE, h2));
        px->y = silk_fx_sat(cy - div_round64((int64_t)e[1] * c->height * SILK_FX_ONE, h2));
    } else {
        int64_t sy = v->proj.m[1][1], w2 = -2 * (int64_t)e[2];
        px->x = silk_fx_sat(cx + scale_div(sy * e[0], c->height, w2));
        px->y = silk_fx_sat(cy - scale_div(sy * e[1], c->height, w2));
    }
    return 1;
}

silk_vec3 silk_view_to_eye(const silk_view *v, silk_vec3 p)
{
    if (v->cam.ortho) return silk_v3_neg(v->forward);
    return silk_v3_sub(v->cam.eye, p);
}
