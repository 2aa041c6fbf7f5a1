/*
 * file.c - host file I/O: read a whole file into memory, and write outputs
 * atomically (temporary file in the same directory, then rename), so that a
 * failure never leaves a partial file under the output's name.
 *
 * Platform code: uses stdio, malloc and POSIX (mkstemp, fsync, rename).
 */
#define _POSIX_C_SOURCE 200809L

#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include "platform.h"

int silk_path_is_stdio(const char *path)
{
    return path && strcmp(path, "-") == 0;
}

silk_status silk_file_read(const char *path, uint8_t **data, size_t *len, silk_error *err)
{
    *data = NULL;
    *len = 0;
    int std = silk_path_is_stdio(path);
    if (std) path = SILK_STDIN_NAME;
    FILE *f = std ? stdin : fopen(path, "rb");
    if (!f) return silk_fail(err, SILK_ERR_IO, path, 0, "cannot open: %s", strerror(errno));

    /* fopen() succeeds on a directory; say so instead of "cannot read". */
    struct stat st;
    int have_stat = fstat(fileno(f), &st) == 0;
    if (have_stat && S_ISDIR(st.st_mode)) {
        if (!std) fclose(f);
        return silk_fail(err, SILK_ERR_IO, path, 0, "cannot read: %s", strerror(EISDIR));
    }

    /* Size from stat when it is a regular file, but keep reading past it:
     * pipes and files that grow still work. */
    size_t cap = 4096;
    if (have_stat && S_ISREG(st.st_mode) && st.st_size > 0 && (uintmax_t)st.st_size < SILK_FILE_MAX)
        cap = (size_t)st.st_size + 2;   /* one more than the data: the short read ends the loop */
    uint8_t *buf = malloc(cap);
    size_t n = 0;
    while (buf) {
        if (n + 1 >= cap) {
            if (cap > SILK_FILE_MAX) {
                free(buf);
                if (!std) fclose(f);
                return silk_fail(err, SILK_ERR_IO, path, 0, "file is too large (more than %zu bytes)",
                                 (size_t)SILK_FILE_MAX);
            }
            uint8_t *bigger = realloc(buf, cap * 2);
            if (!bigger) { free(buf); buf = NULL; break; }
            buf = bigger;
            cap *= 2;
        }
        size_t want = cap - 1 - n;
        size_t got = fread(buf + n, 1, want, f);
        n += got;
        if (got < want) break;   /* end of file or an error, told apart below */
    }
    if (!buf) {
        if (!std) fclose(f);
        return silk_fail(err, SILK_ERR_IO, path, 0, "out of memory reading the file");
    }
    if (ferror(f)) {
        int e = errno;
        free(buf);
        if (!std) fclose(f);
        return silk_fail(err, SILK_ERR_IO, path, 0, "cannot read: %s", strerror(e ? e : EIO));
    }
    if (!std) fclose(f);
    buf[n] = 0;
    *data = buf;
    *len = n;
    return SILK_OK;
}

silk_status silk_file_read_regular(const char *path, size_t max, uint8_t **data, size_t *len, silk_error *err)
{
    *data = NULL;
    *len = 0;
    /* O_NONBLOCK: opening a FIFO does not wait for a writer; it is refused below */
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY);
    if (fd < 0) return silk_fail(err, SILK_ERR_IO, path, 0, "cannot open: %s", strerror(errno));
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        close(fd);
        return silk_fail(err, SILK_ERR_IO, path, 0, "not a regular file");
    }
    if ((uintmax_t)st.st_size > max) {
        close(fd);
        return silk_fail(err, SILK_ERR_IO, path, 0, "%llu bytes, more than %zu", (unsigned long long)st.st_size, max);
    }
    size_t n = (size_t)st.st_size, got = 0;
    uint8_t *buf = malloc(n + 1);
    if (!buf) {
        close(fd);
        return silk_fail(err, SILK_ERR_IO, path, 0, "out of memory reading the file");
    }
    while (got < n) {   /* a file that shrinks meanwhile ends early; one that grows is cut at its size */
        ssize_t r = read(fd, buf + got, n - got);
        if (r < 0 && errno == EINTR) continue;
        if (r < 0) {
            int e = errno;
            free(buf);
            close(fd);
            return silk_fail(err, SILK_ERR_IO, path, 0, "cannot read: %s", strerror(e));
        }
        if (r == 0) break;
        got += (size_t)r;
    }
    close(fd);
    buf[got] = 0;
    *data = buf;
    *len = got;
    return SILK_OK;
}

silk_status silk_outfile_open(silk_outfile *o, const char *path, silk_error *err)
{
    o->fp = NULL;
    o->path = path;
    o->tmp = NULL;
    o->direct = 0;
    if (silk_path_is_stdio(path)) {
        /* Standard output cannot be written atomically: a failure is still
         * reported, but what was written has gone. */
        o->fp = stdout;
        o->path = SILK_STDOUT_NAME;
        o->direct = 1;
        return SILK_OK;
    }

    /* rename() over a directory would fail only at the end; fail early. */
    struct stat st;
    int exists = stat(path, &st) == 0;
    if (exists && S_ISDIR(st.st_mode))
        return silk_fail(err, SILK_ERR_IO, path, 0, "cannot write: %s", strerror(EISDIR));
    if (exists && !S_ISREG(st.st_mode)) {
        o->fp = fopen(path, "wb");
        if (!o->fp) return silk_fail(err, SILK_ERR_IO, path, 0, "cannot write: %s", strerror(errno));
        o->direct = 1;
        return SILK_OK;
    }

    static const char suffix[] = ".tmpXXXXXX";
    size_t n = strlen(path);
    o->tmp = malloc(n + sizeof suffix);
    if (!o->tmp) return silk_fail(err, SILK_ERR_IO, path, 0, "out of memory");
    memcpy(o->tmp, path, n);
    memcpy(o->tmp + n, suffix, sizeof suffix);

    int fd = mkstemp(o->tmp);
    if (fd < 0) {
        int e = errno;
        free(o->tmp);
        o->tmp = NULL;
        /* the usual cause: say which directory is missing */
        const char *slash = strrchr(path, '/');
        if (e == ENOENT && slash && slash > path)
            return silk_fail(err, SILK_ERR_IO, path, 0, "cannot create: the directory %.*s does not exist",
                             (int)(slash - path), path);
        return silk_fail(err, SILK_ERR_IO, path, 0, "cannot create: %s", strerror(e));
    }
    /* mkstemp makes the file private (0600); an output should get the usual
     * permissions, as if created by fopen(). */
    mode_t mask = umask(0);
    umask(mask);
    if (fchmod(fd, 0666 & ~mask) != 0) { /* not fatal: the file is still ours */ }

    o->fp = fdopen(fd, "wb");
    if (!o->fp) {
        int e = errno;
        close(fd);
        silk_outfile_abort(o);
        return silk_fail(err, SILK_ERR_IO, path, 0, "cannot create: %s", strerror(e));
    }
    return SILK_OK;
}

silk_status silk_outfile_commit(silk_outfile *o, silk_error *err)
{
    if (o->direct) {
        FILE *fp = o->fp;
        o->fp = NULL;
        int bad = !fp || fflush(fp) != 0 || ferror(fp);
        int e = errno ? errno : EIO;
        if (fp && fp != stdout && fclose(fp) != 0 && !bad) bad = 1, e = errno ? errno : EIO;
        if (bad) return silk_fail(err, SILK_ERR_IO, o->path, 0, "cannot write: %s", strerror(e));
        return SILK_OK;
    }
    if (!o->fp || !o->tmp) return silk_fail(err, SILK_ERR_IO, o->path, 0, "cannot write: not open");
    int e = 0;
    if (fflush(o->fp) != 0 || ferror(o->fp)) e = errno ? errno : EIO;
    /* Data on disk before the name points at it; tmpfs and pipes say EINVAL. */
    if (!e && fsync(fileno(o->fp)) != 0 && errno != EINVAL && errno != EROFS) e = errno;
    if (fclose(o->fp) != 0 && !e) e = errno ? errno : EIO;
    o->fp = NULL;
    if (!e && rename(o->tmp, o->path) != 0) e = errno;
    if (e) {
        silk_outfile_abort(o);
        return silk_fail(err, SILK_ERR_IO, o->path, 0, "cannot write: %s", strerror(e));
    }
    free(o->tmp);
    o->tmp = NULL;
    return SILK_OK;
}

void silk_outfile_abort(silk_outfile *o)
{
    if (o->direct) {
        if (o->fp && o->fp != stdout) fclose(o->fp);
        else if (o->fp) fflush(o->fp);
        o->fp = NULL;
        return;
    }
    if (o->fp) {
        fclose(o->fp);
        o->fp = NULL;
    }
    if (o->tmp) {
        remove(o->tmp);
        free(o->tmp);
        o->tmp = NULL;
    }
}

int silk_file_remove_stale(const char *path)
{
    struct stat st;
    if (silk_path_is_stdio(path) || lstat(path, &st) != 0 || !S_ISREG(st.st_mode)) return 0;
    return unlink(path) == 0;
}

int silk_file_same(const char *a, const char *b)
{
    struct stat sa, sb;
    if (silk_path_is_stdio(a) || silk_path_is_stdio(b)) return 0;
    return stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

silk_image_format silk_image_format_for_path(const char *path)
{
    const char *dot = strrchr(path, '.');
    const char *slash = strrchr(path, '/');
    if (!dot || (slash && dot < slash)) return SILK_IMAGE_NONE;
    char ext[5] = { 0 };
    size_t i;
    for (i = 0; i < 4 && dot[1 + i]; i++) ext[i] = (char)tolower((unsigned char)dot[1 + i]);
    if (dot[1 + i]) return SILK_IMAGE_NONE;   /* longer than four characters */
    if (strcmp(ext, "png") == 0) return SILK_IMAGE_PNG;
    if (strcmp(ext, "ppm") == 0) return SILK_IMAGE_PPM;
    return SILK_IMAGE_NONE;
}

silk_status silk_image_write(const silk_target *t, const char *path, silk_error *err)
{
    return silk_image_write_as(t, path, silk_image_format_for_path(path), err);
}

silk_status silk_image_write_as(const silk_target *t, const char *path, silk_image_format fmt, silk_error *err)
{
    switch (fmt) {
    case SILK_IMAGE_PNG: return silk_png_write(t, path, err);
    case SILK_IMAGE_PPM: return silk_ppm_write(t, path, err);
    default: break;
    }
    return silk_fail(err, SILK_ERR_ARG, silk_path_is_stdio(path) ? SILK_STDOUT_NAME : path, 0,
                     "unknown image format (use .png or .ppm)");
}
