/* libFuzzer target for every libsample_io reader path: the first byte picks
 * the format hint (and so the OpenImageIO reader), the rest is the file.
 * An OpenEXR or .tx input is also opened by name through a texture system
 * (sample/texsys.h) with a cache of a few tiles and sampled on every
 * level, so that its tiles are read one at a time — by the direct OpenEXR
 * tile reader where it takes the file, else by OpenImageIO's read_tiles —
 * and evicted: a corrupt tile must read as the fill colour, never fault.
 * Seeds: tests/fuzz/corpus_io/ (the test images with their hint byte). */
#define _POSIX_C_SOURCE 200809L /* mkstemp */
#include "sample/sample_io.h"
#include "sample/texsys.h"

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* The file the texture system opens: one per process, rewritten for each
 * input, removed at exit. */
static char path[64];

static void remove_file(void) { unlink(path); }

static int write_file(const uint8_t *data, size_t size)
{
    FILE *f;
    if (!path[0]) {
        int fd;
        snprintf(path, sizeof path, "/tmp/fuzz_io_XXXXXX");
        fd = mkstemp(path);
        if (fd < 0) return 0;
        close(fd);
        atexit(remove_file);
    }
    f = fopen(path, "wb");
    if (!f) return 0;
    if (size && fwrite(data, 1, size, f) != size) {
        fclose(f);
        return 0;
    }
    return fclose(f) == 0;
}

/* Trilinear and EWA queries at λ = 0, 1, …, 15 across the texture, every
 * level's tiles, under a 16 KiB cache (half a 64² half RGBA tile: every
 * load evicts). The cache's size also bounds what a hostile header can
 * claim: a file whose tile table alone exceeds it is refused at open
 * (about 1,800 tiles: under 2,700² texels), so no input makes the system
 * read more than that whole. */
static void sample_by_name(const uint8_t *data, size_t size)
{
    enum { N = 64 };
    sample_texsys_options o;
    sample_texsys *sys = NULL;
    const sample_texture *tex = NULL;
    sample_query q[N];
    float rgba[4 * N];
    sample_batch_args a = {0};
    sample_sampler s;
    int i, f;
    if (!write_file(data, size)) return;
    sample_texsys_options_init(&o);
    o.max_memory_mb = 1.0 / 64.0;
    if (sample_texsys_create(&o, &sys, NULL) != SAMPLE_OK) return;
    if (sample_texsys_open(sys, path, &tex, NULL) == SAMPLE_OK) {
        sample_texsys_info info;
        int w;
        /* A file not in tiles is read whole on a miss, by the reader the
         * first half already ran (and again after every eviction, which
         * under this cache would be every miss): only tiled files are
         * sampled here. */
        if (sample_texsys_texture_info(sys, tex, &info, NULL) != SAMPLE_OK || !info.file_tiled ||
            info.texture.width < 1) {
            sample_texsys_destroy(sys);
            return;
        }
        w = info.texture.width;
        for (i = 0; i < N; ++i) {
            const float d = (float)(1 << (i % 16)) / (float)w;
            q[i].s = (float)((i * 37) % N) / N + 0.5f / N;
            q[i].t = (float)((i * 11) % N) / N + 0.5f / N;
            q[i].dsdx = d, q[i].dtdx = 0, q[i].dsdy = 0, q[i].dtdy = d;
        }
        a.count = N, a.queries = q, a.rgba = rgba;
        for (f = 0; f < 2; ++f) {
            sample_texsys_sampler_init(sys, tex, &s);
            s.min_filter = SAMPLE_LINEAR_MIPMAP_LINEAR;
            if (f == 1) s.footprint = SAMPLE_FOOTPRINT_EWA;
            sample_texsys_batch(sys, tex, &s, &a);
        }
        (void)sample_texsys_texture_error(sys, tex, NULL);
    }
    sample_texsys_destroy(sys);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const hints[] = {"png", "jpg", "tif", "exr", "hdr", "tga", "bmp", "tx", NULL};
    const char *hint;
    sample_io_options o;
    sample_mip_params mip;
    sample_texture *t = NULL;
    if (size < 1) return 0;
    hint = hints[data[0] % (sizeof hints / sizeof hints[0])];
    sample_io_options_init(&o);
    /* Keep allocations below libFuzzer's malloc limit: a claimed size over
     * the budget must be refused, not allocated. */
    o.max_bytes = (size_t)64 << 20;
    sample_mip_params_init(&mip);
    if (sample_io_read_memory(data + 1, size - 1, hint, &o, &mip, &t, NULL) == SAMPLE_OK && !t)
        __builtin_trap(); /* OK must come with a texture */
    sample_texture_destroy(t);
    if (hint && (hint[0] == 'e' || hint[1] == 'x')) sample_by_name(data + 1, size - 1);
    return 0;
}
