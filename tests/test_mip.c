/*
 * Pyramid building (DESIGN §6, doc/mip-and-lod.md): level sizes, the box and
 * odd-axis polyphase weights by hand, mean conservation, sRGB-correct
 * averaging, and the Lanczos-3 / Kaiser kernels' edge handling.
 */
#include "check.h"
#include "internal.h"
#include "mip.h"

#include <sys/resource.h>
#include <unistd.h>

#include <stdint.h>
#include <stdlib.h>

/* Deterministic xorshift32 in [0, 1). */
static float rnd(uint32_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 17;
    *s ^= *s << 5;
    return (float)(*s >> 8) * (1.0f / 16777216.0f);
}

static sample_texture *make_f32(int w, int h, int channels, const float *data, sample_mipgen f,
                                sample_wrap ws, sample_wrap wt)
{
    sample_image im = {w, h, channels, SAMPLE_FORMAT_F32, data, 0};
    sample_mip_params mp;
    sample_texture *tex = NULL;
    sample_error err;
    sample_mip_params_init(&mp);
    mp.filter = f;
    mp.wrap_s = ws;
    mp.wrap_t = wt;
    if (sample_texture_create(&im, &mp, &tex, &err) != SAMPLE_OK) {
        fprintf(stderr, "create %dx%d: %s\n", w, h, err.message);
        return NULL;
    }
    return tex;
}

static float *random_rgba(int w, int h, uint32_t seed)
{
    float *d = (float *)malloc((size_t)w * h * 4 * sizeof(float));
    size_t i;
    for (i = 0; i < (size_t)w * h * 4; ++i) d[i] = rnd(&seed);
    return d;
}

/* Mean of channel c over a level, in double. */
static double level_mean(const sample_texture *tex, int k, int c)
{
    int w, h, i, j;
    double sum = 0.0;
    float v[4];
    sample_texture_level_size(tex, k, &w, &h);
    for (j = 0; j < h; ++j)
        for (i = 0; i < w; ++i) {
            sample_texture_texel(tex, k, i, j, v);
            sum += v[c];
        }
    return sum / ((double)w * h);
}

/* ---- Level sizes ---------------------------------------------------------- */

static void expect_sizes(int w, int h, const int *sizes, int n)
{
    float one[4] = {1, 1, 1, 1};
    float *d = (float *)malloc((size_t)w * h * sizeof(float));
    sample_texture *tex;
    sample_texture_info info;
    int k;
    for (k = 0; k < w * h; ++k) d[k] = one[0];
    tex = make_f32(w, h, 1, d, SAMPLE_MIPGEN_BOX, SAMPLE_WRAP_CLAMP_TO_EDGE, SAMPLE_WRAP_CLAMP_TO_EDGE);
    CHECK(tex != NULL, "%dx%d created", w, h);
    if (tex) {
        sample_texture_info_get(tex, &info);
        CHECK(info.levels == n, "%dx%d: %d levels, expected %d", w, h, info.levels, n);
        for (k = 0; k < n && k < info.levels; ++k) {
            int lw, lh;
            sample_texture_level_size(tex, k, &lw, &lh);
            CHECK(lw == sizes[2 * k] && lh == sizes[2 * k + 1], "%dx%d level %d is %dx%d, expected %dx%d", w,
                  h, k, lw, lh, sizes[2 * k], sizes[2 * k + 1]);
        }
    }
    sample_texture_destroy(tex);
    free(d);
}

static void test_level_sizes(void)
{
    static const int s1x1[] = {1, 1};
    static const int s1x5[] = {1, 5, 1, 2, 1, 1};
    static const int s5x8[] = {5, 8, 2, 4, 1, 2, 1, 1};
    static const int s1000x3[] = {1000, 3, 500, 1, 250, 1, 125, 1, 62, 1, 31, 1, 15, 1, 7, 1, 3, 1, 1, 1};
    expect_sizes(1, 1, s1x1, 1);
    expect_sizes(1, 5, s1x5, 3);
    expect_sizes(5, 8, s5x8, 4);
    expect_sizes(1000, 3, s1000x3, 10);
}

static void test_max_levels(void)
{
    float d[16 * 4] = {0};
    sample_image im = {4, 4, 4, SAMPLE_FORMAT_F32, d, 0};
    sample_mip_params mp;
    sample_texture *tex = NULL;
    sample_texture_info info;
    sample_mip_params_init(&mp);
    mp.max_levels = 2;
    CHECK(sample_texture_create(&im, &mp, &tex, NULL) == SAMPLE_OK, "create");
    sample_texture_info_get(tex, &info);
    CHECK(info.levels == 2, "max_levels 2 gave %d levels", info.levels);
    /* 4x4 + 2x2 RGBA float texels. */
    CHECK(info.bytes == (16 + 4) * 16, "bytes %zu", info.bytes);
    sample_texture_destroy(tex);
}

/* ---- Box and polyphase weights by hand ------------------------------------ */

/* Two float roundings per pass (weight, result): a relative 2^-22 covers it. */
#define HAND_TOL(x) (fabs(x) * 2.4e-7 + 1e-12)

static void test_polyphase_5x1(void)
{
    /* n = 5 = 2·2 + 1 → m = 2. Output 0 weighs texels 0, 1, 2 by 2/5, 2/5,
     * 1/5; output 1 texels 2, 3, 4 by 1/5, 2/5, 2/5. Values 1 … 5:
     * out0 = (2 + 4 + 3)/5 = 1.8, out1 = (3 + 8 + 10)/5 = 4.2; level 2 is
     * their 2-tap box, 3.0. */
    const float d[5] = {1, 2, 3, 4, 5};
    sample_texture *tex = make_f32(5, 1, 1, d, SAMPLE_MIPGEN_BOX, SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_REPEAT);
    float v[4];
    sample_texture_texel(tex, 1, 0, 0, v);
    CHECK_NEAR(v[0], 1.8, HAND_TOL(1.8));
    sample_texture_texel(tex, 1, 1, 0, v);
    CHECK_NEAR(v[0], 4.2, HAND_TOL(4.2));
    sample_texture_texel(tex, 2, 0, 0, v);
    CHECK_NEAR(v[0], 3.0, HAND_TOL(3.0) * 2);
    sample_texture_destroy(tex);
}

static void test_polyphase_7x1_impulses(void)
{
    /* n = 7 → m = 3: output i weighs texels 2i, 2i+1, 2i+2 by (3−i)/7, 3/7,
     * (i+1)/7. An impulse at texel j reads back the weight column j. */
    static const double W[3][7] = {
        {3 / 7.0, 3 / 7.0, 1 / 7.0, 0, 0, 0, 0},
        {0, 0, 2 / 7.0, 3 / 7.0, 2 / 7.0, 0, 0},
        {0, 0, 0, 0, 1 / 7.0, 3 / 7.0, 3 / 7.0},
    };
    int j, i;
    for (j = 0; j < 7; ++j) {
        float d[7] = {0};
        sample_texture *tex;
        d[j] = 1.0f;
        tex = make_f32(7, 1, 1, d, SAMPLE_MIPGEN_BOX, SAMPLE_WRAP_CLAMP_TO_EDGE, SAMPLE_WRAP_CLAMP_TO_EDGE);
        for (i = 0; i < 3; ++i) {
            float v[4];
            sample_texture_texel(tex, 1, i, 0, v);
            CHECK_NEAR(v[0], W[i][j], HAND_TOL(W[i][j]));
        }
        sample_texture_destroy(tex);
    }
}

static void test_polyphase_3x3(void)
{
    /* 3×3 → 1×1: m = 1, weights (1, 1, 1)/3 on each axis, so every texel
     * weighs 1/9: (1 + 2 + … + 256)/9 = 511/9. Two channels check that they
     * are filtered independently: the second is the first mirrored. */
    const float d[18] = {1, 256, 2, 128, 4, 64, 8, 32, 16, 16, 32, 8, 64, 4, 128, 2, 256, 1};
    sample_texture *tex = make_f32(3, 3, 2, d, SAMPLE_MIPGEN_BOX, SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_REPEAT);
    float v[4];
    int w, h;
    sample_texture_level_size(tex, 1, &w, &h);
    CHECK(w == 1 && h == 1, "3x3 level 1 is %dx%d", w, h);
    sample_texture_texel(tex, 1, 0, 0, v);
    CHECK_NEAR(v[0], 511.0 / 9.0, 2 * HAND_TOL(511.0 / 9.0));
    CHECK_NEAR(v[1], 511.0 / 9.0, 2 * HAND_TOL(511.0 / 9.0));
    CHECK_EQF(v[2], 0.0f);
    CHECK_EQF(v[3], 1.0f);
    sample_texture_destroy(tex);
}

static void test_polyphase_5x3(void)
{
    /* 5×3 → 2×1: x weights as in the 5×1 case, y weights 1/3 each. Texel
     * value x + 10y: the y average is x + 10, so the outputs are
     * (2·0 + 2·1 + 2)/5 + 10 = 10.8 and (2 + 2·3 + 2·4)/5 + 10 = 13.2. */
    float d[15];
    int i, j;
    float v[4];
    sample_texture *tex;
    for (j = 0; j < 3; ++j)
        for (i = 0; i < 5; ++i) d[j * 5 + i] = (float)(i + 10 * j);
    tex = make_f32(5, 3, 1, d, SAMPLE_MIPGEN_BOX, SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_REPEAT);
    sample_texture_texel(tex, 1, 0, 0, v);
    CHECK_NEAR(v[0], 10.8, 2 * HAND_TOL(10.8));
    sample_texture_texel(tex, 1, 1, 0, v);
    CHECK_NEAR(v[0], 13.2, 2 * HAND_TOL(13.2));
    sample_texture_destroy(tex);
}

/* ---- Mean conservation ---------------------------------------------------- */

/* The box family conserves the mean exactly in real arithmetic (every source
 * texel of an odd axis 2m + 1 weighs m/n in total). In float, each level's
 * texel carries at most two weight roundings and two result roundings per
 * pass, a relative 4·2^-24 per pass; values lie in [0, 1) so the level mean
 * moves by at most 8·2^-24 ≈ 4.8e-7 per level from its parent's. Over the
 * pyramid's up to 7 levels: 3.4e-6; 4e-6 is the tolerance. */
static void test_npot_mean(void)
{
    static const int sizes[][2] = {{37, 23}, {99, 1}, {1, 45}, {64, 33}};
    size_t n;
    for (n = 0; n < sizeof sizes / sizeof sizes[0]; ++n) {
        int w = sizes[n][0], h = sizes[n][1], k, c;
        float *d = random_rgba(w, h, 1234u + (uint32_t)n);
        sample_texture *tex = make_f32(w, h, 4, d, SAMPLE_MIPGEN_BOX, SAMPLE_WRAP_CLAMP_TO_EDGE,
                                       SAMPLE_WRAP_CLAMP_TO_EDGE);
        sample_texture_info info;
        sample_texture_info_get(tex, &info);
        for (c = 0; c < 4; ++c) {
            double m0 = level_mean(tex, 0, c);
            for (k = 1; k < info.levels; ++k)
                CHECK_NEAR(level_mean(tex, k, c), m0, 4e-6);
        }
        sample_texture_destroy(tex);
        free(d);
    }
}

/* ---- Formats ---------------------------------------------------------------- */

static void test_srgb_average(void)
{
    /* Black and white average to linear 0.5, stored as the sRGB code of 0.5:
     * 255·0.735357 = 187.52 → 188 (decoded 0.5029). Averaging the codes
     * would give 128 (linear 0.2158). Alpha is linear: (0 + 255)/2 → 128. */
    const unsigned char d[8] = {0, 0, 0, 0, 255, 255, 255, 255};
    sample_image im = {2, 1, 4, SAMPLE_FORMAT_SRGB8, d, 0};
    sample_mip_params mp;
    sample_texture *tex = NULL;
    float v[4];
    int c;
    sample_mip_params_init(&mp);
    CHECK(sample_texture_create(&im, &mp, &tex, NULL) == SAMPLE_OK, "create sRGB");
    for (c = 0; c < 3; ++c) CHECK(tex->level[1].data[c] == 188, "code %d", tex->level[1].data[c]);
    CHECK(tex->level[1].data[3] == 128, "alpha code %d", tex->level[1].data[3]);
    sample_texture_texel(tex, 1, 0, 0, v);
    /* One sRGB code step near 188 is 0.0060 linear; rounding to the nearest
     * code is off by at most half of it. */
    CHECK_NEAR(v[0], 0.5, 0.0030);
    sample_texture_destroy(tex);
}

static void test_unorm_and_half(void)
{
    /* UNORM8 2×2 → (10 + 20 + 30 + 41)/4 = 25.25 → code 25. F16 1×2 of 1
     * and 2 → 1.5 exactly. */
    const unsigned char u[4] = {10, 20, 30, 41};
    uint16_t hf[2];
    sample_image iu = {2, 2, 1, SAMPLE_FORMAT_UNORM8, u, 0};
    sample_image ih = {1, 2, 1, SAMPLE_FORMAT_F16, hf, 0};
    sample_mip_params mp;
    sample_texture *tex = NULL;
    float v[4];
    sample_mip_params_init(&mp);
    CHECK(sample_texture_create(&iu, &mp, &tex, NULL) == SAMPLE_OK, "create unorm");
    CHECK(tex->level[1].data[0] == 25, "unorm code %d", tex->level[1].data[0]);
    sample_texture_destroy(tex);
    hf[0] = sample_float_to_half(1.0f);
    hf[1] = sample_float_to_half(2.0f);
    CHECK(sample_texture_create(&ih, &mp, &tex, NULL) == SAMPLE_OK, "create half");
    sample_texture_texel(tex, 1, 0, 0, v);
    CHECK_EQF(v[0], 1.5f);
    sample_texture_destroy(tex);
}

/* ---- Lanczos-3 and Kaiser -------------------------------------------------- */

static const sample_mipgen kernels[2] = {SAMPLE_MIPGEN_LANCZOS3, SAMPLE_MIPGEN_KAISER};

/* Weights are normalized in double and rounded to float: up to 19 taps per
 * axis, so a constant moves by at most 2·19·2^-24 ≈ 2.3e-6 relative per
 * level; over 10 levels 2.3e-5. */
static void test_kernel_constant(void)
{
    static const int sizes[][2] = {{16, 16}, {13, 6}, {1000, 3}, {3, 1}};
    static const sample_wrap wraps[] = {SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_CLAMP_TO_EDGE, SAMPLE_WRAP_CLAMP_TO_BORDER,
                                        SAMPLE_WRAP_MIRRORED_REPEAT, SAMPLE_WRAP_MIRROR_CLAMP};
    size_t s, wi;
    int f;
    for (f = 0; f < 2; ++f)
        for (wi = 0; wi < sizeof wraps / sizeof wraps[0]; ++wi)
            for (s = 0; s < sizeof sizes / sizeof sizes[0]; ++s) {
                int w = sizes[s][0], h = sizes[s][1], k, i, j;
                float *d = (float *)malloc((size_t)w * h * 4 * sizeof(float));
                sample_texture *tex;
                sample_texture_info info;
                for (i = 0; i < w * h; ++i) {
                    d[4 * i] = 0.75f; d[4 * i + 1] = 3.0f; d[4 * i + 2] = 0.0f; d[4 * i + 3] = 1.0f;
                }
                tex = make_f32(w, h, 4, d, kernels[f], wraps[wi], wraps[wi]);
                sample_texture_info_get(tex, &info);
                for (k = 1; k < info.levels; ++k) {
                    int lw, lh;
                    sample_texture_level_size(tex, k, &lw, &lh);
                    for (j = 0; j < lh; ++j)
                        for (i = 0; i < lw; ++i) {
                            float v[4];
                            sample_texture_texel(tex, k, i, j, v);
                            CHECK(fabsf(v[0] - 0.75f) <= 0.75f * 2.3e-5f && fabsf(v[1] - 3.0f) <= 3.0f * 2.3e-5f &&
                                      v[2] == 0.0f && fabsf(v[3] - 1.0f) <= 2.3e-5f,
                                  "%s wrap %s %dx%d level %d (%d,%d): %.9g %.9g %.9g %.9g",
                                  sample_mipgen_name(kernels[f]), sample_wrap_name(wraps[wi]), w, h, k, i, j,
                                  v[0], v[1], v[2], v[3]);
                        }
                }
                sample_texture_destroy(tex);
                free(d);
            }
}

/* Under REPEAT on even axes, source texels at even and odd positions see the
 * kernel at offsets that are each other's negatives, so by the kernel's
 * symmetry every texel weighs ½ in total and the mean is kept exactly in real
 * arithmetic. Float weights (19 taps, 2^-24 each) move a mean of values in
 * [0, 1) by ≤ 2.3e-6 per level; 6 levels: 1.4e-5. */
static void test_kernel_mean_repeat(void)
{
    int f, k, c;
    for (f = 0; f < 2; ++f) {
        float *d = random_rgba(32, 16, 99u);
        sample_texture *tex = make_f32(32, 16, 4, d, kernels[f], SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_REPEAT);
        sample_texture_info info;
        sample_texture_info_get(tex, &info);
        CHECK(info.levels == 6, "levels %d", info.levels);
        for (c = 0; c < 4; ++c) {
            double m0 = level_mean(tex, 0, c);
            for (k = 1; k < info.levels; ++k) CHECK_NEAR(level_mean(tex, k, c), m0, 1.4e-5);
        }
        sample_texture_destroy(tex);
        free(d);
    }
}

/* A REPEAT pyramid of a texture shifted cyclically by 8 texels is the
 * original pyramid shifted by 8/2^k at level k, bit for bit: every output
 * texel sees the same source values at the same kernel offsets, which holds
 * only if the left and right edges are filtered through the wrap (so the
 * levels tile). CLAMP_TO_EDGE must break it, or the test could not fail. */
static int shifted_pyramid_matches(sample_mipgen f, sample_wrap wrap)
{
    const int W = 32, H = 16, SX = 8, SY = 4;
    float *d = random_rgba(W, H, 7u), *e = (float *)malloc((size_t)W * H * 4 * sizeof(float));
    sample_texture *a, *b;
    int i, j, k, same = 1;
    for (j = 0; j < H; ++j)
        for (i = 0; i < W; ++i)
            memcpy(e + 4 * (j * W + i), d + 4 * (((j + SY) % H) * W + (i + SX) % W), 4 * sizeof(float));
    a = make_f32(W, H, 4, d, f, wrap, wrap);
    b = make_f32(W, H, 4, e, f, wrap, wrap);
    for (k = 1; k <= 2; ++k) {
        int lw, lh, sx = SX >> k, sy = SY >> k;
        sample_texture_level_size(a, k, &lw, &lh);
        for (j = 0; j < lh; ++j)
            for (i = 0; i < lw; ++i) {
                float va[4], vb[4];
                sample_texture_texel(a, k, (i + sx) % lw, (j + sy) % lh, va);
                sample_texture_texel(b, k, i, j, vb);
                if (memcmp(va, vb, sizeof va) != 0) same = 0;
            }
    }
    sample_texture_destroy(a);
    sample_texture_destroy(b);
    free(d);
    free(e);
    return same;
}

static void test_kernel_tileable(void)
{
    int f;
    for (f = 0; f < 2; ++f) {
        CHECK(shifted_pyramid_matches(kernels[f], SAMPLE_WRAP_REPEAT), "%s REPEAT pyramid not shift-invariant",
              sample_mipgen_name(kernels[f]));
        CHECK(!shifted_pyramid_matches(kernels[f], SAMPLE_WRAP_CLAMP_TO_EDGE),
              "%s CLAMP_TO_EDGE pyramid unexpectedly shift-invariant", sample_mipgen_name(kernels[f]));
    }
}

static void test_kernel_impulse_response(void)
{
    /* Lanczos-3, 16 → 8 texels, REPEAT. Output 4's centre in source index
     * space is (4 + ½)·2 − ½ = 8.5; texel 8 sits ½ source texel = ¼
     * destination texel from it, so an impulse there reads back
     * L(¼) / Σ_j L((j − 8.5)/2), j over the taps with |j − 8.5| < 6 (3 … 14,
     * all in range, so no wrap is involved). */
    const double pi = 3.14159265358979323846;
    float d[16] = {0};
    double sum = 0.0, expect;
    int j;
    float v[4];
    sample_texture *tex;
    d[8] = 1.0f;
    tex = make_f32(16, 1, 1, d, SAMPLE_MIPGEN_LANCZOS3, SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_REPEAT);
    for (j = 3; j <= 14; ++j) {
        double x = (j - 8.5) / 2.0;
        sum += sin(pi * x) / (pi * x) * sin(pi * x / 3) / (pi * x / 3);
    }
    expect = sin(pi * 0.25) / (pi * 0.25) * sin(pi * 0.25 / 3) / (pi * 0.25 / 3) / sum;
    sample_texture_texel(tex, 1, 4, 0, v);
    CHECK_NEAR(v[0], expect, 1e-6);
    sample_texture_destroy(tex);
}

/* Scratch memory grows with the width, not the area (doc/mip-and-lod.md,
 * "Memory"). A tall 1-channel 8-bit texture, 512 × 8192 (4 MiB), is built
 * in a child process whose peak resident size is read before and after:
 * the texture's copy and levels add 5.3 MiB, a whole-level scratch buffer
 * of floats ((w/2)·h RGBA) would add 32 MiB more. */
static void test_scratch_bounded(void)
{
    const int w = 512, h = 8192;
    int status = 0;
    pid_t pid;
    CHECK(ls_mip_scratch_bytes(65536, SAMPLE_MIPGEN_KAISER) < ((size_t)32 << 20), "Kaiser scratch for 65536 wide: %zu",
          ls_mip_scratch_bytes(65536, SAMPLE_MIPGEN_KAISER));
    CHECK(ls_mip_scratch_bytes(w, SAMPLE_MIPGEN_BOX) < ((size_t)1 << 20), "box scratch for 512 wide: %zu",
          ls_mip_scratch_bytes(w, SAMPLE_MIPGEN_BOX));
    fflush(NULL);
    pid = fork();
    if (pid == 0) {
        struct rusage before, after;
        unsigned char *d = (unsigned char *)malloc((size_t)w * h);
        sample_image im = {w, h, 1, SAMPLE_FORMAT_UNORM8, d, 0};
        sample_mip_params mp;
        sample_texture *tex = NULL;
        sample_error err;
        long grew_kib;
        size_t i;
        if (!d) _exit(2);
        for (i = 0; i < (size_t)w * h; ++i) d[i] = (unsigned char)(i * 2654435761u >> 24);
        sample_mip_params_init(&mp);
        getrusage(RUSAGE_SELF, &before);
        if (sample_texture_create(&im, &mp, &tex, &err) != SAMPLE_OK) _exit(3);
        getrusage(RUSAGE_SELF, &after);
        grew_kib = after.ru_maxrss - before.ru_maxrss;
        fprintf(stderr, "  peak grew by %ld KiB\n", grew_kib);
        _exit(grew_kib < 16 * 1024 ? 0 : 4);
    }
    CHECK(pid > 0 && waitpid(pid, &status, 0) == pid, "fork/wait failed");
    CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0, "child: exit %d (4: peak memory over 16 MiB)",
          WIFEXITED(status) ? WEXITSTATUS(status) : -1);
}

int main(void)
{
    RUN(test_scratch_bounded);
    RUN(test_level_sizes);
    RUN(test_max_levels);
    RUN(test_polyphase_5x1);
    RUN(test_polyphase_7x1_impulses);
    RUN(test_polyphase_3x3);
    RUN(test_polyphase_5x3);
    RUN(test_npot_mean);
    RUN(test_srgb_average);
    RUN(test_unorm_and_half);
    RUN(test_kernel_constant);
    RUN(test_kernel_mean_repeat);
    RUN(test_kernel_tileable);
    RUN(test_kernel_impulse_response);
    return check_finish();
}
