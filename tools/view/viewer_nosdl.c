/*
 * viewer_nosdl.c - the window loop of a silk built without SDL2 (the
 * Makefile builds this file or viewer_sdl.c, never both): there is no
 * window, and cmd_view says so before it would get here.
 */
#include "viewer.h"

int viewer_run_sdl(viewer *v, long frames)
{
    (void)v;
    (void)frames;
    return cli_fail(CLI_EXIT_USAGE, "view: this silk was built without SDL2");
}
