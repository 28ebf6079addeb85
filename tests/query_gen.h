/*
 * Random textures and queries for the tests that compare two ways of
 * sampling bit for bit (test_fastpath, test_source): a fixed xorshift
 * sequence, so that a failure reproduces; coordinates and derivatives
 * drawn from the classes the fast path treats differently.
 */
#ifndef TESTS_QUERY_GEN_H
#define TESTS_QUERY_GEN_H

#include "check.h"
#include "sample/sample.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define RNG_SEED 0x243F6A8885A308D3ull
static uint64_t rng_state = RNG_SEED;

static inline uint32_t rnd(void)
{
    /* xorshift64*: a fixed sequence, so a failure reproduces. */
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return (uint32_t)((rng_state * 2685821657736338717ull) >> 32);
}

static inline float frand(float lo, float hi) { return lo + (hi - lo) * (float)(rnd() >> 8) / 16777216.0f; }

/* A coordinate from one of the classes the fast path treats differently:
 * in range, near the edges, a few periods out, huge, extreme, non-finite. */
static inline float coord(void)
{
    switch (rnd() % 12) {
    case 0: return frand(-0.05f, 0.05f);
    case 1: return frand(0.95f, 1.05f);
    case 2: return frand(-40.0f, 40.0f);
    case 3: return frand(-1.0f, 1.0f) * 3e7f;
    case 4: return (rnd() & 1 ? 1.0f : -1.0f) * 1e30f;
    case 5: return (rnd() & 1 ? 1.0f : -1.0f) * 3.4e38f;
    case 6: return rnd() % 64 == 0 ? NAN : (rnd() & 1 ? INFINITY : -INFINITY);
    case 7: return (float)(rnd() % 33) / 32.0f; /* exact texel edges and centres */
    default: return frand(0.0f, 1.0f);
    }
}

static inline float deriv(void)
{
    switch (rnd() % 8) {
    case 0: return 0.0f;
    case 1: return frand(-1.0f, 1.0f) * 1e-4f;
    case 2: return frand(-1.0f, 1.0f) * 10.0f;
    case 3: return rnd() % 16 == 0 ? INFINITY : 1e20f;
    default: return frand(-0.3f, 0.3f);
    }
}

static inline sample_texture *make_texture(sample_format f, int nc, int w, int h)
{
    size_t n = (size_t)w * h * nc, bytes = n * sample_format_bytes(f), i;
    unsigned char *data = malloc(bytes);
    sample_image im;
    sample_mip_params mp;
    sample_texture *tex = NULL;
    for (i = 0; i < n; ++i) {
        float v = frand(-0.5f, 1.5f);
        switch (f) {
        case SAMPLE_FORMAT_F32: memcpy(data + 4 * i, &v, 4); break;
        case SAMPLE_FORMAT_F16: {
            /* Every half bit pattern but NaN (whose payload is not data). */
            uint16_t hb = (uint16_t)rnd();
            if ((hb & 0x7c00u) == 0x7c00u && (hb & 0x3ffu)) hb &= 0xfc00u;
            memcpy(data + 2 * i, &hb, 2);
            break;
        }
        default: data[i] = (unsigned char)rnd(); break;
        }
    }
    im.width = w;
    im.height = h;
    im.channels = nc;
    im.format = f;
    im.data = data;
    im.row_stride = 0;
    sample_mip_params_init(&mp);
    mp.wrap_s = mp.wrap_t = SAMPLE_WRAP_REPEAT;
    CHECK(sample_texture_create(&im, &mp, &tex, NULL) == SAMPLE_OK, "create");
    free(data);
    return tex;
}

/* Sampler k of the twelve kinds of filtering: the nine OpenGL filters,
 * then anisotropic ×16, Blinn–Newell and EWA; random wrap modes and mag
 * filter, a border colour no texel has. */
#define KIND_SAMPLERS (SAMPLE_FILTER_COUNT + 3)
static inline void kind_sampler(sample_sampler *s, int k)
{
    sample_sampler_init(s);
    s->wrap_s = (sample_wrap)(rnd() % SAMPLE_WRAP_COUNT);
    s->wrap_t = (sample_wrap)(rnd() % SAMPLE_WRAP_COUNT);
    s->mag_filter = rnd() % 3 == 0 ? SAMPLE_NEAREST : (rnd() & 1 ? SAMPLE_LINEAR : SAMPLE_CUBIC);
    s->border_color[0] = 0.25f;
    s->border_color[1] = 0.5f;
    s->border_color[3] = 0.5f;
    if (k < SAMPLE_FILTER_COUNT) {
        s->min_filter = (sample_filter)k;
    } else {
        s->min_filter = SAMPLE_LINEAR_MIPMAP_LINEAR;
        s->footprint = (sample_footprint)(k - SAMPLE_FILTER_COUNT + 1);
        s->max_anisotropy = 16.0f;
    }
}

#endif /* TESTS_QUERY_GEN_H */
