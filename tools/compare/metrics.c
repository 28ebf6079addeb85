/*
 * Scores against the ground truth (DESIGN §8): RMSE and PSNR on linear
 * values over R, G and B (alpha is 1 everywhere in these scenes and would
 * only dilute the error), peak 1 as the textures' range is [0, 1].
 */
#include "cmp_internal.h"

#include <math.h>
#include <stdlib.h>

static double pixel_sq(const float *a, const float *b)
{
    double s = 0.0;
    int c;
    for (c = 0; c < 3; ++c) {
        double d = (double)a[c] - (double)b[c];
        s += d * d;
    }
    return s;
}

void cmp_metrics_compute(const float *img, const float *ref, const unsigned char *mask, size_t n,
                         cmp_metrics *m)
{
    double sum = 0.0, worst = 0.0, mse;
    size_t px, count = 0;
    for (px = 0; px < n; ++px) {
        double s;
        if (mask && !mask[px]) continue;
        s = pixel_sq(img + px * 4, ref + px * 4);
        sum += s;
        if (s > worst) worst = s;
        ++count;
    }
    m->count = count;
    mse = count ? sum / (3.0 * (double)count) : 0.0;
    m->rmse = sqrt(mse);
    m->max_err = sqrt(worst / 3.0);
    m->psnr = mse > 0.0 ? -10.0 * log10(mse) : HUGE_VAL;
}

void cmp_error_map(const float *img, const float *ref, size_t n, float *err)
{
    size_t px;
    for (px = 0; px < n; ++px) err[px] = (float)sqrt(pixel_sq(img + px * 4, ref + px * 4) / 3.0);
}

void cmp_worst_window(const double *score, const unsigned char *mask, int w, int h, int size,
                      int *x0, int *y0)
{
    /* Summed-area table, (w + 1) × (h + 1), so each window costs four reads. */
    double *sat = calloc((size_t)(w + 1) * (size_t)(h + 1), sizeof *sat), best = -1.0;
    int i, j;
    *x0 = *y0 = 0;
    if (size > w) size = w;
    if (size > h) size = h;
    if (!sat) return;
    for (j = 0; j < h; ++j)
        for (i = 0; i < w; ++i) {
            size_t px = (size_t)j * (size_t)w + (size_t)i;
            double s = (!mask || mask[px]) ? score[px] : 0.0;
            sat[(size_t)(j + 1) * (size_t)(w + 1) + (size_t)(i + 1)] =
                s + sat[(size_t)j * (size_t)(w + 1) + (size_t)(i + 1)] +
                sat[(size_t)(j + 1) * (size_t)(w + 1) + (size_t)i] -
                sat[(size_t)j * (size_t)(w + 1) + (size_t)i];
        }
    for (j = 0; j + size <= h; ++j)
        for (i = 0; i + size <= w; ++i) {
            size_t W = (size_t)(w + 1);
            double s = sat[(size_t)(j + size) * W + (size_t)(i + size)] -
                       sat[(size_t)j * W + (size_t)(i + size)] -
                       sat[(size_t)(j + size) * W + (size_t)i] + sat[(size_t)j * W + (size_t)i];
            if (s > best) {
                best = s;
                *x0 = i;
                *y0 = j;
            }
        }
    free(sat);
}

double cmp_median(double *v, int n)
{
    int i, j;
    /* Insertion sort: n is a handful of runs. */
    for (i = 1; i < n; ++i) {
        double x = v[i];
        for (j = i; j > 0 && v[j - 1] > x; --j) v[j] = v[j - 1];
        v[j] = x;
    }
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}
