/*
 * Blinn–Newell (1976) pyramid-weighted quadrilateral (DESIGN §7,
 * doc/footprint-filters.md).
 *
 * The 2 × 2-pixel region around the pixel, screen offsets (x, y) ∈ [−1, 1]²,
 * maps into texture space by the Jacobian (a parallelogram) or by the four
 * exact corners (the homography through them: the exact screen → texture
 * map of a plane under a pinhole camera). A texel centre c is weighted by
 * the screen-space pyramid (1 − |x|)(1 − |y|) at its inverse-mapped position,
 * "a pyramid distorted to fit the quadrilateral" (Blinn & Newell, CACM 19(10)).
 *
 * Reconstruction: the design integrates the *bilinearly reconstructed*
 * texture against the pyramid, i.e. weights the pyramid convolved with the
 * texel tent. We use its moment-matched surrogate, Heckbert's unit-variance
 * term in singular-value form: with J = U·diag(σ)·Vᵀ (texel units) the
 * pyramid is built on J′ = U·diag(√(σ² + 1))·Vᵀ. J′J′ᵀ = JJᵀ + I, so the
 * footprint keeps the exact mean and covariance of pyramid ⊛ tent (the
 * pyramid's covariance is JJᵀ/6, the tent's I/6); J′ → J for large
 * footprints (the quadrilateral's own shape) and J′ → I for J → 0, where the
 * weights are exactly the bilinear ones. It also guarantees a texel centre
 * strictly inside, so the sum is never empty.
 */
#include "footprint.h"

/* One level's footprint in texels of that level. fp_run visits each level
 * twice (count, then accumulate); the second visit reuses the first's
 * arithmetic (as EWA's memo, doc/history/performance-passes.md). */
typedef struct bn_level_geom {
    int lv;   /* −1: empty */
    int fail; /* the level cannot be filtered (unbounded or singular) */
    double ku, kv, nrows;
    fp_level_rows lr;  /* the walk (a parallelogram taller than wide: by columns) */
    double M[2][2];    /* parallelogram: J′⁻¹ (walk-frame texel offset → screen) */
    double P[4];       /* parallelogram: |M₀₀|, ±M₀₁, |M₁₀|, ±M₁₁ (the sign of M·₀) */
    double G[3][3];    /* quad: the pulled-back inverse homography */
    double V[4][2];    /* quad: the widened support's corners */
    fp_spans spans;    /* rows found by the counting pass */
} bn_level_geom;

typedef struct bn_geom {
    float s, t;      /* centre of the footprint (normalized) */
    double J[2][2];  /* rows (s, t), columns (x, y); one pixel, normalized */
    /* Quad mode: the homography (x, y, 1) ↦ w·(s − s_c, t − t_c, 1) through
     * the corners (normalized, relative to the centre; w = 1 at (0, 0)),
     * and the range [wlo, whi] of w on the square (its corner values). */
    double H[3][3], wlo, whi;
    fp_shape base;       /* of J on the base level (the level choice's) */
    bn_level_geom *memo; /* two entries, by the level's parity */
} bn_geom;

/* Each level's span functions (fp_span_fn), named in its walk (fp_level_rows). */
static double bn_affine_span_fn(const void *lg, double dv, double *ilo);
static double bn_quad_span_fn(const void *lg, double dv, double *ilo);

/* w = (1 − |x|)(1 − |y|) on the open square and its gradient; at a crease
 * the gradient is the average of both sides (sign 0). */
static double pyramid(double x, double y, double *gx, double *gy)
{
    double ax = fabs(x), ay = fabs(y);
    if (ax >= 1.0 || ay >= 1.0) return 0.0;
    *gx = -(double)((x > 0.0) - (x < 0.0)) * (1.0 - ay);
    *gy = -(double)((y > 0.0) - (y < 0.0)) * (1.0 - ax);
    return FP_BN_PYRAMID(x, y, fabs, fp_pos);
}

/* Intersect [lo, hi] with {du : |a·du + b| ≤ 1}. */
static void slab(double a, double b, double *lo, double *hi)
{
    double x1, x2;
    if (a == 0.0) {
        if (fabs(b) > 1.0) *lo = INFINITY, *hi = -INFINITY;
        return;
    }
    x1 = (-1.0 - b) / a;
    x2 = (1.0 - b) / a;
    if (x1 > x2) { double tmp = x1; x1 = x2; x2 = tmp; }
    if (x1 > *lo) *lo = x1;
    if (x2 < *hi) *hi = x2;
}

/* Columns of the row interval [lo, hi] (relative to u0) as integer texel
 * indices; returns the count, 0 if none. */
static double row_span(double u0, double lo, double hi, double *ilo)
{
    double a, b;
    if (!(lo <= hi)) return 0.0;
    a = fp_ceil(u0 + lo);
    b = fp_floor(u0 + hi);
    *ilo = a;
    return b >= a ? b - a + 1.0 : 0.0;
}

/* ---- Parallelogram (Jacobian) footprint --------------------------------- */

static void bn_affine_setup(const sample_ctx *c, const bn_geom *g, int lv, bn_level_geom *e)
{
    double J[2][2], Jw[2][2], det, ext, uext, u0, v0;
    int fs, ft, tr;
    fp_shape d;

    e->lv = lv;
    e->fail = 0;
    ls_fp_center(c, lv, g->s, g->t, &u0, &v0, &fs, &ft);
    ls_fp_level_jacobian(c, lv, g->J, fs, ft, J);
    fp_level_scale(c, lv, fs, ft, &e->ku, &e->kv);
    /* Unit-variance widening (file comment): J′ = U·diag(√(σ² + 1))·Vᵀ,
     * M = J′⁻¹ by its adjugate; det J′ = ±√(σ0² + 1)·√(σ1² + 1) ≠ 0. */
    ls_fp_level_shape(c, lv, &g->base, J, fs || ft, &d);
    det = ls_fp_shape_reshape(&d, 1.0, Jw);
    /* The parallelogram J′·[−1, 1]² spans |J′₁₀| + |J′₁₁| in v and
     * |J′₀₀| + |J′₀₁| in u: walked by columns where that saves lines
     * (fp_walk_columns), with u and v exchanged (M's columns too). */
    ext = fabs(Jw[1][0]) + fabs(Jw[1][1]);
    uext = fabs(Jw[0][0]) + fabs(Jw[0][1]);
    tr = fp_walk_columns(uext * uext, ext * ext);
    if (tr) ext = uext;
    e->M[0][tr] = Jw[1][1] / det;
    e->M[0][!tr] = -Jw[0][1] / det;
    e->M[1][tr] = -Jw[1][0] / det;
    e->M[1][!tr] = Jw[0][0] / det;
    e->P[0] = fabs(e->M[0][0]);
    e->P[1] = e->M[0][0] < 0.0 ? -e->M[0][1] : e->M[0][1];
    e->P[2] = fabs(e->M[1][0]);
    e->P[3] = e->M[1][0] < 0.0 ? -e->M[1][1] : e->M[1][1];
    e->nrows = fp_level_rows_init(&e->lr, c, &e->spans, bn_affine_span_fn, e, lv, tr, u0, v0, -ext, ext);
    e->spans.n = 0;
}

/* Row dv's span: the intersection of the slabs |x| ≤ 1 and |y| ≤ 1
 * (footprint_rows.c, bn_bounds); a zero M₀₀ or M₁₀ (a row parallel to a
 * side) takes slab(). */
static int bn_affine_sliced(const bn_level_geom *e) { return e->P[0] > 0.0 && e->P[2] > 0.0; }

static double bn_affine_span(const bn_level_geom *e, double dv, double *ilo)
{
    double lo = -INFINITY, hi = INFINITY;
    if (bn_affine_sliced(e)) return e->lr.k->rows->bn_span(e->P, e->lr.u0, dv, ilo);
    slab(e->M[0][0], e->M[0][1] * dv, &lo, &hi);
    slab(e->M[1][0], e->M[1][1] * dv, &lo, &hi);
    return row_span(e->lr.u0, lo, hi, ilo);
}

/* bn_affine_span as an fp_span_fn. */
static double bn_affine_span_fn(const void *lg, double dv, double *ilo) { return bn_affine_span((const bn_level_geom *)lg, dv, ilo); }

/* The derivative pass of a parallelogram level: each texel's pyramid
 * weight and its gradient (fp_level_walk's row). */
typedef struct bn_affine_deriv {
    fp_pass ps; /* first */
    double M[2][2];
} bn_affine_deriv;

static int bn_affine_weight(const void *dp, double du, double dv, double *w, double *wu, double *wv)
{
    const double(*M)[2] = ((const bn_affine_deriv *)dp)->M;
    double gx = 0.0, gy = 0.0;
    *w = pyramid(M[0][0] * du + M[0][1] * dv, M[1][0] * du + M[1][1] * dv, &gx, &gy);
    if (*w <= 0.0) return 0;
    /* ∂w/∂(du, dv) = ∇pyr · M (the chain rule through x = M·(du, dv)). */
    *wu = gx * M[0][0] + gy * M[1][0];
    *wv = gx * M[0][1] + gy * M[1][1];
    return 1;
}

static void bn_affine_deriv_row(void *dp, const unsigned char *p, size_t pitch, int n, double ilo, double dv)
{
    fp_pass_row(dp, bn_affine_weight, p, pitch, n, ilo, dv);
}

static double bn_affine_level(const sample_ctx *c, const void *gp, int lv, fp_accum *acc,
                              int count_only)
{
    const bn_geom *g = (const bn_geom *)gp;
    const double cap = (double)SAMPLE_MAX_FOOTPRINT_TEXELS;
    bn_level_geom *e = &g->memo[lv & 1];
    float T[SAMPLE_MAX_FOOTPRINT_TEXELS][4]; /* one row's texels, where decoded */
    bn_affine_deriv d;

    if (e->lv != lv) bn_affine_setup(c, g, lv, e);
    if (!(e->nrows <= cap)) return INFINITY;
    if (count_only) {
        if (bn_affine_sliced(e)) return e->lr.k->rows->bn_count(&e->lr, &e->spans, e->P);
        return fp_count_rows(&e->lr, &e->spans, cap);
    }
    /* The pyramid alone, the level at once (footprint_rows.c). With |x|,
     * |y| < 1 both factors are at least 2^−53, so w > 0 there (M and du
     * are finite, ls_fp_shape_reshape: det J′ = ±t0·t1, t ≥ 1). */
    if (!acc->deriv && !acc->draw) return fp_level_sums(acc, &e->lr, e->lr.k->rows->bn_level, &e->M[0][0]);
    memcpy(d.M, e->M, sizeof d.M);
    return fp_pass_run(&d.ps, &e->lr, T, acc, e->ku, e->kv, bn_affine_deriv_row);
}

/* ---- General quadrilateral (exact corners): the projective map --------- */

static double cross2(const double a[2], const double b[2]) { return a[0] * b[1] - a[1] * b[0]; }

/* Row interval of the convex hull of four points (all six segments: the
 * hull's boundary is among them and each lies inside it). */
static void hull_row(const double H[4][2], double dv, double *lo, double *hi)
{
    int p, q;
    *lo = INFINITY;
    *hi = -INFINITY;
    for (p = 0; p < 4; ++p)
        for (q = p + 1; q < 4; ++q) {
            double a = H[p][1] - dv, b = H[q][1] - dv, u0, u1;
            if (a * b > 0.0) continue;
            if (a == b) { /* both on the row: the whole segment */
                u0 = H[p][0];
                u1 = H[q][0];
            } else {
                u0 = u1 = H[p][0] + (H[q][0] - H[p][0]) * (a / (a - b));
            }
            *lo = fmin(*lo, fmin(u0, u1));
            *hi = fmax(*hi, fmax(u0, u1));
        }
}

static void bn_quad_setup(const sample_ctx *c, const bn_geom *g, int lv, bn_level_geom *e)
{
    double ku, kv, H[3][3], Gh[3][3], det, T[2][2], Ti[2][2], vmin, vmax, J[2][2], Jw[2][2], dw, dj, u0, v0;
    int fs, ft, k, i;
    fp_shape sh;

    e->lv = lv;
    e->fail = 1;
    ls_fp_center(c, lv, g->s, g->t, &u0, &v0, &fs, &ft);
    fp_level_scale(c, lv, fs, ft, &e->ku, &e->kv);
    ku = e->ku;
    kv = e->kv;
    /* The homography in texels of this level: rows (u, v) scaled, w kept. */
    for (k = 0; k < 3; ++k) {
        H[0][k] = g->H[0][k] * ku;
        H[1][k] = g->H[1][k] * kv;
        H[2][k] = g->H[2][k];
    }
    /* Widening, in texture space about the centre c0 = H(0, 0): with the
     * centre Jacobian J = U·diag(σ)·Vᵀ, a texel c is weighted at the
     * preimage of c0 + T·(c − c0), T = U·diag(σ/√(σ² + 1))·Uᵀ = J·S⁻¹·J⁻¹.
     * For a parallelogram that is pyr(S⁻¹·J⁻¹·(c − c0)), exactly the
     * Jacobian mode (file comment). Done in texture space rather than on
     * the screen side of H, the widened support is the quad itself grown
     * about c0 by T⁻¹ — a convex quad, far from the horizon whatever σ —
     * and the pulled-back point lies in the quad wherever the weight is
     * nonzero, so w stays within its range on the square. σ > 0: the
     * caller sends only projective, not too eccentric quads here. */
    ls_fp_level_jacobian(c, lv, g->J, fs, ft, J);
    ls_fp_shape_of(J, &sh);
    ls_fp_shape_sigma(&sh); /* T wants J's own σ1, not the eccentricity clamp's */
    if (!(sh.s[1] > 0.0)) return;
    /* Jw = U·diag(√(σ² + 1))·Vᵀ (no trigonometry: ls_fp_shape_reshape), so
     * T = J·Jw⁻¹ and T⁻¹ = Jw·J⁻¹, by adjugates. */
    dw = ls_fp_shape_reshape(&sh, 1.0, Jw);
    dj = J[0][0] * J[1][1] - J[0][1] * J[1][0];
    if (!(dj != 0.0)) return;
    for (i = 0; i < 2; ++i) {
        T[i][0] = (J[i][0] * Jw[1][1] - J[i][1] * Jw[1][0]) / dw;
        T[i][1] = (J[i][1] * Jw[0][0] - J[i][0] * Jw[0][1]) / dw;
        Ti[i][0] = (Jw[i][0] * J[1][1] - Jw[i][1] * J[1][0]) / dj;
        Ti[i][1] = (Jw[i][1] * J[0][0] - Jw[i][0] * J[0][1]) / dj;
    }
    /* Gh = H⁻¹ (adjugate / determinant): Gh·(u, v, 1) = (x, y, 1)/w. */
    Gh[0][0] = H[1][1] * H[2][2] - H[1][2] * H[2][1];
    Gh[0][1] = H[0][2] * H[2][1] - H[0][1] * H[2][2];
    Gh[0][2] = H[0][1] * H[1][2] - H[0][2] * H[1][1];
    Gh[1][0] = H[1][2] * H[2][0] - H[1][0] * H[2][2];
    Gh[1][1] = H[0][0] * H[2][2] - H[0][2] * H[2][0];
    Gh[1][2] = H[0][2] * H[1][0] - H[0][0] * H[1][2];
    Gh[2][0] = H[1][0] * H[2][1] - H[1][1] * H[2][0];
    Gh[2][1] = H[0][1] * H[2][0] - H[0][0] * H[2][1];
    Gh[2][2] = H[0][0] * H[1][1] - H[0][1] * H[1][0];
    det = H[0][0] * Gh[0][0] + H[0][1] * Gh[1][0] + H[0][2] * Gh[2][0];
    if (!(det != 0.0) || !isfinite(det)) return;
    /* G = H⁻¹·[T, c0 − T·c0; 0 0 1]: one 3 × 3 product per texel. */
    for (i = 0; i < 3; ++i) {
        double a0 = Gh[i][0] / det, a1 = Gh[i][1] / det, a2 = Gh[i][2] / det;
        e->G[i][0] = a0 * T[0][0] + a1 * T[1][0];
        e->G[i][1] = a0 * T[0][1] + a1 * T[1][1];
        e->G[i][2] = a0 * (H[0][2] - T[0][0] * H[0][2] - T[0][1] * H[1][2]) +
                     a1 * (H[1][2] - T[1][0] * H[0][2] - T[1][1] * H[1][2]) + a2;
    }
    /* Support: c0 + T⁻¹·(P_k − c0), P_k = H(corner k) (w = λ_k > 0). */
    vmin = INFINITY;
    vmax = -INFINITY;
    for (k = 0; k < 4; ++k) {
        double x = (k == 1 || k == 2) ? 1.0 : -1.0, y = k >= 2 ? 1.0 : -1.0;
        double w = H[2][0] * x + H[2][1] * y + H[2][2];
        double pu = (H[0][0] * x + H[0][1] * y + H[0][2]) / w - H[0][2];
        double pv = (H[1][0] * x + H[1][1] * y + H[1][2]) / w - H[1][2];
        e->V[k][0] = H[0][2] + Ti[0][0] * pu + Ti[0][1] * pv;
        e->V[k][1] = H[1][2] + Ti[1][0] * pu + Ti[1][1] * pv;
        vmin = fmin(vmin, e->V[k][1]);
        vmax = fmax(vmax, e->V[k][1]);
    }
    /* Walked by the level's rows (the hull's rows, hull_row). */
    e->nrows = fp_level_rows_init(&e->lr, c, &e->spans, bn_quad_span_fn, e, lv, 0, u0, v0, vmin, vmax);
    e->spans.n = 0;
    e->fail = 0;
}

/* Row dv's span: the support's hull on that row. */
static double bn_quad_span(const bn_level_geom *e, double dv, double *ilo)
{
    double lo, hi;
    hull_row(e->V, dv, &lo, &hi);
    return row_span(e->lr.u0, lo, hi, ilo);
}

/* bn_quad_span as an fp_span_fn. */
static double bn_quad_span_fn(const void *lg, double dv, double *ilo) { return bn_quad_span((const bn_level_geom *)lg, dv, ilo); }

/* The pass over a quad level (values, and derivatives when asked for):
 * each texel's pulled-back pyramid weight (fp_level_walk's row). */
typedef struct bn_quad_pass {
    fp_pass ps; /* first */
    double G[3][3], wlo, whi;
    int area;
} bn_quad_pass;

static int bn_quad_weight(const void *dp, double du, double dv, double *wp, double *wup, double *wvp)
{
    const bn_quad_pass *d = (const bn_quad_pass *)dp;
    const double(*G)[3] = d->G;
    double gx = 0.0, gy = 0.0, w, W, iw, x, y, wu, wv;
    /* Preimage of the pulled-back point: (X, Y, W) = G·(du, dv, 1)
     * = (x, y, 1)/w. W ≤ 0 (beyond the horizon) only outside the
     * quad, where the pyramid is 0 anyway. */
    W = G[2][0] * du + G[2][1] * dv + G[2][2];
    if (!(W > 0.0)) return 0;
    iw = 1.0 / W;
    x = (G[0][0] * du + G[0][1] * dv + G[0][2]) * iw;
    y = (G[1][0] * du + G[1][1] * dv + G[1][2]) * iw;
    w = pyramid(x, y, &gx, &gy);
    if (w <= 0.0) return 0;
    /* ∂w/∂(x, y) = ∇pyr; ∂x/∂u = (G₀₀ − x·G₂₀)/W etc. (quotient rule on
     * X/W). */
    wu = (gx * (G[0][0] - x * G[2][0]) + gy * (G[1][0] - y * G[2][0])) * iw;
    wv = (gx * (G[0][1] - x * G[2][1]) + gy * (G[1][1] - y * G[2][1])) * iw;
    if (d->area) {
        /* w ← w·m, m = w_h³ (w_h = 1/W clamped): ∇m = 3w_h²·∇w_h,
         * ∇w_h = −(G₂₀, G₂₁)·w_h², 0 where the clamp holds. */
        double wh = iw, m, mu = 0.0, mv = 0.0;
        if (wh < d->wlo) wh = d->wlo;
        else if (wh > d->whi) wh = d->whi;
        else {
            double k4 = -3.0 * wh * wh * wh * wh;
            mu = k4 * G[2][0];
            mv = k4 * G[2][1];
        }
        m = wh * wh * wh;
        wu = m * wu + w * mu;
        wv = m * wv + w * mv;
        w *= m;
    }
    *wp = w;
    *wup = wu;
    *wvp = wv;
    return 1;
}

static void bn_quad_row(void *dp, const unsigned char *p, size_t pitch, int n, double ilo, double dv)
{
    fp_pass_row(dp, bn_quad_weight, p, pitch, n, ilo, dv);
}

static double bn_quad_level(const sample_ctx *c, const void *gp, int lv, fp_accum *acc, int count_only)
{
    const bn_geom *g = (const bn_geom *)gp;
    const double cap = (double)SAMPLE_MAX_FOOTPRINT_TEXELS;
    bn_level_geom *e = &g->memo[lv & 1];
    float tx[SAMPLE_MAX_FOOTPRINT_TEXELS][4]; /* one row's texels, where decoded */
    bn_quad_pass d;

    if (e->lv != lv) bn_quad_setup(c, g, lv, e);
    if (e->fail || !(e->nrows <= cap)) return INFINITY;
    if (count_only) return fp_count_rows(&e->lr, &e->spans, cap);
    /* Area weighting (SAMPLE_OPT_BN_AREA_WEIGHT): the DESIGN §8 truth is
     * ∫ pyr(x, y)·T(H(x, y)) dx dy = ∫ pyr(H⁻¹(u))·T(u) / |det DH| du, so
     * each texel's weight is divided by |det DH| at its preimage. For a
     * homography det DH(x, y) = det(H)/w³ (w the homogeneous coordinate),
     * so with w = 1 at the centre the factor |det DH(0, 0)|/|det DH| is w³:
     * no division, and the constant det(H) cancels. w is affine, so on the
     * square it lies between its corner values [wlo, whi]; the pulled-back
     * points with nonzero weight lie in the quad, so the clamp to that
     * range (|det DH| to its range on the quad) only guards rounding. The
     * entry keeps (whi/wlo)³ ≤ 2²⁰, so weights span at most 2²⁰. */
    d.area = (c->smp->options & SAMPLE_OPT_BN_AREA_WEIGHT) != 0;
    memcpy(d.G, e->G, sizeof d.G);
    d.wlo = g->wlo;
    d.whi = g->whi;
    return fp_pass_run(&d.ps, &e->lr, tx, acc, e->ku, e->kv, bn_quad_row);
}

/* ---- Entry --------------------------------------------------------------- */

/* The projective map through the corners. A homography taking the screen
 * square's corners c_k to the corners P_k maps c_k to λ_k·(P_k, 1), and the
 * square's c0 + c2 = c1 + c3 (homogeneous, weight 1) forces
 * λ0·P̃0 + λ2·P̃2 = λ1·P̃1 + λ3·P̃3: the point where the diagonals meet.
 * Solving by Cramer's rule, λ_k ∝ the signed area of the triangle of the
 * other three corners, i.e. of the turn at the opposite corner k + 2. The
 * λ_k are w at the corners, so w > 0 on the whole square (w is affine) iff
 * all four turns share a sign: iff the quad is strictly convex (either
 * orientation; mirrored quads are fine). Bow-ties, darts and zero-area
 * quads — not the image of a square seen from one side of the horizon —
 * return 0. With Σλ = 4 (w = 1 at the centre), H's columns are
 *   h_x = (λ1P̃1 + λ2P̃2 − λ0P̃0 − λ3P̃3)/4, h_y = (λ2P̃2 + λ3P̃3 − λ0P̃0 − λ1P̃1)/4,
 *   h_1 = Σ λ_k·P̃_k / 4,
 * which for a parallelogram (all λ = 1) is the Jacobian's affine map. */
static int projective(const sample_quad *q, bn_geom *g)
{
    double ms = 0.0, mt = 0.0, P[4][2], turn[4], lam[4], sum = 0.0, cs = 0.0, ct = 0.0;
    int k, pos = 0, neg = 0;
    for (k = 0; k < 4; ++k) {
        ms += 0.25 * q->st[k][0];
        mt += 0.25 * q->st[k][1];
    }
    /* Relative to the corner mean first (rounding), re-centred below. */
    for (k = 0; k < 4; ++k) {
        P[k][0] = (double)q->st[k][0] - ms;
        P[k][1] = (double)q->st[k][1] - mt;
    }
    for (k = 0; k < 4; ++k) {
        const double *a = P[(k + 3) & 3], *b = P[k], *cc = P[(k + 1) & 3];
        double e1[2] = {b[0] - a[0], b[1] - a[1]}, e2[2] = {cc[0] - b[0], cc[1] - b[1]};
        turn[k] = cross2(e1, e2);
        pos += turn[k] > 0.0;
        neg += turn[k] < 0.0;
        sum += turn[k];
    }
    if (pos != 4 && neg != 4) return 0;
    for (k = 0; k < 4; ++k) {
        lam[k] = 4.0 * turn[(k + 2) & 3] / sum;
        if (!(lam[k] > 0.0 && lam[k] < INFINITY)) return 0; /* underflow, overflow */
        cs += 0.25 * lam[k] * P[k][0];
        ct += 0.25 * lam[k] * P[k][1];
    }
    /* Centre: H(0, 0), the meeting point of the diagonals — for a plane
     * seen by a pinhole camera, the exact image of the pixel centre. */
    g->s = (float)(ms + cs);
    g->t = (float)(mt + ct);
    for (k = 0; k < 4; ++k) {
        P[k][0] = (double)q->st[k][0] - g->s;
        P[k][1] = (double)q->st[k][1] - g->t;
    }
    for (k = 0; k < 2; ++k) {
        g->H[k][0] = 0.25 * (lam[1] * P[1][k] + lam[2] * P[2][k] - lam[0] * P[0][k] - lam[3] * P[3][k]);
        g->H[k][1] = 0.25 * (lam[2] * P[2][k] + lam[3] * P[3][k] - lam[0] * P[0][k] - lam[1] * P[1][k]);
        g->H[k][2] = 0.25 * (lam[0] * P[0][k] + lam[1] * P[1][k] + lam[2] * P[2][k] + lam[3] * P[3][k]);
    }
    g->H[2][0] = 0.25 * (lam[1] + lam[2] - lam[0] - lam[3]);
    g->H[2][1] = 0.25 * (lam[2] + lam[3] - lam[0] - lam[1]);
    g->H[2][2] = 1.0;
    /* Centre Jacobian ∂(U/w)/∂(x, y) at (0, 0), where w = 1. */
    for (k = 0; k < 2; ++k) {
        g->J[k][0] = g->H[k][0] - g->H[k][2] * g->H[2][0];
        g->J[k][1] = g->H[k][1] - g->H[k][2] * g->H[2][1];
    }
    g->wlo = fmin(fmin(lam[0], lam[1]), fmin(lam[2], lam[3]));
    g->whi = fmax(fmax(lam[0], lam[1]), fmax(lam[2], lam[3]));
    return 1;
}

/* A plan's geometry: the query's, and its two levels' memos. */
typedef struct bn_plan_geom {
    bn_geom g;
    bn_level_geom memo[2];
} bn_plan_geom;
_Static_assert(sizeof(bn_plan_geom) <= FP_PLAN_BYTES, "FP_PLAN_BYTES too small for Blinn-Newell");

void ls_fp_blinn_newell_plan(const sample_ctx *c, const sample_query *q, const sample_quad *corners, float call_bias,
                          fp_plan *pl)
{
    const struct sample_level *B = &c->tex->level[c->base];
    bn_plan_geom *pg = (bn_plan_geom *)(void *)pl->geom.bytes;
    bn_geom *g = &pg->g;
    double Jb[2][2];
    int quad = 0, k;
    pg->memo[0].lv = pg->memo[1].lv = -1;
    g->memo = pg->memo;
    g->s = q->s;
    g->t = q->t;
    fp_query_jacobian(q, g->J);
    if (corners) {
        quad = projective(corners, g);
        /* |det DH| ∝ 1/w³ varies over the quad by (whi/wlo)³; beyond 2²⁰
         * (a corner within about a pixel of the horizon) the quad is
         * filtered as its centre parallelogram, which stays exact in centre
         * and centre Jacobian. */
        if (quad && !(g->whi * g->whi * g->whi <= 0x1p20 * (g->wlo * g->wlo * g->wlo))) quad = -1;
    }
    if (corners && !quad) {
        /* Not a projective image of the square (bow-tie, dart, zero area,
         * non-finite): the parallelogram of the bilinear centre Jacobian
         * about the corner mean, a defined, bounded result. */
        double ms = 0.0, mt = 0.0, P[4][2];
        for (k = 0; k < 4; ++k) {
            ms += 0.25 * corners->st[k][0];
            mt += 0.25 * corners->st[k][1];
        }
        g->s = (float)ms;
        g->t = (float)mt;
        for (k = 0; k < 4; ++k) {
            P[k][0] = (double)corners->st[k][0] - g->s;
            P[k][1] = (double)corners->st[k][1] - g->t;
        }
        g->J[0][0] = 0.25 * (P[1][0] + P[2][0] - P[0][0] - P[3][0]);
        g->J[0][1] = 0.25 * (P[2][0] + P[3][0] - P[0][0] - P[1][0]);
        g->J[1][0] = 0.25 * (P[1][1] + P[2][1] - P[0][1] - P[3][1]);
        g->J[1][1] = 0.25 * (P[2][1] + P[3][1] - P[0][1] - P[1][1]);
    }
    /* Level choice from the minor semi-axis in base texels (after the
     * eccentricity clamp, which also decides whether a quad stays a quad). */
    Jb[0][0] = g->J[0][0] * B->w;
    Jb[0][1] = g->J[0][1] * B->w;
    Jb[1][0] = g->J[1][0] * B->h;
    Jb[1][1] = g->J[1][1] * B->h;
    ls_fp_shape_of(Jb, &g->base);
    if (quad == 1 && (g->base.clamped || !(g->base.s[1] > 0.0))) quad = 0;
    ls_fp_run_count(c, g, quad == 1 ? bn_quad_level : bn_affine_level, g->base.s[1], g->s, g->t, call_bias,
                 &pl->rs);
}

uint32_t ls_fp_blinn_newell(const sample_ctx *c, const sample_query *q, const sample_quad *corners,
                         float call_bias, float out[4], float dds[4], float ddt[4],
                         sample_stats *st)
{
    fp_plan pl;
    ls_fp_blinn_newell_plan(c, q, corners, call_bias, &pl);
    if (c->env == LS_ENV_CUBE && c->q3) return ls_fp_cube_read(c, call_bias, &pl, out, dds, ddt, st);
    return ls_fp_run_read(c, &pl.rs, out, dds, ddt, st);
}
