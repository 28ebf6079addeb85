/*
 * The instruction-set levels a test runs the fast path under (isa.c,
 * sample_isa_force): every one this build has and this CPU runs, each
 * named on stdout as it runs or with the reason it cannot, so that a pass
 * on a machine without AVX-512 does not read as a pass of the AVX-512
 * kernels. Header-only, like check.h.
 */
#ifndef SAMPLE_TEST_ISA_UTIL_H
#define SAMPLE_TEST_ISA_UTIL_H

#include "internal.h"
#include "sample/testing.h"

#include <stdio.h>

static const char *const test_isa_names[SAMPLE_ISA_COUNT] = {"scalar", "sse2", "avx2", "avx512"};

/* Switch to `name`: 1 if it now runs; 0 (with a "skipped" line) if it
 * cannot run here. */
static int test_isa_enter(const char *name)
{
    int rc = sample_isa_force(name);
    if (rc == 0) {
        printf("isa %s: running\n", name);
        return 1;
    }
    printf("skipped %s: %s\n", name,
           rc == -3   ? "not supported by this CPU"
           : rc == -2 ? "not built into this library (compiler flags missing, or not x86-64)"
                      : "unknown name");
    return 0;
}

#endif
