/*
 * Run-time instruction-set dispatch (isa.c): every build of the fast path
 * this CPU runs decodes all 65536 half bit patterns to exactly
 * sample_half_to_float's bits (the AVX2 and AVX-512 builds through F16C's
 * VCVTPH2PS, simd.h), with 1–4 channels, also with denormals-are-zero and
 * flush-to-zero set; LIBSAMPLE_ISA and sample_isa_force choose as
 * documented. Identity of the filters across builds: test_fastpath.
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
    isa_kernels_active()->readers[SAMPLE_FORMAT_F16][nc - 1].row((const unsigned char *)h, n, out);
    for (k = 0; k < n; ++k)
        for (c = 0; c < 4; ++c) {
            uint32_t want = c < nc ? bits_of(sample_half_to_float(h[nc * k + c])) : bits_of(c == 3 ? 1.0f : 0.0f);
            if (bits_of(out[k][c]) != want && ++bad <= 3)
                fprintf(stderr, "%s, %d channels: half 0x%04x -> 0x%08x, sample_half_to_float 0x%08x\n",
                        sample_isa_name(), nc, c < nc ? (unsigned)h[nc * k + c] : 0u,
                        (unsigned)bits_of(out[k][c]), (unsigned)want);
        }
    free(h);
    free(out);
    return bad;
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
    RUN(test_choice);
    return check_finish();
}
