/*
 * The kernel tables (isa.c, fast_gl.c, footprint_rows.c, reference.c):
 * one per instruction set the build made, plus the reference one. A batch
 * picks its table once (ls_ctx_init) and everything below reads it from the
 * context.
 */
#ifndef SAMPLE_KERNELS_H
#define SAMPLE_KERNELS_H

#include "ctx.h"

/* The specialized batch loop for the OpenGL filters (fast_gl.c): one
 * kernel per format and channel count. Bit-for-bit the general path's
 * results (tests/test_fastpath.c). */
typedef void (*fast_gl_fn)(const sample_ctx *c, const sample_batch_args *a);

/* The readers the footprint filters use, one per (format × channel
 * count) in each kernel table, reached through the batch's kernels
 * (ctx_readers):
 *   row       decodes n in-range texels at p, pitch bytes apart (a level
 *             row or column; tex_decode_v4), of format fmt with nc
 *             channels (the texture's; a reader for one format ignores
 *             them);
 *   bilinear  ls_recon_level(c, lv, SAMPLE_LINEAR, s, t, …) bit for bit (the
 *             fast path's addressing; tests/test_fastpath.c). */
typedef struct tex_readers {
    void (*row)(sample_format fmt, int nc, const unsigned char *p, size_t pitch, int n, float (*out)[4]);
    uint32_t (*bilinear)(const sample_ctx *c, int lv, float s, float t, float out[4],
                         float dds[4], float ddt[4]);
} tex_readers;

/* ---- Run-time instruction-set dispatch (isa.c) --------------------------- */

/* fast_gl.c is compiled once per instruction set (libsample/CMakeLists.txt):
 * plain C structs (SAMPLE_NO_SIMD, the portable kernels every build has),
 * SSE2 (the x86-64 baseline), AVX2 + F16C and AVX-512, never with FMA and
 * always with -ffp-contract=off, so that all give the same bits. Each object
 * defines one isa_kernels table, named by SAMPLE_ISA_NAME (SAMPLE_ISA is
 * set by the build: scalar, sse2, avx2, avx512); isa.c picks one table per
 * process from the CPU and LIBSAMPLE_ISA. Levels are ordered: each one's
 * CPU requirements include the previous one's. */
typedef enum sample_isa {
    SAMPLE_ISA_SCALAR,
    SAMPLE_ISA_SSE2,
    SAMPLE_ISA_AVX2,
    SAMPLE_ISA_AVX512,
    SAMPLE_ISA_COUNT
} sample_isa;

/* The footprint filters' levels without derivatives (footprint_rows.c, the
 * same build per instruction set): every row of one level of Blinn–Newell's
 * parallelogram (M = J′⁻¹, row-major) or of EWA (abc = A, B, C), each texel's weight
 * and the weighted texels added to *s (fp_level_rows says which rows). */
struct fp_sums;
struct fp_spans;
struct fp_level_rows;
typedef struct fp_row_kernels {
    void (*bn_level)(struct fp_sums *s, const struct fp_level_rows *lr, const double *M);
    void (*ewa_level)(struct fp_sums *s, const struct fp_level_rows *lr, const double *abc);
    /* The counting pass (fp_count_rows) over the level's rows, spans of
     * several rows at once: Blinn–Newell's with P = |M₀₀|, ±M₀₁, |M₁₀|,
     * ±M₁₁ (both |M·₀| > 0), EWA's with P = abc. */
    double (*bn_count)(const struct fp_level_rows *lr, struct fp_spans *sp, const double P[4]);
    double (*ewa_count)(const struct fp_level_rows *lr, struct fp_spans *sp, const double P[3]);
    /* One row's span, the counting pass's to the bit (fp_span_fn). */
    double (*bn_span)(const double P[4], double u0, double dv, double *ilo);
    double (*ewa_span)(const double P[3], double u0, double dv, double *ilo);
} fp_row_kernels;

typedef struct isa_kernels {
    fast_gl_fn fast_gl[SAMPLE_FORMAT_COUNT][4]; /* [format][channels − 1] */
    tex_readers readers[SAMPLE_FORMAT_COUNT][4];
    const fp_row_kernels *rows;
} isa_kernels;

#define SAMPLE_ISA_CAT_(a, b) a##_##b
#define SAMPLE_ISA_CAT(a, b) SAMPLE_ISA_CAT_(a, b)
#define SAMPLE_ISA_NAME(x) SAMPLE_ISA_CAT(x, SAMPLE_ISA)

/* The tables the build made (isa.c refers only to those it was told of). */
extern const isa_kernels ls_isa_kernels_scalar, ls_isa_kernels_sse2, ls_isa_kernels_avx2,
    ls_isa_kernels_avx512;

/* The reference kernels (reference.c): no batch loop (fast_gl all NULL),
 * readers that decode texel by texel (tex_decode_v4) and reconstruct
 * through ls_recon_level, and the scalar build's footprint rows. What
 * sample_batch_reference runs; every other table must give its bits. */
extern const isa_kernels ls_isa_kernels_reference;

/* The table sample_batch runs: chosen on the first call from the CPU and
 * LIBSAMPLE_ISA (thread-safe), then a relaxed atomic load — once per
 * batch (ls_ctx_init), never inside a loop. An out-of-line call, so that
 * this header (also read by C++, libsample_io) needs no <stdatomic.h>. */
const isa_kernels *ls_isa_kernels_active(void);

/* Texture t's readers in the kernels k. */
static inline const tex_readers *tex_readers_in(const isa_kernels *k, const sample_texture *t)
{
    return &k->readers[t->format][t->channels - 1];
}

/* The readers of a batch's texture in the batch's kernels. */
static inline const tex_readers *ctx_readers(const sample_ctx *c)
{
    return tex_readers_in(c->isa, c->tex);
}

#endif /* SAMPLE_KERNELS_H */
