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

/* Unit vector along a 64-bit vector, shifted down first so silk_v3_normalize
 * sees as many significant bits as fit.  Returns 0 for the zero vector. */
static int unit64(int64_t x, int64_t y, int64_t z, silk_vec3 *out)
{
    int64_t ax = x < 0 ? -x : x, ay = y < 0 ? -y : y, az = z < 0 ? -z : z;
    int64_t m = ax > ay ? ax : ay;
    if (az > m) m = az;
    if (m == 0) { *out = silk_v3(0, 0, 0); return 0; }
    int s = 0;
    while ((m >> s) > (int64_t)(SILK_FX_MAX / 2)) s++;
    if (s > 0) {
        x = silk_shr_round64(x, s);
        y = silk_shr_round64(y, s);
        z = silk_shr_round64(z, s);
    }
    return silk_v3_normalize(silk_v3((silk_fx)x, (silk_fx)y, (silk_fx)z), out);
}

/* n / d rounded half away from zero, saturated to silk_fx; d > 0. */
static silk_fx div_round(int64_t n, int64_t d)
{
    int64_t q = n >= 0 ? (n + d / 2) / d : -((-n + d / 2) / d);
    return silk_fx_sat(q);
}

/* Eye-space coordinates of p: R * (p - eye), 64-bit, rounded once. */
static void eye_coords(const silk_view *v, silk_vec3 p, silk_fx e[3])
{
    int64_t d[3] = { (int64_t)p.x - v->cam.eye.x, (int64_t)p.y - v->cam.eye.y,
                     (int64_t)p.z - v->cam.eye.z };
    for (int i = 0; i < 3; i++) {
        /* |R| <= 2^16 and |d| < 2^32: each product < 2^48, no overflow */
        int64_t s = (int64_t)v->view.m[i][0] * d[0] + (int64_t)v->view.m[i][1] * d[1] +
                    (int64_t)v->view.m[i][2] * d[2];
        e[i] = silk_fx_sat(silk_shr_round64(s, 16));
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

    int64_t fx = (int64_t)cam->target.x - cam->eye.x, fy = (int64_t)cam->target.y - cam->eye.y,
            fz = (int64_t)cam->target.z - cam->eye.z;
    silk_vec3 fwd, up, right, upv;
    if (!unit64(fx, fy, fz, &fwd)) return bad(err, SILK_ERR_ARG, "eye and target are the same point");
    if (!unit64(cam->up.x, cam->up.y, cam->up.z, &up)) return bad(err, SILK_ERR_ARG, "up vector is zero");
    /* right = fwd x up, exact in Q32: its length is sin(angle(fwd, up)) */
    int64_t rx = (int64_t)fwd.y * up.z - (int64_t)fwd.z * up.y;
    int64_t ry = (int64_t)fwd.z * up.x - (int64_t)fwd.x * up.z;
    int64_t rz = (int64_t)fwd.x * up.y - (int64_t)fwd.y * up.x;
    /* sin < 1/256 (0.22 degrees): the camera's roll would be noise */
    uint64_t ax = (uint64_t)(rx < 0 ? -rx : rx), ay = (uint64_t)(ry < 0 ? -ry : ry),
             az = (uint64_t)(rz < 0 ? -rz : rz);
    uint64_t r2 = ax * (ax >> 16) + ay * (ay >> 16) + az * (az >> 16);   /* sin^2 in Q48 */
    if (r2 < ((uint64_t)1 << 32))
        return bad(err, SILK_ERR_ARG, "up vector is parallel to the view direction");
    unit64(rx, ry, rz, &right);
    int64_t ux = (int64_t)right.y * fwd.z - (int64_t)right.z * fwd.y;
    int64_t uy = (int64_t)right.z * fwd.x - (int64_t)right.x * fwd.z;
    int64_t uz = (int64_t)right.x * fwd.y - (int64_t)right.y * fwd.x;
    unit64(ux, uy, uz, &upv);

    silk_fx sx, sy;   /* clip x, y per eye-space unit (perspective: at depth 1) */
    if (cam->ortho) {
        if (cam->ortho_half_height < SILK_ZNEAR_MIN)
            return bad(err, SILK_ERR_RANGE, "orthographic half height must be at least 1/1024");
        sy = silk_fx_div(SILK_FX_ONE, cam->ortho_half_height);
    } else {
        if (cam->fov_deg <= 0 || cam->fov_deg >= SILK_FX_C(180, 1))
            return bad(err, SILK_ERR_ARG, "field of view must be in (0, 180) degrees");
        if (cam->fov_deg < SILK_FOV_MIN || cam->fov_deg > SILK_FOV_MAX)
            return bad(err, SILK_ERR_RANGE, "field of view must be in [1, 175] degrees for fixed point");
        silk_fx s, c;
        silk_fx_sincos_deg(cam->fov_deg / 2, &s, &c);
        sy = silk_fx_div(c, s);                      /* cot(fov/2), 0.04 .. 114.6 */
    }
    int64_t sx64 = ((int64_t)sy * cam->height + cam->width / 2) / cam->width;
    if (sx64 > SILK_FX_MAX / 4 || sx64 < 1)
        return bad(err, SILK_ERR_RANGE, "aspect ratio and field of view give a scale outside Q16.16");
    sx = (silk_fx)sx64;

    v->cam = *cam;
    v->forward = fwd;
    v->right = right;
    v->upv = upv;
    v->pixels_per_unit = silk_fx_sat(((int64_t)sy * cam->height) / 2);

    silk_mat4 V = silk_mat4_identity();
    silk_vec3 rows[3] = { right, upv, silk_v3_neg(fwd) };
    for (int i = 0; i < 3; i++) {
        V.m[i][0] = rows[i].x;
        V.m[i][1] = rows[i].y;
        V.m[i][2] = rows[i].z;
        V.m[i][3] = silk_fx_sat(-silk_shr_round64(silk_v3_dot64(rows[i], cam->eye), 16));
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
    return SILK_OK;
}

silk_vec4 silk_view_clip(const silk_view *v, silk_vec3 p)
{
    silk_fx e[3];
    eye_coords(v, p, e);
    silk_vec4 c;
    c.x = silk_fx_mul(v->proj.m[0][0], e[0]);
    c.y = silk_fx_mul(v->proj.m[1][1], e[1]);
    if (v->cam.ortho) {
        c.z = ortho_z(&v->cam, e[2]);
        c.w = SILK_FX_ONE;
    } else {
        c.w = -e[2];
        c.z = silk_fx_sub(c.w, 2 * v->cam.znear);
    }
    return c;
}

int silk_view_project(const silk_view *v, silk_vec3 p, silk_vec2 *px)
{
    silk_fx e[3];
    eye_coords(v, p, e);
    if (-(int64_t)e[2] < v->cam.znear) return 0;
    silk_vec4 c = silk_view_clip(v, p);
    /* pixel = (ndc + 1) / 2 * size, y flipped: row 0 at the top */
    int64_t w2 = 2 * (int64_t)c.w;
    px->x = div_round(((int64_t)c.x + c.w) * v->cam.width * SILK_FX_ONE, w2);
    px->y = div_round(((int64_t)c.w - c.y) * v->cam.height * SILK_FX_ONE, w2);
    return 1;
}

silk_vec3 silk_view_to_eye(const silk_view *v, silk_vec3 p)
{
    if (v->cam.ortho) return silk_v3_neg(v->forward);
    return silk_v3_sub(v->cam.eye, p);
}
