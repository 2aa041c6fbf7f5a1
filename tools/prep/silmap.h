/*
 * silmap.h - building blocks of a silhouette map (Gu, Gortler, Hoppe et
 * al., "Silhouette Mapping", Harvard TR-1-99, section 4), host-side in
 * double precision: the views, one per vertex of a subdivided icosahedron
 * around the model (the star-shaped polytope of the paper's section 4);
 * each view's camera; the binary image of the detailed model seen from it;
 * the image's outline traced into closed polygons with holes; and those
 * simplified to a tolerance in pixels (Douglas-Peucker).
 */
#ifndef SILK_TOOLS_SILMAP_H
#define SILK_TOOLS_SILMAP_H

#include <stdint.h>
#include "src/silmap_interp.h"

/* The polytope: unit directions from the centre (its vertices on the unit
 * sphere) and its triangles, counter-clockwise seen from outside. */
typedef struct silmap_polytope {
    uint32_t nviews, ntris;
    double *dir;             /* 3 * nviews */
    uint32_t *tri;           /* 3 * ntris */
} silmap_polytope;

/* The icosahedron with every triangle split into 4, level times, the new
 * vertices pushed onto the sphere: 10 * 4^level + 2 views (12, 42, 162,
 * 642, ...).  level 0..6.  0, or -1 when out of memory or level is out of
 * range. */
int silmap_icosphere(int level, silmap_polytope *p);
void silmap_polytope_free(silmap_polytope *p);

/* A perspective camera of a square image res x res: pixel (x, y), y down,
 * pixel centres at half-integers; the projection of q is
 *   x = res/2 + focal * (q - eye).right / (q - eye).fwd
 *   y = res/2 - focal * (q - eye).up    / (q - eye).fwd. */
typedef struct silmap_camera {
    double eye[3], right[3], up[3], fwd[3];
    double focal;            /* pixels */
    int res;
} silmap_camera;

/* The camera at centre + distance * radius * dir looking at centre, its
 * field of view holding the sphere (centre, radius) with 5% to spare.
 * distance > 1 (in radii). */
void silmap_camera_at(const double centre[3], double radius, const double dir[3], double distance, int res,
                      silmap_camera *cam);
/* 0, or -1 when q is not in front of the camera. */
int silmap_project(const silmap_camera *cam, const double q[3], double out[2]);

/* img (res * res bytes, row by row) := 1 where the pixel centre lies in
 * the projection of some triangle (edges included), else 0.  Every vertex
 * must be in front of the camera.  Returns 0, or -1 if one is not. */
int silmap_rasterize(const silmap_camera *cam, const double *pos, uint32_t nverts, const uint32_t *tri,
                     uint32_t ntris, uint8_t *img);

/* Closed polygons in image coordinates: loop i is pt[2 * start[i]] ..
 * pt[2 * start[i + 1] - 1], its last point joined back to its first.
 * Outer boundaries have positive area (sum of x_i y_{i+1} - x_{i+1} y_i,
 * halved; clockwise on the screen with y down), holes negative. */
typedef struct silmap_contours {
    uint32_t nloops, npts;
    uint32_t *start;         /* nloops + 1 */
    double *pt;              /* 2 * npts */
} silmap_contours;

/* The outline of the set pixels of img (w x h): every boundary between a
 * set pixel and an unset one (or the image's edge) once, on the pixel
 * corners, only the corners where it turns.  Set pixels that touch only
 * at a corner are separate regions (4-connected inside).  0 or -1 (out of
 * memory). */
int silmap_trace(const uint8_t *img, int w, int h, silmap_contours *c);

/* The loops through the middles of the pixel sides instead of their
 * corners: every corner cut by half a pixel each way (the boundary at the
 * pixel centres' resolution, without the staircase's corners).  Each side
 * of length L from A to B gives A + d/2 and B - d/2 (one point if L = 1),
 * d its unit direction.  0 or -1 (out of memory). */
int silmap_midpoints(const silmap_contours *in, silmap_contours *out);

/* Douglas-Peucker on every loop: the points kept are a subset, and every
 * point left out is within tol of the kept polygon's edge across it.  A
 * loop keeps at least three points.  0 or -1 (out of memory). */
int silmap_simplify(const silmap_contours *in, double tol, silmap_contours *out);

/* Twice the signed area of loop i. */
double silmap_loop_area2(const silmap_contours *c, uint32_t i);

void silmap_contours_free(silmap_contours *c);

/* ---- the whole dense map -------------------------------------------------------- */

typedef struct silmap_params {
    int level;               /* icosahedron subdivisions: 10 * 4^level + 2 views */
    int res;                 /* image side in pixels */
    double tol;              /* Douglas-Peucker tolerance in pixels */
    double distance;         /* eyes this many bounding radii from the centre, > 1 */
} silmap_params;

/* level 2 (162 views), 256 pixels, 0.5 pixel, 3 radii. */
void silmap_params_default(silmap_params *p);

typedef struct silmap_view {
    silmap_camera cam;
    silmap_contours outline;  /* traced, through the sides' middles, simplified */
    uint32_t traced_pts;      /* corners before simplification */
} silmap_view;

typedef struct silmap {
    silmap_params params;
    silmap_polytope poly;     /* view i at centre + distance * radius * poly.dir[i] */
    double centre[3], radius; /* the mesh's bounding sphere (about its box's centre) */
    silmap_view *views;       /* poly.nviews */
} silmap;

/* Every view of the mesh (pos: 3 * nverts, tri: 3 * ntris): its camera,
 * image, outline.  0, or -1 when out of memory or the parameters are out
 * of range (level 0..6, res 8..4096, tol >= 0, distance > 1). */
int silmap_build(const double *pos, uint32_t nverts, const uint32_t *tri, uint32_t ntris, const silmap_params *p,
                 silmap *m);
void silmap_free(silmap *m);

/* ---- the map as the renderer reads it ------------------------------------------- */

/* The triangle across the edge opposite corner k of every triangle
 * (3 * ntris, UINT32_MAX where none), from the polytope's shared edges. */
uint32_t *silmap_adjacency(const silmap_polytope *p);

/* A view's camera in fixed point; 0, or -1 when it does not fit Q16.16. */
int silmap_cam_export(const silmap_camera *cam, silk_silmap_cam *c);

/* The map in fixed point, its arrays in one heap block (block). */
typedef struct silmap_fixed {
    silk_silmap map;
    void *block;
} silmap_fixed;

/* Round the map to the layout of src/silmap_interp.h: cameras and world
 * points to Q16.16, outlines to Q16.16 pixels.  0, or -1 when out of memory
 * or a number does not fit Q16.16. */
int silmap_export(const silmap *m, silmap_fixed *out);
void silmap_fixed_free(silmap_fixed *f);

#endif
