/*
 * test_platform.c - the host platform code: whole-file reading, atomic
 * outputs (nothing partial or temporary left behind on any failure), and the
 * PNG and PPM sinks, read back with libpng / by hand and compared pixel for
 * pixel in both pixel formats.
 */
#define _POSIX_C_SOURCE 200809L

#include <dirent.h>
#include <errno.h>
#include <png.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check.h"
#include "silk/silk.h"
#include "platform/platform.h"

static char dir[64];

static const char *path_in(const char *name)
{
    static char buf[4][512];
    static int k;
    k = (k + 1) % 4;
    snprintf(buf[k], sizeof buf[k], "%s/%s", dir, name);
    return buf[k];
}

static int exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

/* Files in the test directory whose name contains ".tmp": leftovers of an
 * output that was not committed. */
static int count_tmp_files(void)
{
    DIR *d = opendir(dir);
    int n = 0;
    struct dirent *e;
    while (d && (e = readdir(d)))
        if (strstr(e->d_name, ".tmp")) n++;
    if (d) closedir(d);
    return n;
}

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "wb");
    if (f) {
        fputs(text, f);
        fclose(f);
    }
}

/* A w x h target over malloc'd memory with a pattern that exercises every
 * channel bit: pixel (x, y) = colour_at(x, y). */
static uint32_t colour_at(int x, int y)
{
    return (uint32_t)((x * 37 + y * 11) & 255) << 16 | (uint32_t)((x * 5 + y * 53) & 255) << 8 |
           (uint32_t)((x ^ y) * 7 & 255);
}

static void make_target(silk_target *t, int w, int h, silk_pixfmt fmt)
{
    size_t bpp = fmt == SILK_PIX_RGB565 ? 2 : 3;
    memset(t, 0, sizeof *t);
    t->width = w;
    t->height = h;
    t->rows = h;
    t->fmt = fmt;
    t->stride = (size_t)w * bpp;
    t->color = malloc(t->stride * (size_t)h);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            uint32_t c = colour_at(x, y);
            uint8_t *p = t->color + (size_t)y * t->stride + (size_t)x * bpp;
            if (fmt == SILK_PIX_RGB888) {
                p[0] = (uint8_t)(c >> 16);
                p[1] = (uint8_t)(c >> 8);
                p[2] = (uint8_t)c;
            } else {
                unsigned v = ((c >> 19) & 31u) << 11 | ((c >> 10) & 63u) << 5 | ((c >> 3) & 31u);
                p[0] = (uint8_t)v;
                p[1] = (uint8_t)(v >> 8);
            }
        }
}

/* What the sinks must produce for pixel (x, y) of make_target's pattern:
 * exact for RGB888, widened by bit replication for RGB565. */
static uint32_t expected_at(int x, int y, silk_pixfmt fmt)
{
    uint32_t c = colour_at(x, y);
    if (fmt == SILK_PIX_RGB888) return c;
    unsigned r = (c >> 19) & 31u, g = (c >> 10) & 63u, b = (c >> 3) & 31u;
    return (uint32_t)(r << 3 | r >> 2) << 16 | (uint32_t)(g << 2 | g >> 4) << 8 | (b << 3 | b >> 2);
}

TEST(read_whole_file)
{
    const char *p = path_in("a.obj");
    write_text(p, "v 0 0 0\nv 1 0 0\n");
    uint8_t *data;
    size_t len;
    silk_error err;
    CHECK(silk_file_read(p, &data, &len, &err) == SILK_OK);
    CHECK(len == 16);
    CHECK(data && memcmp(data, "v 0 0 0\nv 1 0 0\n", 16) == 0 && data[16] == 0);
    free(data);

    write_text(p, "");
    CHECK(silk_file_read(p, &data, &len, &err) == SILK_OK);
    CHECK(len == 0 && data && data[0] == 0);
    free(data);

    /* Larger than the first guess of a non-regular file: read from a pipe-like
     * growth path is exercised by a file bigger than 4096 bytes too. */
    FILE *f = fopen(p, "wb");
    for (int i = 0; i < 100000; i++) fputc('a' + i % 26, f);
    fclose(f);
    CHECK(silk_file_read(p, &data, &len, &err) == SILK_OK);
    CHECK(len == 100000);
    int same = 1;
    for (int i = 0; data && i < 100000; i++) same &= data[i] == 'a' + i % 26;
    CHECK(same);
    free(data);
}

TEST(read_errors_name_the_file)
{
    uint8_t *data = (uint8_t *)1;
    size_t len = 7;
    silk_error err;
    const char *p = path_in("nope.obj");
    CHECK(silk_file_read(p, &data, &len, &err) == SILK_ERR_IO);
    CHECK(data == NULL && len == 0);
    char want[300];
    snprintf(want, sizeof want, "%s: cannot open: No such file or directory", p);
    CHECKF(strcmp(err.msg, want) == 0, "got \"%s\"", err.msg);

    CHECK(silk_file_read(dir, &data, &len, &err) == SILK_ERR_IO);
    snprintf(want, sizeof want, "%s: cannot read: Is a directory", dir);
    CHECKF(strcmp(err.msg, want) == 0, "got \"%s\"", err.msg);
}

TEST(outfile_is_atomic)
{
    const char *p = path_in("out.txt");
    silk_outfile o;
    silk_error err;
    write_text(p, "old");

    /* Until commit, the old file is what readers see. */
    CHECK(silk_outfile_open(&o, p, &err) == SILK_OK);
    fputs("new contents", o.fp);
    fflush(o.fp);
    uint8_t *data;
    size_t len;
    CHECK(silk_file_read(p, &data, &len, &err) == SILK_OK && len == 3 && memcmp(data, "old", 3) == 0);
    free(data);
    CHECK(count_tmp_files() == 1);
    CHECK(silk_outfile_commit(&o, &err) == SILK_OK);
    CHECK(silk_file_read(p, &data, &len, &err) == SILK_OK && len == 12 && memcmp(data, "new contents", 12) == 0);
    free(data);
    CHECK(count_tmp_files() == 0);

    /* Abort: the old file stays, the temporary goes. */
    CHECK(silk_outfile_open(&o, p, &err) == SILK_OK);
    fputs("half", o.fp);
    silk_outfile_abort(&o);
    silk_outfile_abort(&o);   /* twice is harmless */
    CHECK(silk_file_read(p, &data, &len, &err) == SILK_OK && len == 12);
    free(data);
    CHECK(count_tmp_files() == 0);

    /* The output gets ordinary permissions, not mkstemp's 0600. */
    struct stat st;
    mode_t mask = umask(022);
    CHECK(silk_outfile_open(&o, p, &err) == SILK_OK);
    CHECK(silk_outfile_commit(&o, &err) == SILK_OK);
    CHECK(stat(p, &st) == 0 && (st.st_mode & 0777) == 0644);
    umask(mask);

    char other[300];
    snprintf(other, sizeof other, "%s/./out.txt", dir);
    CHECK(silk_file_same(p, other) == 1);     /* another name, the same file */
    CHECK(silk_file_same(p, dir) == 0);
    CHECK(silk_file_same(p, path_in("missing")) == 0);

    CHECK(silk_file_remove_stale(p) == 1);
    CHECK(!exists(p));
    CHECK(silk_file_remove_stale(p) == 0);
    CHECK(silk_file_remove_stale(dir) == 0);   /* never a directory */
    CHECK(exists(dir));
}

TEST(outfile_errors)
{
    silk_outfile o;
    silk_error err;
    char p[300], want[800];
    snprintf(p, sizeof p, "%s/no/such/dir/x.png", dir);
    CHECK(silk_outfile_open(&o, p, &err) == SILK_ERR_IO);
    snprintf(want, sizeof want, "%s: cannot create: the directory %s/no/such/dir does not exist", p, dir);
    CHECKF(strcmp(err.msg, want) == 0, "got \"%s\"", err.msg);

    CHECK(silk_outfile_open(&o, dir, &err) == SILK_ERR_IO);
    snprintf(want, sizeof want, "%s: cannot write: Is a directory", dir);
    CHECKF(strcmp(err.msg, want) == 0, "got \"%s\"", err.msg);
    CHECK(count_tmp_files() == 0);
}

TEST(format_from_extension)
{
    CHECK(silk_image_format_for_path("a.png") == SILK_IMAGE_PNG);
    CHECK(silk_image_format_for_path("dir/A.PNG") == SILK_IMAGE_PNG);
    CHECK(silk_image_format_for_path("x.ppm") == SILK_IMAGE_PPM);
    CHECK(silk_image_format_for_path("x.Ppm") == SILK_IMAGE_PPM);
    CHECK(silk_image_format_for_path("x.png.txt") == SILK_IMAGE_NONE);
    CHECK(silk_image_format_for_path("png") == SILK_IMAGE_NONE);
    CHECK(silk_image_format_for_path("dir.png/x") == SILK_IMAGE_NONE);
    CHECK(silk_image_format_for_path("x.pngg") == SILK_IMAGE_NONE);
    CHECK(silk_image_format_for_path("x.") == SILK_IMAGE_NONE);
    CHECK(silk_image_format_for_path("") == SILK_IMAGE_NONE);

    silk_target t;
    make_target(&t, 4, 4, SILK_PIX_RGB888);
    silk_error err;
    const char *p = path_in("x.jpg");
    CHECK(silk_image_write(&t, p, &err) == SILK_ERR_ARG);
    CHECK(strstr(err.msg, "unknown image format") != NULL);
    CHECK(!exists(p));
    free(t.color);
}

/* Read a PNG back with libpng's simplified API as 8-bit RGB. */
static uint8_t *read_png(const char *path, int *w, int *h)
{
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&img, path)) return NULL;
    img.format = PNG_FORMAT_RGB;
    uint8_t *buf = malloc(PNG_IMAGE_SIZE(img));
    if (!buf || !png_image_finish_read(&img, NULL, buf, 0, NULL)) {
        free(buf);
        png_image_free(&img);
        return NULL;
    }
    *w = (int)img.width;
    *h = (int)img.height;
    return buf;
}

/* A P6 file as written by the sink: header, then w*h*3 bytes. */
static uint8_t *read_ppm(const char *path, int *w, int *h)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    int maxval = 0;
    uint8_t *buf = NULL;
    if (fscanf(f, "P6 %d %d %d", w, h, &maxval) == 3 && maxval == 255 && fgetc(f) == '\n') {
        size_t n = (size_t)*w * (size_t)*h * 3;
        buf = malloc(n + 1);
        if (buf && fread(buf, 1, n + 1, f) != n) {   /* exactly n bytes, nothing after */
            free(buf);
            buf = NULL;
        }
    }
    fclose(f);
    return buf;
}

static int pixels_match(const uint8_t *rgb, int w, int h, silk_pixfmt fmt)
{
    int bad = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            const uint8_t *p = rgb + ((size_t)y * w + x) * 3;
            uint32_t got = (uint32_t)p[0] << 16 | (uint32_t)p[1] << 8 | p[2];
            if (got != expected_at(x, y, fmt)) bad++;
        }
    return bad == 0;
}

TEST(png_and_ppm_round_trip)
{
    static const int sizes[][2] = { { 1, 1 }, { 3, 2 }, { 17, 5 }, { 64, 48 }, { 301, 7 } };
    for (int f = 0; f < 2; f++)
        for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; k++) {
            silk_pixfmt fmt = f ? SILK_PIX_RGB565 : SILK_PIX_RGB888;
            silk_target t;
            silk_error err;
            int w = 0, h = 0;
            make_target(&t, sizes[k][0], sizes[k][1], fmt);

            const char *png = path_in("round.png");
            CHECK(silk_image_write(&t, png, &err) == SILK_OK);
            uint8_t *rgb = read_png(png, &w, &h);
            CHECKF(rgb && w == t.width && h == t.height, "png %dx%d fmt %d", t.width, t.height, f);
            CHECKF(rgb && pixels_match(rgb, w, h, fmt), "png pixels %dx%d fmt %d", t.width, t.height, f);
            free(rgb);

            const char *ppm = path_in("round.ppm");
            CHECK(silk_image_write(&t, ppm, &err) == SILK_OK);
            rgb = read_ppm(ppm, &w, &h);
            CHECKF(rgb && w == t.width && h == t.height, "ppm %dx%d fmt %d", t.width, t.height, f);
            CHECKF(rgb && pixels_match(rgb, w, h, fmt), "ppm pixels %dx%d fmt %d", t.width, t.height, f);
            free(rgb);
            free(t.color);
        }
    CHECK(count_tmp_files() == 0);
}

/* The sinks read rows through stride, so a frame that is part of a wider
 * buffer is written correctly. */
TEST(sink_honours_stride)
{
    silk_target wide, t;
    silk_error err;
    int w, h;
    make_target(&wide, 20, 6, SILK_PIX_RGB888);
    t = wide;
    t.width = 8;   /* the left 8 columns, rows still 20 pixels apart */
    const char *p = path_in("stride.png");
    CHECK(silk_png_write(&t, p, &err) == SILK_OK);
    uint8_t *rgb = read_png(p, &w, &h);
    CHECK(rgb && w == 8 && h == 6 && pixels_match(rgb, w, h, SILK_PIX_RGB888));
    free(rgb);
    free(wide.color);
}

TEST(sink_rejects_bands)
{
    silk_target t;
    silk_error err;
    make_target(&t, 8, 8, SILK_PIX_RGB888);
    t.rows = 4;
    const char *p = path_in("band.png");
    CHECK(silk_png_write(&t, p, &err) == SILK_ERR_ARG);
    CHECKF(strstr(err.msg, "full frame") != NULL, "got \"%s\"", err.msg);
    CHECK(silk_ppm_write(&t, path_in("band.ppm"), &err) == SILK_ERR_ARG);
    CHECK(!exists(p) && !exists(path_in("band.ppm")));
    free(t.color);
}

/* A write that fails part way (the file size limit, as on a full disk):
 * one clear error, no file under the name, no temporary left; an older
 * file with that name is kept (the caller decides to remove it). */
TEST(write_failure_leaves_nothing)
{
    struct rlimit old, small;
    if (getrlimit(RLIMIT_FSIZE, &old) != 0) return;
    small = old;
    small.rlim_cur = 1000;
    void (*prev)(int) = signal(SIGXFSZ, SIG_IGN);   /* EFBIG instead of a signal */
    silk_target t;
    silk_error err;
    make_target(&t, 256, 256, SILK_PIX_RGB888);
    for (int k = 0; k < 2; k++) {
        const char *p = path_in(k ? "big.ppm" : "big.png");
        write_text(p, "older");
        CHECK(setrlimit(RLIMIT_FSIZE, &small) == 0);
        silk_status s = silk_image_write(&t, p, &err);
        setrlimit(RLIMIT_FSIZE, &old);
        CHECKF(s == SILK_ERR_IO, "%s: status %d", p, (int)s);
        CHECKF(strstr(err.msg, "cannot write") && strstr(err.msg, p), "got \"%s\"", err.msg);
        uint8_t *data;
        size_t len;
        CHECK(silk_file_read(p, &data, &len, &err) == SILK_OK && len == 5);
        free(data);
        CHECK(count_tmp_files() == 0);
        remove(p);
    }
    signal(SIGXFSZ, prev);
    free(t.color);
}

static void remove_dir(void)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    while (d && (e = readdir(d)))
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) remove(path_in(e->d_name));
    if (d) closedir(d);
    rmdir(dir);
}

int main(void)
{
    const char *tmp = getenv("TMPDIR");
    snprintf(dir, sizeof dir, "%s/silk-platform-XXXXXX", tmp && strlen(tmp) < 30 ? tmp : "/tmp");
    if (!mkdtemp(dir)) {
        perror("mkdtemp");
        return 1;
    }
    RUN(read_whole_file);
    RUN(read_errors_name_the_file);
    RUN(outfile_is_atomic);
    RUN(outfile_errors);
    RUN(format_from_extension);
    RUN(png_and_ppm_round_trip);
    RUN(sink_honours_stride);
    RUN(sink_rejects_bands);
    RUN(write_failure_leaves_nothing);
    remove_dir();
    return check_done();
}
