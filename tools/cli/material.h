/*
 * material.h - what the command line adds to the Phong stages besides its
 * look options: the OBJ file's material (mtllib / usemtl: Kd, Ks, Ns,
 * map_Kd), a --texture image, and the mesh's vertex colours.
 */
#ifndef SILK_TOOLS_MATERIAL_H
#define SILK_TOOLS_MATERIAL_H

#include <stddef.h>
#include <stdint.h>
#include "silk/hal.h"
#include "silk/texture.h"

typedef struct cli_material {
    int have_kd, have_ks, have_ns;
    double kd[3], ks[3], ns;
    int have_texture;
    silk_texture texture;      /* with every mipmap level */
    uint8_t *pixels;           /* malloc'd */
    uint32_t palette[256];     /* SILK_TEX_PAL8: 6 x 7 x 6 levels of red, green, blue */
} cli_material;

/* --texture checker[:N]: a built-in N x N (default CLI_CHECKER_SIZE) image
 * of 8 x 8 squares (gen_checker). */
#define CLI_CHECKER "checker"
#define CLI_CHECKER_SIZE 256

/* How a texture is stored and sampled (--texture-format, --texture-filter,
 * --texture-wrap); zeros are RGB888, bilinear, repeating. */
typedef struct cli_texture_opts {
    silk_texfmt format;
    silk_texfilter filter;
    silk_texwrap wrap;
} cli_texture_opts;

/* The texture of an image (rgb: width * height R, G, B bytes) with every
 * mipmap level; palette: 256 colours for SILK_TEX_PAL8.  Returns 0, or -1
 * after filling msg. */
int cli_texture_from_rgb(const uint8_t *rgb, int width, int height, const cli_texture_opts *to,
                         const uint32_t *palette, silk_texture *t, uint8_t **pixels, char *msg, size_t msglen);

/* Read the material of the mesh file (file, len: its bytes; path: where it
 * is, for the .mtl next to it) and the texture (texture_path, or map_Kd
 * when it is NULL).  A missing .mtl or map_Kd image is a one-line warning
 * (unless quiet) and the model renders untextured; an unreadable
 * texture_path, or one given for a mesh without texture coordinates, is an
 * error.  Returns 0 or an exit code after printing the error. */
int cli_material_load(cli_material *mt, const char *path, const uint8_t *file, size_t len, const silk_mesh *m,
                      const char *texture_path, const cli_texture_opts *to, int quiet);
/* Material values the user did not set on the command line (have_color,
 * have_specular, have_shininess say which they did), the texture, and the
 * vertex colours of m. */
void cli_material_apply(const cli_material *mt, const silk_mesh *m, int have_color, int have_specular,
                        int have_shininess, silk_phong *p);
void cli_material_free(cli_material *mt);

#endif
