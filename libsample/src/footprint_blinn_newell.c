/*
 * Blinn–Newell (1976) pyramid-weighted quadrilateral (DESIGN §7,
 * doc/footprint-filters.md).
 *
 * The 2 × 2-pixel region around the pixel, screen offsets (x, y) ∈ [−1, 1]²,
 * maps into texture space by the Jacobian (a parallelogram) or by the four
 * exact corners (a bilinear quadrilateral). A texel centre c is weighted by
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
#include "internal.h"

typedef struct bn_geom {
    float s, t;      /* centre of the footprint (normalized) */
    double J[2][2];  /* rows (s, t), columns (x, y); one pixel, normalized */
    double P[4][2];  /* corners minus the centre (normalized), quad mode */
} bn_geom;

/* w = (1 − |x|)(1 − |y|) on the open square and its gradient; at a crease
 * the gradient is the average of both sides (sign 0). */
static double pyramid(double x, double y, double *gx, double *gy)
{
    double ax = fabs(x), ay = fabs(y);
    if (ax >= 1.0 || ay >= 1.0) return 0.0;
    *gx = -(double)((x > 0.0) - (x < 0.0)) * (1.0 - ay);
    *gy = -(double)((y > 0.0) - (y < 0.0)) * (1.0 - ax);
    return (1.0 - ax) * (1.0 - ay);
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
    a = ceil(u0 + lo);
    b = floor(u0 + hi);
    *ilo = a;
    return b >= a ? b - a + 1.0 : 0.0;
}

/* ---- Parallelogram (Jacobian) footprint --------------------------------- */

static double bn_affine_level(const sample_ctx *c, const void *gp, int lv, fp_accum *acc,
                              int count_only)
{
    const bn_geom *g = (const bn_geom *)gp;
    const struct sample_level *L = &c->tex->level[lv];
    const double cap = (double)SAMPLE_MAX_FOOTPRINT_TEXELS;
    double u0, v0, J[2][2], Jw[2][2], M[2][2], s0, s1, ext, jlo, nrows, total = 0.0, ku, kv;
    int fs, ft, r, i, k;
    fp_svd d;

    fp_center(c, lv, g->s, g->t, &u0, &v0, &fs, &ft);
    fp_level_jacobian(c, lv, g->J, fs, ft, J);
    fp_svd2(J[0][0], J[0][1], J[1][0], J[1][1], &d);
    fp_clamp_eccentricity(&d);
    /* Unit-variance widening (file comment); M = J′⁻¹ = V·diag(1/σ′)·Uᵀ. */
    s0 = sqrt(d.s[0] * d.s[0] + 1.0);
    s1 = sqrt(d.s[1] * d.s[1] + 1.0);
    fp_svd_compose(&d, s0, s1, Jw);
    for (i = 0; i < 2; ++i)
        for (k = 0; k < 2; ++k) M[i][k] = d.V[i][0] * d.U[k][0] / s0 + d.V[i][1] * d.U[k][1] / s1;
    /* ∂u0/∂s (negative on a mirrored axis). */
    ku = fs ? -(double)L->w : (double)L->w;
    kv = ft ? -(double)L->h : (double)L->h;

    /* Rows: the parallelogram J′·[−1, 1]² spans |J′₁₀| + |J′₁₁| in v. */
    ext = fabs(Jw[1][0]) + fabs(Jw[1][1]);
    jlo = ceil(v0 - ext);
    nrows = floor(v0 + ext) - jlo + 1.0;
    if (!(nrows <= cap)) return INFINITY;
    for (r = 0; r < (int)nrows; ++r) {
        double j = jlo + r, dv = j - v0, lo = -INFINITY, hi = INFINITY, ilo = 0.0, ncol;
        slab(M[0][0], M[0][1] * dv, &lo, &hi);
        slab(M[1][0], M[1][1] * dv, &lo, &hi);
        ncol = row_span(u0, lo, hi, &ilo);
        if (count_only) {
            total += ncol;
            if (total > cap) return INFINITY;
            continue;
        }
        if (ncol > cap) return total; /* unreachable after a successful count */
        for (k = 0; k < (int)ncol; ++k) {
            double ii = ilo + k, du = ii - u0, gx = 0.0, gy = 0.0, w;
            float T[4];
            w = pyramid(M[0][0] * du + M[0][1] * dv, M[1][0] * du + M[1][1] * dv, &gx, &gy);
            if (w <= 0.0) continue;
            ctx_texel(c, lv, ii, j, 1, T);
            /* w depends on c − u0: ∂w/∂u0 = −(gx·M₀₀ + gy·M₁₀). */
            fp_accum_add(acc, w, -(gx * M[0][0] + gy * M[1][0]) * ku, -(gx * M[0][1] + gy * M[1][1]) * kv, T);
            total += 1.0;
        }
    }
    return total;
}

/* ---- General quadrilateral (exact corners) ------------------------------ */

/* P(x, y) = bilinear interpolation of the corners d[0..3] at screen offsets
 * (−1,−1), (+1,−1), (+1,+1), (−1,+1); a = (x + 1)/2, b = (y + 1)/2. */
static void bil(double d[4][2], double a, double b, double p[2])
{
    int k;
    for (k = 0; k < 2; ++k)
        p[k] = d[0][k] + (d[1][k] - d[0][k]) * a + (d[3][k] - d[0][k]) * b +
               (d[0][k] - d[1][k] + d[2][k] - d[3][k]) * a * b;
}

static double cross2(const double a[2], const double b[2]) { return a[0] * b[1] - a[1] * b[0]; }

/* Inverse of the bilinear map, extended beyond the quad: h − d0 = e·a + f·b
 * + g·a·b gives, crossing with (e + g·b), the quadratic
 * (g × f)·b² + (h × g + e × f)·b + h × e = 0. Of its (up to) two roots the
 * one nearer the quad is the preimage. Returns 0 if there is none (a point
 * beyond a fold of the extended map, which the filter weights 0). */
static int bil_inverse(double d[4][2], const double q[2], double *x, double *y,
                       double D[2][2])
{
    double e[2] = {d[1][0] - d[0][0], d[1][1] - d[0][1]};
    double f[2] = {d[3][0] - d[0][0], d[3][1] - d[0][1]};
    double g[2] = {d[0][0] - d[1][0] + d[2][0] - d[3][0], d[0][1] - d[1][1] + d[2][1] - d[3][1]};
    double h[2] = {q[0] - d[0][0], q[1] - d[0][1]};
    double k2 = cross2(g, f), k1 = cross2(h, g) + cross2(e, f), k0 = cross2(h, e);
    double disc = k1 * k1 - 4.0 * k2 * k0, qq, cand[2], best = INFINITY;
    int n = 0, m, found = 0;
    if (disc < 0.0) return 0;
    /* Numerically stable roots (no cancellation in −k1 ± √disc). */
    qq = -0.5 * (k1 + (k1 < 0.0 ? -sqrt(disc) : sqrt(disc)));
    if (qq != 0.0) cand[n++] = k0 / qq;
    if (k2 != 0.0) cand[n++] = qq / k2;
    for (m = 0; m < n; ++m) {
        double b = cand[m], eb[2] = {e[0] + g[0] * b, e[1] + g[1] * b};
        double den = eb[0] * eb[0] + eb[1] * eb[1], a, xx, yy, dist;
        if (!(den > 0.0)) continue;
        a = ((h[0] - f[0] * b) * eb[0] + (h[1] - f[1] * b) * eb[1]) / den;
        xx = 2.0 * a - 1.0;
        yy = 2.0 * b - 1.0;
        dist = fmax(fabs(xx), fabs(yy));
        if (dist < best) {
            best = dist;
            *x = xx;
            *y = yy;
            /* ∂P/∂x = ½(e + g·b), ∂P/∂y = ½(f + g·a): columns of D. */
            D[0][0] = 0.5 * eb[0];
            D[1][0] = 0.5 * eb[1];
            D[0][1] = 0.5 * (f[0] + g[0] * a);
            D[1][1] = 0.5 * (f[1] + g[1] * a);
            found = 1;
        }
    }
    return found;
}

/* Row interval of the convex hull of four points (all six segments: the
 * hull's boundary is among them and each lies inside it). */
static void hull_row(double H[4][2], double dv, double *lo, double *hi)
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

static double bn_quad_level(const sample_ctx *c, const void *gp, int lv, fp_accum *acc, int count_only)
{
    const bn_geom *g = (const bn_geom *)gp;
    const struct sample_level *L = &c->tex->level[lv];
    const double cap = (double)SAMPLE_MAX_FOOTPRINT_TEXELS;
    double u0, v0, ku, kv, d[4][2], H[4][2], Si[2][2], S[2][2], mx, my, vmin, vmax, jlo, nrows;
    double total = 0.0, dlo = 0.0, dhi = 0.0, dref = 0.0, dgx = 0.0, dgy = 0.0, dsg = 1.0;
    int fs, ft, r, k, i, area = 0;
    fp_svd sv;

    fp_center(c, lv, g->s, g->t, &u0, &v0, &fs, &ft);
    ku = fs ? -(double)L->w : (double)L->w;
    kv = ft ? -(double)L->h : (double)L->h;
    for (k = 0; k < 4; ++k) {
        d[k][0] = g->P[k][0] * ku;
        d[k][1] = g->P[k][1] * kv;
    }
    /* Widening in screen space: at the centre P ≈ J·(x, y), and J′ = J·S
     * with S = V·diag(√(σ² + 1)/σ)·Vᵀ, so the weight is pyr(S⁻¹·(x, y)); for
     * a parallelogram this is exactly the Jacobian mode. σ > 0: the caller
     * sends only strictly convex, not too eccentric quads here. */
    fp_svd2((d[1][0] + d[2][0] - d[0][0] - d[3][0]) * 0.25, (d[2][0] + d[3][0] - d[0][0] - d[1][0]) * 0.25,
            (d[1][1] + d[2][1] - d[0][1] - d[3][1]) * 0.25, (d[2][1] + d[3][1] - d[0][1] - d[1][1]) * 0.25, &sv);
    if (!(sv.s[1] > 0.0)) return INFINITY;
    for (i = 0; i < 2; ++i)
        for (k = 0; k < 2; ++k) {
            double f0 = sqrt(sv.s[0] * sv.s[0] + 1.0) / sv.s[0], f1 = sqrt(sv.s[1] * sv.s[1] + 1.0) / sv.s[1];
            S[i][k] = sv.V[i][0] * f0 * sv.V[k][0] + sv.V[i][1] * f1 * sv.V[k][1];
            Si[i][k] = sv.V[i][0] / f0 * sv.V[k][0] + sv.V[i][1] / f1 * sv.V[k][1];
        }
    /* The widened support S·[−1, 1]² lies in [−mx, mx] × [−my, my], whose
     * bilinear image lies in the convex hull of its four corner images. */
    mx = fabs(S[0][0]) + fabs(S[0][1]);
    my = fabs(S[1][0]) + fabs(S[1][1]);
    bil(d, 0.5 * (1.0 - mx), 0.5 * (1.0 - my), H[0]);
    bil(d, 0.5 * (1.0 + mx), 0.5 * (1.0 - my), H[1]);
    bil(d, 0.5 * (1.0 + mx), 0.5 * (1.0 + my), H[2]);
    bil(d, 0.5 * (1.0 - mx), 0.5 * (1.0 + my), H[3]);
    vmin = fmin(fmin(H[0][1], H[1][1]), fmin(H[2][1], H[3][1]));
    vmax = fmax(fmax(H[0][1], H[1][1]), fmax(H[2][1], H[3][1]));
    jlo = ceil(v0 + vmin);
    nrows = floor(v0 + vmax) - jlo + 1.0;
    if (!(nrows <= cap)) return INFINITY;
    if (!count_only && (c->smp->options & SAMPLE_OPT_BN_AREA_WEIGHT)) {
        /* Area weighting (SAMPLE_OPT_BN_AREA_WEIGHT): the DESIGN §8 truth is
         * ∫ pyr(x, y)·T(P(x, y)) dx dy = ∫ pyr(P⁻¹(u))·T(u) / |det DP| du,
         * so each texel's weight is divided by |det DP| at its preimage.
         * With e = d1 − d0, f = d3 − d0, g = d0 − d1 + d2 − d3 and
         * DP = ½[e + g·b | f + g·a], det DP = ¼(e×f + a·e×g + b·g×f) (the
         * g×g term vanishes): affine in (x, y), so over the quad its
         * extremes are at the corners, where it is ¼ of the corner's edge
         * cross product — one sign for a strictly convex quad. Beyond the
         * quad (the widened support) the extension may approach 0 or change
         * sign, so |det| is clamped to the range it takes on the quad, and
         * that range's floor to 2⁻²⁰ of its top (rounding cannot then make
         * a weight infinite). dref (|det| at the centre) only scales. */
        double e[2] = {d[1][0] - d[0][0], d[1][1] - d[0][1]}, f[2] = {d[3][0] - d[0][0], d[3][1] - d[0][1]};
        double gg[2] = {d[0][0] - d[1][0] + d[2][0] - d[3][0], d[0][1] - d[1][1] + d[2][1] - d[3][1]};
        double A0 = 0.25 * cross2(e, f), Aa = 0.25 * cross2(e, gg), Ab = 0.25 * cross2(gg, f);
        double dc[4];
        dsg = A0 + 0.5 * (Aa + Ab) < 0.0 ? -1.0 : 1.0;
        dc[0] = dsg * A0;
        dc[1] = dsg * (A0 + Aa);
        dc[2] = dsg * (A0 + Aa + Ab);
        dc[3] = dsg * (A0 + Ab);
        dlo = fmin(fmin(dc[0], dc[1]), fmin(dc[2], dc[3]));
        dhi = fmax(fmax(dc[0], dc[1]), fmax(dc[2], dc[3]));
        dlo = fmax(dlo, dhi * 0x1p-20);
        dref = dsg * (A0 + 0.5 * (Aa + Ab));
        /* ∂(dsg·det)/∂x = dsg·Aa/2 (a = (x + 1)/2), likewise y. */
        dgx = 0.5 * dsg * Aa;
        dgy = 0.5 * dsg * Ab;
        area = dhi > 0.0 && dref > 0.0; /* else (no area at all) unweighted */
    }
    for (r = 0; r < (int)nrows; ++r) {
        double j = jlo + r, dv = j - v0, lo, hi, ilo = 0.0, ncol;
        hull_row(H, dv, &lo, &hi);
        ncol = row_span(u0, lo, hi, &ilo);
        if (count_only) {
            total += ncol;
            if (total > cap) return INFINITY;
            continue;
        }
        if (ncol > cap) return total; /* unreachable after a successful count */
        for (k = 0; k < (int)ncol; ++k) {
            double ii = ilo + k, q[2] = {ii - u0, dv}, x, y, D[2][2], gx = 0.0, gy = 0.0, w, det, ax, ay;
            float T[4];
            if (!bil_inverse(d, q, &x, &y, D)) continue;
            w = pyramid(Si[0][0] * x + Si[0][1] * y, Si[1][0] * x + Si[1][1] * y, &gx, &gy);
            if (w <= 0.0) continue;
            det = D[0][0] * D[1][1] - D[0][1] * D[1][0];
            if (det == 0.0) continue;
            ctx_texel(c, lv, ii, j, 1, T);
            /* ∂w/∂q = ∇pyr·S⁻¹·D⁻¹; the centre moves opposite to q. */
            ax = gx * Si[0][0] + gy * Si[1][0];
            ay = gx * Si[0][1] + gy * Si[1][1];
            if (area) {
                /* w ← w·m, m = dref/|det|: ∇(w·m) = m·(∇w − w·∇|det|/|det|),
                 * the last term 0 where the clamp holds |det| fixed; past
                 * a fold (sign opposite to the centre's) the floor holds. */
                double dd = dsg * det, m, hx = 0.0, hy = 0.0;
                if (dd < dlo) dd = dlo;
                else if (dd > dhi) dd = dhi;
                else hx = dgx, hy = dgy;
                m = dref / dd;
                ax = m * (ax - w * hx / dd);
                ay = m * (ay - w * hy / dd);
                w *= m;
            }
            fp_accum_add(acc, w, -((ax * D[1][1] - ay * D[1][0]) / det) * ku,
                         -((-ax * D[0][1] + ay * D[0][0]) / det) * kv, T);
            total += 1.0;
        }
    }
    return total;
}

/* ---- Entry --------------------------------------------------------------- */

/* A quad is filtered as a quad only when strictly convex (the four turns of
 * its boundary share one sign: mirrored, "inside-out" quads are fine) and
 * its centre Jacobian is within the eccentricity clamp. Anything else —
 * zero area, a bow-tie, a dart, a sliver — is filtered as the parallelogram
 * of its centre Jacobian, which has a defined, bounded result. */
static int quad_convex(double P[4][2])
{
    int k, pos = 0, neg = 0;
    for (k = 0; k < 4; ++k) {
        const double *a = P[k], *b = P[(k + 1) & 3], *cc = P[(k + 2) & 3];
        double e1[2] = {b[0] - a[0], b[1] - a[1]}, e2[2] = {cc[0] - b[0], cc[1] - b[1]};
        double z = cross2(e1, e2);
        pos += z > 0.0;
        neg += z < 0.0;
    }
    return pos == 4 || neg == 4;
}

uint32_t fp_blinn_newell(const sample_ctx *c, const sample_query *q, const sample_quad *corners,
                         float call_bias, float out[4], float dds[4], float ddt[4],
                         sample_stats *st)
{
    const struct sample_level *B = &c->tex->level[c->base];
    bn_geom g;
    fp_svd d;
    int quad = 0, k;
    g.s = q->s;
    g.t = q->t;
    g.J[0][0] = q->dsdx;
    g.J[0][1] = q->dsdy;
    g.J[1][0] = q->dtdx;
    g.J[1][1] = q->dtdy;
    if (corners) {
        /* The quad's own centre and centre Jacobian replace the query's. */
        double ms = 0.0, mt = 0.0;
        for (k = 0; k < 4; ++k) {
            ms += 0.25 * corners->st[k][0];
            mt += 0.25 * corners->st[k][1];
        }
        g.s = (float)ms;
        g.t = (float)mt;
        for (k = 0; k < 4; ++k) {
            g.P[k][0] = (double)corners->st[k][0] - g.s;
            g.P[k][1] = (double)corners->st[k][1] - g.t;
        }
        g.J[0][0] = 0.25 * (g.P[1][0] + g.P[2][0] - g.P[0][0] - g.P[3][0]);
        g.J[0][1] = 0.25 * (g.P[2][0] + g.P[3][0] - g.P[0][0] - g.P[1][0]);
        g.J[1][0] = 0.25 * (g.P[1][1] + g.P[2][1] - g.P[0][1] - g.P[3][1]);
        g.J[1][1] = 0.25 * (g.P[2][1] + g.P[3][1] - g.P[0][1] - g.P[1][1]);
        quad = quad_convex(g.P);
    }
    /* Level choice from the minor semi-axis in base texels (after the
     * eccentricity clamp, which also decides whether a quad stays a quad). */
    fp_svd2(g.J[0][0] * B->w, g.J[0][1] * B->w, g.J[1][0] * B->h, g.J[1][1] * B->h, &d);
    if (quad && !(d.s[1] * FP_MAX_ECCENTRICITY >= d.s[0] && d.s[1] > 0.0)) quad = 0;
    fp_clamp_eccentricity(&d);
    return fp_run(c, &g, quad ? bn_quad_level : bn_affine_level, d.s[1], g.s, g.t, call_bias, out,
                  dds, ddt, st);
}
