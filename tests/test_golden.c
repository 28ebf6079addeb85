/*
 * Golden results: every filter, in three texel formats, on fixed textures
 * and fixed queries, hashed (values, ∂/∂s, ∂/∂t and stats, λ included) and
 * compared with hashes recorded when this test was written.
 *
 * test_fastpath and test_isa show that every instruction set gives the
 * same bits on *this* machine. This test carries the bits to every other
 * machine: sampling uses only IEEE 754's basic operations (no libm,
 * portable_math.h; no fused multiply-add, -ffp-contract=off), so a
 * conforming compiler and CPU anywhere must reproduce these hashes.
 * A mismatch after an intended change to a filter means the recorded
 * hashes must be updated (GOLDEN_PRINT=1 prints the table to paste);
 * a mismatch anywhere else is a portability bug.
 *
 * The textures are given level by level (sample_texture_create_levels),
 * random on every level, so that the hashes pin sampling alone; the mip
 * builder (also libm-free) has its own tests (test_mip, test_math).
 */
#include "check.h"
#include "internal.h"
#include "isa_util.h"

#include <stdint.h>
#include <stdlib.h>

#define BASE_W 61
#define BASE_H 47
#define LEVELS 6 /* 61×47 … 1×1 */
#define QUERIES 1024

static uint64_t rng;

static uint32_t rnd(void)
{
    rng ^= rng >> 12;
    rng ^= rng << 25;
    rng ^= rng >> 27;
    return (uint32_t)((rng * 2685821657736338717ull) >> 32);
}

/* Uniform in [lo, hi) with 24 random bits: exact floats, no libm. */
static float frand(float lo, float hi) { return lo + (hi - lo) * (float)(rnd() >> 8) * 0x1p-24f; }

static const sample_format formats[] = {SAMPLE_FORMAT_F32, SAMPLE_FORMAT_F16, SAMPLE_FORMAT_SRGB8};
#define NFORMATS 3

static sample_texture *make_texture(sample_format fmt)
{
    sample_image lv[LEVELS];
    void *data[LEVELS];
    sample_texture *tex = NULL;
    sample_error err;
    int k, w = BASE_W, h = BASE_H;
    size_t i;
    rng = 0x243F6A8885A308D3ull + (uint64_t)fmt;
    for (k = 0; k < LEVELS; ++k) {
        size_t n = (size_t)w * h * 4;
        lv[k] = (sample_image){w, h, 4, fmt, NULL, 0};
        if (fmt == SAMPLE_FORMAT_F32) {
            float *p = malloc(n * sizeof *p);
            for (i = 0; p && i < n; ++i) p[i] = frand(0.0f, 1.0f);
            data[k] = p;
        } else if (fmt == SAMPLE_FORMAT_F16) {
            uint16_t *p = malloc(n * sizeof *p);
            for (i = 0; p && i < n; ++i) p[i] = sample_float_to_half(frand(0.0f, 1.0f));
            data[k] = p;
        } else {
            unsigned char *p = malloc(n);
            for (i = 0; p && i < n; ++i) p[i] = (unsigned char)(rnd() >> 24);
            data[k] = p;
        }
        CHECK(data[k] != NULL, "out of memory");
        lv[k].data = data[k];
        w = w > 1 ? w / 2 : 1;
        h = h > 1 ? h / 2 : 1;
    }
    CHECK(sample_texture_create_levels(lv, LEVELS, &tex, &err) == SAMPLE_OK, "%s", err.message);
    for (k = 0; k < LEVELS; ++k) free(data[k]);
    return tex;
}

typedef struct config {
    const char *name;
    sample_filter min, mag;
    sample_footprint fp;
    int corners;
} config;

static const config configs[] = {
    {"nearest", SAMPLE_NEAREST_MIPMAP_NEAREST, SAMPLE_NEAREST, SAMPLE_FOOTPRINT_NONE, 0},
    {"bilinear", SAMPLE_LINEAR, SAMPLE_LINEAR, SAMPLE_FOOTPRINT_NONE, 0},
    {"bicubic", SAMPLE_CUBIC_MIPMAP_LINEAR, SAMPLE_CUBIC, SAMPLE_FOOTPRINT_NONE, 0},
    {"trilinear", SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_LINEAR, SAMPLE_FOOTPRINT_NONE, 0},
    {"aniso16", SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_LINEAR, SAMPLE_FOOTPRINT_ANISOTROPIC, 0},
    {"blinn-newell", SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_LINEAR, SAMPLE_FOOTPRINT_BLINN_NEWELL, 0},
    {"blinn-newell corners", SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_LINEAR, SAMPLE_FOOTPRINT_BLINN_NEWELL, 1},
    {"ewa", SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_LINEAR, SAMPLE_FOOTPRINT_EWA, 0},
};
#define NCONFIGS (sizeof configs / sizeof configs[0])

/* Recorded hashes, [config][format] (float, half, srgb8). */
static const uint64_t golden[NCONFIGS][NFORMATS] = {
    {0x258c2a05dff5b78dull, 0xa1933969d03ad034ull, 0x20e9fad1075a191bull}, /* nearest */
    {0x0c0bf3ea9b83a3deull, 0x6fd656dd896ac87dull, 0x58e935ffe15b2708ull}, /* bilinear */
    {0x501eb153e8e97132ull, 0xc656cf18e301c0ceull, 0x9f0190863dbc2c2aull}, /* bicubic */
    {0x95651bb59dbca0a6ull, 0x264d4120a63ac0c5ull, 0x4b48e1bf02ee63beull}, /* trilinear */
    {0x5f93b7a698834cf3ull, 0x1665d7d240ff6d8cull, 0x08e55b53f8d4cc0cull}, /* aniso16 */
    {0x1a61dfd84b49eb73ull, 0xd8b9bd58b9e8c0a1ull, 0xbf33a174201bb0edull}, /* blinn-newell */
    {0x3aa35475baf05079ull, 0xc33970c55bc0b814ull, 0x9680d8b1017f6122ull}, /* blinn-newell corners */
    {0x34877c229108d994ull, 0x0d3b72fdccfb88dbull, 0xe7eb866d11255259ull}, /* ewa */
};

static uint64_t fnv(uint64_t h, const void *p, size_t n)
{
    const unsigned char *b = p;
    size_t i;
    for (i = 0; i < n; ++i) h = (h ^ b[i]) * 0x100000001b3ull;
    return h;
}

/* Queries over two periods and beyond, footprints from a quarter texel to
 * the whole texture, any orientation and up to about 16:1, with corners
 * that are the parallelogram's, each moved by up to a tenth of it
 * (projective quads). Alternate wraps per half of the set. */
static void make_queries(sample_query *q, sample_quad *quad)
{
    int i, k;
    rng = 0x13198A2E03707344ull;
    for (i = 0; i < QUERIES; ++i) {
        float sc = (float)(1u << (rnd() % 9)) * 0x1p-8f, r = frand(1.0f / 16.0f, 1.0f);
        sample_query *x = &q[i];
        x->s = frand(-1.0f, 2.0f);
        x->t = frand(-1.0f, 2.0f);
        x->dsdx = frand(-1.0f, 1.0f) * sc;
        x->dtdx = frand(-1.0f, 1.0f) * sc;
        x->dsdy = frand(-1.0f, 1.0f) * sc * r;
        x->dtdy = frand(-1.0f, 1.0f) * sc * r;
        for (k = 0; k < 4; ++k) {
            float ox = (k == 1 || k == 2) ? 1.0f : -1.0f, oy = k >= 2 ? 1.0f : -1.0f;
            quad[i].st[k][0] = x->s + ox * x->dsdx + oy * x->dsdy + frand(-0.1f, 0.1f) * sc;
            quad[i].st[k][1] = x->t + ox * x->dtdx + oy * x->dtdy + frand(-0.1f, 0.1f) * sc;
        }
    }
}

static uint64_t run_config(const sample_texture *tex, const config *cf, const sample_query *q,
                           const sample_quad *quad)
{
    static float rgba[QUERIES][4], ds[QUERIES][4], dt[QUERIES][4];
    static sample_stats st[QUERIES];
    static const sample_wrap wraps[2][2] = {{SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_CLAMP_TO_EDGE},
                                            {SAMPLE_WRAP_MIRROR_CLAMP_TO_EDGE, SAMPLE_WRAP_MIRRORED_REPEAT}};
    uint64_t h = 0xcbf29ce484222325ull;
    int half;
    for (half = 0; half < 2; ++half) {
        sample_sampler s;
        sample_batch_args a;
        size_t lo = (size_t)half * QUERIES / 2;
        sample_sampler_init(&s);
        s.min_filter = cf->min;
        s.mag_filter = cf->mag;
        s.footprint = cf->fp;
        s.max_anisotropy = 16.0f;
        s.wrap_s = wraps[half][0];
        s.wrap_t = wraps[half][1];
        memset(&a, 0, sizeof a);
        a.count = QUERIES / 2;
        a.queries = q + lo;
        a.corners = cf->corners ? quad + lo : NULL;
        a.rgba = rgba[lo];
        a.drgba_ds = ds[lo];
        a.drgba_dt = dt[lo];
        a.stats = st + lo;
        CHECK(sample_batch(tex, &s, &a) == SAMPLE_OK, "%s", cf->name);
    }
    h = fnv(h, rgba, sizeof rgba);
    h = fnv(h, ds, sizeof ds);
    h = fnv(h, dt, sizeof dt);
    for (half = 0; half < QUERIES; ++half) {
        /* Field by field: the struct's padding is not ours to hash. */
        h = fnv(h, &st[half].texels, sizeof st[half].texels);
        h = fnv(h, &st[half].level0, sizeof st[half].level0);
        h = fnv(h, &st[half].level1, sizeof st[half].level1);
        h = fnv(h, &st[half].level_frac, sizeof st[half].level_frac);
        h = fnv(h, &st[half].lod, sizeof st[half].lod);
    }
    return h;
}

static void test_golden(void)
{
    static sample_query q[QUERIES];
    static sample_quad quad[QUERIES];
    int print = getenv("GOLDEN_PRINT") != NULL, f, k;
    size_t c;
    uint64_t got[NCONFIGS][NFORMATS];
    make_queries(q, quad);
    for (k = 0; k < SAMPLE_ISA_COUNT; ++k) {
        if (!test_isa_enter(test_isa_names[k])) continue;
        for (f = 0; f < NFORMATS; ++f) {
            sample_texture *tex = make_texture(formats[f]);
            if (!tex) return;
            for (c = 0; c < NCONFIGS; ++c) {
                got[c][f] = run_config(tex, &configs[c], q, quad);
                CHECK(print || got[c][f] == golden[c][f], "%s, %s, %s: hash 0x%016llx, recorded 0x%016llx",
                      test_isa_names[k], configs[c].name, sample_format_name(formats[f]), (unsigned long long)got[c][f],
                      (unsigned long long)golden[c][f]);
            }
            sample_texture_destroy(tex);
        }
        if (print && k == 0)
            for (c = 0; c < NCONFIGS; ++c)
                printf("    {0x%016llxull, 0x%016llxull, 0x%016llxull}, /* %s */\n", (unsigned long long)got[c][0],
                       (unsigned long long)got[c][1], (unsigned long long)got[c][2], configs[c].name);
    }
    sample_isa_force(NULL);
}

int main(void)
{
    RUN(test_golden);
    return check_finish();
}
