/*
 * 3D textures (DESIGN §11, doc/volumes.md): pyramids (sizes, box and
 * polyphase weights, sRGB on linear values), creation errors, exact values
 * by hand — texel centres, midpoints, every wrap mode on r at −0.1 and
 * 1.1, level-of-detail switch points on levels of distinct constants, ρ
 * over three components, bias, clamps, base and max level — constant
 * volumes under every filter, non-finite input, every format and channel
 * count, and the footprint filters: Blinn–Newell against a dense
 * screen-space integral of the trilinear volume over the patch, EWA
 * against its definition evaluated independently (Σ = JJᵀ + I), the
 * anisotropic probes against trilinear lookups, degenerate Jacobians
 * within the texel cap.
 */
#include "check.h"
#include "internal.h"
#include "volume.h"

#include <stdint.h>
#include <stdlib.h>

static uint32_t rng_state = 0x9e3779b9u;
static double urand(void)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 17;
    rng_state ^= rng_state << 5;
    return (double)(rng_state >> 8) / 16777216.0;
}

static sample_texture *vol_f32(int w, int h, int d, int nc, const float *data, const sample_mip_params *mip)
{
    sample_volume v = {w, h, d, nc, SAMPLE_FORMAT_F32, data, 0, 0};
    sample_texture *tex = NULL;
    sample_error err;
    if (sample_texture_create_3d(&v, mip, &tex, &err) != SAMPLE_OK) fprintf(stderr, "create: %s\n", err.message);
    return tex;
}

/* One query with a zero Jacobian unless given. */
static void look(const sample_texture *tex, const sample_sampler *s, const float p[3], const float dx[3],
                 const float dy[3], float out[4], sample_stats *st)
{
    sample_query3 q;
    sample_batch3_args a;
    sample_stats local;
    memset(&q, 0, sizeof q);
    memcpy(q.p, p, sizeof q.p);
    if (dx) memcpy(q.dpdx, dx, sizeof q.dpdx);
    if (dy) memcpy(q.dpdy, dy, sizeof q.dpdy);
    memset(&a, 0, sizeof a);
    a.count = 1;
    a.queries = &q;
    a.rgba = out;
    a.stats = st ? st : &local;
    CHECK(sample_batch_3d(tex, s, &a) == SAMPLE_OK, "sample_batch_3d");
}

/* ---- Pyramids and creation ------------------------------------------- */

static void pyramid_sizes_and_box(void)
{
    /* 4 × 2 × 2 → 2 × 1 × 1 → 1 × 1 × 1: each level-1 texel the mean of
     * its 2 × 2 × 2 block (dyadic values: exact). */
    float data[16], rgba[4];
    int i, w, h, d;
    sample_mip_params mp;
    sample_texture_info info;
    sample_texture *tex;
    for (i = 0; i < 16; ++i) data[i] = (float)i / 8.0f;
    sample_mip_params_init(&mp);
    CHECK(mp.wrap_r == SAMPLE_WRAP_CLAMP_TO_EDGE, "wrap_r default");
    tex = vol_f32(4, 2, 2, 1, data, &mp);
    if (!tex) return;
    sample_texture_info_get(tex, &info);
    CHECK(info.kind == SAMPLE_TEXTURE_3D && info.depth == 2 && info.levels == 3, "kind %d depth %d levels %d",
          (int)info.kind, info.depth, info.levels);
    CHECK(info.bytes == (16 + 2 + 1) * sizeof(float), "bytes %zu", info.bytes);
    CHECK(sample_texture_level_size3(tex, 1, &w, &h, &d) && w == 2 && h == 1 && d == 1, "level 1 %d %d %d", w, h, d);
    CHECK(!sample_texture_level_size3(tex, 3, &w, &h, &d) && w == 0 && d == 0, "level 3 out of range");
    /* Block x ∈ {0,1}: texels 0,1,4,5 (z 0) and 8,9,12,13 (z 1). */
    sample_texture_texel_layer(tex, 1, 0, 0, 0, rgba);
    CHECK_EQF(rgba[0], (0 + 1 + 4 + 5 + 8 + 9 + 12 + 13) / 64.0f);
    sample_texture_texel_layer(tex, 1, 0, 1, 0, rgba);
    CHECK_EQF(rgba[0], (2 + 3 + 6 + 7 + 10 + 11 + 14 + 15) / 64.0f);
    sample_texture_texel_layer(tex, 2, 0, 0, 0, rgba);
    CHECK_EQF(rgba[0], 120.0f / 16.0f / 8.0f);
    sample_texture_texel_layer(tex, 0, 1, 3, 1, rgba);
    CHECK_EQF(rgba[0], 15.0f / 8.0f);
    CHECK_EQF(rgba[3], 1.0f);
    sample_texture_texel_layer(tex, 0, 2, 0, 0, rgba);
    CHECK_EQF(rgba[0], 0.0f);
    sample_texture_destroy(tex);

    /* Depth alone decides the chain: 1 × 1 × 8 has 4 levels, 2 × 2 × 16 5. */
    {
        float z[32] = {0};
        tex = vol_f32(1, 1, 8, 1, z, &mp);
        sample_texture_info_get(tex, &info);
        CHECK(info.levels == 4, "1x1x8 levels %d", info.levels);
        sample_texture_destroy(tex);
        tex = vol_f32(2, 2, 8, 1, z, &mp);
        sample_texture_info_get(tex, &info);
        CHECK(info.levels == 4, "2x2x8 levels %d", info.levels);
        sample_texture_destroy(tex);
    }
}

static void pyramid_odd_polyphase(void)
{
    /* 1 × 1 × 3 → 1 × 1 × 1: the 3-tap polyphase box (weights 1/3 each
     * for n = 3, m = 1); 1 × 1 × 5 → 2: (2/5, 2/5, 1/5) and (1/5, 2/5, 2/5). */
    float d3[3] = {0.0f, 3.0f, 6.0f}, d5[5] = {5.0f, 10.0f, 0.0f, 0.0f, 5.0f}, rgba[4];
    sample_mip_params mp;
    sample_texture *tex;
    sample_mip_params_init(&mp);
    tex = vol_f32(1, 1, 3, 1, d3, &mp);
    sample_texture_texel_layer(tex, 1, 0, 0, 0, rgba);
    CHECK_NEAR(rgba[0], 3.0, 1e-6);
    sample_texture_destroy(tex);
    tex = vol_f32(1, 1, 5, 1, d5, &mp);
    sample_texture_texel_layer(tex, 1, 0, 0, 0, rgba);
    CHECK_NEAR(rgba[0], 0.4 * 5 + 0.4 * 10 + 0.2 * 0, 1e-6);
    sample_texture_texel_layer(tex, 1, 1, 0, 0, rgba);
    CHECK_NEAR(rgba[0], 0.2 * 0 + 0.4 * 0 + 0.4 * 5, 1e-6);
    sample_texture_destroy(tex);
}

static void pyramid_srgb_linear(void)
{
    /* Two slices, codes 0 and 255: level 1 is linear ½, stored as its
     * sRGB code (averaging codes would give 128). */
    unsigned char px[2] = {0, 255};
    sample_volume v = {1, 1, 2, 1, SAMPLE_FORMAT_SRGB8, px, 0, 0};
    sample_mip_params mp;
    sample_texture *tex = NULL;
    float rgba[4];
    sample_mip_params_init(&mp);
    CHECK(sample_texture_create_3d(&v, &mp, &tex, NULL) == SAMPLE_OK, "create");
    sample_texture_texel_layer(tex, 1, 0, 0, 0, rgba);
    CHECK_EQF(rgba[0], ls_srgb_table[ls_srgb_encode8(0.5f)]);
    sample_texture_destroy(tex);
}

static void creation_errors(void)
{
    float data[64] = {0};
    sample_volume v = {2, 2, 2, 4, SAMPLE_FORMAT_F32, data, 0, 0}, lv[3];
    sample_texture *tex = (sample_texture *)1;
    sample_error err;
    sample_mip_params mp;
    sample_sampler s;
    sample_batch3_args a;
    sample_batch_args a2;
    sample_query3 q;
    sample_query q2;
    float out[4];
    v.depth = 0;
    CHECK(sample_texture_create_3d(&v, NULL, &tex, &err) == SAMPLE_E_BAD_SIZE && !tex, "depth 0: %s", err.message);
    v.depth = SAMPLE_MAX_SIZE + 1;
    CHECK(sample_texture_create_3d(&v, NULL, &tex, &err) == SAMPLE_E_TOO_LARGE, "depth too large");
    v.depth = 2;
    v.slice_stride = 16;
    CHECK(sample_texture_create_3d(&v, NULL, &tex, &err) == SAMPLE_E_BAD_SIZE, "short slice stride: %s", err.message);
    v.slice_stride = 0;
    sample_mip_params_init(&mp);
    mp.wrap_r = (sample_wrap)99;
    CHECK(sample_texture_create_3d(&v, &mp, &tex, &err) == SAMPLE_E_INVALID_ARGUMENT, "bad wrap_r");
    /* 65536 × 65536 × 8 bytes of texels: over the byte limit, before any
     * allocation. */
    {
        sample_volume big = {65536, 65536, 8, 1, SAMPLE_FORMAT_UNORM8, data, 0, 0};
        CHECK(sample_texture_create_3d(&big, NULL, &tex, &err) == SAMPLE_E_TOO_LARGE, "bytes: %s", err.message);
    }
    lv[0] = v;
    lv[1] = v;
    lv[1].width = lv[1].height = lv[1].depth = 1;
    lv[2] = lv[1];
    CHECK(sample_texture_create_3d_levels(lv, 3, &tex, &err) == SAMPLE_E_BAD_SIZE, "3 levels of a 2^3: %s",
          err.message);
    lv[1].depth = 2;
    CHECK(sample_texture_create_3d_levels(lv, 2, &tex, &err) == SAMPLE_E_BAD_SIZE, "level 1 depth: %s", err.message);
    lv[1].depth = 1;
    CHECK(sample_texture_create_3d_levels(lv, 2, &tex, &err) == SAMPLE_OK, "two levels");
    /* A 3D texture refuses 2D queries, and a 2D texture 3D ones. */
    sample_sampler_init(&s);
    memset(&q, 0, sizeof q);
    memset(&q2, 0, sizeof q2);
    memset(&a, 0, sizeof a);
    memset(&a2, 0, sizeof a2);
    a.count = a2.count = 1;
    a.queries = &q;
    a2.queries = &q2;
    a.rgba = a2.rgba = out;
    CHECK(sample_batch(tex, &s, &a2) == SAMPLE_E_INVALID_ARGUMENT, "2D query on a volume");
    s.wrap_r = (sample_wrap)42;
    CHECK(sample_batch_3d(tex, &s, &a) == SAMPLE_E_INVALID_ARGUMENT, "bad wrap_r");
    sample_texture_destroy(tex);
    {
        sample_image im = {2, 2, 4, SAMPLE_FORMAT_F32, data, 0};
        sample_sampler_init(&s);
        CHECK(sample_texture_create(&im, NULL, &tex, NULL) == SAMPLE_OK, "2D");
        CHECK(sample_batch_3d(tex, &s, &a) == SAMPLE_E_INVALID_ARGUMENT, "3D query on a 2D texture");
        sample_texture_destroy(tex);
    }
}

/* ---- Exact values by hand --------------------------------------------- */

static void centres_and_midpoints(void)
{
    /* 4 × 2 × 8 RGBA, dyadic values: NEAREST and LINEAR at texel centres
     * give the texel; LINEAR at the corner shared by 8 texels gives their
     * mean, exactly. */
    enum { W = 4, H = 2, D = 8 };
    float data[W * H * D * 4], out[4], p[3];
    sample_sampler s;
    sample_texture *tex;
    int i, j, k, c;
    for (i = 0; i < W * H * D * 4; ++i) data[i] = (float)(int)(urand() * 64) / 16.0f;
    tex = vol_f32(W, H, D, 4, data, NULL);
    sample_sampler_init(&s);
    for (k = 0; k < D; ++k)
        for (j = 0; j < H; ++j)
            for (i = 0; i < W; ++i) {
                const float *t = data + 4 * (i + W * (j + H * k));
                p[0] = (i + 0.5f) / W;
                p[1] = (j + 0.5f) / H;
                p[2] = (k + 0.5f) / D;
                s.mag_filter = SAMPLE_NEAREST;
                look(tex, &s, p, NULL, NULL, out, NULL);
                for (c = 0; c < 4; ++c) CHECK(out[c] == t[c], "nearest (%d,%d,%d)[%d] %g vs %g", i, j, k, c, out[c], t[c]);
                s.mag_filter = SAMPLE_LINEAR;
                look(tex, &s, p, NULL, NULL, out, NULL);
                for (c = 0; c < 4; ++c) CHECK(out[c] == t[c], "linear (%d,%d,%d)[%d] %g vs %g", i, j, k, c, out[c], t[c]);
                if (i + 1 < W && j + 1 < H && k + 1 < D) {
                    float mean[4] = {0, 0, 0, 0};
                    int n;
                    for (n = 0; n < 8; ++n) {
                        const float *u = data + 4 * ((i + (n & 1)) + W * ((j + (n >> 1 & 1)) + H * (k + (n >> 2))));
                        for (c = 0; c < 4; ++c) mean[c] += u[c] / 8.0f;
                    }
                    p[0] = (float)(i + 1) / W;
                    p[1] = (float)(j + 1) / H;
                    p[2] = (float)(k + 1) / D;
                    look(tex, &s, p, NULL, NULL, out, NULL);
                    for (c = 0; c < 4; ++c) CHECK(out[c] == mean[c], "midpoint (%d,%d,%d)[%d] %g vs %g", i, j, k, c, out[c], mean[c]);
                }
            }
    sample_texture_destroy(tex);
}

static void wraps_on_r(void)
{
    /* 1 × 1 × 4, slices 1, 2, 3, 4; border 9. At r = −0.1 (w = −0.4) and
     * r = 1.1 (w = 4.4), NEAREST and LINEAR; values from DESIGN §3's table
     * by hand:
     *   NEAREST −0.1: k = −1.  LINEAR −0.1: k0 = −1, γ = 0.1 → 0.9·T(−1) + 0.1·T(0).
     *   NEAREST  1.1: k = 4.   LINEAR  1.1: k0 = 3, γ = 0.9 → 0.1·T(3) + 0.9·T(4).
     * REPEAT: T(−1) = 4, T(4) = 1. MIRRORED_REPEAT: T(−1) = 1, T(4) = 4.
     * CLAMP_TO_EDGE, MIRROR_CLAMP_TO_EDGE: the edge slices. CLAMP_TO_BORDER:
     * 9. Legacy CLAMP: r clamped to [0, 1] first (w = 0 or 4): NEAREST the
     * edge, LINEAR half edge, half border. MIRROR_CLAMP_EXT: |r| clamped to
     * [1/8, 1]: −0.1 → 0.125 (w = ½, slice 0 alone), 1.1 → 1 (as CLAMP).
     * MIRROR_CLAMP_TO_BORDER_EXT: [1/8, 1 + 1/8]: −0.1 → 0.125, 1.1 stays. */
    static const float expect[SAMPLE_WRAP_COUNT][4] = {
        /* nearest −0.1, linear −0.1, nearest 1.1, linear 1.1 */
        [SAMPLE_WRAP_REPEAT] = {4, 3.7f, 1, 1.3f},
        [SAMPLE_WRAP_MIRRORED_REPEAT] = {1, 1, 4, 4},
        [SAMPLE_WRAP_CLAMP_TO_EDGE] = {1, 1, 4, 4},
        [SAMPLE_WRAP_CLAMP_TO_BORDER] = {9, 8.2f, 9, 8.5f},
        [SAMPLE_WRAP_MIRROR_CLAMP_TO_EDGE] = {1, 1, 4, 4},
        [SAMPLE_WRAP_CLAMP] = {1, 5, 4, 6.5f},
        [SAMPLE_WRAP_MIRROR_CLAMP] = {1, 1, 4, 6.5f},
        [SAMPLE_WRAP_MIRROR_CLAMP_TO_BORDER] = {1, 1, 9, 8.5f},
    };
    float data[4] = {1, 2, 3, 4}, out[4];
    sample_texture *tex = vol_f32(1, 1, 4, 1, data, NULL);
    sample_sampler s;
    int m, n;
    for (m = 0; m < SAMPLE_WRAP_COUNT; ++m)
        for (n = 0; n < 4; ++n) {
            float p[3] = {0.5f, 0.5f, n < 2 ? -0.1f : 1.1f};
            sample_sampler_init(&s);
            s.wrap_r = (sample_wrap)m;
            s.border_color[0] = s.border_color[1] = s.border_color[2] = s.border_color[3] = 9.0f;
            s.mag_filter = (n & 1) ? SAMPLE_LINEAR : SAMPLE_NEAREST;
            look(tex, &s, p, NULL, NULL, out, NULL);
            CHECK(fabs(out[0] - expect[m][n]) <= 4e-6, "%s %s r = %g: %.9g, expected %g", sample_wrap_name((sample_wrap)m),
                  (n & 1) ? "linear" : "nearest", p[2], out[0], expect[m][n]);
        }
    sample_texture_destroy(tex);
}

/* 8 × 8 × 8 with explicit levels of constants 10, 20, 30, 40. */
static sample_texture *level_constants(void)
{
    static float buf[4][8 * 8 * 8];
    sample_volume lv[4];
    sample_texture *tex = NULL;
    int k, i;
    for (k = 0; k < 4; ++k) {
        int n = 8 >> k;
        for (i = 0; i < n * n * n; ++i) buf[k][i] = 10.0f * (k + 1);
        lv[k] = (sample_volume){n, n, n, 1, SAMPLE_FORMAT_F32, buf[k], 0, 0};
    }
    CHECK(sample_texture_create_3d_levels(lv, 4, &tex, NULL) == SAMPLE_OK, "levels");
    return tex;
}

static void lod_switch_points(void)
{
    /* ρ from the r derivative alone (ρ = dr/dx · 8): NEAREST_MIPMAP_NEAREST
     * switches level at λ = k + ½ (d = ⌈λ + ½⌉ − 1), q = 3 beyond. */
    static const struct {
        double log2rho;
        float expect;
    } nmn[] = {{0.49, 10}, {0.51, 20}, {1.49, 20}, {1.51, 30}, {2.49, 30}, {2.51, 40}, {10, 40}};
    sample_texture *tex = level_constants();
    sample_sampler s;
    sample_stats st;
    float out[4], p[3] = {0.3f, 0.6f, 0.2f};
    size_t n;
    sample_sampler_init(&s);
    s.min_filter = SAMPLE_NEAREST_MIPMAP_NEAREST;
    for (n = 0; n < sizeof nmn / sizeof nmn[0]; ++n) {
        float dx[3] = {0, 0, (float)(pow(2.0, nmn[n].log2rho) / 8.0)};
        look(tex, &s, p, dx, NULL, out, &st);
        CHECK(out[0] == nmn[n].expect, "log2 ρ %g: %g, expected %g", nmn[n].log2rho, out[0], nmn[n].expect);
    }
    /* Trilinear at λ = 1.25: levels 1 and 2, ¼ of the second. */
    s.min_filter = SAMPLE_LINEAR_MIPMAP_LINEAR;
    {
        float dy[3] = {0, (float)(pow(2.0, 1.25) / 8.0), 0};
        look(tex, &s, p, NULL, dy, out, &st);
        CHECK_NEAR(out[0], 22.5, 2e-5);
        CHECK(st.level0 == 1 && st.level1 == 2 && fabs(st.level_frac - 0.25) < 1e-6, "levels %d %d %g", st.level0,
              st.level1, st.level_frac);
    }
    /* ρ over three components: (3, 4, 12) texels → 13; the longer column. */
    {
        float dx[3] = {3.0f / 8, 4.0f / 8, 12.0f / 8}, dy[3] = {1.0f / 8, 0, 0};
        look(tex, &s, p, dx, dy, out, &st);
        CHECK_NEAR(st.lod, log2(13.0), 1e-6);
        look(tex, &s, p, dy, dx, out, &st);
        CHECK_NEAR(st.lod, log2(13.0), 1e-6);
    }
    /* Bias (sampler and per call), min_lod, base and max level. */
    s.min_filter = SAMPLE_NEAREST_MIPMAP_NEAREST;
    {
        float dx[3] = {0, 0, (float)(pow(2.0, 0.25) / 8.0)};
        sample_query3 q = {{0.3f, 0.6f, 0.2f}, {0, 0, 0}, {0, 0, 0}};
        float bias = 1.0f;
        sample_batch3_args a = {1, &q, &bias, out, &st};
        s.lod_bias = 1.0f;
        look(tex, &s, p, dx, NULL, out, &st); /* λ = 1.25 → level 1 */
        CHECK(out[0] == 20.0f, "bias: %g", out[0]);
        memcpy(q.dpdx, dx, sizeof dx);
        CHECK(sample_batch_3d(tex, &s, &a) == SAMPLE_OK && out[0] == 30.0f, "two biases: %g", out[0]); /* λ 2.25 */
        s.lod_bias = 0.0f;
        s.min_lod = 2.0f; /* zero Jacobian: λ = −∞ clamped to 2 → level 2 */
        look(tex, &s, p, NULL, NULL, out, &st);
        CHECK(out[0] == 30.0f, "min_lod: %g", out[0]);
        s.min_lod = -1000.0f;
        s.base_level = 1; /* magnification of level_base */
        look(tex, &s, p, NULL, NULL, out, &st);
        CHECK(out[0] == 20.0f && st.level0 == 1, "base level: %g", out[0]);
        s.base_level = 0;
        s.max_level = 2;
        dx[2] = 100.0f;
        look(tex, &s, p, dx, NULL, out, &st);
        CHECK(out[0] == 30.0f, "max level: %g", out[0]);
    }
    sample_texture_destroy(tex);
}

/* ---- Constant volumes, bad input, formats ------------------------------ */

static void constant_every_filter(void)
{
    enum { W = 5, H = 3, D = 6 };
    static const float val[4] = {0.25f, 0.5f, 0.75f, 1.0f};
    static const sample_wrap wraps[] = {SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_MIRRORED_REPEAT, SAMPLE_WRAP_CLAMP_TO_EDGE,
                                        SAMPLE_WRAP_MIRROR_CLAMP_TO_EDGE};
    float data[W * H * D * 4], out[4];
    sample_mip_params mp;
    sample_texture *tex;
    sample_sampler s;
    sample_stats st;
    int i, f, fp, n, c;
    for (i = 0; i < W * H * D; ++i) memcpy(data + 4 * i, val, sizeof val);
    sample_mip_params_init(&mp);
    tex = vol_f32(W, H, D, 4, data, &mp);
    for (fp = 0; fp < SAMPLE_FOOTPRINT_COUNT; ++fp)
        for (f = 0; f < SAMPLE_FILTER_COUNT; ++f)
            for (n = 0; n < 12; ++n) {
                float p[3], dx[3], dy[3], scale = (float)pow(10.0, urand() * 4 - 2);
                for (c = 0; c < 3; ++c) {
                    p[c] = (float)(urand() * 3 - 1);
                    dx[c] = (float)(urand() - 0.5) * scale;
                    dy[c] = (float)(urand() - 0.5) * scale * (n & 1 ? 0.05f : 1.0f);
                }
                sample_sampler_init(&s);
                s.min_filter = (sample_filter)f;
                s.mag_filter = f == SAMPLE_CUBIC ? SAMPLE_CUBIC : SAMPLE_LINEAR;
                s.footprint = (sample_footprint)fp;
                s.max_anisotropy = 16.0f;
                s.wrap_s = wraps[n % 4];
                s.wrap_t = wraps[(n + 1) % 4];
                s.wrap_r = wraps[(n + 2) % 4];
                look(tex, &s, p, dx, dy, out, &st);
                for (c = 0; c < 4; ++c)
                    CHECK(fabs(out[c] - val[c]) <= 1e-6, "filter %s footprint %s n %d [%d] %.9g",
                          sample_filter_name((sample_filter)f), sample_footprint_name((sample_footprint)fp), n, c,
                          out[c]);
                CHECK(st.texels <= SAMPLE_MAX_FOOTPRINT_TEXELS && st.texels > 0, "texels %u", (unsigned)st.texels);
            }
    sample_texture_destroy(tex);
}

static void non_finite_gives_border(void)
{
    float data[8 * 4] = {0}, out[4];
    sample_mip_params mp;
    sample_texture *tex;
    sample_sampler s;
    sample_stats st;
    const float bad[3] = {NAN, INFINITY, -INFINITY};
    int fp, slot, b;
    sample_mip_params_init(&mp);
    tex = vol_f32(2, 2, 2, 4, data, &mp);
    for (fp = 0; fp < SAMPLE_FOOTPRINT_COUNT; ++fp)
        for (slot = 0; slot < 10; ++slot)
            for (b = 0; b < 3; ++b) {
                sample_query3 q = {{0.5f, 0.5f, 0.5f}, {0.3f, 0.1f, 0.2f}, {0.0f, 0.2f, 0.1f}};
                float bias = 0.0f;
                sample_batch3_args a = {1, &q, &bias, out, &st};
                if (slot < 9) ((float *)&q)[slot] = bad[b];
                else bias = bad[b];
                sample_sampler_init(&s);
                s.footprint = (sample_footprint)fp;
                s.border_color[0] = 0.125f;
                s.border_color[3] = 0.5f;
                CHECK(sample_batch_3d(tex, &s, &a) == SAMPLE_OK, "batch");
                CHECK(out[0] == 0.125f && out[1] == 0.0f && out[3] == 0.5f && st.texels == 0 && st.level0 == -1,
                      "footprint %d slot %d bad %d: %g %g", fp, slot, b, out[0], out[3]);
            }
    sample_texture_destroy(tex);
}

static void every_format(void)
{
    /* 2 × 2 × 2 of random texels in every format and channel count: NEAREST
     * at each centre is the decoded texel (sample_texture_texel_layer, GL's
     * channel expansion), LINEAR at the centre of the block the mean. */
    int fmt, nc, n, c;
    for (fmt = 0; fmt < SAMPLE_FORMAT_COUNT; ++fmt)
        for (nc = 1; nc <= 4; ++nc) {
            unsigned char bytes[8 * 4 * 4];
            sample_volume v = {2, 2, 2, nc, (sample_format)fmt, bytes, 0, 0};
            sample_texture *tex = NULL;
            sample_sampler s;
            float mean[4] = {0, 0, 0, 0}, out[4], t[4];
            for (n = 0; n < (int)sizeof bytes; ++n) bytes[n] = (unsigned char)(urand() * 256);
            if (fmt == SAMPLE_FORMAT_F32)
                for (n = 0; n < 8 * nc; ++n) ((float *)(void *)bytes)[n] = (float)urand();
            if (fmt == SAMPLE_FORMAT_F16)
                for (n = 0; n < 8 * nc; ++n) {
                    uint16_t h = sample_float_to_half((float)urand());
                    memcpy(bytes + 2 * n, &h, 2);
                }
            CHECK(sample_texture_create_3d(&v, NULL, &tex, NULL) == SAMPLE_OK, "create");
            sample_sampler_init(&s);
            for (n = 0; n < 8; ++n) {
                float p[3] = {(n & 1) ? 0.75f : 0.25f, (n & 2) ? 0.75f : 0.25f, (n & 4) ? 0.75f : 0.25f};
                s.mag_filter = SAMPLE_NEAREST;
                look(tex, &s, p, NULL, NULL, out, NULL);
                sample_texture_texel_layer(tex, 0, n >> 2, n & 1, n >> 1 & 1, t);
                for (c = 0; c < 4; ++c) {
                    CHECK(out[c] == t[c], "%s x%d texel %d [%d]", sample_format_name((sample_format)fmt), nc, n, c);
                    mean[c] += t[c];
                }
                CHECK(nc > 1 || (t[1] == 0.0f && t[2] == 0.0f), "G, B of one channel read 0");
                CHECK(nc > 3 || t[3] == 1.0f, "missing alpha reads 1");
            }
            {
                float p[3] = {0.5f, 0.5f, 0.5f};
                s.mag_filter = SAMPLE_LINEAR;
                look(tex, &s, p, NULL, NULL, out, NULL);
                for (c = 0; c < 4; ++c) CHECK_NEAR(out[c], mean[c] / 8.0, 1e-6);
            }
            sample_texture_destroy(tex);
        }
}

/* ---- Footprint filters --------------------------------------------------- */

enum { FN = 16 };
static float smooth_data[FN * FN * FN * 4];

static float smooth_fn(int i, int j, int k, int c)
{
    /* Periodic in 16 on every axis (REPEAT), mild. */
    const double w = 2.0 * 3.14159265358979323846 / FN;
    return (float)(0.5 + 0.2 * sin(w * i + 0.3 * c) * cos(w * j + 0.1) + 0.15 * cos(w * (k + i) + 0.7 * c));
}

static void smooth_fill(void)
{
    int i, j, k, c;
    for (k = 0; k < FN; ++k)
        for (j = 0; j < FN; ++j)
            for (i = 0; i < FN; ++i)
                for (c = 0; c < 4; ++c) smooth_data[4 * (i + FN * (j + FN * k)) + c] = smooth_fn(i, j, k, c);
}

/* smooth_data as a one-level volume. */
static sample_texture *smooth_volume(void)
{
    smooth_fill();
    return vol_f32(FN, FN, FN, 4, smooth_data, NULL);
}

/* The trilinear reconstruction of smooth_data at texel coordinates u
 * (texel centres at integers), REPEAT, written out independently. */
static double trilinear(const double u[3], int c)
{
    double f[3], acc = 0.0;
    int i0[3], a, n;
    for (a = 0; a < 3; ++a) {
        double fl = floor(u[a]);
        i0[a] = (int)fl;
        f[a] = u[a] - fl;
    }
    for (n = 0; n < 8; ++n) {
        int x = ((i0[0] + (n & 1)) % FN + FN) % FN, y = ((i0[1] + (n >> 1 & 1)) % FN + FN) % FN;
        int z = ((i0[2] + (n >> 2)) % FN + FN) % FN;
        double w = ((n & 1) ? f[0] : 1 - f[0]) * ((n & 2) ? f[1] : 1 - f[1]) * ((n & 4) ? f[2] : 1 - f[2]);
        acc += w * smooth_data[4 * (x + FN * (y + FN * z)) + c];
    }
    return acc;
}

/* A random patch: centre in the volume, columns of 1.5 … 5 texels in
 * random directions (eccentricity well under 16). */
static void random_patch(float p[3], float dx[3], float dy[3])
{
    double a[3], b[3], la, lb, l;
    int k;
    for (k = 0; k < 3; ++k) {
        p[k] = (float)urand();
        a[k] = urand() - 0.5;
        b[k] = urand() - 0.5;
    }
    la = 1.5 + 3.5 * urand();
    lb = 1.5 + 3.5 * urand();
    l = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    for (k = 0; k < 3; ++k) dx[k] = (float)(a[k] / l * la / FN);
    l = sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
    for (k = 0; k < 3; ++k) dy[k] = (float)(b[k] / l * lb / FN);
}

static void blinn_newell_dense(void)
{
    /* Blinn–Newell should be the pyramid-weighted integral of the trilinear
     * volume over the patch P + x·dPdx + y·dPdy, (x, y) ∈ [−1, 1]²; the
     * reference integrates that on a 96 × 96 midpoint grid. One level, so
     * the level choice plays no part. */
    enum { G = 96, NQ = 24 };
    sample_texture *tex = smooth_volume();
    sample_sampler s;
    sample_stats st;
    double worst = 0.0;
    int n, a, b, c, k;
    sample_sampler_init(&s);
    s.footprint = SAMPLE_FOOTPRINT_BLINN_NEWELL;
    s.max_level = 0;
    for (n = 0; n < NQ; ++n) {
        float p[3], dx[3], dy[3], out[4];
        double num[4] = {0, 0, 0, 0}, den = 0.0;
        random_patch(p, dx, dy);
        look(tex, &s, p, dx, dy, out, &st);
        for (b = 0; b < G; ++b)
            for (a = 0; a < G; ++a) {
                double x = -1.0 + (a + 0.5) * 2.0 / G, y = -1.0 + (b + 0.5) * 2.0 / G, u[3];
                double w = (1 - fabs(x)) * (1 - fabs(y));
                for (k = 0; k < 3; ++k) u[k] = ((double)p[k] + x * dx[k] + y * dy[k]) * FN - 0.5;
                for (c = 0; c < 4; ++c) num[c] += w * trilinear(u, c);
                den += w;
            }
        for (c = 0; c < 4; ++c) {
            double e = fabs(out[c] - num[c] / den);
            if (e > worst) worst = e;
        }
        CHECK(st.texels <= SAMPLE_MAX_FOOTPRINT_TEXELS, "texels %u", (unsigned)st.texels);
    }
    printf("Blinn-Newell 3D vs dense integral: worst %.3g\n", worst);
    /* The weights are the moment-matched surrogate of pyramid ⊛ trilinear
     * tent (doc/volumes.md), as in 2D; measured worst 3.45e-3 here (the
     * 2D filter's bound is 3e-3 on a milder texture). */
    CHECK(worst <= 4e-3, "worst |BN − reference| = %.3g", worst);
    sample_texture_destroy(tex);
}

/* The inverse of a symmetric 3 × 3 matrix by cofactors. */
static void inverse3(double S[3][3], double I[3][3])
{
    double det;
    int r, c;
    I[0][0] = S[1][1] * S[2][2] - S[1][2] * S[2][1];
    I[0][1] = S[0][2] * S[2][1] - S[0][1] * S[2][2];
    I[0][2] = S[0][1] * S[1][2] - S[0][2] * S[1][1];
    I[1][0] = S[1][2] * S[2][0] - S[1][0] * S[2][2];
    I[1][1] = S[0][0] * S[2][2] - S[0][2] * S[2][0];
    I[1][2] = S[0][2] * S[1][0] - S[0][0] * S[1][2];
    I[2][0] = S[1][0] * S[2][1] - S[1][1] * S[2][0];
    I[2][1] = S[0][1] * S[2][0] - S[0][0] * S[2][1];
    I[2][2] = S[0][0] * S[1][1] - S[0][1] * S[1][0];
    det = S[0][0] * I[0][0] + S[0][1] * I[1][0] + S[0][2] * I[2][0];
    for (r = 0; r < 3; ++r)
        for (c = 0; c < 3; ++c) I[r][c] /= det;
}

static void ewa_definition(void)
{
    /* EWA in 3D is the Gaussian e^(−2r²) − e^(−2) (r² < 1) of
     * r² = dᵀ Σ⁻¹ d, Σ = JJᵀ + I in texels, over every texel: evaluated
     * here with exp and a cofactor inverse, nothing shared with the
     * library's frame (U, σ, V). */
    enum { NQ = 24 };
    sample_texture *tex = smooth_volume();
    sample_sampler s;
    sample_stats st;
    double worst = 0.0;
    int n, i, j, k, r, c;
    sample_sampler_init(&s);
    s.footprint = SAMPLE_FOOTPRINT_EWA;
    s.max_level = 0;
    for (n = 0; n < NQ; ++n) {
        float p[3], dx[3], dy[3], out[4];
        double S[3][3], Si[3][3], u0[3], num[4] = {0, 0, 0, 0}, den = 0.0;
        random_patch(p, dx, dy);
        look(tex, &s, p, dx, dy, out, &st);
        for (r = 0; r < 3; ++r) {
            u0[r] = (double)p[r] * FN - 0.5;
            for (c = 0; c < 3; ++c)
                S[r][c] = (double)dx[r] * FN * dx[c] * FN + (double)dy[r] * FN * dy[c] * FN + (r == c);
        }
        inverse3(S, Si);
        for (k = -12; k <= 28; ++k)
            for (j = -12; j <= 28; ++j)
                for (i = -12; i <= 28; ++i) {
                    double d[3] = {i - u0[0], j - u0[1], k - u0[2]}, r2 = 0.0, w;
                    for (r = 0; r < 3; ++r)
                        for (c = 0; c < 3; ++c) r2 += d[r] * Si[r][c] * d[c];
                    if (!(r2 < 1.0)) continue;
                    w = exp(-2.0 * r2) - exp(-2.0);
                    for (c = 0; c < 4; ++c)
                        num[c] += w * smooth_data[4 * (((i % FN + FN) % FN) + FN * (((j % FN + FN) % FN) + FN * ((k % FN + FN) % FN))) + c];
                    den += w;
                }
        for (c = 0; c < 4; ++c) {
            double e = fabs(out[c] - num[c] / den);
            if (e > worst) worst = e;
        }
    }
    printf("EWA 3D vs its definition: worst %.3g\n", worst);
    CHECK(worst <= 1e-4, "worst |EWA − definition| = %.3g", worst);
    sample_texture_destroy(tex);
}

static void zero_jacobian_is_trilinear(void)
{
    /* min_lod > 0 sends even a zero Jacobian to the footprint filters;
     * on one level Blinn–Newell's weights are then the trilinear ones. */
    sample_texture *tex = smooth_volume();
    sample_sampler s, t;
    int n, c;
    sample_sampler_init(&s);
    s.footprint = SAMPLE_FOOTPRINT_BLINN_NEWELL;
    s.min_lod = 0.5f;
    s.max_level = 0;
    sample_sampler_init(&t);
    for (n = 0; n < 16; ++n) {
        float p[3] = {(float)urand(), (float)urand(), (float)urand()}, a[4], b[4];
        look(tex, &s, p, NULL, NULL, a, NULL);
        look(tex, &t, p, NULL, NULL, b, NULL);
        for (c = 0; c < 4; ++c) CHECK_NEAR(a[c], b[c], 1e-6);
    }
    sample_texture_destroy(tex);
}

static void aniso_probes(void)
{
    /* max_anisotropy 4, a footprint 4 times longer along dP/dx (mostly r)
     * than along dP/dy: the mean of trilinear lookups at offsets
     * i/5 − ½ of dP/dx, each at λ = log2(Pmax / 4) (a Jacobian of a
     * quarter of dP/dx gives that λ to trilinear). */
    sample_mip_params mp;
    sample_texture *tex;
    sample_sampler s, t;
    sample_stats st;
    int n, i, c, k;
    smooth_fill();
    sample_mip_params_init(&mp);
    tex = vol_f32(FN, FN, FN, 4, smooth_data, &mp);
    sample_sampler_init(&s);
    s.footprint = SAMPLE_FOOTPRINT_ANISOTROPIC;
    s.min_filter = SAMPLE_LINEAR_MIPMAP_LINEAR;
    s.max_anisotropy = 4.0f;
    sample_sampler_init(&t);
    t.min_filter = SAMPLE_LINEAR_MIPMAP_LINEAR;
    for (n = 0; n < 8; ++n) {
        float p[3] = {(float)urand(), (float)urand(), (float)urand()}, out[4], ref[4];
        float L = (float)(6.0 + 20.0 * urand()) / FN;
        float dx[3] = {0.1f * L, -0.2f * L, L}, dy[3], q[3], dq[3];
        double norm = sqrt(0.01 + 0.04 + 1.0), acc[4] = {0, 0, 0, 0};
        dy[0] = (float)(L * norm / 4.0);
        dy[1] = dy[2] = 0.0f;
        look(tex, &s, p, dx, dy, out, &st);
        for (k = 0; k < 3; ++k) dq[k] = dx[k] / 4.0f;
        for (i = 1; i <= 4; ++i) {
            double off = i / 5.0 - 0.5;
            for (k = 0; k < 3; ++k) q[k] = (float)(p[k] + off * dx[k]);
            look(tex, &t, q, dq, NULL, ref, NULL);
            for (c = 0; c < 4; ++c) acc[c] += ref[c] / 4.0;
        }
        for (c = 0; c < 4; ++c) CHECK_NEAR(out[c], acc[c], 2e-5);
        CHECK(st.texels == 4 * 16 || st.texels == 4 * 8, "texels %u", (unsigned)st.texels);
    }
    sample_texture_destroy(tex);
}

static void degenerate_within_cap(void)
{
    /* Rank 0, rank 1 (one column zero, or the two parallel), huge, tiny
     * and mixed Jacobians: defined (finite) results within the cap under
     * every footprint filter, and constants stay constant. */
    static const float J[][6] = {
        {0, 0, 0, 0, 0, 0},          {0.3f, 0.1f, 0.2f, 0, 0, 0}, {0.3f, 0.1f, 0.2f, 0.6f, 0.2f, 0.4f},
        {1e20f, 0, 0, 0, 1e20f, 0},  {1e-30f, 0, 0, 0, 1e-30f, 0}, {1e20f, 1e-20f, 0, 0, 0, 1e-20f},
        {0, 0, 40.0f, 0, 0, 0},      {0.01f, 0.01f, 0.01f, -0.01f, 0.01f, 0}, {3e4f, 0, 0, 0, 0, 3e-4f},
    };
    float data[8 * 8 * 8 * 4];
    sample_mip_params mp;
    sample_texture *tex;
    sample_sampler s;
    sample_stats st;
    size_t n;
    int fp, i, c, lod;
    for (i = 0; i < 8 * 8 * 8 * 4; ++i) data[i] = 0.375f;
    sample_mip_params_init(&mp);
    tex = vol_f32(8, 8, 8, 4, data, &mp);
    for (fp = 1; fp < SAMPLE_FOOTPRINT_COUNT; ++fp)
        for (lod = 0; lod < 2; ++lod)
            for (n = 0; n < sizeof J / sizeof J[0]; ++n) {
                float p[3] = {0.3f, 0.7f, 0.1f}, out[4];
                sample_sampler_init(&s);
                s.footprint = (sample_footprint)fp;
                s.max_anisotropy = 64.0f;
                s.min_lod = lod ? 1.0f : -1000.0f;
                look(tex, &s, p, J[n], J[n] + 3, out, &st);
                CHECK(st.texels <= SAMPLE_MAX_FOOTPRINT_TEXELS, "footprint %d J %zu: texels %u", fp, n,
                      (unsigned)st.texels);
                for (c = 0; c < 4; ++c)
                    CHECK(fabs(out[c] - 0.375f) <= 1e-6, "footprint %d J %zu [%d]: %g", fp, n, c, out[c]);
            }
    sample_texture_destroy(tex);
}

static void border_footprint(void)
{
    /* A footprint across r's edge under CLAMP_TO_BORDER reads the border
     * colour for the slices outside, as single fetches do: a constant 1
     * volume with border 0 gives a value strictly between, and with
     * REPEAT exactly 1. */
    float data[4 * 4 * 4];
    sample_texture *tex;
    sample_sampler s;
    int fp, i;
    for (i = 0; i < 64; ++i) data[i] = 1.0f;
    tex = vol_f32(4, 4, 4, 1, data, NULL);
    for (fp = 1; fp < SAMPLE_FOOTPRINT_COUNT; ++fp) {
        float p[3] = {0.5f, 0.5f, 0.0f}, dx[3] = {0.5f, 0, 0.25f}, dy[3] = {0, 0.5f, 0}, out[4];
        sample_sampler_init(&s);
        s.footprint = (sample_footprint)fp;
        s.max_anisotropy = 4.0f;
        s.wrap_r = SAMPLE_WRAP_CLAMP_TO_BORDER;
        look(tex, &s, p, dx, dy, out, NULL);
        CHECK(out[0] > 0.2f && out[0] < 0.9f, "footprint %d at the border: %g", fp, out[0]);
        s.wrap_r = SAMPLE_WRAP_REPEAT;
        look(tex, &s, p, dx, dy, out, NULL);
        CHECK_NEAR(out[0], 1.0, 1e-6);
    }
    sample_texture_destroy(tex);
}

int main(void)
{
    RUN(pyramid_sizes_and_box);
    RUN(pyramid_odd_polyphase);
    RUN(pyramid_srgb_linear);
    RUN(creation_errors);
    RUN(centres_and_midpoints);
    RUN(wraps_on_r);
    RUN(lod_switch_points);
    RUN(constant_every_filter);
    RUN(non_finite_gives_border);
    RUN(every_format);
    RUN(blinn_newell_dense);
    RUN(ewa_definition);
    RUN(zero_jacobian_is_trilinear);
    RUN(aniso_probes);
    RUN(degenerate_within_cap);
    RUN(border_footprint);
    return check_finish();
}
