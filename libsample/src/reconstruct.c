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

void ls_recon_cubic_combine(float tx[16][4], const double wx[4], const double wy[4],
                         const double dwx[4], const double dwy[4], int clamp, float out[4],
                         float ddu[4], float ddv[4])
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
        if (clamp) {
            /* Optional overshoot clamp to the central 2×2 range; where it
             * clamps, the result is locally constant. */
            float lo = fminf(fminf(tx[5][k], tx[6][k]), fminf(tx[9][k], tx[10][k]));
            float hi = fmaxf(fmaxf(tx[5][k], tx[6][k]), fmaxf(tx[9][k], tx[10][k]));
            if (out[k] < lo || out[k] > hi) {
                out[k] = out[k] < lo ? lo : hi;
                if (ddu) ddu[k] = 0.0f;
                if (ddv) ddv[k] = 0.0f;
            }
        }
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
    ls_recon_cubic_combine(T, wx, wy, dwx, dwy, (c->smp->options & SAMPLE_OPT_CUBIC_CLAMP) != 0, out,
                        ddu, ddv);
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
