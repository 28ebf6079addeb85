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

/* A copy of a (resident) texture whose levels are held as tiles of
 * 2^tile_log2 × 2^tile_log2 texels in memory of their own, reached texel by
 * texel through the texel source interface (libsample/src/texel.h): the
 * shape a tile cache holds textures in. sample_batch gives it the
 * original's results bit for bit (tests/test_source.c). */
sample_status sample_texture_tiled_copy(const sample_texture *tex, int tile_log2, sample_texture **out,
                                        sample_error *err);

/* Drop tile (tx, ty) of a level of a tiled copy, as if it had failed to
 * load: its texels read as `fill` (the source's fill colour, one per
 * texture) from then on. Not while another thread samples the texture. */
sample_status sample_texture_tile_drop(sample_texture *tex, int level, int tx, int ty, const float fill[4]);

#ifdef __cplusplus
}
#endif

#endif /* SAMPLE_TESTING_H */
