/*
 * Golden results: every filter, in every texel format and channel count,
 * on fixed textures and fixed queries, hashed (values, ∂/∂s, ∂/∂t and stats, λ included) and
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

static const sample_format formats[] = {SAMPLE_FORMAT_F32, SAMPLE_FORMAT_F16, SAMPLE_FORMAT_SRGB8,
                                        SAMPLE_FORMAT_UNORM8};
#define NFORMATS 4

/* A texture of nc channels, random on every level. */
static sample_texture *make_texture(sample_format fmt, int nc)
{
    sample_image lv[LEVELS];
    void *data[LEVELS];
    sample_texture *tex = NULL;
    sample_error err;
    int k, w = BASE_W, h = BASE_H;
    size_t i;
    rng = 0x243F6A8885A308D3ull + (uint64_t)fmt + 16u * (uint64_t)nc;
    for (k = 0; k < LEVELS; ++k) {
        size_t n = (size_t)w * h * (size_t)nc;
        lv[k] = (sample_image){w, h, nc, fmt, NULL, 0};
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

/* Recorded hashes, [config][format] (float, half, srgb8, unorm8), each
 * over textures of 1, 2, 3 and 4 channels. */
static const uint64_t golden[NCONFIGS][NFORMATS] = {
    {0x090bf118e12479a6ull, 0x2632481a4ed62381ull, 0xfff0d3a2708bc1baull, 0x8e41c95b055e53c3ull}, /* nearest */
    {0x479574b48992a7e5ull, 0x7f29c1db1e168fdaull, 0x1d78a8e159c4b25cull, 0x0c411c66d8e75263ull}, /* bilinear */
    {0xa8ba40ebea16551eull, 0x32a6b695acc2b69full, 0x50de124bd0a33b0aull, 0xfb1f3909c48627daull}, /* bicubic */
    {0x3f71a304131b6645ull, 0xb9bd74ad7fb29787ull, 0x4c05050d802ee4ecull, 0x4c4b75a7891ecbcfull}, /* trilinear */
    {0x2ab795244bb1da8aull, 0x61d7e56624feb0b4ull, 0xce6da48a7c84f6d1ull, 0xbec0599d814eb4b1ull}, /* aniso16 */
    {0xaa49048b3399e045ull, 0x7e7d6a05a504727eull, 0xe662b1b992ed0c37ull, 0x0949e01521e47b8dull}, /* blinn-newell */
    {0x5c2f52f74f4232acull, 0xee9cd3e3838b2c78ull, 0x8b25cfd716dda579ull, 0x8390017bcadb860bull}, /* blinn-newell corners */
    {0x5b2a54ae770e73abull, 0x24c4d2c42ff7ed88ull, 0x70477c1ebec8bfe7ull, 0xd9a57da470f083cdull}, /* ewa */
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
    static float rgba[QUERIES][4], ds[QUERIES][4], dt[QUERIES][4], plain[QUERIES][4];
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
        /* Asking for derivatives and stats does not change the values (the
         * derivative passes weigh and add the same texels in the same
         * order as the plain kernels). */
        a.rgba = plain[lo];
        a.drgba_ds = a.drgba_dt = NULL;
        a.stats = NULL;
        CHECK(sample_batch(tex, &s, &a) == SAMPLE_OK, "%s", cf->name);
    }
    CHECK(!memcmp(rgba, plain, sizeof rgba), "%s: values with derivatives and stats differ from those without",
          cf->name);
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
    int print = getenv("GOLDEN_PRINT") != NULL, f, k, nc;
    size_t c;
    uint64_t got[NCONFIGS][NFORMATS];
    make_queries(q, quad);
    for (k = 0; k < SAMPLE_ISA_COUNT; ++k) {
        if (!test_isa_enter(test_isa_names[k])) continue;
        for (f = 0; f < NFORMATS; ++f) {
            /* One hash per filter and format over 1 … 4 channels: the fast
             * path is a separate instantiation for each (fast_gl.c). */
            for (c = 0; c < NCONFIGS; ++c) got[c][f] = 0xcbf29ce484222325ull;
            for (nc = 1; nc <= 4; ++nc) {
                sample_texture *tex = make_texture(formats[f], nc);
                if (!tex) return;
                for (c = 0; c < NCONFIGS; ++c) {
                    uint64_t h = run_config(tex, &configs[c], q, quad);
                    got[c][f] = fnv(got[c][f], &h, sizeof h);
                }
                sample_texture_destroy(tex);
            }
            for (c = 0; c < NCONFIGS; ++c)
                CHECK(print || got[c][f] == golden[c][f], "%s, %s, %s: hash 0x%016llx, recorded 0x%016llx",
                      test_isa_names[k], configs[c].name, sample_format_name(formats[f]),
                      (unsigned long long)got[c][f], (unsigned long long)golden[c][f]);
        }
        if (print && k == 0)
            for (c = 0; c < NCONFIGS; ++c)
                printf("    {0x%016llxull, 0x%016llxull, 0x%016llxull, 0x%016llxull}, /* %s */\n",
                       (unsigned long long)got[c][0], (unsigned long long)got[c][1], (unsigned long long)got[c][2],
                       (unsigned long long)got[c][3], configs[c].name);
    }
    sample_isa_force(NULL);
}

int main(void)
{
    RUN(test_golden);
    return check_finish();
}
