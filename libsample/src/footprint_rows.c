/*
 * The footprint filters' levels without derivatives: Blinn–Newell's
 * parallelogram and EWA, every row's span in the counting pass and every
 * row's weights and weighted sums (fp_sums) in the accumulating pass. Built
 * once per instruction set next to fast_gl.c (libsample/CMakeLists.txt,
 * isa.c) and reached through isa_kernels (fp_row_kernels). A "row" is a
 * row of the walk (fp_level_rows): a level's row, or its column where the
 * footprint is tall; texels lie `pitch` bytes apart either way.
 *
 * Footprint rows are short — about four texels on a 2.5-texel
 * minification, a handful more on 8:1 footprints — and many: the work is
 * per row and per four texels as much as per texel. With AVX (the AVX2 and
 * AVX-512 builds) the spans of four rows come from one pass of 4-lane
 * double vectors (GCC/Clang vector extensions), so do the weights of four
 * texels of a row, and each texel's four channels are added as one vector.
 * The other builds (portable, SSE2) run the same formulas one lane at a
 * time: 4-lane doubles on SSE2 are register pairs, and measured slower
 * there than one lane (measured: doc/history/performance-passes.md).
 *
 * Every operation is lane-wise IEEE (no FMA: -ffp-contract=off, and none
 * is written), spans and weights are formed by the same expressions in the
 * same order in every build, and the sums are added texel by texel in row
 * order, so every build returns the same bits (tests/test_fastpath.c).
 */
#include "footprint.h"

#ifndef SAMPLE_ISA
#error "footprint_rows.c is built once per instruction set with SAMPLE_ISA set (libsample/CMakeLists.txt)"
#endif

#if SAMPLE_VEC_AVX
#define FP_ROWS_VECTOR 1

static inline d4 d4_set1(double x) { return (d4){x, x, x, x}; }
static inline l4 l4_set1(int64_t x) { return (l4){x, x, x, x}; }
/* |x|: the sign bit cleared, as fabs. */
static inline d4 d4_abs(d4 x) { return (d4)((l4)x & INT64_MAX); }
/* x > 0 ? x : +0 on each lane (NaN gives +0). */
static inline d4 d4_pos(d4 x) { return (d4)((l4)x & (x > 0.0)); }

/* Texel p's weighted channels added to the sums when w > 0 (fp_sums_add);
 * w ≤ 0 (outside the footprint) adds nothing: a texel there may be ±inf or
 * NaN. */
typedef struct sums_reg {
    d4 t;
    double w;
    uint32_t n;
} sums_reg;

static inline void sums_load(sums_reg *r, const fp_sums *s)
{
    memcpy(&r->t, s->sT, sizeof r->t);
    r->w = s->sw;
    r->n = s->n;
}

static inline void sums_store(fp_sums *s, const sums_reg *r)
{
    memcpy(s->sT, &r->t, sizeof r->t);
    s->sw = r->w;
    s->n = r->n;
}

/* Texels k < e of a chunk whose weights (lanes of w) are ≥ +0 and never
 * NaN, added to the sums in order: fp_sums_add's on the texels with w > 0.
 * Inside a span nearly every texel has w > 0 (the spans are the filters'
 * own bounds), and then the chunk needs no mask. A texel of weight 0 must
 * add nothing (it may be ±inf or NaN); where the chunk has one, products
 * are masked to +0 rather than skipped: +0 added to a sum that started at
 * +0 leaves it unchanged (round-to-nearest never makes −0 from a +0
 * start), and so does adding its weight to Σw. */
static inline void sums_chunk(sums_reg *r, d4 w, const unsigned char *p, size_t pitch, int e)
{
    const l4 live = (d4){0.0, 1.0, 2.0, 3.0} < d4_set1((double)e), in = w > 0.0, out = live & ~in;
    int j, all = _mm256_testz_si256((__m256i)out, (__m256i)out);
    for (j = 0; j < e; ++j) {
        d4 wv = d4_set1(w[j]), t = _mm256_cvtps_pd(_mm_loadu_ps((const float *)(const void *)(p + pitch * (size_t)j)));
        if (all)
            r->t += wv * t;
        else
            r->t += (d4)((l4)(wv * t) & l4_set1(in[j]));
        r->w += w[j];
    }
    r->n += all ? (uint32_t)e : (uint32_t)-(in[0] & live[0]) - (uint32_t)(in[1] & live[1]) -
                                    (uint32_t)(in[2] & live[2]) - (uint32_t)(in[3] & live[3]);
}
#endif

/* ---- Lanes: four texels or rows (AVX), or one ---------------------------- */

/* The kernels below are written once over `lanes`: four doubles where the
 * vectors are used, one double otherwise, with the same operations lane by
 * lane. LANES_MASK is a comparison's result (all ones or 0 per lane). */
#if FP_ROWS_VECTOR
typedef d4 lanes;
#define LANES 4
#define LANES_MASK l4
#define LANE(x, k) ((x)[k])
static inline lanes lanes_set1(double x) { return d4_set1(x); }
static inline lanes lanes_iota(void) { return (d4){0.0, 1.0, 2.0, 3.0}; }
static inline lanes lanes_abs(lanes x) { return d4_abs(x); }
static inline lanes lanes_pos(lanes x) { return d4_pos(x); }
static inline LANES_MASK lanes_lt(lanes a, lanes b) { return a < b; }
static inline LANES_MASK lanes_le(lanes a, lanes b) { return a <= b; }
static inline lanes lanes_sqrt(lanes x) { return _mm256_sqrt_pd(x); }
/* c ? a : b on each lane. */
static inline lanes lanes_select(LANES_MASK c, lanes a, lanes b) { return (d4)(((l4)a & c) | ((l4)b & ~c)); }
/* x where r2 < 1, else +0 (x is ≥ +0 and not NaN there). */
static inline lanes lanes_inside(lanes r2, lanes x) { return (d4)((l4)x & (r2 < 1.0)); }
/* fp_ceil and fp_floor: the rounding instruction (+ 0.0 turns its −0 into
 * +0, as theirs, and leaves every other value as it is). */
static inline lanes lanes_ceil(lanes x) { return _mm256_round_pd(x, _MM_FROUND_TO_POS_INF | _MM_FROUND_NO_EXC) + 0.0; }
static inline lanes lanes_floor(lanes x) { return _mm256_round_pd(x, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC) + 0.0; }
/* fp_ewa_weight's interpolation on each lane; x = 128·r² ∈ [0, 128). */
static inline lanes lanes_ewa_lut(lanes x)
{
    i4 ie = __builtin_convertvector(x, i4);
#if defined(__AVX2__)
    /* The same loads as below, gathered (exact copies: the same bits). */
    d4 lo = _mm256_i32gather_pd(ls_fp_ewa_lut, (__m128i)ie, 8), hi = _mm256_i32gather_pd(ls_fp_ewa_lut + 1, (__m128i)ie, 8);
#else
    d4 lo = {ls_fp_ewa_lut[ie[0]], ls_fp_ewa_lut[ie[1]], ls_fp_ewa_lut[ie[2]], ls_fp_ewa_lut[ie[3]]};
    d4 hi = {ls_fp_ewa_lut[ie[0] + 1], ls_fp_ewa_lut[ie[1] + 1], ls_fp_ewa_lut[ie[2] + 1], ls_fp_ewa_lut[ie[3] + 1]};
#endif
    return FP_EWA_LERP(lo, hi, x, __builtin_convertvector(ie, d4));
}
#else
typedef double lanes;
#define LANES 1
#define LANES_MASK int
#define LANE(x, k) ((void)(k), (x))
typedef fp_sums sums_reg;
static inline lanes lanes_set1(double x) { return x; }
static inline lanes lanes_iota(void) { return 0.0; }
static inline lanes lanes_abs(lanes x) { return fabs(x); }
static inline lanes lanes_pos(lanes x) { return fp_pos(x); }
static inline LANES_MASK lanes_lt(lanes a, lanes b) { return a < b; }
static inline LANES_MASK lanes_le(lanes a, lanes b) { return a <= b; }
static inline lanes lanes_sqrt(lanes x) { return sqrt(x); }
static inline lanes lanes_select(LANES_MASK c, lanes a, lanes b) { return c ? a : b; }
static inline lanes lanes_inside(lanes r2, lanes x) { return r2 < 1.0 ? x : 0.0; }
static inline lanes lanes_ceil(lanes x) { return fp_ceil(x); }
static inline lanes lanes_floor(lanes x) { return fp_floor(x); }
/* fp_ewa_weight at r² = x / 128 (both scalings exact). */
static inline lanes lanes_ewa_lut(lanes x) { return fp_ewa_weight(x * (1.0 / 128.0), NULL); }
static inline void sums_load(sums_reg *r, const fp_sums *s) { *r = *s; }
static inline void sums_store(fp_sums *s, const sums_reg *r) { *s = *r; }
/* The one texel at p when w > 0 (w is ≥ +0 and not NaN). */
static inline void sums_chunk(sums_reg *r, lanes w, const unsigned char *p, size_t pitch, int e)
{
    float t4[4];
    (void)e, (void)pitch;
    if (!(w > 0.0)) return;
    memcpy(t4, p, sizeof t4);
    fp_sums_add(r, w, t4);
}
#endif

/* A row's constants: Blinn–Newell's x = m₀·du + m₁, y = m₂·du + m₃ (the
 * row's offset dv folded into m₁, m₃); EWA's r² = A·du² + B·dv·du + C·dv²
 * (A, B·dv, C·dv²). */
typedef struct row_consts {
    lanes k[4]; /* on every lane */
} row_consts;

/* Blinn–Newell (footprint_blinn_newell.c, the parallelogram): the pyramid
 * w = (1 − |x|)(1 − |y|) where both are inside (−1, 1), else 0. Each factor
 * is clamped at 0 instead of testing |x| < 1: 1 − |x| ≤ 0 exactly when
 * |x| ≥ 1. Both factors lie in [+0, 1], so w is ≥ +0 and not NaN. */
static inline void bn_consts(const double *par, double dv, row_consts *rc)
{
    rc->k[0] = lanes_set1(par[0]);
    rc->k[1] = lanes_set1(par[1] * dv);
    rc->k[2] = lanes_set1(par[2]);
    rc->k[3] = lanes_set1(par[3] * dv);
}

static inline lanes bn_weights(const row_consts *rc, lanes du)
{
    return FP_BN_PYRAMID(rc->k[0] * du + rc->k[1], rc->k[2] * du + rc->k[3], lanes_abs, lanes_pos);
}

/* EWA (footprint_ewa.c): the truncated Gaussian fp_ewa_weight(r²) where
 * r² < 1 (r² < 0, rounding, as 0), else 0. Lanes outside read the table
 * at 0 and are masked to +0 after; r² < 1 keeps the index ≤ 127. Table
 * values are in [0, 1), so w is ≥ +0 and not NaN. */
static inline void ewa_consts(const double *par, double dv, row_consts *rc)
{
    rc->k[0] = lanes_set1(par[0]);
    rc->k[1] = lanes_set1(par[1]);
    rc->k[2] = lanes_set1(par[2] * dv * dv);
    rc->k[3] = lanes_set1(dv);
}

static inline lanes ewa_weights(const row_consts *rc, lanes du)
{
    lanes r2 = FP_EWA_R2(rc->k[0], rc->k[1], rc->k[2], du, rc->k[3]);
    return lanes_inside(r2, lanes_ewa_lut(lanes_inside(r2, lanes_pos(r2)) * 128.0));
}

/* ---- Row spans ------------------------------------------------------------ */

/* Each filter's span on rows dv texels from the centre, before rounding:
 * the columns lo ≤ c − u0 ≤ hi, NaN where the row is empty.
 *
 * Blinn–Newell (P = |M₀₀|, ±M₀₁, |M₁₀|, ±M₁₁, both |M·₀| > 0,
 * footprint_blinn_newell.c): the intersection of the slabs |x| ≤ 1 and
 * |y| ≤ 1; with a = |M₀₀| and b = ±M₀₁·dv (the sign of M₀₀) the x slab is
 * [(−1 − b)/a, (1 − b)/a]. An empty intersection (lo > hi) needs no NaN:
 * the rounding below finds no column in it. */
static inline void bn_bounds(const double *P, lanes dv, lanes *lo, lanes *hi)
{
    lanes b0 = P[1] * dv, b1 = P[3] * dv;
    lanes l0 = (-1.0 - b0) / P[0], h0 = (1.0 - b0) / P[0], l1 = (-1.0 - b1) / P[2], h1 = (1.0 - b1) / P[2];
    *lo = lanes_select(lanes_lt(l1, l0), l0, l1);
    *hi = lanes_select(lanes_lt(h0, h1), h0, h1);
}

/* EWA (P = A, B, C of the normalized ellipse, footprint_ewa.c): the roots of
 * A·du² + B·dv·du + C·dv² = 1; none (NaN) unless the discriminant is > 0. */
static inline void ewa_bounds(const double *P, lanes dv, lanes *lo, lanes *hi)
{
    lanes disc = P[1] * P[1] * dv * dv - 4.0 * P[0] * (P[2] * dv * dv - 1.0), sq;
    sq = lanes_sqrt(lanes_select(lanes_lt(lanes_set1(0.0), disc), disc, lanes_set1(NAN)));
    *lo = (-P[1] * dv - sq) / (2.0 * P[0]);
    *hi = (-P[1] * dv + sq) / (2.0 * P[0]);
}

/* The texel columns of rows dv: the count (0 if none) and the first, as
 * integers in double (fp_ceil/fp_floor of u0 + lo, u0 + hi). */
SAMPLE_FORCE_INLINE lanes spans_of(const double *P, double u0, lanes dv, lanes *ilo,
                                   void (*bounds)(const double *P, lanes dv, lanes *lo, lanes *hi))
{
    lanes lo, hi, a, b;
    bounds(P, dv, &lo, &hi);
    a = lanes_ceil(u0 + lo);
    b = lanes_floor(u0 + hi);
    *ilo = a;
    return lanes_select(lanes_le(lo, hi) & lanes_le(a, b), b - a + 1.0, lanes_set1(0.0));
}

/* The counting pass of a level (fp_count_rows with LANES rows at once):
 * each row's span, whether it lies inside the level (fp_span_at's test),
 * kept and prefetched (fp_span_keep), the texels added up; INFINITY once
 * over the cap. */
SAMPLE_FORCE_INLINE double count_level(const fp_level_rows *lr, fp_spans *sp, const double *P,
                                       void (*bounds)(const double *P, lanes dv, lanes *lo, lanes *hi))
{
    const double cap = (double)SAMPLE_MAX_FOOTPRINT_TEXELS;
    const double w = lr->wlim, h = lr->hlim;
    double total = 0.0;
    int r, k;
    sp->n = 0;
    for (r = 0; r < lr->nrows; r += LANES) {
        lanes j = lr->jlo + ((double)r + lanes_iota()), ilo, ncol = spans_of(P, lr->u0, j - lr->v0, &ilo, bounds);
        /* In the level (fp_span_at's test), and at most the cap. */
        LANES_MASK in = lanes_lt(lanes_set1(0.0), ncol) & lanes_le(ncol, lanes_set1(cap)) & lanes_le(lanes_set1(0.0), j) &
                        lanes_lt(j, lanes_set1(h)) & lanes_le(lanes_set1(0.0), ilo) & lanes_le(ilo + ncol, lanes_set1(w));
        for (k = 0; k < LANES && r + k < lr->nrows; ++k) {
            const unsigned char *at = LANE(in, k) ? fp_texel_at(lr, LANE(j, k), LANE(ilo, k)) : NULL;
            fp_span_keep(lr, sp, r + k, LANE(j, k), LANE(ilo, k), LANE(ncol, k), at);
            total += LANE(ncol, k);
        }
        if (total > cap) return INFINITY;
    }
    sp->n = lr->nrows < FP_SPAN_MEMO ? lr->nrows : FP_SPAN_MEMO;
    return total;
}

/* One row's span (the counting pass's, bit for bit), for rows past
 * FP_SPAN_MEMO. */
SAMPLE_FORCE_INLINE double span_one(const double *P, double u0, double dv, double *ilo,
                                    void (*bounds)(const double *P, lanes dv, lanes *lo, lanes *hi))
{
    lanes a, n = spans_of(P, u0, lanes_set1(dv), &a, bounds);
    *ilo = LANE(a, 0);
    return LANE(n, 0);
}

static double bn_count(const fp_level_rows *lr, fp_spans *sp, const double P[4]) { return count_level(lr, sp, P, bn_bounds); }
static double ewa_count(const fp_level_rows *lr, fp_spans *sp, const double P[3]) { return count_level(lr, sp, P, ewa_bounds); }
static double bn_span(const double P[4], double u0, double dv, double *ilo) { return span_one(P, u0, dv, ilo, bn_bounds); }
static double ewa_span(const double P[3], double u0, double dv, double *ilo) { return span_one(P, u0, dv, ilo, ewa_bounds); }

/* ---- A level's rows ------------------------------------------------------ */

/* The sums of a level being walked (kept in registers: the walk and the
 * rows are inlined into bn_level / ewa_level) and the level's constants. */
typedef struct walk_state {
    sums_reg r;
    const double *par;
    double u0;
} walk_state;

/* One row's texels weighted by the filter's weights and added texel by
 * texel in row order. Texel positions are the scalar filters' to the bit:
 * du = (ilo + k) − u0 (ilo and k integral, so ilo + k is exact). */
SAMPLE_FORCE_INLINE void weigh_row(walk_state *ws, const unsigned char *p, size_t pitch, int n, double ilo, double dv,
                                   void (*consts)(const double *par, double dv, row_consts *rc),
                                   lanes (*weights)(const row_consts *rc, lanes du))
{
    row_consts rc;
    lanes kk = lanes_iota();
    int k;
    consts(ws->par, dv, &rc);
    for (k = 0; k < n; k += LANES, kk += (double)LANES)
        sums_chunk(&ws->r, weights(&rc, (ilo + kk) - ws->u0), p + pitch * (size_t)k, pitch, n - k < LANES ? n - k : LANES);
}

static inline void bn_row(void *ws, const unsigned char *p, size_t pitch, int n, double ilo, double dv)
{
    weigh_row((walk_state *)ws, p, pitch, n, ilo, dv, bn_consts, bn_weights);
}

static inline void ewa_row(void *ws, const unsigned char *p, size_t pitch, int n, double ilo, double dv)
{
    weigh_row((walk_state *)ws, p, pitch, n, ilo, dv, ewa_consts, ewa_weights);
}

/* Every row of one level (fp_level_walk) into *s, with sums in registers
 * for the whole level. */
SAMPLE_FORCE_INLINE void walk_level(fp_sums *s, const fp_level_rows *lr, const double *par, fp_row_fn row)
{
    float T[SAMPLE_MAX_FOOTPRINT_TEXELS][4]; /* one row's texels, where decoded */
    walk_state ws;
    ws.par = par;
    ws.u0 = lr->u0;
    sums_load(&ws.r, s);
    fp_level_walk(lr, T, &ws, row);
    sums_store(s, &ws.r);
}

/* m = M (the parallelogram's J′⁻¹, row-major). */
static void bn_level(fp_sums *s, const fp_level_rows *lr, const double *M) { walk_level(s, lr, M, bn_row); }

/* abc = A, B, C of the normalized ellipse. */
static void ewa_level(fp_sums *s, const fp_level_rows *lr, const double *abc) { walk_level(s, lr, abc, ewa_row); }

/* ---- This build's level kernels (isa.c) --------------------------------- */

const fp_row_kernels SAMPLE_ISA_NAME(ls_fp_row_kernels) = {
    .bn_level = bn_level,
    .ewa_level = ewa_level,
    .bn_count = bn_count,
    .ewa_count = ewa_count,
    .bn_span = bn_span,
    .ewa_span = ewa_span,
};
