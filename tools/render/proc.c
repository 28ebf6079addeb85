/*
 * Procedural textures from the literature, each an exact function of (s, t)
 * (the ground truth of DESIGN §8) and a baked image texture for libsample
 * (256 × 256 like the paper's texture store, box-filtered bake_samples² per
 * texel so that the bake itself does not alias).
 *
 * Every pattern is a scalar v ∈ [0, 1] blending two colours a → b, and
 * repeats an integer number of times over the unit square, so that a REPEAT
 * texture tiles without a seam (Blinn–Newell's condition on Fourier
 * synthesis, "continuous across the boundaries", applied to all of them).
 */
#include "rn_internal.h"

#include <stdio.h>
#include <stdlib.h>

const char *const rn_tex_kind_names[RN_TEX_KIND_COUNT] = {
    [RN_TEX_IMAGE] = "image",       [RN_TEX_GRID] = "grid",
    [RN_TEX_CHECKER] = "checker",   [RN_TEX_TILES] = "tiles",
    [RN_TEX_BRICKS] = "bricks",     [RN_TEX_NOISE] = "noise",
    [RN_TEX_TURBULENCE] = "turbulence", [RN_TEX_MARBLE] = "marble",
    [RN_TEX_SOLID] = "solid",       [RN_TEX_FOURIER] = "fourier",
    [RN_TEX_ZONEPLATE] = "zoneplate",
};

static uint32_t hash2(int i, int j, uint32_t seed)
{
    uint32_t h = (uint32_t)i * 73856093u ^ (uint32_t)j * 19349663u ^ seed * 83492791u;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return h;
}

/* Fourier synthesis spectrum (Blinn–Newell 1976, Fig. 6): integer
 * frequencies (so the pattern is periodic on the unit square) inside a
 * disc of radius freq, amplitude ∝ 1/|k| (a "wavy" 1/f spectrum), random
 * phases; amplitudes normalized so that v stays in [0, 1]. */
static void fourier_spectrum(rn_texture *t)
{
    uint32_t x = t->seed * 747796405u + 2891336453u;
    double total = 0.0;
    int k, r = (int)t->freq;
    if (r < 1) r = 1;
    t->nfourier = t->nfourier > 0 && t->nfourier <= RN_FOURIER_MAX ? t->nfourier : 24;
    for (k = 0; k < t->nfourier; ++k) {
        int kx, ky;
        do {
            x = x * 1664525u + 1013904223u;
            kx = (int)((x >> 16) % (uint32_t)(2 * r + 1)) - r;
            x = x * 1664525u + 1013904223u;
            ky = (int)((x >> 16) % (uint32_t)(2 * r + 1)) - r;
        } while ((kx == 0 && ky == 0) || kx * kx + ky * ky > r * r);
        t->fk[k][0] = kx;
        t->fk[k][1] = ky;
        t->famp[k] = 1.0 / sqrt((double)(kx * kx + ky * ky));
        x = x * 1664525u + 1013904223u;
        t->fphase[k] = 2.0 * RN_PI * (double)(x >> 8) / 16777216.0;
        total += t->famp[k];
    }
    for (k = 0; k < t->nfourier; ++k) t->famp[k] *= 0.5 / total;
}

void proc_defaults(rn_texture *t, rn_tex_kind kind)
{
    memset(t, 0, sizeof *t);
    t->kind = kind;
    t->a[0] = t->a[1] = t->a[2] = 0.05f;
    t->b[0] = t->b[1] = t->b[2] = 0.9f;
    t->a[3] = t->b[3] = 1.0f;
    t->freq = 8.0;
    t->width = 0.1;
    t->octaves = 4;
    t->amount = kind == RN_TEX_ZONEPLATE ? 160.0 : 4.0;
    t->seed = 1;
    t->bake_size = 256;
    t->bake_samples = 4;
    t->wrap_s = t->wrap_t = SAMPLE_WRAP_REPEAT;
}

static double frac(double x) { return x - floor(x); }

/* 1 on a line of width w (fraction of a cell) centred on each integer. */
static double on_line(double x, double w)
{
    double f = frac(x);
    return (f < 0.5 * w || f >= 1.0 - 0.5 * w) ? 1.0 : 0.0;
}

/* The pattern at X: (s, t, 0) for a surface texture, the point P for a
 * solid one (wood, or any kind with a "solid" block). The kinds that are
 * functions of three coordinates (checker, noise, turbulence, marble, wood)
 * read all of X, so a surface texture is their z = 0 slice. */
static double pattern(const rn_texture *t, const double X[3])
{
    const double F = t->freq, s = X[0], tt = X[1], z = X[2];
    switch (t->kind) {
    case RN_TEX_GRID:
        /* Blinn–Newell Fig. 2: the parametric lines painted on. */
        return fmax(on_line(s * F, t->width), on_line(tt * F, t->width));
    case RN_TEX_CHECKER:
        return (double)(((long long)floor(s * F) + (long long)floor(tt * F) +
                         (long long)floor(z * F)) & 1);
    case RN_TEX_TILES: {
        double i = floor(s * F), j = floor(tt * F);
        if (on_line(s * F, t->width) > 0.0 || on_line(tt * F, t->width) > 0.0) return 0.0;
        return 0.6 + 0.4 * (double)(hash2((int)fmod(i, 65536.0), (int)fmod(j, 65536.0), t->seed) &
                                    1023u) / 1023.0;
    }
    case RN_TEX_BRICKS: {
        /* Rows 1/F high, bricks 2/F long, every other row shifted by half a
         * brick; mortar of width `width` (fraction of a row). */
        double row = floor(tt * F), x = s * F * 0.5 + 0.5 * fmod(fabs(row), 2.0);
        if (on_line(tt * F, t->width) > 0.0 || on_line(x, 0.5 * t->width) > 0.0) return 0.0;
        return 1.0;
    }
    case RN_TEX_NOISE:
        return 0.5 + 0.5 * noise3(&t->noise, s * F, tt * F, z * F);
    case RN_TEX_TURBULENCE:
        return fmin(1.0, turbulence3(&t->noise, s * F, tt * F, z * F, t->octaves));
    case RN_TEX_MARBLE:
        /* Perlin 1985: marble = sin(x + turbulence). */
        return 0.5 + 0.5 * sin(2.0 * RN_PI * s * F +
                               t->amount * turbulence3(&t->noise, s * F, tt * F, z * F, t->octaves));
    case RN_TEX_SOLID: {
        /* Wood (Peachey 1985, Perlin 1985): rings around the z axis of the
         * solid, perturbed by noise. */
        double r = sqrt(s * s + tt * tt) * F + 0.3 * t->amount * noise3(&t->noise, s * F, tt * F, z * F);
        return frac(r);
    }
    case RN_TEX_FOURIER: {
        double v = 0.5;
        int k;
        for (k = 0; k < t->nfourier; ++k)
            v += t->famp[k] * cos(2.0 * RN_PI * (t->fk[k][0] * s + t->fk[k][1] * tt) + t->fphase[k]);
        return v;
    }
    case RN_TEX_ZONEPLATE: {
        /* cos(π k r²): local frequency k·r cycles per unit, growing from the
         * centre outwards — every frequency up to k/√2 in one image. */
        double dx = s - 0.5, dy = tt - 0.5;
        return 0.5 + 0.5 * cos(RN_PI * t->amount * (dx * dx + dy * dy));
    }
    case RN_TEX_IMAGE:
    case RN_TEX_KIND_COUNT:
        break;
    }
    return 0.0;
}

void proc_eval(const rn_texture *t, double s, double t_, const double P[3], float out[4])
{
    double X[3] = {s, t_, 0.0}, v;
    int c;
    if (P && (t->kind == RN_TEX_SOLID || t->solid.on)) memcpy(X, P, sizeof X);
    v = pattern(t, X);
    for (c = 0; c < 4; ++c) out[c] = (float)(t->a[c] + v * (t->b[c] - t->a[c]));
}

int proc_bake(rn_texture *t, char *err, size_t errlen)
{
    const int n = t->bake_size, m = t->bake_samples;
    float *px;
    sample_image img;
    sample_mip_params mip;
    sample_error e;
    int i, j;
    if (n < 1 || n > 8192 || m < 1 || m > 16) {
        rn_seterr(err, errlen, "texture bake size %d / samples %d out of range (1..8192, 1..16)", n, m);
        return 0;
    }
    if (t->kind == RN_TEX_NOISE || t->kind == RN_TEX_TURBULENCE || t->kind == RN_TEX_MARBLE ||
        t->kind == RN_TEX_SOLID)
        /* A surface texture's lattice repeats once over the unit square
         * (seamless tiling); a solid's does not repeat within 256 cells. */
        noise_init(&t->noise, t->seed, t->solid.on ? 0 : (int)t->freq);
    if (t->kind == RN_TEX_FOURIER) fourier_spectrum(t);
    if (t->solid.on) return solid_bake(t, err, errlen);
    px = malloc(sizeof *px * 4 * (size_t)n * (size_t)n);
    if (!px) {
        rn_seterr(err, errlen, "out of memory baking a %d x %d texture", n, n);
        return 0;
    }
    for (j = 0; j < n; ++j)
        for (i = 0; i < n; ++i) {
            double acc[4] = {0, 0, 0, 0};
            int a, b, c;
            for (b = 0; b < m; ++b)
                for (a = 0; a < m; ++a) {
                    float v[4];
                    proc_eval(t, (i + (a + 0.5) / m) / n, (j + (b + 0.5) / m) / n, NULL, v);
                    for (c = 0; c < 4; ++c) acc[c] += v[c];
                }
            for (c = 0; c < 4; ++c) px[4 * ((size_t)j * n + i) + c] = (float)(acc[c] / (m * m));
        }
    img.width = img.height = n;
    img.channels = 4;
    img.format = SAMPLE_FORMAT_F32;
    img.data = px;
    img.row_stride = 0;
    sample_mip_params_init(&mip);
    mip.wrap_s = t->wrap_s;
    mip.wrap_t = t->wrap_t;
    if (sample_texture_create(&img, &mip, &t->tex, &e) != SAMPLE_OK) {
        rn_seterr(err, errlen, "baking texture: %s", e.message);
        free(px);
        return 0;
    }
    free(px);
    return 1;
}
