/*
 * golden.c - frames against their reference images (golden.h).
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "golden.h"
#include "platform/platform.h"
#include "platform/png_read.h"

static int n_same, n_changed, n_new;

const char *golden_dir(void)
{
    const char *d = getenv("SILK_GOLDEN");
    return d && *d ? d : "tests/golden";
}

const char *golden_out_dir(void)
{
    const char *d = getenv("SILK_TEST_OUT");
    return d && *d ? d : "build/tests/out";
}

static int updating(void)
{
    const char *u = getenv("SILK_GOLDEN_UPDATE");
    return u && strcmp(u, "1") == 0;
}

/* mkdir -p */
static int make_dirs(const char *path)
{
    char buf[1024];
    snprintf(buf, sizeof buf, "%s", path);
    for (char *p = buf + 1; *p; p++)
        if (*p == '/') {
            *p = 0;
            if (mkdir(buf, 0777) != 0 && errno != EEXIST) return -1;
            *p = '/';
        }
    return mkdir(buf, 0777) != 0 && errno != EEXIST ? -1 : 0;
}

/* A binary PPM (P6, maxval 255) as RGB bytes, or NULL. */
static uint8_t *ppm_read(const char *path, int *w, int *h)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    int maxv = 0;
    uint8_t *px = NULL;
    if (fscanf(f, "P6 %d %d %d", w, h, &maxv) == 3 && maxv == 255 && fgetc(f) != EOF && *w > 0 && *h > 0) {
        size_t n = (size_t)*w * (size_t)*h * 3;
        px = malloc(n);
        if (px && fread(px, 1, n, f) != n) {
            free(px);
            px = NULL;
        }
    }
    fclose(f);
    return px;
}

static int ppm_write(const char *path, const uint8_t *rgb, int w, int h)
{
    FILE *f = fopen(path, "wb");
    if (!f) return -1;
    fprintf(f, "P6\n%d %d\n255\n", w, h);
    size_t n = (size_t)w * (size_t)h * 3;
    int ok = fwrite(rgb, 1, n, f) == n;
    return fclose(f) == 0 && ok ? 0 : -1;
}

static int png_write_rgb(const char *path, uint8_t *rgb, int w, int h)
{
    silk_target t;
    silk_error err;
    silk_target_init(&t, w, h, 0, h, SILK_PIX_RGB888, rgb, NULL);
    return silk_png_write(&t, path, &err) == SILK_OK ? 0 : -1;
}

/* The reference NAME.png or NAME.ppm that exists (PNG when neither does). */
static void reference_path(const char *name, char *path, size_t n, int *ppm)
{
    struct stat st;
    snprintf(path, n, "%s/%s.ppm", golden_dir(), name);
    *ppm = stat(path, &st) == 0;
    if (!*ppm) snprintf(path, n, "%s/%s.png", golden_dir(), name);
}

/* The frame and the difference under the out directory. */
static void leave_images(const char *name, uint8_t *mine, const uint8_t *ref, int w, int h, char *msg, size_t n)
{
    char path[1024];
    size_t len = strlen(msg);
    if (make_dirs(golden_out_dir()) != 0) {
        snprintf(msg + len, n - len, " (cannot make %s)", golden_out_dir());
        return;
    }
    snprintf(path, sizeof path, "%s/%s.png", golden_out_dir(), name);
    int ok = png_write_rgb(path, mine, w, h) == 0;
    if (ok && ref) {
        size_t px = (size_t)w * (size_t)h;
        uint8_t *d = malloc(px * 3);
        ok = d != NULL;
        for (size_t i = 0; d && i < px; i++) {
            const uint8_t *a = mine + 3 * i, *b = ref + 3 * i;
            if (memcmp(a, b, 3) != 0) {
                d[3 * i] = 255, d[3 * i + 1] = 0, d[3 * i + 2] = 0;
            } else {
                unsigned grey = (77u * b[0] + 150u * b[1] + 29u * b[2]) >> 8;
                d[3 * i] = d[3 * i + 1] = d[3 * i + 2] = (uint8_t)(192 + grey / 4);
            }
        }
        snprintf(path, sizeof path, "%s/%s-diff.png", golden_out_dir(), name);
        ok = ok && png_write_rgb(path, d, w, h) == 0;
        free(d);
    }
    len = strlen(msg);
    snprintf(msg + len, n - len, ok ? "; the frame%s in %s/%s%s" : " (cannot write to %s)", ref ? " and the difference are" : " is",
             golden_out_dir(), name, ref ? ".png, -diff.png" : ".png");
}

int golden_compare(const silk_target *t, const char *name, char *msg, size_t n)
{
    char path[1024];
    int ppm;
    reference_path(name, path, sizeof path, &ppm);
    int w = t->width, h = t->rows;
    size_t bytes = (size_t)w * (size_t)h * 3;
    uint8_t *mine = malloc(bytes ? bytes : 1), *ref = NULL;
    if (!mine) {
        snprintf(msg, n, "%s: out of memory", name);
        return 0;
    }
    for (int y = 0; y < h; y++) silk_target_row_rgb888(t, y, mine + (size_t)y * (size_t)w * 3);

    struct stat st;
    int exists = stat(path, &st) == 0, rw = 0, rh = 0;
    silk_error err;
    if (exists && ppm) ref = ppm_read(path, &rw, &rh);
    else if (exists && silk_png_read(path, &ref, &rw, &rh, &err) != SILK_OK) ref = NULL;
    long differ = -1;
    if (ref && rw == w && rh == h) {
        differ = 0;
        for (size_t i = 0; i < bytes; i += 3) differ += memcmp(mine + i, ref + i, 3) != 0;
    }
    int same = differ == 0;
    if (same) {
        n_same++;
    } else if (updating()) {
        int bad = ppm ? ppm_write(path, mine, w, h) : png_write_rgb(path, mine, w, h);
        if (bad) {
            snprintf(msg, n, "%s: cannot write", path);
        } else {
            printf("%s: %s\n", exists ? "changed" : "new", name);
            exists ? n_changed++ : n_new++;
            same = 1;
        }
    } else if (!exists) {
        snprintf(msg, n, "%s: no reference image (make golden makes it)", path);
        leave_images(name, mine, NULL, w, h, msg, n);
    } else if (differ < 0) {
        snprintf(msg, n, "%s: the reference is %dx%d, the frame %dx%d", path, rw, rh, w, h);
        leave_images(name, mine, NULL, w, h, msg, n);
    } else {
        snprintf(msg, n, "%s: %ld pixels differ from %s", name, differ, path);
        leave_images(name, mine, ref, w, h, msg, n);
    }
    free(ref);
    free(mine);
    return same;
}

void golden_summary(void)
{
    if (updating())
        printf("golden: %d changed, %d new, %d unchanged in %s\n", n_changed, n_new, n_same, golden_dir());
}
