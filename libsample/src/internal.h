/*
 * libsample internal header: the one place the library's pieces meet.
 *
 *   texture.c      storage, formats, texel decode, creation/validation
 *   color.c        sRGB EOTF table, half <-> float
 *   wrap.c         the single texel-addressing function (DESIGN §3)
 *   reconstruct.c  nearest / bilinear / bicubic on one level (DESIGN §4)
 *   lod.c          λ and level selection (DESIGN §5, GL 4.6 §8.14); the
 *                  per-query lod_lambda / lod_select are inline below
 *   mip.c          pyramid building (DESIGN §6)
 *   footprint_*.c  anisotropic, Blinn–Newell, EWA (DESIGN §7)
 *   sampler.c      validation and per-batch dispatch
 *   names.c        enum <-> string, strerror
 */
#ifndef SAMPLE_INTERNAL_H
#define SAMPLE_INTERNAL_H

#include "sample/sample.h"
#include "simd.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "portable_math.h"

/* Return early with a status and a formatted message (sample_error_set). */
#define RETURN_ERROR_IF(cond, err, status, ...)                                \
    do {                                                                       \
        if (cond) return sample_error_set((err), (status), __VA_ARGS__);       \
    } while (0)

/* ---- Storage ------------------------------------------------------------ */

struct sample_level {
    int w, h;
    size_t stride;       /* bytes per row */
    unsigned char *data; /* owned */
};

struct sample_texture {
    int width, height, channels, nlevels;
    sample_format format;
    size_t texel_bytes; /* channels × format bytes */
    size_t bytes;       /* all levels */
    struct sample_level level[SAMPLE_MAX_LEVELS];
};

/* The exact sRGB EOTF for each 8-bit code ([0]) and c / 255 ([1]), one
 * array (color.c). */
extern const float sample_u8_decode[2][256];
#define sample_srgb_table (sample_u8_decode[0])
#define sample_unorm8_table (sample_u8_decode[1])
/* The 8-bit sRGB code of a linear value, rounded to nearest in the encoded
 * domain (color.c; no libm); what the mip builder writes into sRGB8
 * levels. */
unsigned char sample_srgb_encode8(float v);

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

/* Decode one texel at p to linear RGBA with the OpenGL channel expansion
 * (missing G, B → 0, missing A → 1). With `format` and `nc` constants (the
 * fast path instantiates it per format and channel count) the switches
 * vanish; every reader, fast or general, decodes through this one function.
 * Reads exactly nc channels: shorter texels are copied into a padded buffer
 * first, so the last texel of a level is never over-read. */
SAMPLE_FORCE_INLINE v4f tex_decode_v4(sample_format format, int nc, const unsigned char *p)
{
    switch (format) {
    case SAMPLE_FORMAT_F32: {
        /* Constant-size copies inline to plain loads; a variable-length copy
         * (which GCC also makes of a per-channel loop) is a libc call. */
        float v[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        switch (nc) {
        case 4: memcpy(v, p, 16); break;
        case 3: memcpy(v, p, 12); break;
        case 2: memcpy(v, p, 8); break;
        default: memcpy(v, p, 4); break;
        }
        return v4_load(v);
    }
    case SAMPLE_FORMAT_F16: {
        /* Padding halves: 0, 0, 0, 1.0 (0x3c00). */
        uint16_t h[4] = {0, 0, 0, 0x3c00};
        switch (nc) {
        case 4: return v4_from_f16x4(p);
        case 3: memcpy(h, p, 6); break;
        case 2: memcpy(h, p, 4); break;
        default: memcpy(h, p, 2); break;
        }
        return v4_from_f16x4((const unsigned char *)h);
    }
    case SAMPLE_FORMAT_UNORM8:
        /* c / 255 correctly rounded (GL 4.6 eq. 2.1), from a table. */
        return v4_set(sample_unorm8_table[p[0]], nc > 1 ? sample_unorm8_table[p[1]] : 0.0f,
                      nc > 2 ? sample_unorm8_table[p[2]] : 0.0f,
                      nc > 3 ? sample_unorm8_table[p[3]] : 1.0f);
    case SAMPLE_FORMAT_SRGB8:
        /* Alpha of an sRGB format is linear (GL 4.6 §8.24). */
        return v4_set(sample_srgb_table[p[0]], nc > 1 ? sample_srgb_table[p[1]] : 0.0f,
                      nc > 2 ? sample_srgb_table[p[2]] : 0.0f,
                      nc > 3 ? sample_unorm8_table[p[3]] : 1.0f);
    default:
        return v4_set(0.0f, 0.0f, 0.0f, 1.0f);
    }
}

/* Decode texel (i, j) (both in range) of a level. */
static inline void tex_decode(const sample_texture *tex, const struct sample_level *lv,
                              int i, int j, float out[4])
{
    const unsigned char *p = lv->data + (size_t)j * lv->stride + (size_t)i * tex->texel_bytes;
    v4_store(out, tex_decode_v4(tex->format, tex->channels, p));
}

/* Encode linear RGBA (first `channels` values) into one texel of the
 * texture's format; used by the pyramid builder. */
void tex_encode(const sample_texture *tex, const float in[4], unsigned char *dst);

/* Allocate level k's storage (size from the level rule); tex->bytes updated. */
sample_status tex_alloc_level(sample_texture *tex, int k, sample_error *err);

/* ---- Wrapping (wrap.c) -------------------------------------------------- */

/* Wrap modes that transform the coordinate before indexing (GL_CLAMP and the
 * EXT mirror-clamps) do it here: s → s', normalized, for an axis of n texels.
 * Other modes return s unchanged. NaN must be rejected before. */
float wrap_coord(sample_wrap mode, float s, int n);

/* Whether `mode` transforms the coordinate (wrap_coord) before indexing:
 * legacy CLAMP and the EXT mirror-clamps (DESIGN §3). A predicate, so that
 * nothing depends on the enum's numeric order. */
static inline int wrap_transforms_coord(sample_wrap mode)
{
    switch (mode) {
    case SAMPLE_WRAP_CLAMP:
    case SAMPLE_WRAP_MIRROR_CLAMP:
    case SAMPLE_WRAP_MIRROR_CLAMP_TO_BORDER:
        return 1;
    default:
        return 0;
    }
}

/* The single addressing function (DESIGN §3): integral index i (a double so
 * that any float coordinate's floor is exact) on an axis of n texels → a
 * texel index in [0, n), or −1 for "border colour". `linear` selects the
 * LINEAR/footprint rule of legacy CLAMP (clamp to [−1, n]) instead of the
 * NEAREST rule (clamp to [0, n−1]). */
int wrap_index(sample_wrap mode, double i, int n, int linear);

/* ---- Per-batch context --------------------------------------------------- */

struct isa_kernels;
typedef struct sample_ctx {
    const sample_texture *tex;
    const sample_sampler *smp;
    float border[4];
    int base;      /* effective base level */
    int maxlev;    /* q: last level that may be used (GL 4.6 §8.14.3) */
    /* The kernels of this batch, chosen once when the batch starts (as
     * zstd's dctx->bmi2): every loop below reads this, never a global. */
    const struct isa_kernels *isa;
} sample_ctx;

/* The context of a batch: level_base and q (GL 4.6 §8.14.3) from the
 * sampler and the levels present, the border colour, and the kernels k
 * (isa_kernels_active(), or isa_kernels_reference). */
void ctx_init(sample_ctx *c, const sample_texture *tex, const sample_sampler *smp,
              const struct isa_kernels *k);

/* Read texel (i, j) of level `lv` through the wrap modes; border colour where
 * the wrap says so. Every filter reads texels through this. */
static inline void ctx_texel(const sample_ctx *c, int lv, double i, double j, int linear,
                             float out[4])
{
    const struct sample_level *L = &c->tex->level[lv];
    int x, y;
    /* Every wrap mode maps an in-range index to itself (wrap_index's own
     * first test); checking here saves two calls on most reads. */
    if (i >= 0.0 && i < (double)L->w && j >= 0.0 && j < (double)L->h) {
        tex_decode(c->tex, L, (int)i, (int)j, out);
        return;
    }
    x = wrap_index(c->smp->wrap_s, i, L->w, linear);
    y = wrap_index(c->smp->wrap_t, j, L->h, linear);
    if (x < 0 || y < 0) {
        out[0] = c->border[0]; out[1] = c->border[1];
        out[2] = c->border[2]; out[3] = c->border[3];
        return;
    }
    tex_decode(c->tex, L, x, y, out);
}

/* Whether the n floats stored at p are all finite. A float is ±inf or NaN
 * when its magnitude bits are ≥ 0x7f800000; adding 0x00800000 carries
 * exactly those into bit 31, so one OR over the words and one test decide
 * (a loop the compiler vectorizes, no branch per float). The words are
 * read with memcpy: p may be a struct of floats (sample_query). */
static inline int floats_finite(const void *p, size_t n)
{
    const unsigned char *b = (const unsigned char *)p;
    uint32_t bad = 0, w;
    size_t k;
    for (k = 0; k < n; ++k) {
        memcpy(&w, b + 4 * k, 4);
        bad |= (w & 0x7fffffffu) + 0x00800000u;
    }
    return !(bad & 0x80000000u);
}

_Static_assert(sizeof(sample_query) == 6 * sizeof(float) && sizeof(sample_quad) == 8 * sizeof(float),
               "queries and corners are plain arrays of floats");

/* Whether queries first … first + n − 1 of a batch can all be filtered:
 * DESIGN §10, non-finite coordinates, Jacobian, bias or corners give the
 * border colour, decided before any arithmetic could turn them into an
 * index. The fast path asks once for a block of queries, whose planning
 * steps then run as passes over the block with no border case
 * (fast_gl.c, gl_blocks). */
static inline int batch_range_finite(const sample_batch_args *a, size_t first, size_t n)
{
    return floats_finite(a->queries + first, 6 * n) && (!a->lod_bias || floats_finite(a->lod_bias + first, n)) &&
           (!a->corners || floats_finite(a->corners + first, 8 * n));
}

/* Whether query k of a batch can be filtered (batch_range_finite). */
static inline int batch_query_finite(const sample_batch_args *a, size_t k)
{
    return batch_range_finite(a, k, 1);
}

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
 *   bilinear  recon_level(c, lv, SAMPLE_LINEAR, s, t, …) bit for bit (the
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
 * parallelogram (M = J′⁻¹) or of EWA (abc = A, B, C), each texel's weight
 * and the weighted texels added to *s (fp_level_rows says which rows). */
struct fp_sums;
struct fp_spans;
struct fp_level_rows;
typedef struct fp_row_kernels {
    void (*bn_level)(struct fp_sums *s, const struct fp_level_rows *lr, const double M[2][2]);
    void (*ewa_level)(struct fp_sums *s, const struct fp_level_rows *lr, const double abc[3]);
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
extern const isa_kernels isa_kernels_scalar, isa_kernels_sse2, isa_kernels_avx2,
    isa_kernels_avx512;

/* The reference kernels (reference.c): no batch loop (fast_gl all NULL),
 * readers that decode texel by texel (tex_decode_v4) and reconstruct
 * through recon_level, and the scalar build's footprint rows. What
 * sample_batch_reference runs; every other table must give its bits. */
extern const isa_kernels isa_kernels_reference;

/* The table sample_batch runs: chosen on the first call from the CPU and
 * LIBSAMPLE_ISA (thread-safe), then a relaxed atomic load — once per
 * batch (ctx_init), never inside a loop. An out-of-line call, so that
 * this header (also read by C++, libsample_io) needs no <stdatomic.h>. */
const isa_kernels *isa_kernels_active(void);

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

/* The footprint queries of a batch (sampler.c): query i (finite, λ > 0)
 * through the sampler's footprint filter, with its stats. The fast path
 * hands these back; its λ ≤ 0 queries are the mag filter's. With `pl`
 * (Blinn–Newell, EWA: fp_footprint_plan of query i, done earlier) only
 * the accumulating pass runs; NULL runs the whole filter. */
struct fp_plan;
void sample_run_footprint(const sample_ctx *c, const sample_batch_args *a, size_t i,
                          const struct fp_plan *pl);

/* ---- Reconstruction on one level (reconstruct.c) ------------------------ */

/* kind is SAMPLE_NEAREST, SAMPLE_LINEAR or SAMPLE_CUBIC. (s, t) normalized.
 * dds/ddt (may be NULL) receive ∂/∂s and ∂/∂t of the result. Returns the
 * number of texels read. */
uint32_t recon_level(const sample_ctx *c, int lv, sample_filter kind, float s, float t,
                     float out[4], float dds[4], float ddt[4]);

/* The bilinear combination of the 2 × 2 texels T[0] = (i0, j0), T[1] =
 * (i0+1, j0), T[2] = (i0, j0+1), T[3] = (i0+1, j0+1) with fractions α, β
 * (GL 4.6 eq. 8.13), and its derivatives d/du, d/dv (may be NULL). The one
 * copy of this arithmetic: the general and the fast path both call it, so
 * they round identically. */
SAMPLE_FORCE_INLINE void recon_bilerp(const v4f T[4], float al, float be, float out[4], float ddu[4],
                                float ddv[4])
{
    v4f a1 = v4_set1(1.0f - al), b1 = v4_set1(1.0f - be), a = v4_set1(al), b = v4_set1(be);
    /* (1−α)(1−β)·T00 + α(1−β)·T10 + (1−α)β·T01 + αβ·T11, left to right. */
    v4f r = v4_add(v4_add(v4_add(v4_mul(v4_mul(a1, b1), T[0]), v4_mul(v4_mul(a, b1), T[1])),
                          v4_mul(v4_mul(a1, b), T[2])),
                   v4_mul(v4_mul(a, b), T[3]));
    v4_store(out, r);
    if (ddu) v4_store(ddu, v4_add(v4_mul(b1, v4_sub(T[1], T[0])), v4_mul(b, v4_sub(T[3], T[2]))));
    if (ddv) v4_store(ddv, v4_add(v4_mul(a1, v4_sub(T[2], T[0])), v4_mul(a, v4_sub(T[3], T[1]))));
}

/* a ← (1 − f)·a + f·b: the blend of two mip levels (GL 4.6 eq. 8.18). */
SAMPLE_FORCE_INLINE void recon_blend(float a[4], const float b[4], float f)
{
    v4_store(a, v4_add(v4_mul(v4_set1(1.0f - f), v4_load(a)), v4_mul(v4_set1(f), v4_load(b))));
}

/* The texel coordinate u = s'·n of a query on an axis of n texels, after the
 * wraps that transform s (wrap_coord). s·n may overflow to ±inf for finite s
 * near FLT_MAX; it is kept finite so that the fractional weights stay
 * defined (α = u − ⌊u⌋ would be inf − inf). */
static inline float recon_texel_coord(sample_wrap mode, float s, int n)
{
    float u = (wrap_transforms_coord(mode) ? wrap_coord(mode, s, n) : s) * (float)n;
    return u > FLT_MAX ? FLT_MAX : (u < -FLT_MAX ? -FLT_MAX : u);
}

/* The Mitchell–Netravali combination of a 4 × 4 block T[y][x] (taps −1 … 2
 * around (i0, j0)) with weights wx, wy and their derivatives, accumulated
 * in double (16 float products would lose the exact reproduction of
 * constants and ramps); `clamp` is SAMPLE_OPT_CUBIC_CLAMP. Shared by the
 * general and the fast path. Texels as plain floats, not v4f: v4f is a
 * different type in each instruction-set build of the fast path (isa.c),
 * and this function is compiled once. T is only read (not const-qualified
 * because C before C23 does not convert float (*)[4] to that implicitly). */
void recon_cubic_combine(float T[16][4], const double wx[4], const double wy[4],
                         const double dwx[4], const double dwy[4], int clamp, float out[4],
                         float ddu[4], float ddv[4]);

/* Cubic kernel weights for fractional offset f ∈ [0, 1): taps at −1, 0, 1, 2,
 * and their derivatives d/df (dw may be NULL). */
void cubic_weights(sample_cubic kind, float f, double w[4], double dw[4]);

/* ---- Level of detail (lod.c) --------------------------------------------- */

/* log2 ρ in double for a Jacobian in normalized coordinates, on level
 * `base` (GL 4.6 §8.14.1 eq. 8.9, ρ = max of the two column lengths), and
 * the squared column lengths ρx², ρy² in base texels (the anisotropic
 * filter's Px², Py²). In double: a 1e20 Jacobian squared overflows float,
 * and λ must still be right; float inputs times a level size squared stay
 * far inside double's range, so no hypot is needed. −inf for a zero
 * Jacobian. */
static inline double lod_log2_rho(const sample_ctx *c, const sample_query *q, double rho2[2])
{
    const struct sample_level *L = &c->tex->level[c->base];
    double ux = (double)q->dsdx * L->w, vx = (double)q->dtdx * L->h;
    double uy = (double)q->dsdy * L->w, vy = (double)q->dtdy * L->h;
    rho2[0] = ux * ux + vx * vx;
    rho2[1] = uy * uy + vy * vy;
    /* log2 ρ = ½ log2 ρ² (sample_log2: the same bits on any machine). */
    return 0.5 * sample_log2(rho2[0] > rho2[1] ? rho2[0] : rho2[1]);
}

/* λ_base = log2 ρ (eq. 8.7 before bias and clamps), as a float. */
static inline float lod_lambda_base(const sample_ctx *c, const sample_query *q)
{
    double rho2[2];
    return (float)lod_log2_rho(c, q, rho2);
}

typedef struct lod_choice {
    int magnify;      /* 1: use mag_filter on level base */
    sample_filter kind; /* per-level reconstruction: NEAREST, LINEAR or CUBIC */
    int level0, level1; /* level1 = −1 unless two levels are blended */
    float frac;       /* weight of level1 */
} lod_choice;

/* λ after sampler bias, per-call bias (clamped to ±max_lod_bias) and the
 * min/max lod clamp (GL 4.6 §8.14.1). Inline (with lod_select): the fast
 * path calls both for every query. */
static inline float lod_lambda(const sample_ctx *c, float lambda_base, float call_bias)
{
    /* λ' = λ_base + clamp(bias_texobj + bias_shader, ±MAX_TEXTURE_LOD_BIAS)
     * (eq. 8.6); λ = clamp(λ', lod_min, lod_max) (eq. 8.7). */
    const sample_sampler *s = c->smp;
    float bias = s->lod_bias + call_bias;
    float lam;
    if (bias > s->max_lod_bias) bias = s->max_lod_bias;
    if (bias < -s->max_lod_bias) bias = -s->max_lod_bias;
    lam = lambda_base + bias;
    if (lam > s->max_lod) lam = s->max_lod;
    if (lam < s->min_lod) lam = s->min_lod;
    return lam;
}

/* The per-level reconstruction of a filter. */
static inline sample_filter lod_level_kind(sample_filter f)
{
    switch (f) {
    case SAMPLE_NEAREST:
    case SAMPLE_NEAREST_MIPMAP_NEAREST:
    case SAMPLE_NEAREST_MIPMAP_LINEAR:
        return SAMPLE_NEAREST;
    case SAMPLE_CUBIC:
    case SAMPLE_CUBIC_MIPMAP_NEAREST:
    case SAMPLE_CUBIC_MIPMAP_LINEAR:
        return SAMPLE_CUBIC;
    default:
        return SAMPLE_LINEAR;
    }
}

/* Level selection for the OpenGL filters (GL 4.6 §8.14.2–8.14.3). */
SAMPLE_FORCE_INLINE lod_choice lod_select(const sample_ctx *c, float lambda)
{
    const sample_sampler *s = c->smp;
    lod_choice r;
    float cswitch = 0.0f;
    int base = c->base, q = c->maxlev;
    r.level1 = -1;
    r.frac = 0.0f;
    /* §8.14.3: λ ≤ c selects magnification. Since GL 4.5 c = 0; the older
     * c = 0.5 for (mag LINEAR, min NEAREST_MIPMAP_*) is an option. */
    if ((s->options & SAMPLE_OPT_LEGACY_SWITCHOVER) && s->mag_filter == SAMPLE_LINEAR &&
        (s->min_filter == SAMPLE_NEAREST_MIPMAP_NEAREST || s->min_filter == SAMPLE_NEAREST_MIPMAP_LINEAR))
        cswitch = 0.5f;
    if (lambda <= cswitch) {
        r.magnify = 1;
        r.kind = lod_level_kind(s->mag_filter);
        r.level0 = base;
        return r;
    }
    r.magnify = 0;
    r.kind = lod_level_kind(s->min_filter);
    switch (s->min_filter) {
    case SAMPLE_NEAREST_MIPMAP_NEAREST:
    case SAMPLE_LINEAR_MIPMAP_NEAREST:
    case SAMPLE_CUBIC_MIPMAP_NEAREST: {
        /* d = level_base                     if λ ≤ ½
         *     ⌈level_base + λ + ½⌉ − 1       if λ > ½ and level_base + λ ≤ q + ½
         *     q                              if λ > ½ and level_base + λ > q + ½
         * (eq. 8.16; ⌊level_base + λ + ½⌋ is the permitted alternative). */
        double p = (double)base + (double)lambda;
        if (lambda <= 0.5f)
            r.level0 = base;
        else if (p > (double)q + 0.5)
            r.level0 = q;
        else if (s->options & SAMPLE_OPT_NEAREST_LEVEL_FLOOR)
            r.level0 = (int)floor(p + 0.5);
        else
            r.level0 = (int)ceil(p + 0.5) - 1;
        if (r.level0 > q) r.level0 = q;
        return r;
    }
    case SAMPLE_NEAREST_MIPMAP_LINEAR:
    case SAMPLE_LINEAR_MIPMAP_LINEAR:
    case SAMPLE_CUBIC_MIPMAP_LINEAR: {
        /* d1 = q if level_base + λ ≥ q, else ⌊level_base + λ⌋; d2 = d1 + 1
         * (or q); τ = (1 − frac(λ)) τ1 + frac(λ) τ2 (eqs. 8.17–8.18). */
        double p = (double)base + (double)lambda;
        if (p >= (double)q) {
            r.level0 = q;
        } else {
            r.level0 = (int)floor(p);
            r.level1 = r.level0 + 1;
            r.frac = (float)(p - floor(p));
            if (r.frac == 0.0f) r.level1 = -1;
        }
        return r;
    }
    default:
        /* NEAREST, LINEAR, CUBIC: level_base only. */
        r.level0 = base;
        return r;
    }
}

/* For footprint filters: continuous level position for λ (clamped to the
 * usable range), split into two adjacent levels and the weight of the upper. */
void lod_split(const sample_ctx *c, float lambda, int *l0, int *l1, float *frac);

/* ---- Pyramid (mip.c) ----------------------------------------------------- */

/* Fill levels 1 … of a texture whose level 0 is loaded (DESIGN §6).
 * On failure the extra levels are freed and tex->nlevels is back to 1. */
sample_status mip_build(sample_texture *tex, const sample_mip_params *p, sample_error *err);

/* ---- Footprint filters --------------------------------------------------- */

/* Each returns texels read, fills out (and dds/ddt if non-NULL) and stats
 * (if non-NULL: level0/level1/level_frac). `lambda_base` is lod_lambda_base
 * of q; the filter applies sampler/per-call bias itself via lod_lambda. Each
 * reads at most SAMPLE_MAX_FOOTPRINT_TEXELS texels. */
uint32_t fp_anisotropic(const sample_ctx *c, const sample_query *q, float call_bias,
                        float out[4], float dds[4], float ddt[4], sample_stats *st);

/* What the anisotropic filter decides per query before reading a texel
 * (footprint_aniso.c): N probes along the major column, λ' and its two
 * levels. The fast path computes it when it plans a query and runs the
 * probes later with its own bilinear; fp_anisotropic does both at once. */
typedef struct fp_aniso_setup {
    int n, l0, l1;  /* probe count; levels (l1 == l0: a single level) */
    float lam, f;   /* λ' after biases and clamps; the weight of level l1 */
    double ms, mt;  /* the major column (normalized): the probes' axis */
} fp_aniso_setup;

/* From lod_log2_rho's ρx², ρy² and log2 ρ of the query. */
void fp_aniso_setup_of(const sample_ctx *c, const sample_query *q, const double rho2[2],
                       double log2_rho, float call_bias, fp_aniso_setup *a);
/* A prefetch of every probe's rows (a hint), from positions stepped in
 * float: the fast path's planning step for the queries whose probes it does
 * not address exactly ahead (fast_gl.c, aniso_address). */
void fp_aniso_prefetch(const sample_ctx *c, const sample_query *q, const fp_aniso_setup *a);

/* Probe i (1 … N) of a query: offsets i/(N + 1) − ½ of the major column. */
SAMPLE_FORCE_INLINE void fp_aniso_probe(const sample_query *q, const fp_aniso_setup *a, int i, float *s,
                                        float *t)
{
    double off = (double)i / (a->n + 1) - 0.5;
    *s = (float)(q->s + off * a->ms);
    *t = (float)(q->t + off * a->mt);
}

/* One probe's trilinear value (1 − f)·a + f·b added to the sums: equal
 * weights, summed in double so that the mean of N equal probes is that
 * probe exactly. */
SAMPLE_FORCE_INLINE void fp_aniso_add(double acc[4], double f, const float a[4], const float b[4])
{
    /* acc + ((1 − f)·a + f·b) on each channel (simd.h's v4d, so that the
     * four channels are one or two vector operations, not eight scalar
     * ones). */
    v4d p = v4d_add(v4d_mul(v4d_set1(1.0 - f), v4d_of(v4_load(a))), v4d_mul(v4d_set1(f), v4d_of(v4_load(b))));
    v4d_store(acc, v4d_add(v4d_load(acc), p));
}

/* The mean of n probes' sums. */
SAMPLE_FORCE_INLINE void fp_aniso_mean(const double acc[4], int n, float out[4])
{
    int k;
    for (k = 0; k < 4; ++k) out[k] = (float)(acc[k] / n);
}

/* One level's bilinear value at (s, t), as recon_level computes it; the
 * per-format tex_readers.bilinear, or the fast path's inline copy of it. */
typedef uint32_t (*fp_bilinear_fn)(const sample_ctx *c, int lv, float s, float t, float out[4],
                                   float dds[4], float ddt[4]);

/* The N trilinear probes and their mean. Generic over the bilinear reader
 * so that the fast path's instantiation inlines it (zstd style) while
 * fp_anisotropic calls the reader table: one loop, the same bits. */
SAMPLE_FORCE_INLINE uint32_t fp_aniso_probes(const sample_ctx *c, const sample_query *q,
                                             const fp_aniso_setup *a, fp_bilinear_fn bilinear,
                                             float out[4], float dds[4], float ddt[4])
{
    double acc[4] = {0, 0, 0, 0}, as[4] = {0, 0, 0, 0}, at[4] = {0, 0, 0, 0};
    double f = (double)a->f;
    uint32_t texels = 0;
    int i;
    for (i = 1; i <= a->n; ++i) {
        float s, t, o0[4], s0[4], t0[4], o1[4], s1[4], t1[4];
        fp_aniso_probe(q, a, i, &s, &t);
        /* Derivatives only where asked for: they do not touch the value. */
        texels += bilinear(c, a->l0, s, t, o0, dds ? s0 : NULL, ddt ? t0 : NULL);
        if (a->l1 != a->l0) {
            texels += bilinear(c, a->l1, s, t, o1, dds ? s1 : NULL, ddt ? t1 : NULL);
        } else {
            memcpy(o1, o0, sizeof o1);
            if (dds) memcpy(s1, s0, sizeof s1);
            if (ddt) memcpy(t1, t0, sizeof t1);
        }
        fp_aniso_add(acc, f, o0, o1);
        if (dds) fp_aniso_add(as, f, s0, s1);
        if (ddt) fp_aniso_add(at, f, t0, t1);
    }
    fp_aniso_mean(acc, a->n, out);
    if (dds) fp_aniso_mean(as, a->n, dds);
    if (ddt) fp_aniso_mean(at, a->n, ddt);
    return texels;
}

/* The levels and λ' of an anisotropic query, as sample_stats reports them. */
static inline void fp_aniso_stats(const fp_aniso_setup *a, sample_stats *st)
{
    st->level0 = (int16_t)a->l0;
    st->level1 = (int16_t)(a->l1 != a->l0 ? a->l1 : -1);
    st->level_frac = a->l1 != a->l0 ? a->f : 0.0f;
    st->lod = a->lam;
}
uint32_t fp_blinn_newell(const sample_ctx *c, const sample_query *q, const sample_quad *corners,
                         float call_bias, float out[4], float dds[4], float ddt[4],
                         sample_stats *st);
uint32_t fp_ewa(const sample_ctx *c, const sample_query *q, float call_bias, float out[4],
                float dds[4], float ddt[4], sample_stats *st);

/* The footprint filters' shared geometry, sums, row spans, level walks
 * and level loop (Blinn–Newell and EWA): footprint.h. */
#include "footprint.h"

/* Anisotropic probe count N for Pmax ≥ Pmin (base texels) under the
 * sampler's max_anisotropy and SAMPLE_OPT_ANISO_POW2 (footprint_aniso.c). */
int fp_aniso_count(const sample_sampler *smp, double pmax, double pmin);

/* One OpenGL-filtered query (LOD + level selection + reconstruction +
 * blend); the anisotropic probes use it. Returns texels read. */
uint32_t sample_gl(const sample_ctx *c, const sample_query *q, float call_bias, float out[4],
                   float dds[4], float ddt[4], sample_stats *st);

#endif /* SAMPLE_INTERNAL_H */
