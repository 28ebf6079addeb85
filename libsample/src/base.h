/*
 * What every internal header of libsample builds on: the public API, the
 * vector types (simd.h), the portable maths (portable_math.h), and the
 * few macros for inlining, prefetching and errors (doc/architecture.md).
 */
#ifndef SAMPLE_BASE_H
#define SAMPLE_BASE_H

#include "sample/sample.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "portable_math.h"
#include "simd.h"

/* Return early with a status and a formatted message (sample_error_set). */
#define RETURN_ERROR_IF(cond, err, status, ...)                                \
    do {                                                                       \
        if (cond) return sample_error_set((err), (status), __VA_ARGS__);       \
    } while (0)

/* For the generic functions that the fast path instantiates per format:
 * GCC otherwise keeps some of them out of line, and the constants that
 * remove the per-texel switches never reach them. */
#if defined(__GNUC__)
#define SAMPLE_FORCE_INLINE static inline __attribute__((always_inline))
#define SAMPLE_NOINLINE __attribute__((noinline))
#else
#define SAMPLE_FORCE_INLINE static inline
#define SAMPLE_NOINLINE
#endif
/* SAMPLE_NOINLINE keeps rarely taken, bulky branches (another filter's
 * planning) out of a hot loop, whose registers and code size they would
 * otherwise cost on every iteration. */

/* A branch that is almost always taken (a resident texture's texels). */
#if defined(__GNUC__)
#define SAMPLE_LIKELY(x) __builtin_expect(!!(x), 1)
#else
#define SAMPLE_LIKELY(x) (x)
#endif

/* Prefetch hint; never dereferences, but callers keep the address inside
 * the level anyway so that no invalid pointer is ever formed. A function
 * whose only effect is prefetching looks side-effect free to GCC, which
 * then deletes calls to it (this silently disabled the batch loop's
 * prefetch before): helpers built on this are SAMPLE_FORCE_INLINE, so the
 * builtin lands in a caller that has effects. */
#if defined(__GNUC__)
#define SAMPLE_PREFETCH(p) __builtin_prefetch(p)
#else
#define SAMPLE_PREFETCH(p) ((void)(p))
#endif

#endif /* SAMPLE_BASE_H */
