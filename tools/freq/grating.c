/* Gratings and the zone plate (doc/frequency-tests.md §2). */
#include "freq.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

fq_wave fq_wave_nearest(int n, double f, double theta)
{
    fq_wave w;
    w.n = n;
    /* Integer cycles across the texture on both axes is what makes the
     * grating tile under REPEAT; the price is that (f, θ) move to the nearest
     * lattice point, so the sweep records the realized values. */
    w.p = (int)lround(f * n * cos(theta));
    w.q = (int)lround(f * n * sin(theta));
    w.f = sqrt((double)w.p * w.p + (double)w.q * w.q) / n;
    w.theta = (w.p == 0 && w.q == 0) ? theta : atan2((double)w.q, (double)w.p);
    return w;
}

float *fq_grating_texels(const fq_wave *w)
{
    int n = w->n, i, j;
    float *t = (float *)malloc((size_t)n * (size_t)n * 2 * sizeof *t);
    long two_n = 2L * n;
    if (!t) return NULL;
    for (j = 0; j < n; ++j)
        for (i = 0; i < n; ++i) {
            /* The phase at the texel centre (i + ½, j + ½) is
             * π·(p(2i+1) + q(2j+1))/N; reducing the integer numerator mod 2N
             * first keeps the argument small, so every period is bit-identical
             * (a float cos of a large argument would not be). */
            long a = ((long)w->p * (2L * i + 1) + (long)w->q * (2L * j + 1)) % two_n;
            double ph = FQ_PI * (double)(a < 0 ? a + two_n : a) / n;
            t[2 * ((size_t)j * n + i)] = (float)cos(ph);
            t[2 * ((size_t)j * n + i) + 1] = (float)sin(ph);
        }
    return t;
}

sample_status fq_texture_create(const float *texels, int n, int channels, sample_texture **out,
                                sample_error *err)
{
    sample_image img = {0};
    sample_mip_params mip;
    img.width = img.height = n;
    img.channels = channels;
    img.format = SAMPLE_FORMAT_F32;
    img.data = texels;
    sample_mip_params_init(&mip);
    mip.filter = SAMPLE_MIPGEN_BOX;
    mip.wrap_s = mip.wrap_t = SAMPLE_WRAP_REPEAT;
    return sample_texture_create(&img, &mip, out, err);
}

sample_status fq_grating_texture(const fq_wave *w, sample_texture **out, sample_error *err)
{
    sample_status st;
    float *t = fq_grating_texels(w);
    *out = NULL;
    if (!t) {
        if (err) {
            err->status = SAMPLE_E_OUT_OF_MEMORY;
            snprintf(err->message, sizeof err->message, "grating %d x %d: out of memory", w->n,
                     w->n);
        }
        return SAMPLE_E_OUT_OF_MEMORY;
    }
    st = fq_texture_create(t, w->n, 2, out, err);
    free(t);
    return st;
}

float *fq_zone_plate_texels(int n)
{
    int i, j;
    float *t = (float *)malloc((size_t)n * (size_t)n * sizeof *t);
    if (!t) return NULL;
    for (j = 0; j < n; ++j)
        for (i = 0; i < n; ++i) {
            /* x² + y² with integer x, y from the centre: adding N to x adds
             * 2xN + N² to it, an even multiple of N for even N, so the plate
             * tiles (the phase is π·(x² + y²)/N), and the local frequency
             * x/N reaches ½ cycle/texel at the edge. Reduced mod 2N as in
             * fq_grating_texels. */
            long x = i - n / 2, y = j - n / 2;
            long a = (x * x + y * y) % (2L * n);
            t[(size_t)j * n + i] = (float)cos(FQ_PI * (double)a / n);
        }
    return t;
}
