/*
 * The measurement (doc/frequency-tests.md §3): sample a grating on a small
 * screen at many offsets and fit the known frequency by least squares.
 *
 * Why the fit is unbiased. A filter that is linear in the texels and
 * periodic on the texel lattice of each level it reads turns the grating
 * exp(2πi k·p) into Σ_n c_n exp(2πi (k + n)·p), n over the reciprocal
 * lattice of those levels: n = 0 is the coherent response H = c_0, the rest
 * are images of the texel grid. The model c + a·cos φ + b·sin φ, φ the
 * grating's phase at each sample's exact position, holds the n = 0 term
 * exactly (Re(H e^{iφ}) = Re H·cos φ − Im H·sin φ), so least squares
 * returns it without error; each image term carries a factor exp(2πi n·o)
 * relative to it, o the screen offset, whose mean over offsets uniform on the
 * torus is 0, so it adds zero-mean noise, not bias, and the standard error
 * reported says how much. Above Nyquist the pixels see the same samples as a
 * sinusoid at the alias frequency F − round(F) with the same phase φ, so the
 * one fit measures leakage there too.
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
    l->width = 32;
    l->rows = 2;
    l->phases = 16;
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
    for (j = 0; j < l->phases; ++j) {
        double ou, ov;
        /* Normal mode: u stratified over the texture (one stratum per
         * offset), v uniform: each offset is uniform on the torus, which is
         * what makes the image terms average out. */
        double xi = next_uniform(&state), eta = next_uniform(&state);
        ou = N * ((j + xi) / l->phases);
        ov = N * eta;
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

/* Solve the symmetric 3 × 3 system A x = b by Gaussian elimination with
 * partial pivoting, also returning A⁻¹ (for the standard errors). Returns
 * 0, or −1 when A is singular to working precision. */
static int solve3(double A[3][3], const double b[3], double x[3], double inv[3][3])
{
    double M[3][7];
    int i, j, k;
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            M[i][j] = A[i][j];
            M[i][3 + j] = (i == j);
        }
        M[i][6] = b[i];
    }
    for (k = 0; k < 3; ++k) {
        int piv = k;
        double scale = fabs(A[0][0]) + fabs(A[1][1]) + fabs(A[2][2]);
        for (i = k + 1; i < 3; ++i)
            if (fabs(M[i][k]) > fabs(M[piv][k])) piv = i;
        if (!(fabs(M[piv][k]) > 1e-12 * scale)) return -1;
        if (piv != k)
            for (j = 0; j < 7; ++j) {
                double t = M[k][j];
                M[k][j] = M[piv][j];
                M[piv][j] = t;
            }
        for (i = 0; i < 3; ++i) {
            double fac;
            if (i == k) continue;
            fac = M[i][k] / M[k][k];
            for (j = k; j < 7; ++j) M[i][j] -= fac * M[k][j];
        }
    }
    for (i = 0; i < 3; ++i) {
        x[i] = M[i][6] / M[i][i];
        for (j = 0; j < 3; ++j) inv[i][j] = M[i][3 + j] / M[i][i];
    }
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
    double *ph, texels = 0.0, t0, t1;
    double A[3][3] = {{0}}, rhs[3] = {0}, beta[3], inv[3][3], yy = 0.0;
    size_t n, i;
    float *rgba;
    int rc;
    memset(out, 0, sizeof *out);
    if (fq_layout_queries(w, l, &q, &ph, &n) != 0) {
        snprintf(err, errlen, "out of memory for %d x %d x %d queries", l->width, l->rows,
                 l->phases);
        return -1;
    }
    rgba = (float *)malloc(n * 4 * sizeof *rgba);
    if (!rgba) {
        free(q);
        free(ph);
        snprintf(err, errlen, "out of memory for %zu results", n);
        return -1;
    }
    t0 = now_ns();
    rc = b->sample(ctx, q, n, rgba, &texels, err, errlen);
    t1 = now_ns();
    free(q);
    if (rc != 0) {
        free(ph);
        free(rgba);
        return -1;
    }
    out->F = w->f * l->m;
    out->alias_F = fabs(out->F - floor(out->F + 0.5));
    out->texels = b->counts_texels ? texels / (double)n : NAN;
    out->ns = (t1 - t0) / (double)n;
    if (w->p == 0 && w->q == 0) {
        /* The constant texture (1): the response is the mean output. */
        double sum = 0.0, sum2 = 0.0, mean;
        for (i = 0; i < n; ++i) {
            sum += rgba[4 * i];
            sum2 += (double)rgba[4 * i] * rgba[4 * i];
        }
        mean = sum / (double)n;
        out->re = out->amp = mean;
        out->residual = sqrt(2.0 * fmax(0.0, sum2 / (double)n - mean * mean));
        out->stderr_ = out->residual / sqrt(2.0 * (double)n);
        free(ph);
        free(rgba);
        return 0;
    }
    /* Normal equations of y = c + a·cos φ + b·sin φ. */
    for (i = 0; i < n; ++i) {
        double x[3] = {1.0, cos(ph[i]), sin(ph[i])}, y = rgba[4 * i];
        int r, c;
        for (r = 0; r < 3; ++r) {
            for (c = 0; c < 3; ++c) A[r][c] += x[r] * x[c];
            rhs[r] += x[r] * y;
        }
        yy += y * y;
    }
    free(ph);
    free(rgba);
    if (solve3(A, rhs, beta, inv) != 0) {
        snprintf(err, errlen,
                 "degenerate fit at (p, q) = (%d, %d): the offsets do not spread the phase",
                 w->p, w->q);
        return -1;
    }
    {
        /* RSS = yᵀy − βᵀXᵀy for the least-squares β. */
        double rss = fmax(0.0, yy - (beta[0] * rhs[0] + beta[1] * rhs[1] + beta[2] * rhs[2]));
        double s2 = n > 3 ? rss / (double)(n - 3) : 0.0;
        double a = beta[1], bb = beta[2], amp = hypot(a, bb);
        double va = s2 * inv[1][1], vb = s2 * inv[2][2], cab = s2 * inv[1][2];
        out->re = a;
        out->im = -bb;
        out->amp = amp;
        /* Delta method for |H|; at H = 0 the spread of either component. */
        out->stderr_ = amp > 0.0 ? sqrt(fmax(0.0, a * a * va + bb * bb * vb + 2.0 * a * bb * cab)) / amp
                                 : sqrt(0.5 * (va + vb));
        out->residual = sqrt(2.0 * rss / (double)n);
    }
    return 0;
}
