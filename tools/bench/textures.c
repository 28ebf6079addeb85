/*
 * The benchmark's synthetic texture in each storage format, as libsample's
 * texture (OpenImageIO's rows read their backend's file of it in the same
 * format: tools/backends/oiio.c). The content only has to defeat constant-
 * colour shortcuts and give every mip level real detail: a 32-texel
 * checker, two ramps and per-texel hash noise.
 */
#include "bench.h"
#include "sample/texsys.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *const bench_format_names[BENCH_FMT_COUNT] = {
    [BENCH_FMT_F32] = "float",
    [BENCH_FMT_F16] = "half",
    [BENCH_FMT_SRGB8] = "srgb8",
};

/* As OpenImageIO's backend writes them: OIIO 2.4's TIFF writer cannot hold
 * half, nor OpenEXR 8-bit (oiio_ts.h). */
const char *const bench_oiio_file_names[BENCH_FMT_COUNT] = {
    [BENCH_FMT_F32] = "bench_float.tx",
    [BENCH_FMT_F16] = "bench_half.exr",
    [BENCH_FMT_SRGB8] = "bench_srgb8.tx",
};

/* A 32-bit integer hash (Wang-style mixing): noise without a generator. */
static uint32_t hash2(uint32_t i, uint32_t j)
{
    uint32_t h = i * 0x8DA6B343u ^ j * 0xD8163841u;
    h ^= h >> 16;
    h *= 0x7FEB352Du;
    h ^= h >> 15;
    h *= 0x846CA68Bu;
    return h ^ (h >> 16);
}

float *bench_content(int size)
{
    size_t n = (size_t)size * (size_t)size;
    float *p = malloc(n * 4 * sizeof *p);
    int i, j;
    if (!p) return NULL;
    for (j = 0; j < size; ++j)
        for (i = 0; i < size; ++i) {
            uint32_t h = hash2((uint32_t)i, (uint32_t)j);
            float noise = (float)(h >> 8) / 16777216.0f;
            float *t = p + 4 * ((size_t)j * (size_t)size + (size_t)i);
            t[0] = 0.2f * noise + (((i >> 5) ^ (j >> 5)) & 1 ? 0.8f : 0.1f);
            t[1] = 0.8f * (float)i / (float)size + 0.2f * noise;
            t[2] = 0.8f * (float)j / (float)size + 0.2f * (1.0f - noise);
            t[3] = 1.0f;
        }
    return p;
}

/* 8-bit sRGB codes of linear content (alpha stays linear, GL 4.6 §8.24). */
static unsigned char *to_srgb8(const float *c, size_t n)
{
    unsigned char *p = malloc(n * 4);
    size_t k;
    if (!p) return NULL;
    for (k = 0; k < n * 4; ++k) {
        float v = (k % 4 == 3) ? c[k] : sample_linear_to_srgb(c[k]);
        p[k] = (unsigned char)(v * 255.0f + 0.5f);
    }
    return p;
}

int bench_texture_make(const float *content, int size, bench_format fmt, bench_texture *out)
{
    size_t n = (size_t)size * (size_t)size, k;
    void *stored = NULL;
    sample_image img = {size, size, 4, SAMPLE_FORMAT_F32, content, 0};
    sample_mip_params mip;
    sample_error err;
    int rc = -1;

    memset(out, 0, sizeof *out);
    if (fmt == BENCH_FMT_F16) {
        uint16_t *h = malloc(n * 4 * sizeof *h);
        if (h)
            for (k = 0; k < n * 4; ++k) h[k] = sample_float_to_half(content[k]);
        stored = h;
        img.format = SAMPLE_FORMAT_F16;
    } else if (fmt == BENCH_FMT_SRGB8) {
        stored = to_srgb8(content, n);
        img.format = SAMPLE_FORMAT_SRGB8;
    }
    if (fmt != BENCH_FMT_F32) {
        if (!stored) {
            fprintf(stderr, "texsample bench: out of memory\n");
            return -1;
        }
        img.data = stored;
    }
    sample_mip_params_init(&mip);
    mip.wrap_s = mip.wrap_t = SAMPLE_WRAP_REPEAT;
    if (sample_texture_create(&img, &mip, &out->ours, &err) != SAMPLE_OK) {
        fprintf(stderr, "texsample bench: %s texture: %s\n", bench_format_names[fmt], err.message);
    } else {
        rc = 0;
    }
    free(stored);
    if (rc != 0) bench_texture_free(out);
    return rc;
}

sample_status bench_texsys_batch(void *sys, const sample_texture *tex, const sample_sampler *s,
                                 const sample_batch_args *a)
{
    return sample_texsys_batch((sample_texsys *)sys, tex, s, a);
}

int bench_texture_cache(bench_texture *t, const char *path, double cache_mb)
{
    sample_texsys_options o;
    sample_texsys *sys = NULL;
    const sample_texture *tex = NULL;
    sample_error err;
    char what[64];
    sample_texsys_options_init(&o);
    o.max_memory_mb = cache_mb;
    if (sample_texsys_create(&o, &sys, &err) != SAMPLE_OK || sample_texsys_open(sys, path, &tex, &err) != SAMPLE_OK) {
        fprintf(stderr, "texsample bench: --cache-mb: %s\n", err.message);
        sample_texsys_destroy(sys);
        return -1;
    }
    /* The system owns tex; bench_texture_free destroys the system. */
    t->cached = tex;
    t->sys = sys;
    snprintf(what, sizeof what, "texture system of %g MiB", cache_mb);
    if (!(t->cached_backend = malloc(sizeof *t->cached_backend)) ||
        tool_backend_libsample_ctx(t->cached_backend, bench_texsys_batch, sys, what) != 0) {
        fprintf(stderr, "texsample bench: out of memory\n");
        bench_texture_free(t);
        return -1;
    }
    return 0;
}

void bench_texture_stats(const bench_texture *t, FILE *f)
{
    sample_texsys_stats st;
    if (!t->sys) return;
    sample_texsys_stats_get((sample_texsys *)t->sys, &st);
    fprintf(f, "libsample cache: tiles read %llu, bytes read %llu, peak memory %zu bytes\n",
            (unsigned long long)st.tiles_read, (unsigned long long)st.bytes_read, st.peak_memory);
}

void bench_texture_free(bench_texture *t)
{
    /* A cached texture belongs to its texture system. */
    if (t->cached_backend) tool_backend_close(t->cached_backend);
    free(t->cached_backend);
    sample_texsys_destroy((sample_texsys *)t->sys);
    sample_texture_destroy(t->ours);
    memset(t, 0, sizeof *t);
}
