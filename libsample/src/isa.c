/*
 * Which instruction set the fast path runs on this CPU (internal.h,
 * "Run-time instruction-set dispatch"): one of the isa_kernels tables that
 * fast_gl.c was compiled into, picked once per process from what the CPU
 * supports and the LIBSAMPLE_ISA environment variable.
 *
 * Every table computes the same bits (simd.h, tests/test_fastpath.c,
 * tests/test_isa.c), so the choice changes speed only; LIBSAMPLE_ISA
 * exists to measure and to check that.
 *
 * The build says which tables exist (SAMPLE_HAVE_ISA_SSE2/AVX2/AVX512,
 * libsample/CMakeLists.txt); the scalar one always does. The CPU is asked
 * with __builtin_cpu_supports (GCC, Clang), which also checks that the OS
 * saves the AVX and AVX-512 registers (libgcc's cpuinfo reads XGETBV);
 * without it only the baseline tables are used.
 */
#include "kernels.h"
#include "sample/testing.h"

#include <stdatomic.h>
#include <stdlib.h>

#if defined(__GNUC__) && defined(__x86_64__)
#define ISA_X86_DETECT 1
#include <cpuid.h>
#endif

static const char *const isa_names[] = {
    [SAMPLE_ISA_SCALAR] = "scalar",
    [SAMPLE_ISA_SSE2] = "sse2",
    [SAMPLE_ISA_AVX2] = "avx2",
    [SAMPLE_ISA_AVX512] = "avx512",
};
_Static_assert(sizeof isa_names / sizeof isa_names[0] == SAMPLE_ISA_COUNT, "one name per instruction set");

/* The tables this build made; NULL where it made none. */
static const isa_kernels *const isa_tables[SAMPLE_ISA_COUNT] = {
    [SAMPLE_ISA_SCALAR] = &ls_isa_kernels_scalar,
#if defined(SAMPLE_HAVE_ISA_SSE2)
    [SAMPLE_ISA_SSE2] = &ls_isa_kernels_sse2,
#endif
#if defined(SAMPLE_HAVE_ISA_AVX2)
    [SAMPLE_ISA_AVX2] = &ls_isa_kernels_avx2,
#endif
#if defined(SAMPLE_HAVE_ISA_AVX512)
    [SAMPLE_ISA_AVX512] = &ls_isa_kernels_avx512,
#endif
};

#if defined(ISA_X86_DETECT)
/* F16C (CPUID.1:ECX bit 29): Clang 14's __builtin_cpu_supports does not
 * know "f16c". Its register state is AVX's, which "avx2" checks. */
static int cpu_f16c(void)
{
    unsigned a, b, c, d;
    return __get_cpuid(1, &a, &b, &c, &d) && (c & bit_F16C) != 0;
}
#endif

/* Whether this CPU runs level i's table (given that it was built). */
static int isa_cpu_has(int i)
{
    /* The scalar and SSE2 tables need nothing beyond what the rest of the
     * library was compiled for: SSE2 is built only where it is the
     * compiler's baseline. */
    if (i <= SAMPLE_ISA_SSE2) return 1;
#if defined(ISA_X86_DETECT)
    __builtin_cpu_init();
    if (!__builtin_cpu_supports("avx2") || !cpu_f16c()) return 0;
    if (i == SAMPLE_ISA_AVX2) return 1;
    return i == SAMPLE_ISA_AVX512 && __builtin_cpu_supports("avx512f") &&
           __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512bw") &&
           __builtin_cpu_supports("avx512dq");
#else
    return 0;
#endif
}

static int isa_usable(int i) { return isa_tables[i] && isa_cpu_has(i); }

static int isa_parse(const char *name)
{
    int i;
    for (i = 0; i < SAMPLE_ISA_COUNT; ++i)
        if (!strcmp(name, isa_names[i])) return i;
    return -1;
}

/* The automatic choice: the best usable level, or the best one not above
 * LIBSAMPLE_ISA when that names a level (a level this CPU or build lacks
 * then falls back; an unknown name is ignored). */
static int isa_auto(void)
{
    const char *env = getenv("LIBSAMPLE_ISA");
    int want = env ? isa_parse(env) : -1;
    if (want < 0) want = SAMPLE_ISA_COUNT - 1;
    while (want > SAMPLE_ISA_SCALAR && !isa_usable(want)) --want;
    return want;
}

/* The level in use plus one; 0 until the first use decides. Only this int
 * is shared: the tables are constant, so relaxed ordering is enough. Two
 * threads deciding at once compute the same value and one store wins. */
static atomic_int isa_current;

static int isa_level(void)
{
    int v = atomic_load_explicit(&isa_current, memory_order_relaxed), expect = 0;
    if (v) return v - 1;
    v = isa_auto() + 1;
    /* A sample_isa_force between the two lines above wins. */
    if (!atomic_compare_exchange_strong_explicit(&isa_current, &expect, v, memory_order_relaxed,
                                                 memory_order_relaxed))
        v = expect;
    return v - 1;
}

const isa_kernels *ls_isa_kernels_active(void) { return isa_tables[isa_level()]; }

int sample_isa_force(const char *name)
{
    int i;
    if (!name) {
        atomic_store_explicit(&isa_current, isa_auto() + 1, memory_order_relaxed);
        return 0;
    }
    if ((i = isa_parse(name)) < 0) return -1;
    if (!isa_tables[i]) return -2;
    if (!isa_cpu_has(i)) return -3;
    atomic_store_explicit(&isa_current, i + 1, memory_order_relaxed);
    return 0;
}

const char *sample_isa_name(void) { return isa_names[isa_level()]; }
