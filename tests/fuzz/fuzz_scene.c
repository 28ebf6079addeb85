/*
 * Fuzzes the scene-file parser (doc/renderer.md, "Limits"): arbitrary bytes
 * as a scene text, then, when a scene comes out, a 4 × 4 render of it with
 * every per-pixel buffer. The oracle is the sanitizers (ASan, UBSan, LeakSanitizer) and
 * libFuzzer's time and memory limits: every loop and allocation that scene
 * data drives must be bounded.
 *
 * The parser runs with small budgets (a full-size default bake is a second
 * of work, too slow per input) and with image textures refused: reading
 * files named by the input would fuzz the file system, and the image
 * readers have their own fuzzer (fuzz_io).
 */
#include "render.h"

#include <stddef.h>
#include <stdint.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    render_parse_options po;
    render_scene *sc = NULL;
    render_options o;
    render_image img;
    char err[256];
    render_parse_options_init(&po);
    po.images = 0;
    po.max_bake_work = 1 << 21; /* the built-in teapot's grid and sky fit */
    po.max_texels = 1 << 19;
    if (render_scene_parse_ex((const char *)data, size, 4, 4, &po, &sc, err, sizeof err) != 0)
        return 0;
    render_options_init(&o);
    o.buffers = RENDER_BUF_ST | RENDER_BUF_JACOBIAN | RENDER_BUF_LOD | RENDER_BUF_TEXELS |
                RENDER_BUF_DEPTH | RENDER_BUF_NORMAL | RENDER_BUF_ID;
    o.corners = (size & 1) != 0; /* both the Jacobian and the corner paths */
    if (render_image_run(sc, &o, &img, err, sizeof err) == 0) render_image_free(&img);
    render_scene_destroy(sc);
    return 0;
}
