/*
 * The measurement (doc/frequency-tests.md §3): sample the complex grating
 * e^{2πi k·u} (cos in channel 0, sin in channel 1) on a small screen at
 * many offsets and fit its known frequency by least squares.
 *
 * Why the fit is unbiased. A filter that is linear in the texels and
 * periodic on the texel lattice of each level it reads turns the grating
 * e^{2πi k·p} into Σ_n c_n e^{2πi (k + n)·p}, n over the reciprocal lattice
 * of those levels: n = 0 is the coherent response H = c_0, the rest are
 * images of the texel grid. The least-squares fit of z ≈ H·e^{iφ}, φ the
 * grating's phase at each sample's exact position, is Ĥ = mean(z·e^{−iφ})
 * (|e^{iφ}| = 1), which holds c_0 exactly plus c_n·mean(e^{2πi n·p}) for
 * each image; with every offset uniform on the torus the expectation of
 * each of those is 0, so Ĥ is unbiased, and the standard error reported
 * says how far one run may be off. A real grating would instead fold the
 * image n = −2k onto the conjugate term wherever 2k is a lattice vector
 * (a level's Nyquist frequency), making the result depend on where the
 * texel centres fall on the wave; the complex grating is the same linear
 * system averaged over that phase. Above Nyquist the pixels see the same
 * samples as a sinusoid at the alias frequency F − round(F) with the same
 * phase φ, so the one fit measures leakage there too.
 */
#define _POSIX_C_SOURCE 199309L
#include "freq.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

void fq_layout_init(fq_layout *l, double m, double r)
{
    l->m = m;
    l->r = r;
    l->width = 16;
    l->rows = 1;
    l->phases = 64;
    l->subtexel = -1.0;
    l->lattice = 1;
    l->seed = 1;
}

/* splitmix64: a fixed-seed generator, so every run measures the same
 * offsets and the outputs are reproducible bit for bit. */
static double next_uniform(uint64_t *state)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

static double frac1(double x) { return x - floor(x); }

/* x mod n in [0, n). */
static double wrap_n(double x, double n)
{
    double r = x - n * floor(x / n);
    return r >= n ? 0.0 : r;
}

int fq_layout_queries(const fq_wave *w, const fq_layout *l, sample_query **queries,
                      double **phase, size_t *count)
{
    size_t n = (size_t)l->width * (size_t)l->rows * (size_t)l->phases, k = 0;
    double N = w->n, c = cos(w->theta), s = sin(w->theta);
    uint64_t state = l->seed;
    double xi_u, xi_v;
    sample_query *q;
    double *ph;
    int j, x, y;
    *queries = NULL;
    *phase = NULL;
    *count = 0;
    if (n == 0) return -1;
    q = (sample_query *)malloc(n * sizeof *q);
    ph = (double *)malloc(n * sizeof *ph);
    if (!q || !ph) {
        free(q);
        free(ph);
        return -1;
    }
    /* One uniform shift ξ for the whole set; the offsets are the R2
     * low-discrepancy sequence (Roberts 2018: multiples of 1/φ₂ and 1/φ₂²,
     * φ₂ the plastic number) shifted by ξ mod 1. Each offset is then
     * uniform on the torus (what unbiasedness needs) while the set covers
     * the texel cells of every level far more evenly than independent
     * draws, so the image terms cancel to O(log P / P), not O(1/√P). */
    xi_u = next_uniform(&state);
    xi_v = next_uniform(&state);
    for (j = 0; j < l->phases; ++j) {
        double ou = N * frac1(xi_u + j * 0.75487766624669276),
               ov = N * frac1(xi_v + j * 0.56984029099805327);
        if (l->subtexel >= 0.0) {
            double L = l->lattice > 0 ? l->lattice : 1;
            ou = L * floor(ou / L) + l->subtexel;
            ov = L * floor(ov / L) + l->subtexel;
        }
        for (y = 0; y < l->rows; ++y)
            for (x = 0; x < l->width; ++x, ++k) {
                double a = l->m * x, b = l->m * l->r * y;
                double u = wrap_n(ou + a * c - b * s, N), v = wrap_n(ov + a * s + b * c, N);
                float sf = (float)(u / N), tf = (float)(v / N);
                double uf, vf, cyc;
                if (sf >= 1.0f) sf = 0.0f;
                if (tf >= 1.0f) tf = 0.0f;
                q[k].s = sf;
                q[k].t = tf;
                /* Columns m·e1/N and m·r·e2/N (freq.h). */
                q[k].dsdx = (float)(l->m * c / N);
                q[k].dtdx = (float)(l->m * s / N);
                q[k].dsdy = (float)(-l->m * l->r * s / N);
                q[k].dtdy = (float)(l->m * l->r * c / N);
                /* The reference phase at the position the filter actually
                 * got (the float s, t), so rounding of the query is not
                 * counted against the filter. */
                uf = (double)sf * N;
                vf = (double)tf * N;
                cyc = (w->p * uf + w->q * vf) / N;
                ph[k] = 2.0 * FQ_PI * (cyc - floor(cyc));
            }
    }
    *queries = q;
    *phase = ph;
    *count = n;
    return 0;
}

static double now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

int fq_measure(const fq_backend *b, void *ctx, const fq_wave *w, const fq_layout *l,
               fq_result *out, char *err, size_t errlen)
{
    sample_query *q;
    double *ph, texels = 0.0, t0, t1, sr = 0.0, si = 0.0, *hr, *hi, rss = 0.0, var = 0.0;
    size_t n, i, j, per = (size_t)l->width * (size_t)l->rows, P = (size_t)l->phases;
    float *rgba;
    int rc;
    memset(out, 0, sizeof *out);
    if (fq_layout_queries(w, l, &q, &ph, &n) != 0) {
        snprintf(err, errlen, "out of memory for %d x %d x %d queries", l->width, l->rows,
                 l->phases);
        return -1;
    }
    rgba = (float *)malloc(n * 4 * sizeof *rgba);
    hr = (double *)malloc(2 * P * sizeof *hr);
    if (!rgba || !hr) {
        free(q);
        free(ph);
        free(rgba);
        free(hr);
        snprintf(err, errlen, "out of memory for %zu results", n);
        return -1;
    }
    hi = hr + P;
    t0 = now_ns();
    rc = b->sample(ctx, q, n, rgba, &texels, err, errlen);
    t1 = now_ns();
    free(q);
    if (rc != 0) {
        free(ph);
        free(rgba);
        free(hr);
        return -1;
    }
    out->F = w->f * l->m;
    out->alias_F = fabs(out->F - floor(out->F + 0.5));
    out->texels = b->counts_texels ? texels / (double)n : NAN;
    out->ns = (t1 - t0) / (double)n;
    /* Ĥ = mean of z·e^{−iφ}, kept per offset for the standard error. */
    for (j = 0; j < P; ++j) {
        double ar = 0.0, ai = 0.0;
        for (i = j * per; i < (j + 1) * per; ++i) {
            double zr = rgba[4 * i], zi = rgba[4 * i + 1], c = cos(ph[i]), s = sin(ph[i]);
            ar += zr * c + zi * s;
            ai += zi * c - zr * s;
        }
        hr[j] = ar / (double)per;
        hi[j] = ai / (double)per;
        sr += hr[j];
        si += hi[j];
    }
    out->re = sr / (double)P;
    out->im = si / (double)P;
    out->amp = hypot(out->re, out->im);
    for (i = 0; i < n; ++i) {
        double c = cos(ph[i]), s = sin(ph[i]);
        double er = rgba[4 * i] - (out->re * c - out->im * s);
        double ei = rgba[4 * i + 1] - (out->re * s + out->im * c);
        rss += er * er + ei * ei;
    }
    /* Standard error clustered by offset: the residual is the image terms,
     * which repeat from pixel to pixel when m is an integer, so only the
     * offsets are independent; the spread of the per-offset estimates,
     * projected on Ĥ's direction (delta method for |Ĥ|), divided by √P.
     * Conservative with low-discrepancy offsets. */
    for (j = 0; j < P; ++j) {
        double dr = hr[j] - out->re, di = hi[j] - out->im;
        double d = out->amp > 0.0 ? (dr * out->re + di * out->im) / out->amp
                                  : sqrt(0.5 * (dr * dr + di * di));
        var += d * d;
    }
    out->stderr_ = P > 1 ? sqrt(var / ((double)P * (double)(P - 1))) : NAN;
    out->residual = sqrt(rss / (double)n);
    free(ph);
    free(rgba);
    free(hr);
    return 0;
}
