/*
 * fw_io_host.c - fw_io.h with stdio, so the firmware's scene runs on the
 * host too: `fw-host PREFIX` writes the same frames and report as the
 * board under QEMU, which is how tests/boards/cli_qemu.sh tells a difference of
 * the target (compiler, 32-bit CPU) from a difference of the scene.  The
 * host measures no stack and has no instruction timer; static sizes and
 * ticks are reported as 0.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fw_io.h"

#define MAX_FILES 8

static char cmdline[512];
static FILE *files[MAX_FILES];

void fw_cmdline(char *buf, size_t size)
{
    if (size == 0) return;
    snprintf(buf, size, "%s", cmdline);
}

int fw_open_write(const char *path)
{
    for (int h = 0; h < MAX_FILES; h++)
        if (!files[h]) return (files[h] = fopen(path, "wb")) ? h : -1;
    return -1;
}

int fw_write(int handle, const void *data, size_t n)
{
    if (handle < 0 || handle >= MAX_FILES || !files[handle]) return -1;
    return fwrite(data, 1, n, files[handle]) == n ? 0 : -1;
}

int fw_close(int handle)
{
    if (handle < 0 || handle >= MAX_FILES || !files[handle]) return -1;
    int r = fclose(files[handle]);
    files[handle] = NULL;
    return r == 0 ? 0 : -1;
}

void fw_print(const char *s)
{
    fputs(s, stdout);
    fflush(stdout);
}

void fw_exit(int status)
{
    exit(status);
}

void fw_memory(fw_mem *m)
{
    memset(m, 0, sizeof *m);
}

int main(int argc, char **argv)
{
    /* As QEMU passes it: the program's name, then its arguments. */
    size_t n = 0;
    for (int i = 0; i < argc && n + 1 < sizeof cmdline; i++) {
        int w = snprintf(cmdline + n, sizeof cmdline - n, "%s%s", i ? " " : "", argv[i]);
        if (w < 0) break;
        n += (size_t)w;
    }
    return fw_scene();
}

uint32_t fw_ticks(void)
{
    return 0;
}

void fw_spin(uint32_t n)
{
    (void)n;
}
