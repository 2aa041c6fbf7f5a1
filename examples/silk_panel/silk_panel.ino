/*
 * silk_panel.ino - silk on an ILI9341 SPI panel from an Arduino board: the
 * model in model.h turning through its packed views, each frame drawn
 * smooth in bands of 16 rows and sent band by band over SPI.
 *
 * model.h is a torus packed by `silk pack`; to draw your own model:
 *   silk pack MESH -o model.h --name model --size 320x240 --format rgb565 --views 12 --visibility brute
 * The usual ILI9341 breakout's wiring: SCK and MOSI to the board's SPI
 * pins, CS to pin 10, D/C to pin 9, RESET to pin 8.  A 32-bit board with
 * 64 KiB of RAM or more (SAMD51, nRF52, RP2040, ESP32, Teensy 3 and 4):
 * the arena below holds a band of colour and depth (30 KiB) and a
 * frame's scratch (docs/porting.md says how to size it for a model).
 */
#include <SPI.h>
#include <silk.h>
#include "model.h"

static const int PIN_CS = 10, PIN_DC = 9, PIN_RESET = 8;
static const int WIDTH = 320, HEIGHT = 240, BAND_ROWS = 16;
static SPISettings spi_settings(24000000, MSBFIRST, SPI_MODE0);
alignas(SILK_ARENA_ALIGN) static uint8_t arena_mem[48 * 1024];

static silk_panel panel;
static silk_mesh mesh;
static silk_arena arena;
static silk_target band;
static silk_sink sink;
static int view_k;

// The bus: bytes with the D/C line low (a command) or high (parameters,
// pixels).  Pixels come from the band buffer, which the renderer draws
// again for the next band, so the block transfer may overwrite it with what
// it reads back.
static int spi_write(void *user, int dc, const uint8_t *data, size_t n)
{
    (void)user;
    digitalWrite(PIN_DC, dc ? HIGH : LOW);
    digitalWrite(PIN_CS, LOW);
    SPI.beginTransaction(spi_settings);
    if (n > 16) SPI.transfer((void *)data, n);
    else for (size_t i = 0; i < n; i++) SPI.transfer(data[i]);
    SPI.endTransaction();
    digitalWrite(PIN_CS, HIGH);
    return 0;
}

static void wait_ms(void *user, uint32_t ms)
{
    (void)user;
    delay(ms);
}

static void stop(const char *what, const silk_error *err)
{
    Serial.print(what);
    Serial.print(": ");
    Serial.println(err->msg);
    for (;;) delay(1000);
}

void setup()
{
    Serial.begin(115200);
    pinMode(PIN_CS, OUTPUT);
    pinMode(PIN_DC, OUTPUT);
    pinMode(PIN_RESET, OUTPUT);
    digitalWrite(PIN_CS, HIGH);
    digitalWrite(PIN_RESET, LOW);   // a hardware reset before the init sequence's own
    delay(10);
    digitalWrite(PIN_RESET, HIGH);
    delay(120);
    SPI.begin();

    silk_error err;
    silk_panel_io io = { spi_write, NULL, NULL, wait_ms, NULL };
    silk_panel_config cfg;
    silk_panel_config_default(&cfg, SILK_PANEL_ILI9341);   // 320x240 landscape
    if (silk_panel_init(&panel, &cfg, &io, &err) != SILK_OK) stop("panel", &err);
    // the model stays in flash: the mesh reads it in place
    if (model_mesh(&mesh) != SILK_OK || silk_mesh_validate(&mesh, "model", &err) != SILK_OK) stop("model", &err);

    silk_arena_init(&arena, arena_mem, sizeof arena_mem);
    uint8_t *color = static_cast<uint8_t *>(silk_arena_array(&arena, WIDTH * BAND_ROWS, 2, SILK_MEM_RASTER));
    uint32_t *depth = static_cast<uint32_t *>(silk_arena_array(&arena, WIDTH * BAND_ROWS, 4, SILK_MEM_RASTER));
    silk_target_init(&band, WIDTH, HEIGHT, 0, BAND_ROWS, SILK_PIX_RGB565, color, depth);
    silk_panel_sink(&panel, NULL, &sink);   // one band buffer: the bus has no DMA here
}

void loop()
{
    silk_error err;
    silk_view view;
    if (silk_view_init(&view, model_camera(view_k), &err) != SILK_OK) stop("camera", &err);
    silk_phong phong;
    silk_hal hal;
    silk_phong_default(&phong, &view);
    model_look(&phong);
    silk_hal_phong(&hal, &phong);
    silk_render_opts ro;
    silk_render_opts_default(&ro);
    ro.aa = 0;                   // anti-aliased outlines take 12 KiB more a band
    ro.vertex_cache_bytes = 0;   // nothing kept for speed: a frame takes its frame_bytes
    silk_frame_stats st;
    unsigned long t0 = millis();
    if (silk_render_bands(&arena, &mesh, &view, &hal, &ro, &band, &sink, &st, &err) != SILK_OK) stop("frame", &err);
    Serial.print("view ");
    Serial.print(view_k);
    Serial.print(": ");
    Serial.print(millis() - t0);
    Serial.println(st.fell_back ? " ms, unsmoothed: the arena is short" : " ms");
    view_k = (view_k + 1) % model_NCAMERAS;
}
