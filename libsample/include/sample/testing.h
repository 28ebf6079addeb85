/*
 * libsample's testing interface: not installed, not part of the public
 * API, and not exported by the shared library (the tests and tools that
 * use it link the static library).
 *
 * libsample has two ways of computing every result:
 *
 *   - the reference path: one query at a time, texel by texel through the
 *     wrap modes (DESIGN §3–§7), with no planning, prefetching or vector
 *     kernels — the code to read when checking the library against the
 *     OpenGL specification or a paper;
 *   - the fast path that sample_batch() runs: queries planned in blocks,
 *     kernels per texel format and instruction set.
 *
 * The fast path must give the reference path's results bit for bit, for
 * every filter, format, channel count and wrap mode (tests/test_fastpath.c).
 */
#ifndef SAMPLE_TESTING_H
#define SAMPLE_TESTING_H

#include "sample/sample.h"

#ifdef __cplusplus
extern "C" {
#endif

/* sample_batch() through the reference path. Same arguments, checks and
 * results (bit for bit); slower. */
sample_status sample_batch_reference(const sample_texture *tex, const sample_sampler *smp,
                                     const sample_batch_args *args);

/* Run the fast path's kernels for instruction set `name` ("scalar",
 * "sse2", "avx2", "avx512") from the next sample_batch() call on,
 * process-wide. Returns 0 when done; −1 for an unknown name, −2 when this
 * build has no kernels for it (compiler without the flags, or not x86-64),
 * −3 when this CPU lacks it; the choice is then unchanged. NULL returns to
 * the automatic choice (the CPU and LIBSAMPLE_ISA, read again). A batch
 * already running keeps the kernels it started with. */
int sample_isa_force(const char *name);

#ifdef __cplusplus
}
#endif

#endif /* SAMPLE_TESTING_H */
