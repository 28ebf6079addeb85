/*
 * Reconstruction on one level (DESIGN §4, GL 4.6 §8.14.2):
 * NEAREST, LINEAR (bilinear) and CUBIC (Mitchell–Netravali family).
 */
#include "recon.h"

#include <float.h>

/* Mitchell–Netravali (B, C) kernel, Mitchell & Netravali 1988 eq. 8:
 *   k(x) = 1/6 [ (12 − 9B − 6C)|x|³ + (−18 + 12B + 6C)|x|² + (6 − 2B) ]     |x| < 1
 *   k(x) = 1/6 [ (−B − 6C)|x|³ + (6B + 30C)|x|² + (−12B − 48C)|x| + 8B + 24C ] 1 ≤ |x| < 2
 * Catmull–Rom is (0, ½), the cubic B-spline (1, 0), Mitchell (⅓, ⅓). */
static const double cubic_bc[SAMPLE_CUBIC_COUNT][2] = {
    [SAMPLE_CUBIC_CATMULL_ROM] = {0.0, 0.5},
    [SAMPLE_CUBIC_BSPLINE] = {1.0, 0.0},
    [SAMPLE_CUBIC_MITCHELL] = {1.0 / 3.0, 1.0 / 3.0},
};

/* k(x) and k'(x) for x ≥ 0. */
static void kernel(double B, double C, double x, double *k, double *dk)
{
    if (x < 1.0) {
        double a = 12 - 9 * B - 6 * C, b = -18 + 12 * B + 6 * C, c = 6 - 2 * B;
        *k = ((a * x + b) * x * x + c) / 6.0;
        *dk = (3 * a * x + 2 * b) * x / 6.0;
    } else if (x < 2.0) {
        double a = -B - 6 * C, b = 6 * B + 30 * C, c = -12 * B - 48 * C, d = 8 * B + 24 * C;
        *k = (((a * x + b) * x + c) * x + d) / 6.0;
        *dk = ((3 * a * x + 2 * b) * x + c) / 6.0;
    } else {
        *k = 0.0;
        *dk = 0.0;
    }
}

void ls_cubic_weights(sample_cubic kind, float f, double w[4], double dw[4])
{
    /* Taps −1, 0, 1, 2 sit at distances 1 + f, f, 1 − f, 2 − f; the
     * distance grows with f for the first two and shrinks for the others.
     * Evaluated in double so that the weights sum to 1 and reproduce linear
     * ramps to float rounding. */
    const double B = cubic_bc[kind][0], C = cubic_bc[kind][1];
    const double x[4] = {1.0 + f, f, 1.0 - f, 2.0 - f}, sgn[4] = {1, 1, -1, -1};
    double k[4], dk[4];
    int n;
    for (n = 0; n < 4; ++n) kernel(B, C, x[n], &k[n], &dk[n]);
    /* The kernel family is a partition of unity; renormalize the last
     * rounding so that constants come back exactly. */
    k[1] = 1.0 - (k[0] + k[2] + k[3]);
    for (n = 0; n < 4; ++n) {
        w[n] = k[n];
        if (dw) dw[n] = sgn[n] * dk[n];
    }
}

static void zero4(float *v)
{
    if (v) v[0] = v[1] = v[2] = v[3] = 0.0f;
}

static uint32_t recon_nearest(const sample_ctx *c, int lv, float u, float v, float out[4])
{
    /* i = ⌊u⌋, j = ⌊v⌋ (GL 4.6 eq. 8.12). */
    ctx_texel(c, lv, floorf(u), floorf(v), 0, out);
    return 1;
}

static uint32_t recon_linear(const sample_ctx *c, int lv, float u, float v, float out[4],
                             float ddu[4], float ddv[4])
{
    float al, be, i0 = recon_linear_origin(u, &al), j0 = recon_linear_origin(v, &be);
    float T[4][4];
    v4f V[4];
    int k;
    ctx_texel(c, lv, i0, j0, 1, T[0]);
    ctx_texel(c, lv, (double)i0 + 1.0, j0, 1, T[1]);
    ctx_texel(c, lv, i0, (double)j0 + 1.0, 1, T[2]);
    ctx_texel(c, lv, (double)i0 + 1.0, (double)j0 + 1.0, 1, T[3]);
    for (k = 0; k < 4; ++k) V[k] = v4_load(T[k]);
    recon_bilerp(V, al, be, out, ddu, ddv);
    return 4;
}

/* One of the clamp's bounds (cubic_clamp): a value of the bilinear
 * interpolant and its derivatives by u and v (texel units). */
typedef struct clamp_point {
    double v, du, dv;
} clamp_point;

/* The four values of the bilinear interpolant along one line of taps a[0 …
 * 3] (offsets −1 … 2, fraction f) where the window [x − 1, x + 1] meets its
 * knots: the window's ends, x − 1 and x + 1, which lie at fraction f
 * between taps −1, 0 and 1, 2, and the two knots inside, 0 and 1; with
 * each value's derivative along the line. */
static void clamp_line(const clamp_point a[4], double f, clamp_point out[4], int along_u)
{
    int k;
    for (k = 0; k < 2; ++k) {
        const clamp_point *p = &a[2 * k], *q = &a[2 * k + 1];
        clamp_point *e = &out[3 * k];
        e->v = (1.0 - f) * p->v + f * q->v;
        e->du = (1.0 - f) * p->du + f * q->du;
        e->dv = (1.0 - f) * p->dv + f * q->dv;
        if (along_u) e->du = q->v - p->v;
        else e->dv = q->v - p->v;
    }
    out[1] = a[1];
    out[2] = a[2];
}

/* SAMPLE_OPT_CUBIC_CLAMP for channel k: the result is clamped to the range
 * of the bilinear interpolant of the texels over the square of one texel
 * either side of the sample point, [x − 1, x + 1] × [y − 1, y + 1] (x = i0
 * + fu, y = j0 + fv in texel-centre units). That range holds the central
 * 2 × 2 texels (the knots inside the square), so it removes the ringing of
 * Catmull–Rom and Mitchell past a step's own values; and it moves
 * continuously with the sample point — when the 4 × 4 block shifts by a
 * texel at fu = 1 → 0 the square's bounds are the same — so the clamped
 * result is continuous, where a clamp to the central 2 × 2 alone jumps at
 * texel centres (by 1/6 for the B-spline on a step). On each cell of the
 * square the interpolant is bilinear, so its extremes lie at the 4 × 4
 * points where the square's edges and the grid lines inside it cross.
 * Where the result is clamped its derivatives are the bound's. */
static void cubic_clamp(float tx[16][4], int k, float fu, float fv, float *out, float *ddu, float *ddv)
{
    clamp_point row[4][4], col[4], pts[4], line[4], lo, hi;
    int x, y;
    for (y = 0; y < 4; ++y) {
        for (x = 0; x < 4; ++x) line[x] = (clamp_point){tx[4 * y + x][k], 0.0, 0.0};
        clamp_line(line, fu, row[y], 1);
    }
    lo = hi = row[1][1];
    for (x = 0; x < 4; ++x) {
        for (y = 0; y < 4; ++y) col[y] = row[y][x];
        clamp_line(col, fv, pts, 0);
        for (y = 0; y < 4; ++y) {
            if (pts[y].v < lo.v) lo = pts[y];
            if (pts[y].v > hi.v) hi = pts[y];
        }
    }
    if (*out < lo.v || *out > hi.v) {
        const clamp_point *b = *out < lo.v ? &lo : &hi;
        *out = (float)b->v;
        if (ddu) *ddu = (float)b->du;
        if (ddv) *ddv = (float)b->dv;
    }
}

void ls_recon_cubic_combine(float tx[16][4], const double wx[4], const double wy[4],
                         const double dwx[4], const double dwy[4], int clamp, float fu, float fv,
                         float out[4], float ddu[4], float ddv[4])
{
    /* Separable: each row is first combined across x (with wx, and with dwx
     * for ∂/∂u), then the rows across y — 5 × 16 products instead of 3 × 32,
     * and the derivative sums only when asked for. In double, so that the
     * kernels' exact reproduction of constants and ramps survives. */
    double row[4][4], drow[4][4], acc[4] = {0, 0, 0, 0}, au[4] = {0, 0, 0, 0}, av[4] = {0, 0, 0, 0};
    int x, y, k, deriv = ddu || ddv;
    for (y = 0; y < 4; ++y) {
        for (k = 0; k < 4; ++k) {
            double r = 0.0, dr = 0.0;
            for (x = 0; x < 4; ++x) {
                r += wx[x] * tx[4 * y + x][k];
                if (deriv) dr += dwx[x] * tx[4 * y + x][k];
            }
            row[y][k] = r;
            drow[y][k] = dr;
        }
    }
    for (y = 0; y < 4; ++y)
        for (k = 0; k < 4; ++k) {
            acc[k] += wy[y] * row[y][k];
            if (deriv) {
                au[k] += wy[y] * drow[y][k];
                av[k] += dwy[y] * row[y][k];
            }
        }
    for (k = 0; k < 4; ++k) {
        out[k] = (float)acc[k];
        if (ddu) ddu[k] = (float)au[k];
        if (ddv) ddv[k] = (float)av[k];
        if (clamp) cubic_clamp(tx, k, fu, fv, &out[k], ddu ? &ddu[k] : NULL, ddv ? &ddv[k] : NULL);
    }
}

static uint32_t recon_cubic(const sample_ctx *c, int lv, float u, float v, float out[4],
                            float ddu[4], float ddv[4])
{
    float al, be, i0 = recon_linear_origin(u, &al), j0 = recon_linear_origin(v, &be);
    double wx[4], wy[4], dwx[4], dwy[4];
    float T[16][4];
    int x, y;
    ls_cubic_weights(c->smp->cubic, al, wx, dwx);
    ls_cubic_weights(c->smp->cubic, be, wy, dwy);
    for (y = 0; y < 4; ++y)
        for (x = 0; x < 4; ++x)
            ctx_texel(c, lv, (double)i0 + (x - 1), (double)j0 + (y - 1), 1, T[4 * y + x]);
    ls_recon_cubic_combine(T, wx, wy, dwx, dwy, (c->smp->options & SAMPLE_OPT_CUBIC_CLAMP) != 0, al, be,
                           out, ddu, ddv);
    return 16;
}

uint32_t ls_recon_level(const sample_ctx *c, int lv, sample_filter kind, float s, float t,
                     float out[4], float dds[4], float ddt[4])
{
    const struct sample_level *L = &c->tex->level[lv];
    float u = recon_texel_coord(c->smp->wrap_s, s, L->w);
    float v = recon_texel_coord(c->smp->wrap_t, t, L->h);
    uint32_t n;
    int k;
    switch (kind) {
    case SAMPLE_NEAREST:
        zero4(dds);
        zero4(ddt);
        return recon_nearest(c, lv, u, v, out);
    case SAMPLE_CUBIC:
        n = recon_cubic(c, lv, u, v, out, dds, ddt);
        break;
    case SAMPLE_LINEAR:
    default:
        n = recon_linear(c, lv, u, v, out, dds, ddt);
        break;
    }
    /* ∂/∂s = ∂/∂u · w (before any mirror-clamp fold, which the derivative
     * ignores). */
    for (k = 0; k < 4; ++k) {
        if (dds) dds[k] *= (float)L->w;
        if (ddt) ddt[k] *= (float)L->h;
    }
    return n;
}
