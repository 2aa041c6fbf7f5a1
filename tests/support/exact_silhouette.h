/*
 * exact_silhouette.h - test support, double precision: the exact object
 * masks of analytic surfaces (sphere, torus, capped cylinder, capped cone)
 * seen by a camera, and the measures that compare a rendered mask with
 * them.
 *
 * Camera conventions are those of silk/camera.h: OpenGL lookAt (the camera
 * looks down -z, x right, y up), a vertical field of view or an orthographic
 * half height, aspect = width / height, and image coordinates with (0,0) at
 * the top-left corner of the image, y down, pixel (x,y) covering
 * [x, x+1) x [y, y+1) and sampled at its centre (x + 0.5, y + 0.5).
 *
 * A mask is width*height bytes, row by row from the top, 1 = object.
 */
#ifndef EXACT_SILHOUETTE_H
#define EXACT_SILHOUETTE_H

#include "silk/camera.h"

typedef struct es_camera {
    double eye[3], target[3], up[3];
    int ortho;
    double fov_deg;            /* perspective: vertical field of view */
    double ortho_half_height;  /* orthographic: half the view height, world units */
    double znear, zfar;        /* visible depth range along the view axis */
    int width, height;
} es_camera;

/* The same camera as a silk_camera (Q16.16 fields read as their values). */
void es_camera_from_silk(es_camera *c, const silk_camera *s);

typedef enum es_kind { ES_SPHERE = 0, ES_TORUS = 1, ES_CYLINDER = 2, ES_CONE = 3 } es_kind;

typedef struct es_shape {
    es_kind kind;
    double centre[3];          /* cylinder, cone: the centre of the base disc */
    double radius;             /* sphere; cylinder and cone: of the base */
    double R, r;               /* torus: radius of the tube's centre circle, tube radius (r < R) */
    double axis[3];            /* torus, cylinder, cone: symmetry axis, unit (from the base up) */
    double height;             /* cylinder, cone: from the base along the axis (the cone's apex) */
} es_shape;

es_shape es_sphere(double cx, double cy, double cz, double radius);
/* axis need not be unit; it is normalised. */
es_shape es_torus(double cx, double cy, double cz, double ax, double ay, double az, double R, double r);
/* Solids of revolution standing on the disc of the given radius centred at
 * (cx, cy, cz) across the axis: a cylinder capped at both ends, and a cone
 * closed by its base disc with its apex height along the axis. */
es_shape es_cylinder(double cx, double cy, double cz, double ax, double ay, double az, double radius, double height);
es_shape es_cone(double cx, double cy, double cz, double ax, double ay, double az, double radius, double height);

/* 1 when the ray through image point (px, py) meets the shape's surface at
 * a depth in [znear, zfar].  The sphere is solved in closed form; the torus
 * quartic by isolating the extrema of its polynomial along the ray (roots
 * of the derivative, bracketed by the roots of the second derivative), so
 * grazing rays are decided by the sign of the polynomial, not by a
 * marching tolerance.  The cylinder and the cone are convex: the ray's
 * interval inside the side's quadric, cut by the slab between base and top
 * (apex). */
int es_hit(const es_camera *c, const es_shape *s, double px, double py);

/* mask[y * width + x] = es_hit at the pixel's centre. */
void es_mask(const es_camera *c, const es_shape *s, unsigned char *mask);

/* The exact silhouette, sampled where it crosses the segments between
 * 4-neighbouring pixel centres whose mask values differ (bisection of
 * es_hit to 1e-6 px).  Consecutive samples are at most sqrt(2) px apart
 * along a smooth silhouette. */
typedef struct es_points {
    int n, cap;
    double *x, *y;
} es_points;

int  es_silhouette_points(const es_camera *c, const es_shape *s, const unsigned char *exact_mask,
                          es_points *out);   /* returns out->n, or -1 when out of memory */
void es_points_free(es_points *p);

typedef struct es_stats {
    long differing;            /* pixels where test and exact differ */
    long extra, missing;       /* ... of which only in test / only in exact */
    long boundary;             /* boundary pixels of the exact mask: inside, with a 4-neighbour outside */
    double mean_error;         /* differing / boundary, px: the mean distance between the boundaries */
    double max_dist;           /* largest distance from a differing pixel's centre to the exact
                                  silhouette, px (0 when none differ): an approximate Hausdorff.
                                  The silhouette there is its samples joined by segments where
                                  two are less than 1.5 px apart. */
    /* Per sample of the exact silhouette: its distance to the test mask's
     * boundary (the pixel edges between test-in and test-out pixels),
     * positive where the test mask covers the sample (drawn too big there),
     * negative where it does not.  A perfect rasterization gives |.| <= 0.5. */
    double mean_offset, mean_abs_offset, max_abs_offset;
    int samples;
} es_stats;

/* Compare a test mask with the exact one; pts from es_silhouette_points. */
int es_compare(const unsigned char *test, const unsigned char *exact, const es_points *pts,
               int width, int height, es_stats *out);   /* 0, or -1 when out of memory */

/* The signed offsets summarised in es_stats, one per sample:
 * out[i] for pts->x[i], pts->y[i] (pts->n doubles). */
int es_offsets(const unsigned char *test, const es_points *pts, int width, int height, double *out);

/* How far the boundaries of two masks are apart: the largest distance from
 * the middle of a boundary pixel edge of one to the nearest boundary pixel
 * edge of the other, both ways, in px.  Equal masks give 0, a mask shifted
 * by one pixel gives 1.  Returns 1e9 when only one of them has a boundary,
 * -1 when out of memory. */
double es_boundary_hausdorff(const unsigned char *a, const unsigned char *b, int width, int height);

#endif
