/*
 * Run-time instruction-set dispatch (isa.c): every build of the fast path
 * this CPU runs decodes all 65536 half bit patterns to exactly
 * sample_half_to_float's bits (the AVX2 and AVX-512 builds through F16C's
 * VCVTPH2PS, simd.h), with 1–4 channels, also with denormals-are-zero and
 * flush-to-zero set, and every 8-bit code of UNORM8 and SRGB8 to its
 * table entry; NaN texels filter to NaN in every build where they do
 * in the scalar one (only a NaN's payload may differ); LIBSAMPLE_ISA and
 * sample_isa_force choose as documented. Identity of the filters across
 * builds: test_fastpath.
 */
#define _POSIX_C_SOURCE 200809L /* setenv, unsetenv: before any system header */
#include "check.h"
#include "internal.h"
#include "isa_util.h"

#include <stdint.h>
#include <stdlib.h>
#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

static uint32_t bits_of(float f)
{
    uint32_t u;
    memcpy(&u, &f, 4);
    return u;
}

/* All 65536 halves as texels of nc channels, decoded by the active build's
 * row reader; channels past nc must read 0, 0, 0, 1. */
static int check_halves(int nc)
{
    enum { NH = 65536 };
    const int n = (NH + nc - 1) / nc;
    uint16_t *h = calloc((size_t)n * nc, sizeof *h);
    float(*out)[4] = malloc((size_t)n * sizeof *out);
    int k, c, bad = 0;
    for (k = 0; k < NH; ++k) h[k] = (uint16_t)k;
    ls_isa_kernels_active()->readers[SAMPLE_FORMAT_F16][nc - 1].row(SAMPLE_FORMAT_F16, nc, (const unsigned char *)h, 2 * (size_t)nc, n, out);
    for (k = 0; k < n; ++k)
        for (c = 0; c < 4; ++c) {
            uint32_t want = c < nc ? bits_of(sample_half_to_float(h[nc * k + c])) : bits_of(c == 3 ? 1.0f : 0.0f);
            if (bits_of(out[k][c]) != want && ++bad <= 3)
                fprintf(stderr, "%s, %d channels: half 0x%04x -> 0x%08x, sample_half_to_float 0x%08x\n",
                        sample_isa_name(), nc, c < nc ? (unsigned)h[nc * k + c] : 0u,
                        (unsigned)bits_of(out[k][c]), (unsigned)want);
        }
    /* Strided (a level's column, fp_span_texels): every third texel. */
    {
        float(*o3)[4] = malloc((size_t)(n / 3) * sizeof *o3);
        ls_isa_kernels_active()->readers[SAMPLE_FORMAT_F16][nc - 1].row(SAMPLE_FORMAT_F16, nc, (const unsigned char *)h, 6 * (size_t)nc, n / 3, o3);
        for (k = 0; k < n / 3; ++k)
            if (memcmp(o3[k], out[3 * k], sizeof o3[k]) != 0 && ++bad <= 3)
                fprintf(stderr, "%s, %d channels: strided read of texel %d differs\n", sample_isa_name(), nc, 3 * k);
        free(o3);
    }
    free(h);
    free(out);
    return bad;
}

/* Every 8-bit code in every channel (texel k holds k, k + 1, … mod 256),
 * decoded by the active build's row reader, by rows and every third
 * texel: the sRGB EOTF table on the colour channels of SRGB8, c / 255 on
 * its alpha and on every UNORM8 channel (the AVX2 and AVX-512 builds
 * gather them, fast_gl.c texel_v4 and texel_pair). */
static int check_u8(sample_format fmt, int nc)
{
    enum { N = 257 }; /* odd: a row's last texel has no pair */
    unsigned char *b = malloc((size_t)N * nc);
    float(*out)[4] = malloc(N * sizeof *out), (*o3)[4] = malloc(N * sizeof *o3);
    int k, c, bad = 0;
    for (k = 0; k < N * nc; ++k) b[k] = (unsigned char)(k / nc + k % nc);
    ls_isa_kernels_active()->readers[fmt][nc - 1].row(fmt, nc, b, (size_t)nc, N, out);
    ls_isa_kernels_active()->readers[fmt][nc - 1].row(fmt, nc, b, 3 * (size_t)nc, N / 3, o3);
    for (k = 0; k < N; ++k)
        for (c = 0; c < 4; ++c) {
            int code = b[nc * k + (c < nc ? c : 0)];
            float want = c >= nc ? (c == 3 ? 1.0f : 0.0f)
                                 : (fmt == SAMPLE_FORMAT_SRGB8 && c < 3 ? ls_srgb_table[code] : ls_unorm8_table[code]);
            if ((bits_of(out[k][c]) != bits_of(want) || (k % 3 == 0 && k / 3 < N / 3 && bits_of(o3[k / 3][c]) != bits_of(want))) &&
                ++bad <= 3)
                fprintf(stderr, "%s, format %d, %d channels: texel %d channel %d code %d -> %a, want %a\n",
                        sample_isa_name(), (int)fmt, nc, k, c, code, out[k][c], want);
        }
    free(b);
    free(out);
    free(o3);
    return bad;
}

static void test_u8_decode_exhaustive(void)
{
    int k, nc;
    for (k = 0; k < SAMPLE_ISA_COUNT; ++k) {
        if (!test_isa_enter(test_isa_names[k])) continue;
        for (nc = 1; nc <= 4; ++nc) {
            CHECK(check_u8(SAMPLE_FORMAT_UNORM8, nc) == 0, "%s, unorm8, %d channels", test_isa_names[k], nc);
            CHECK(check_u8(SAMPLE_FORMAT_SRGB8, nc) == 0, "%s, srgb8, %d channels", test_isa_names[k], nc);
        }
    }
    CHECK(sample_isa_force(NULL) == 0, "automatic choice");
}

static void test_half_decode_exhaustive(void)
{
    int k, nc;
    for (k = 0; k < SAMPLE_ISA_COUNT; ++k) {
        if (!test_isa_enter(test_isa_names[k])) continue;
        for (nc = 1; nc <= 4; ++nc) CHECK(check_halves(nc) == 0, "%s, %d channels", test_isa_names[k], nc);
#if defined(__SSE2__)
        {
            /* DAZ | FTZ, as a renderer may set them: VCVTPH2PS ignores DAZ
             * and no build's widening meets a float subnormal. */
            unsigned csr = _mm_getcsr();
            _mm_setcsr(csr | 0x8040u);
            for (nc = 1; nc <= 4; ++nc)
                CHECK(check_halves(nc) == 0, "%s, %d channels, DAZ|FTZ", test_isa_names[k], nc);
            _mm_setcsr(csr);
        }
#endif
    }
    CHECK(sample_isa_force(NULL) == 0, "automatic choice");
}

/* Texels that are NaN, with payloads: every build returns NaN exactly where
 * the scalar build does and the same bits everywhere else, but which
 * NaN's payload a sum of two NaNs carries is the compiler's choice of
 * operand order (IEEE 754 §6.2.3 leaves it open; C lets + and * commute),
 * and the plain-struct and SSE builds do choose differently. For every
 * non-NaN operand the commuted operation is exact, so that is the only
 * difference there can be. */
static uint64_t rng = 0x9E3779B97F4A7C15ull;
static uint32_t rnd(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (uint32_t)rng;
}

enum { NQ = 400 };

static int same_or_both_nan(const float *x, const float *y, int n)
{
    int k;
    for (k = 0; k < n; ++k)
        if (bits_of(x[k]) != bits_of(y[k]) && !(isnan(x[k]) && isnan(y[k]))) return 0;
    return 1;
}

static void test_nan_texels(void)
{
    static const sample_filter filters[4] = {SAMPLE_NEAREST, SAMPLE_LINEAR, SAMPLE_CUBIC,
                                             SAMPLE_LINEAR_MIPMAP_LINEAR};
    static sample_query q[NQ];
    static float ref[3][NQ * 4], got[3][NQ * 4];
    int f, nc, fl, k, i;
    for (f = 0; f < 2; ++f)
        for (nc = 1; nc <= 4; ++nc) {
            const int w = 17, h = 9;
            size_t n = (size_t)w * h * nc, e;
            unsigned char *data = malloc(n * 4);
            sample_image im;
            sample_mip_params mp;
            sample_texture *tex = NULL;
            for (e = 0; e < n; ++e) {
                /* One texel in four a NaN of random sign and payload. */
                int nan = rnd() % 4 == 0;
                if (f == 0) {
                    uint32_t b = nan ? 0x7f800001u | (rnd() & 0x807fffffu) : 0x3f000000u + (rnd() & 0xffffu);
                    memcpy(data + 4 * e, &b, 4);
                } else {
                    uint16_t b = (uint16_t)(nan ? 0x7c01u | (rnd() & 0x83ffu) : 0x3800u + (rnd() & 0x3ffu));
                    memcpy(data + 2 * e, &b, 2);
                }
            }
            im.width = w;
            im.height = h;
            im.channels = nc;
            im.format = f == 0 ? SAMPLE_FORMAT_F32 : SAMPLE_FORMAT_F16;
            im.data = data;
            im.row_stride = 0;
            sample_mip_params_init(&mp);
            CHECK(sample_texture_create(&im, &mp, &tex, NULL) == SAMPLE_OK, "create");
            free(data);
            if (!tex) continue;
            for (fl = 0; fl < 4; ++fl) {
                sample_sampler s;
                sample_sampler_init(&s);
                s.min_filter = filters[fl];
                s.mag_filter = fl < 3 ? filters[fl] : SAMPLE_LINEAR;
                for (k = 0; k < NQ; ++k) {
                    q[k].s = (float)(rnd() % 20000) / 18000.0f - 0.05f;
                    q[k].t = (float)(rnd() % 20000) / 18000.0f - 0.05f;
                    q[k].dsdx = q[k].dtdy = (float)(rnd() % 100) / 400.0f;
                    q[k].dtdx = q[k].dsdy = 0.0f;
                }
                for (i = 0; i < SAMPLE_ISA_COUNT; ++i) {
                    sample_batch_args a;
                    if (sample_isa_force(test_isa_names[i]) != 0) continue;
                    memset(&a, 0, sizeof a);
                    a.count = NQ;
                    a.queries = q;
                    a.rgba = i ? got[0] : ref[0];
                    a.drgba_ds = i ? got[1] : ref[1];
                    a.drgba_dt = i ? got[2] : ref[2];
                    CHECK(sample_batch(tex, &s, &a) == SAMPLE_OK, "sample_batch");
                    if (i)
                        for (k = 0; k < 3; ++k)
                            CHECK(same_or_both_nan(got[k], ref[k], NQ * 4),
                                  "%s vs scalar, format %d, %d channels, filter %d, output %d",
                                  test_isa_names[i], f, nc, (int)filters[fl], k);
                }
            }
            sample_texture_destroy(tex);
        }
    CHECK(sample_isa_force(NULL) == 0, "automatic choice");
}

static int usable(const char *name)
{
    const char *was = sample_isa_name();
    int ok = sample_isa_force(name) == 0;
    CHECK(sample_isa_force(was) == 0, "back to %s", was);
    return ok;
}

static void test_choice(void)
{
    int k, best = 0;
    CHECK(usable("scalar"), "the portable build is always there");
    CHECK(sample_isa_force("avx3") == -1, "unknown name");
    for (k = 0; k < SAMPLE_ISA_COUNT; ++k)
        if (usable(test_isa_names[k])) best = k;
    /* No LIBSAMPLE_ISA: the best this CPU runs. */
    unsetenv("LIBSAMPLE_ISA");
    CHECK(sample_isa_force(NULL) == 0, "auto");
    CHECK(!strcmp(sample_isa_name(), test_isa_names[best]), "auto: %s, best %s", sample_isa_name(),
          test_isa_names[best]);
    printf("automatic choice on this CPU: %s\n", sample_isa_name());
    /* LIBSAMPLE_ISA=x: x where usable, else the best usable level below x
     * (levels are nested, so that is the best usable of all). */
    for (k = 0; k < SAMPLE_ISA_COUNT; ++k) {
        int want = k;
        while (want > 0 && !usable(test_isa_names[want])) --want;
        setenv("LIBSAMPLE_ISA", test_isa_names[k], 1);
        CHECK(sample_isa_force(NULL) == 0, "auto");
        CHECK(!strcmp(sample_isa_name(), test_isa_names[want]), "LIBSAMPLE_ISA=%s gives %s, expected %s",
              test_isa_names[k], sample_isa_name(), test_isa_names[want]);
    }
    /* An unknown value is ignored. */
    setenv("LIBSAMPLE_ISA", "avx1024", 1);
    CHECK(sample_isa_force(NULL) == 0, "auto");
    CHECK(!strcmp(sample_isa_name(), test_isa_names[best]), "unknown LIBSAMPLE_ISA: %s", sample_isa_name());
    unsetenv("LIBSAMPLE_ISA");
    CHECK(sample_isa_force(NULL) == 0, "auto");
}

int main(void)
{
    RUN(test_half_decode_exhaustive);
    RUN(test_u8_decode_exhaustive);
    RUN(test_nan_texels);
    RUN(test_choice);
    return check_finish();
}
