/*
 * fw_say.h - the firmware's report lines ("fw NAME key=value ..."), printf
 * style, on the console of the machine it runs on (fw_io.h), and the board
 * settings both scenes read (firmware.mk passes them), for the scenes
 * fw_main.c and fw_soak.c.
 */
#ifndef SILK_FW_SAY_H
#define SILK_FW_SAY_H

#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "silk/silk.h"
#include "fw_io.h"

#ifndef FW_BOARD
#define FW_BOARD "unknown"
#endif
#ifndef FW_FORMAT
#define FW_FORMAT SILK_PIX_RGB565
#endif
#ifndef FW_BAND_ROWS
#define FW_BAND_ROWS 8
#endif
#ifndef FW_ARENA_BYTES
#define FW_ARENA_BYTES 49152
#endif

#if defined(__GNUC__)
__attribute__((format(printf, 1, 2)))
#endif
static void say(const char *fmt, ...)
{
    char line[160];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(line, sizeof line - 1, fmt, ap);
    va_end(ap);
    strcat(line, "\n");
    fw_print(line);
}

#endif
