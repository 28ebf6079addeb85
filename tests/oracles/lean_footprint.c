/*
 * lean_footprint: an independent implementation of libsample's
 * Jacobian-mode Blinn–Newell and EWA, the oracle the suite checks them
 * against (tests/oracles.cmake), and a measuring stick for how fast the two
 * filters could be, timed beside libsample's own trilinear and footprint
 * filter in the same run (the measurements are in
 * doc/history/performance-passes-2.md).
 *
 * "lean" is the same filter as libsample's Jacobian-mode Blinn–Newell or
 * EWA (DESIGN §7, doc/footprint-filters.md: the level where the minor
 * semi-axis spans FP_MINOR_TEXELS = 2 texels, two levels blended, Blinn–
 * Newell's unit-variance widening J′ = U·diag(√(σ² + 1))·Vᵀ and pyramid at
 * the inverse-mapped texel centre, EWA's ellipse with Heckbert's unit
 * variance and libsample's weight table, sums in double) written only for
 * the case the bench's random sets are: float RGBA, REPEAT, no biases, no
 * derivatives, no texel cap. With AVX-512 (where the CPU has it) a level
 * inside the texture is walked eight texels a vector with eight partial
 * sums per channel: Blinn–Newell over the footprint's bounding box, EWA
 * over each row's span; other levels, and the scalar form, walk texel by
 * texel with wrapping. Query i + 1 is planned (its geometry, its rows
 * prefetched) before query i is read. The order of the sums differs from
 * libsample's, so the results are compared by their largest difference,
 * not by a hash: an independent implementation of the two filters, which
 * must agree with libsample's to 1e-5 (exit status 1 otherwise; ctest runs
 * it so, tests/oracles.cmake). A measuring stick, not a second
 * implementation: nothing in the product calls it.
 *
 *   lean_footprint [blinn-newell|ewa [SET [QUERIES [RUNS]]]]   (env PB_SIZE: texture side, default 2048)
 *   tests/oracles/lean_footprint.sh BUILD_DIR …   (a link to dev/perf_probe.sh, which builds it)
 */
#define _GNU_SOURCE
#include "probe_util.h"
#include "internal.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
/* The AVX-512 walks are compiled for AVX-512 whatever the build's flags
 * and run only where the CPU has it. */
#define LEAN_AVX512 1
#define LEAN_TARGET __attribute__((target("avx512f,avx512dq")))
#else
#define LEAN_AVX512 0
#endif

/* One level of one query: the centre, M = J′⁻¹ (texel offset → screen) and
 * the bounding box of J′·[−1, 1]² in texels. */
typedef struct lv_plan {
    const struct sample_level *L;
    double u0, v0, M[2][2], ilo, ihi, jlo, jhi, wt;
    double abc[3]; /* EWA: A, B, C over F (F = 1) */
    int ewa;
} lv_plan;

typedef struct q_plan {
    lv_plan lv[2];
    int n;
} q_plan;

/* 2^−l, exact, without a libm call (0 ≤ l < 1023). */
static double pow2_neg(int l)
{
    uint64_t b = (uint64_t)(1023 - l) << 52;
    double d;
    memcpy(&d, &b, sizeof d);
    return d;
}

static void plan_query(const sample_texture *tex, const sample_query *q, int ewa, q_plan *p)
{
    const double W = tex->level[0].w, H = tex->level[0].h;
    double J[2][2] = {{q->dsdx * W, q->dsdy * W}, {q->dtdx * H, q->dtdy * H}};
    double E = 0.5 * (J[0][0] + J[1][1]), F = 0.5 * (J[0][0] - J[1][1]);
    double G = 0.5 * (J[1][0] + J[0][1]), Hh = 0.5 * (J[1][0] - J[0][1]);
    double Q = sqrt(E * E + Hh * Hh), R = sqrt(F * F + G * G), s0 = Q + R, s1 = fabs(Q - R), pos, fl;
    int clamped = s1 < s0 / 16.0, k, maxlev = tex->nlevels - 1;
    float lam, f;
    if (clamped) s1 = s0 / 16.0;
    lam = (float)(sample_log2(s1) - 1.0);
    pos = lam > 0.0f ? (double)lam : 0.0;
    if (pos >= maxlev) pos = maxlev;
    fl = floor(pos);
    f = (float)(pos - fl);
    p->n = f > 0.0f ? 2 : 1;
    for (k = 0; k < p->n; ++k) {
        lv_plan *e = &p->lv[k];
        int l = (int)fl + k;
        double sc = pow2_neg(l), sx = s0 * sc, sy = s1 * sc, t0 = sqrt(sx * sx + 1.0), t1 = sqrt(sy * sy + 1.0);
        double Qs = Q * sc, Rs = R * sc, big = Qs >= Rs ? Qs : Rs, small = Qs >= Rs ? Rs : Qs, kb, ks, kc, ka, det;
        double Jw[2][2], ue, ve;
        if (ewa) { /* the clamped Jacobian (wid = 0), or J itself */
            t0 = sx;
            t1 = sy;
        }
        kb = (t0 + t1) / (2.0 * big);
        ks = clamped ? (sx - sy) * (sx + sy) / ((t0 + t1) * 2.0 * small) : 2.0 * big / (t0 + t1);
        kc = Qs >= Rs ? kb : ks;
        ka = Qs >= Rs ? ks : kb;
        Jw[0][0] = kc * E * sc + ka * F * sc;
        Jw[0][1] = ka * G * sc - kc * Hh * sc;
        Jw[1][0] = kc * Hh * sc + ka * G * sc;
        Jw[1][1] = kc * E * sc - ka * F * sc;
        det = Qs >= Rs ? t0 * t1 : -(t0 * t1);
        e->L = &tex->level[l];
        e->ewa = ewa;
        e->u0 = q->s * (double)e->L->w - 0.5;
        e->v0 = q->t * (double)e->L->h - 0.5;
        e->wt = p->n == 1 ? 1.0 : k == 0 ? 1.0 - f : f;
        if (ewa) {
            /* Heckbert's ellipse with the unit-variance term (footprint_ewa.c). */
            double A, B, C, Fq;
            if (!clamped) {
                Jw[0][0] = J[0][0] * sc;
                Jw[0][1] = J[0][1] * sc;
                Jw[1][0] = J[1][0] * sc;
                Jw[1][1] = J[1][1] * sc;
            }
            A = Jw[1][0] * Jw[1][0] + Jw[1][1] * Jw[1][1] + 1.0;
            B = -2.0 * (Jw[0][0] * Jw[1][0] + Jw[0][1] * Jw[1][1]);
            C = Jw[0][0] * Jw[0][0] + Jw[0][1] * Jw[0][1] + 1.0;
            Fq = A * C - 0.25 * B * B;
            e->abc[0] = A / Fq;
            e->abc[1] = B / Fq;
            e->abc[2] = C / Fq;
            ue = sqrt(C);
            ve = sqrt(A);
            e->ilo = ceil(e->u0 - ue);
            e->ihi = floor(e->u0 + ue);
            e->jlo = ceil(e->v0 - ve);
            e->jhi = floor(e->v0 + ve);
            continue;
        }
        e->M[0][0] = Jw[1][1] / det;
        e->M[0][1] = -Jw[0][1] / det;
        e->M[1][0] = -Jw[1][0] / det;
        e->M[1][1] = Jw[0][0] / det;
        ue = fabs(Jw[0][0]) + fabs(Jw[0][1]);
        ve = fabs(Jw[1][0]) + fabs(Jw[1][1]);
        e->ilo = ceil(e->u0 - ue);
        e->ihi = floor(e->u0 + ue);
        e->jlo = ceil(e->v0 - ve);
        e->jhi = floor(e->v0 + ve);
    }
}

static int inside(const lv_plan *e) { return e->ilo >= 0 && e->ihi < e->L->w && e->jlo >= 0 && e->jhi < e->L->h; }

static const float *texel(const lv_plan *e, double i, double j)
{
    long w = e->L->w, h = e->L->h, ii = (long)i % w, jj = (long)j % h;
    if (ii < 0) ii += w;
    if (jj < 0) jj += h;
    return (const float *)(e->L->data + (size_t)jj * e->L->stride) + 4 * ii;
}

/* Texel (i, j) of a box inside the level: no wrapping. */
static const float *texel_in(const lv_plan *e, double i, double j)
{
    return (const float *)(e->L->data + (size_t)j * e->L->stride) + 4 * (size_t)i;
}

static void prefetch_plan(const q_plan *p)
{
    int k;
    for (k = 0; k < p->n; ++k) {
        const lv_plan *e = &p->lv[k];
        double j;
        if (!inside(e)) continue;
        for (j = e->jlo; j <= e->jhi; j += 1.0) {
            const char *a = (const char *)texel_in(e, e->ilo, j), *b = (const char *)texel_in(e, e->ihi, j) + 15;
            for (; a <= b; a += 64) __builtin_prefetch(a);
            __builtin_prefetch(b);
        }
    }
}

/* Σw, Σw·T over a level, texel by texel (any box, wrapped). */
static void walk_scalar(const lv_plan *e, double s[5])
{
    double i, j;
    int c;
    for (c = 0; c < 5; ++c) s[c] = 0.0;
    for (j = e->jlo; j <= e->jhi; j += 1.0)
        for (i = e->ilo; i <= e->ihi; i += 1.0) {
            double du = i - e->u0, dv = j - e->v0, x = e->M[0][0] * du + e->M[0][1] * dv,
                   y = e->M[1][0] * du + e->M[1][1] * dv, w = (1.0 - fabs(x)) * (1.0 - fabs(y));
            const float *T;
            if (!(fabs(x) < 1.0 && fabs(y) < 1.0)) continue;
            T = texel(e, i, j);
            s[0] += w;
            for (c = 0; c < 4; ++c) s[1 + c] += w * T[c];
        }
}

/* EWA's row span: the columns where a·du² + b·dv·du + c·dv² < 1. */
static int ewa_row(const lv_plan *e, double dv, double *ilo, double *ihi)
{
    double a = e->abc[0], b = e->abc[1], c = e->abc[2], disc = b * b * dv * dv - 4.0 * a * (c * dv * dv - 1.0), sq;
    if (!(disc > 0.0)) return 0;
    sq = sqrt(disc);
    *ilo = ceil(e->u0 + (-b * dv - sq) / (2.0 * a));
    *ihi = floor(e->u0 + (-b * dv + sq) / (2.0 * a));
    return *ilo <= *ihi;
}

/* e^(−2r²) − e^(−2) from libsample's table (footprint_ewa.c). */
static double ewa_w(double r2)
{
    double x = (r2 > 0.0 ? r2 : 0.0) * 128.0;
    int k = (int)x;
    if (k > 127) k = 127;
    return ls_fp_ewa_lut[k] + (x - k) * (ls_fp_ewa_lut[k + 1] - ls_fp_ewa_lut[k]);
}

static void walk_scalar_ewa(const lv_plan *e, double s[5])
{
    double i, j, ilo, ihi;
    int c;
    for (c = 0; c < 5; ++c) s[c] = 0.0;
    for (j = e->jlo; j <= e->jhi; j += 1.0) {
        double dv = j - e->v0, cdv = e->abc[2] * dv * dv;
        if (!ewa_row(e, dv, &ilo, &ihi)) continue;
        for (i = ilo; i <= ihi; i += 1.0) {
            double du = i - e->u0, r2 = e->abc[0] * du * du + e->abc[1] * du * dv + cdv, w;
            const float *T;
            if (!(r2 < 1.0)) continue;
            w = ewa_w(r2);
            T = texel(e, i, j);
            s[0] += w;
            for (c = 0; c < 4; ++c) s[1 + c] += w * T[c];
        }
    }
}

#if LEAN_AVX512
/* Eight texels' weighted channels into four partial sums each (texel k of
 * a chunk: accumulator k / 2); lanes of weight 0 add nothing (a masked
 * add: a texel there may be inf). */
LEAN_TARGET static inline void add8(__m512d acc[5], __m512d w, const float *row, int ncol)
{
    const __m512i p0 = _mm512_set_epi64(1, 1, 1, 1, 0, 0, 0, 0), p1 = _mm512_set_epi64(3, 3, 3, 3, 2, 2, 2, 2),
                  p2 = _mm512_set_epi64(5, 5, 5, 5, 4, 4, 4, 4), p3 = _mm512_set_epi64(7, 7, 7, 7, 6, 6, 6, 6);
    const __m512d zero = _mm512_setzero_pd();
    __mmask16 m0, m1;
    w = _mm512_maskz_mov_pd((__mmask8)((1u << ncol) - 1), w);
    m0 = ncol >= 4 ? 0xffff : (__mmask16)((1u << (4 * ncol)) - 1);
    m1 = ncol <= 4 ? 0 : ncol >= 8 ? 0xffff : (__mmask16)((1u << (4 * (ncol - 4))) - 1);
    __m512 t0 = _mm512_maskz_loadu_ps(m0, row), t1 = _mm512_maskz_loadu_ps(m1, row + 16);
    __m512d w0 = _mm512_permutexvar_pd(p0, w), w1 = _mm512_permutexvar_pd(p1, w);
    __m512d w2 = _mm512_permutexvar_pd(p2, w), w3 = _mm512_permutexvar_pd(p3, w);
    acc[4] = _mm512_add_pd(acc[4], w);
    acc[0] = _mm512_mask_add_pd(acc[0], _mm512_cmp_pd_mask(w0, zero, _CMP_GT_OQ), acc[0],
                                _mm512_mul_pd(w0, _mm512_cvtps_pd(_mm512_castps512_ps256(t0))));
    acc[1] = _mm512_mask_add_pd(acc[1], _mm512_cmp_pd_mask(w1, zero, _CMP_GT_OQ), acc[1],
                                _mm512_mul_pd(w1, _mm512_cvtps_pd(_mm512_extractf32x8_ps(t0, 1))));
    acc[2] = _mm512_mask_add_pd(acc[2], _mm512_cmp_pd_mask(w2, zero, _CMP_GT_OQ), acc[2],
                                _mm512_mul_pd(w2, _mm512_cvtps_pd(_mm512_castps512_ps256(t1))));
    acc[3] = _mm512_mask_add_pd(acc[3], _mm512_cmp_pd_mask(w3, zero, _CMP_GT_OQ), acc[3],
                                _mm512_mul_pd(w3, _mm512_cvtps_pd(_mm512_extractf32x8_ps(t1, 1))));
}

LEAN_TARGET static void sums_out(const __m512d acc[5], double s[5])
{
    __m512d sum = _mm512_add_pd(_mm512_add_pd(acc[0], acc[1]), _mm512_add_pd(acc[2], acc[3]));
    __m256d h = _mm256_add_pd(_mm512_castpd512_pd256(sum), _mm512_extractf64x4_pd(sum, 1));
    s[0] = _mm512_reduce_add_pd(acc[4]);
    _mm256_storeu_pd(s + 1, h);
}

/* EWA over a level whose box is inside it: each row's span eight texels a
 * vector, the weights from the table by gathers. */
LEAN_TARGET static void walk_avx512_ewa(const lv_plan *e, double s[5])
{
    const __m512d iota = _mm512_set_pd(7, 6, 5, 4, 3, 2, 1, 0), zero = _mm512_setzero_pd(),
                  one = _mm512_set1_pd(1.0), k128 = _mm512_set1_pd(128.0);
    const __m256i top = _mm256_set1_epi32(127);
    __m512d acc[5] = {zero, zero, zero, zero, zero};
    double j, i, ilo, ihi;
    for (j = e->jlo; j <= e->jhi; j += 1.0) {
        double dv = j - e->v0;
        __m512d bdv = _mm512_set1_pd(e->abc[1] * dv), cdv = _mm512_set1_pd(e->abc[2] * dv * dv),
                a = _mm512_set1_pd(e->abc[0]);
        if (!ewa_row(e, dv, &ilo, &ihi)) continue;
        for (i = ilo; i <= ihi; i += 8.0) {
            int ncol = (int)(ihi - i) + 1;
            __m512d du = _mm512_add_pd(iota, _mm512_set1_pd(i - e->u0));
            __m512d r2 = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(_mm512_mul_pd(a, du), du), _mm512_mul_pd(bdv, du)), cdv);
            __mmask8 in = _mm512_cmp_pd_mask(r2, one, _CMP_LT_OQ);
            __m512d x = _mm512_mul_pd(_mm512_max_pd(r2, zero), k128);
            __m256i k = _mm256_min_epi32(_mm512_cvttpd_epi32(_mm512_maskz_mov_pd(in, x)), top);
            __m512d l0 = _mm512_i32gather_pd(k, ls_fp_ewa_lut, 8), l1 = _mm512_i32gather_pd(k, ls_fp_ewa_lut + 1, 8);
            __m512d w = _mm512_add_pd(l0, _mm512_mul_pd(_mm512_sub_pd(x, _mm512_cvtepi32_pd(k)), _mm512_sub_pd(l1, l0)));
            if (ncol > 8) ncol = 8;
            add8(acc, _mm512_maskz_mov_pd(in, w), texel_in(e, i, j), ncol);
        }
    }
    sums_out(acc, s);
}

/* The same sums over a box inside the level, eight texels of a row a
 * vector: lanes outside the pyramid weigh 0 and add nothing (a masked add:
 * a texel there may be inf). */
LEAN_TARGET static void walk_avx512(const lv_plan *e, double s[5])
{
    const __m512d iota = _mm512_set_pd(7, 6, 5, 4, 3, 2, 1, 0), one = _mm512_set1_pd(1.0), zero = _mm512_setzero_pd();
    __m512d acc[5] = {zero, zero, zero, zero, zero};
    double i, j;
    for (i = e->ilo; i <= e->ihi; i += 8.0) {
        int ncol = (int)(e->ihi - i) + 1;
        __m512d du = _mm512_add_pd(iota, _mm512_set1_pd(i - e->u0));
        __m512d xd = _mm512_mul_pd(_mm512_set1_pd(e->M[0][0]), du), yd = _mm512_mul_pd(_mm512_set1_pd(e->M[1][0]), du);
        if (ncol > 8) ncol = 8;
        for (j = e->jlo; j <= e->jhi; j += 1.0) {
            double dv = j - e->v0;
            __m512d x = _mm512_add_pd(xd, _mm512_set1_pd(e->M[0][1] * dv));
            __m512d y = _mm512_add_pd(yd, _mm512_set1_pd(e->M[1][1] * dv));
            __m512d w = _mm512_mul_pd(_mm512_max_pd(_mm512_sub_pd(one, _mm512_abs_pd(x)), zero),
                                      _mm512_max_pd(_mm512_sub_pd(one, _mm512_abs_pd(y)), zero));
            add8(acc, w, texel_in(e, i, j), ncol);
        }
    }
    sums_out(acc, s);
}
#endif

/* vec: 0 the scalar walks, 1 the AVX-512 ones where the box is inside the
 * level, 2 no walk at all (the plan's cost alone: the level's weight as
 * its value). */
static void read_query(const q_plan *p, float out[4], int vec)
{
    double r[4] = {0.0, 0.0, 0.0, 0.0}, s[5];
    int k, c;
    for (k = 0; k < p->n; ++k) {
        if (vec == 2) {
            for (c = 0; c < 4; ++c) r[c] += p->lv[k].wt;
            continue;
        }
#if LEAN_AVX512
        if (vec && inside(&p->lv[k])) (p->lv[k].ewa ? walk_avx512_ewa : walk_avx512)(&p->lv[k], s);
        else
#endif
            (p->lv[k].ewa ? walk_scalar_ewa : walk_scalar)(&p->lv[k], s);
        for (c = 0; c < 4; ++c) r[c] += p->lv[k].wt * (s[1 + c] / s[0]);
    }
    for (c = 0; c < 4; ++c) out[c] = (float)r[c];
}

/* How many queries ahead a query is planned and its rows prefetched:
 * the DRAM latency of a random query's dozen lines (2048² float RGBA is
 * 64 MiB) is longer than one query's work. */
#ifndef LEAN_AHEAD
#define LEAN_AHEAD 1
#endif

/* Best CPU time of RUNS passes (one untimed warm-up) over the queries. */
static double time_lean(const sample_texture *tex, const sample_query *q, size_t n, int runs, int ewa, int vec,
                         float *out)
{
    double best = 1e30;
    int r;
    for (r = 0; r <= runs; ++r) {
        double t0 = probe_cpu_now(), t;
        q_plan pl[LEAN_AHEAD + 1];
        size_t i;
        for (i = 0; i < LEAN_AHEAD && i < n; ++i) {
            plan_query(tex, &q[i], ewa, &pl[i]);
            prefetch_plan(&pl[i]);
        }
        for (i = 0; i < n; ++i) {
            if (i + LEAN_AHEAD < n) {
                q_plan *nx = &pl[(i + LEAN_AHEAD) % (LEAN_AHEAD + 1)];
                plan_query(tex, &q[i + LEAN_AHEAD], ewa, nx);
                prefetch_plan(nx);
            }
            read_query(&pl[i % (LEAN_AHEAD + 1)], out + 4 * i, vec);
        }
        t = probe_cpu_now() - t0;
        if (r > 0 && t < best) best = t;
    }
    return best;
}

static double max_diff(const float *a, const float *b, size_t n)
{
    double m = 0.0;
    size_t i;
    for (i = 0; i < n; ++i) {
        double d = fabs((double)a[i] - (double)b[i]);
        if (!(d <= m)) m = d;
    }
    return m;
}

int main(int argc, char **argv)
{
    const char *filt = argc > 1 ? argv[1] : "blinn-newell", *set = argc > 2 ? argv[2] : "minify";
    size_t n = argc > 3 ? strtoul(argv[3], NULL, 10) : 65536;
    int runs = argc > 4 ? atoi(argv[4]) : 5, size = getenv("PB_SIZE") ? atoi(getenv("PB_SIZE")) : 2048;
    int ewa = !strcmp(filt, "ewa"), si = -1, k, status;
    bench_engine eng[32];
    int ne = bench_engines(eng, 32), tri = -1, fp = -1;
    float *content, *o_tri, *o_fp, *o_ln;
    sample_image img;
    sample_texture *tex;
    sample_query *q;
    double t_tri, t_fp, t_ls, t_lv, d, worst;

    for (k = 0; k < BENCH_SET_COUNT; ++k)
        if (!strcmp(bench_set_names[k], set)) si = k;
    for (k = 0; k < ne; ++k) {
        if (eng[k].oiio) continue;
        if (!strcmp(eng[k].name, "trilinear")) tri = k;
        if (!strcmp(eng[k].name, filt) && (ewa || !strcmp(filt, "blinn-newell"))) fp = k;
    }
    if (si < 0 || tri < 0 || fp < 0 || n == 0 || n > PROBE_MAX_QUERIES || runs < 1 || size < 1 ||
        size > PROBE_MAX_SIZE) {
        fprintf(stderr, "usage: lean_footprint [blinn-newell|ewa [SET [QUERIES [RUNS]]]]"
                        "   (env PB_SIZE: texture side, default 2048)\n");
        return 2;
    }
    content = probe_noise(size);
    q = malloc(n * sizeof *q);
    o_tri = malloc(n * 16);
    o_fp = malloc(n * 16);
    o_ln = malloc(n * 16);
    if (!content || !q || !o_tri || !o_fp || !o_ln) return 1;
    img = (sample_image){size, size, 4, SAMPLE_FORMAT_F32, content, 0};
    if (!(tex = probe_texture(&img))) return 1;
    bench_queries((bench_set)si, size, q, n);
    t_tri = probe_time_batches(sample_batch, tex, &eng[tri].smp, q, n, runs, o_tri);
    t_fp = probe_time_batches(sample_batch, tex, &eng[fp].smp, q, n, runs, o_fp);
    if (t_tri < 0.0 || t_fp < 0.0) return 1;
    printf("%s on %s, float RGBA %d², %zu queries, best of %d (1 thread, CPU time)\n", filt, set, size, n, runs);
    printf("  %-22s %8.2f M/s %8.1f ns  %6.2f× trilinear's time\n", "libsample trilinear", n / t_tri / 1e6,
           t_tri / n * 1e9, 1.0);
    printf("  libsample %-12s %8.2f M/s %8.1f ns  %6.2f×\n", filt, n / t_fp / 1e6, t_fp / n * 1e9, t_fp / t_tri);
    t_ls = time_lean(tex, q, n, runs, ewa, 0, o_ln);
    d = max_diff(o_ln, o_fp, 4 * n);
    printf("  %-22s %8.2f M/s %8.1f ns  %6.2f×   max |lean − libsample| %.2g\n", "lean, scalar", n / t_ls / 1e6,
           t_ls / n * 1e9, t_ls / t_tri, d);
    worst = d;
#if LEAN_AVX512
    if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq")) {
        t_lv = time_lean(tex, q, n, runs, ewa, 1, o_ln);
        d = max_diff(o_ln, o_fp, 4 * n);
        printf("  %-22s %8.2f M/s %8.1f ns  %6.2f×   max |lean − libsample| %.2g\n", "lean, AVX-512",
               n / t_lv / 1e6, t_lv / n * 1e9, t_lv / t_tri, d);
        if (!(d <= worst)) worst = d;
    } else
#endif
        printf("  (lean, AVX-512: this CPU has no AVX-512)\n");
    t_lv = time_lean(tex, q, n, runs, ewa, 2, o_ln);
    printf("  %-22s %8.2f M/s %8.1f ns  %6.2f×   (geometry, level choice and prefetches; no texel read)\n",
           "lean, plan only", n / t_lv / 1e6, t_lv / n * 1e9, t_lv / t_tri);
    status = worst <= 1e-5 ? 0 : 1;
    if (status) fprintf(stderr, "lean_footprint: the lean %s differs from libsample's by %g\n", filt, worst);
    sample_texture_destroy(tex);
    free(content);
    free(q);
    free(o_tri);
    free(o_fp);
    free(o_ln);
    return status;
}
