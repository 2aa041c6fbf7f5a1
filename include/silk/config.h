/*
 * silk/config.h - every build option of the core, in one place: what each
 * does, what it costs and what it buys.
 *
 * Each option is 0 or 1.  A build sets them in a header of its own named
 * by SILK_CONFIG_FILE, read first (a board's is boards/NAME/config.h; the
 * Makefile passes -DSILK_CONFIG_FILE for the board it builds), or with
 * -DOPTION=0; what it does not set takes the default below, and an option
 * that follows from others is derived from them.  The defaults are a
 * host's: every mode and feature built in, every shortcut taken.
 *
 * The core reads an option as `if (SILK_OPTION)` in its functions, so
 * every branch compiles in every build and what an option turns off is
 * dropped by the compiler (the boards build at -Os and link only what they
 * call); no public header's layout depends on an option, so a program
 * built against the headers links with a core built with any of them.
 * `make test` runs the core's unit tests in every board's configuration
 * (docs/small-devices.md).
 */
#ifndef SILK_CONFIG_H
#define SILK_CONFIG_H

#include <stdint.h>

#ifdef SILK_CONFIG_FILE
#include SILK_CONFIG_FILE
#endif

#if defined(SILK_NO_REFERENCE_MODES) || defined(SILK_NO_LINES) || defined(SILK_NO_CLIP_MODE) || \
    defined(SILK_NO_SILTEX_MODE) || defined(SILK_NO_AA) || defined(SILK_NO_AA_CREASE) || \
    defined(SILK_NO_TEXTURE) || defined(SILK_NO_VERTEX_CACHE)
#error "the -DSILK_NO_... flags are options of silk/config.h now: set SILK_AA to 0 instead of SILK_NO_AA, and so on"
#endif
#ifdef SILK_INDEX_T
#error "silk_index is 32 bits in every build now; SILK_PLAN_INDEX16 keeps a small board's plan in 16 (silk/config.h)"
#endif

/* ---- what the core draws ---------------------------------------------------- */

/* PN and BLEND, the comparison modes (docs/methods.md): about 9 KiB of Cortex-M3 code; 0: asking for one is SILK_ERR_ARG */
#ifndef SILK_REFERENCE_MODES
#define SILK_REFERENCE_MODES 1
#endif

/* Pen-and-ink lines (--lines) and --wire: lines.c and the rasterizer's lines, about 7 KiB; 0: SILK_ERR_ARG */
#ifndef SILK_LINES
#define SILK_LINES 1
#endif

/* CLIP mode, the silhouette map's outline as a stencil (docs/clipping.md): about 11 KiB; 0: SILK_ERR_ARG */
#ifndef SILK_CLIP_MODE
#define SILK_CLIP_MODE 1
#endif

/* SILTEX mode, the silhouette texture (docs/siltex.md): 6.7 KiB of code and tables; 0: SILK_ERR_ARG, textures refused */
#ifndef SILK_SILTEX_MODE
#define SILK_SILTEX_MODE 1
#endif

/* Anti-aliased outlines (silk_render_opts.aa): 3.0 KiB, and per band two apron rows and the outline's pixels */
#ifndef SILK_AA
#define SILK_AA 1
#endif

/* Visible creases blended as outlines are (aa = 1; aa = 2 leaves them hard): about 1 KiB (needs SILK_AA) */
#ifndef SILK_AA_CREASES
#define SILK_AA_CREASES SILK_AA
#endif

/* Texture sampling (silk_phong.texture, mipmaps): 1.2 KiB; 0: a textured model is drawn in its material colour */
#ifndef SILK_TEXTURES
#define SILK_TEXTURES 1
#endif

/* Several objects a frame (silk/scene.h, src/scene.c): about 3.2 KiB of Cortex-M3 code, and render.c's steps for
 * it; 0 leaves out both (silk_render_scene is then SILK_ERR_ARG) and render.c's frames are compiled as without them */
#ifndef SILK_SCENES
#define SILK_SCENES 1
#endif

/* Frames stored whole, which lines, PN and BLEND need (derived, not set): without them every frame is drawn share by share */
#define SILK_STORED_FRAMES (SILK_LINES || SILK_REFERENCE_MODES)

/* ---- memory ------------------------------------------------------------------- */

/* The per-frame plan's mesh indices in 16 bits (half its RAM); a mesh with 65 535 or more vertices, normals, uvs or edges then falls back */
#ifndef SILK_PLAN_INDEX16
#define SILK_PLAN_INDEX16 0
#endif

/* The mesh accessors of silk/mesh.h written out where they are used (a
 * test of the mesh's kind and an array read, inline); 0: one call each,
 * which keeps a small part's code and its deepest stack frames smaller
 * (its model is a compact one, read by a call anyway) */
#ifndef SILK_INLINE_ACCESS
#define SILK_INLINE_ACCESS 1
#endif

/* ---- shortcuts: code bytes or spare arena for instructions, the same bits ---- */

/* Every shortcut below (a host's choice); 0: none, a small part's, whose code budget is tight (each may still be set alone) */
#ifndef SILK_SHORTCUTS
#define SILK_SHORTCUTS 1
#endif

/* Shortcuts that take arena do so only from what silk_render_opts.vertex_cache_bytes allows. */

/* A vertex cache for frames drawn share by share: a corner's vertex stage once a frame, not once per triangle */
#ifndef SILK_VERTEX_CACHE
#define SILK_VERTEX_CACHE SILK_SHORTCUTS
#endif

/* Triangles drawn as they are (FLAT's, SMOOTH's off the silhouette) straight from the vertex cache, each vertex placed once a frame */
#ifndef SILK_DRAW_DIRECT
#define SILK_DRAW_DIRECT SILK_VERTEX_CACHE
#endif

/* A share's records placed on the screen once, and its triangles that cover no pixel centre skipped from the places alone */
#ifndef SILK_PLACE_ONCE
#define SILK_PLACE_ONCE SILK_SHORTCUTS
#endif

/* SMOOTH: the shares near the silhouette kept as first built, which the depth pass and the outline read again */
#ifndef SILK_KEEP_SHARES
#define SILK_KEEP_SHARES SILK_SHORTCUTS
#endif

/* SMOOTH: the plan keeps each silhouette segment, its layout and its points once made, and every carrying edge's tangents */
#ifndef SILK_KEEP_SEGMENTS
#define SILK_KEEP_SEGMENTS SILK_SHORTCUTS
#endif

/* SMOOTH: the carrying edges ranked (4 bytes per 8 mesh edges), an edge's slot found without a binary search */
#ifndef SILK_CARRY_RANK
#define SILK_CARRY_RANK SILK_SHORTCUTS
#endif

/* SMOOTH with a depth pass: which triangles of each share wrote a depth (4 bytes a triangle); the shading pass skips the rest */
#ifndef SILK_DEPTH_WINS
#define SILK_DEPTH_WINS SILK_SHORTCUTS
#endif

/* The depth pass draws the re-meshed parts' back faces last, so that most write no depth and are not shaded (needs SILK_DEPTH_WINS) */
#ifndef SILK_BACK_FACES_LAST
#define SILK_BACK_FACES_LAST SILK_DEPTH_WINS
#endif

/* Outlines of a closed mesh: their candidates found once a frame in a pass over the edges (a bit a triangle), and prefetched */
#ifndef SILK_AA_CANDIDATES
#define SILK_AA_CANDIDATES (SILK_SHORTCUTS && SILK_AA)
#endif

/* SMOOTH on a mesh that lists its triangles' edges (a loaded one): the silhouette and its sides found from the edges */
#ifndef SILK_PLAN_BY_EDGES
#define SILK_PLAN_BY_EDGES SILK_SHORTCUTS
#endif

/* The default stages' usual case (perspective, two directional lights, no texture) shaded with its tests made per triangle */
#ifndef SILK_PHONG_PLAIN
#define SILK_PHONG_PLAIN SILK_SHORTCUTS
#endif

/* A span's first depth stepped from the row above's by additions, where it moved by a few pixels, not divided */
#ifndef SILK_SPAN_DEPTH_STEP
#define SILK_SPAN_DEPTH_STEP SILK_SHORTCUTS
#endif

/* Hot tests written out again for their usual case (corners inside the clip volume, triangles the silhouette leaves alone) */
#ifndef SILK_FAST_CASES
#define SILK_FAST_CASES SILK_SHORTCUTS
#endif

/* ---- the target ---------------------------------------------------------------- */

/* 1 on a processor with 32-bit registers (Cortex-M): there a 64-bit product
 * takes three multiply instructions and a 64-bit division a library call,
 * so the hot paths take 32-bit routes where their operands allow, with the
 * same results; 0 on a 64-bit host, where either is one instruction.
 * Derived from the pointer size; a board's configuration sets it, so that
 * its unit tests on a host take the board's routes too. */
#ifndef SILK_CPU32
#define SILK_CPU32 (UINTPTR_MAX <= UINT32_MAX)
#endif

/* ---- what the options need of each other --------------------------------------- */

#if SILK_AA_CREASES && !SILK_AA
#error "SILK_AA_CREASES needs SILK_AA"
#endif
#if SILK_DRAW_DIRECT && !SILK_VERTEX_CACHE
#error "SILK_DRAW_DIRECT needs SILK_VERTEX_CACHE"
#endif
#if SILK_BACK_FACES_LAST && !SILK_DEPTH_WINS
#error "SILK_BACK_FACES_LAST needs SILK_DEPTH_WINS"
#endif
#if SILK_AA_CANDIDATES && !SILK_AA
#error "SILK_AA_CANDIDATES needs SILK_AA"
#endif

#endif
