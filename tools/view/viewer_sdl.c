/*
 * viewer_sdl.c - the window of `silk view` (SDL2; built only when the
 * Makefile finds it with pkg-config).  Everything the viewer does is in
 * cmd_view.c; this file turns SDL's events into viewer calls and copies
 * each finished frame into the window's surface (SDL converts RGB888 or
 * RGB565 to whatever the display uses).  Nothing is drawn while nothing
 * changes: the loop sleeps in SDL_WaitEventTimeout unless the model spins
 * or --frames N asks for N frames.
 *
 * Without a display SDL would fall back to its invisible "offscreen" driver
 * and wait for input that never comes; the viewer says there is no display
 * instead (unless SDL_VIDEODRIVER asks for such a driver by name).
 */
#define _POSIX_C_SOURCE 200809L
#define SDL_MAIN_HANDLED
#include <SDL.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "viewer.h"

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec / 1e6;
}

/* The viewer's key for an SDL key, or -1. */
static int key_of(SDL_Keycode k)
{
    switch (k) {
    case SDLK_LEFT: return VIEWER_KEY_LEFT;
    case SDLK_RIGHT: return VIEWER_KEY_RIGHT;
    case SDLK_UP: return VIEWER_KEY_UP;
    case SDLK_DOWN: return VIEWER_KEY_DOWN;
    case SDLK_ESCAPE: return 'q';
    case SDLK_F12: return 's';
    case SDLK_KP_PLUS: case SDLK_PLUS: return '+';
    case SDLK_KP_MINUS: return '-';
    case SDLK_KP_1: return '1';
    case SDLK_KP_2: return '2';
    case SDLK_KP_3: return '3';
    case SDLK_KP_4: return '4';
    default: break;
    }
    /* SDL's keycodes of printable keys are their (unshifted) characters. */
    return k > 0 && k < 128 ? (int)k : -1;
}

/* Copy the frame into the window.  Returns 0, or -1 when the surface is
 * gone (the window is being resized: the next frame will do). */
static int present(SDL_Window *win, const viewer *v)
{
    SDL_Surface *surf = SDL_GetWindowSurface(win);
    if (!surf) return -1;
    int w = surf->w < v->w ? surf->w : v->w, h = surf->h < v->h ? surf->h : v->h;
    Uint32 fmt = v->o.fmt == SILK_PIX_RGB565 ? SDL_PIXELFORMAT_RGB565 : SDL_PIXELFORMAT_RGB24;
    if (SDL_MUSTLOCK(surf) && SDL_LockSurface(surf) != 0) return -1;
    int rc = SDL_ConvertPixels(w, h, fmt, v->t.color, (int)v->t.stride, surf->format->format, surf->pixels, surf->pitch);
    if (SDL_MUSTLOCK(surf)) SDL_UnlockSurface(surf);
    if (rc != 0) return -1;
    return SDL_UpdateWindowSurface(win) == 0 ? 0 : -1;
}

/* One event; returns 0 or an exit code. */
static int handle(viewer *v, SDL_Window *win, const SDL_Event *e)
{
    switch (e->type) {
    case SDL_QUIT:
        v->quit = 1;
        return 0;
    case SDL_KEYDOWN: {
        int k = key_of(e->key.keysym.sym);
        if (k < 0) return 0;
        /* A failed screenshot is reported and the viewer goes on. */
        if (viewer_key(v, k) && k != 's') return CLI_EXIT_INPUT;
        return 0;
    }
    case SDL_MOUSEMOTION:
        if (e->motion.state & SDL_BUTTON_LMASK) viewer_orbit(v, e->motion.xrel, e->motion.yrel);
        else if (e->motion.state & (SDL_BUTTON_RMASK | SDL_BUTTON_MMASK)) viewer_pan(v, e->motion.xrel, e->motion.yrel);
        return 0;
    case SDL_MOUSEWHEEL: {
        int y = e->wheel.direction == SDL_MOUSEWHEEL_FLIPPED ? -e->wheel.y : e->wheel.y;
        if (y) viewer_zoom(v, y);
        return 0;
    }
    case SDL_WINDOWEVENT:
        if (e->window.event == SDL_WINDOWEVENT_SIZE_CHANGED || e->window.event == SDL_WINDOWEVENT_RESIZED) {
            int w, h;
            SDL_GetWindowSize(win, &w, &h);
            if (w != v->w || h != v->h) return viewer_resize(v, w, h);
        }
        if (e->window.event == SDL_WINDOWEVENT_EXPOSED) v->dirty = 1;
        return 0;
    default:
        return 0;
    }
}

static int has_env(const char *name)
{
    const char *s = getenv(name);
    return s && *s;
}

/* SDL's video, on a display the user can see.  Returns 0 or an exit code. */
static int open_video(void)
{
    static const char no_display[] =
        "view: no display to open a window on (%s); use --fb DEVICE, --benchmark N or --events";
    int chosen = has_env("SDL_VIDEODRIVER");
    int x11 = has_env("DISPLAY"), wayland = has_env("WAYLAND_DISPLAY");
    /* Only the drivers whose display is named (a Linux console, KMS, when
     * none is): SDL's probes of the others print their own complaints. */
    if (!chosen) {
#ifdef SDL_HINT_VIDEODRIVER   /* SDL 2.0.22 and later: a list */
        SDL_SetHint(SDL_HINT_VIDEODRIVER, wayland && x11 ? "wayland,x11" : wayland ? "wayland" : x11 ? "x11" : "KMSDRM");
#else
        setenv("SDL_VIDEODRIVER", x11 ? "x11" : wayland ? "wayland" : "KMSDRM", 1);
#endif
    }
    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
        int rc = chosen || x11 || wayland
                     ? cli_fail(CLI_EXIT_INPUT, "view: cannot open a window: %s (no display? try --fb or --benchmark)",
                                SDL_GetError())
                     : cli_fail(CLI_EXIT_INPUT, no_display, "DISPLAY and WAYLAND_DISPLAY are not set");
        SDL_Quit();
        return rc;
    }
    const char *drv = SDL_GetCurrentVideoDriver();
    if (!chosen && drv && (strcmp(drv, "offscreen") == 0 || strcmp(drv, "dummy") == 0)) {
        SDL_Quit();
        return cli_fail(CLI_EXIT_INPUT, no_display, "only an invisible one");
    }
    return 0;
}

int viewer_run_sdl(viewer *v, long frames)
{
    int rc = open_video();
    if (rc) return rc;
    const char *base = strrchr(v->o.mesh_path, '/');
    char title[300];
    snprintf(title, sizeof title, "silk view - %s", base ? base + 1 : v->o.mesh_path);
    SDL_Window *win = SDL_CreateWindow(title, SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED, v->w, v->h,
                                       SDL_WINDOW_RESIZABLE);
    if (!win) {
        int rc = cli_fail(CLI_EXIT_INPUT, "view: cannot open a window: %s", SDL_GetError());
        SDL_Quit();
        return rc;
    }
    long drawn = 0;
    v->dirty = 1;
    while (!v->quit && !rc) {
        SDL_Event e;
        /* Idle: wait for input; spinning or counting frames: take what is
         * there and draw. */
        if (frames > 0) v->dirty = 1;
        int have = (v->dirty || v->spin) ? SDL_PollEvent(&e) : SDL_WaitEventTimeout(&e, 250);
        while (have && !rc) {
            rc = handle(v, win, &e);
            have = SDL_PollEvent(&e);
        }
        if (rc || v->quit || !(v->dirty || v->spin)) continue;
        if ((rc = viewer_frame(v)) != 0) break;
        drawn++;
        double t0 = now_ms();
        if (present(win, v) != 0) {
            v->dirty = 1;
            SDL_Delay(10);
        }
        v->present_ms = now_ms() - t0;
        /* Counted when drawn, so that a window that cannot show them (being
         * resized, or invisible) still ends. */
        if (frames > 0 && drawn >= frames) {
            rc = viewer_screenshot(v, NULL);
            v->quit = 1;
        }
    }
    SDL_DestroyWindow(win);
    SDL_Quit();
    return rc;
}
