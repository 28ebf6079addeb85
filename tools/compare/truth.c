/*
 * The ground truth of DESIGN §8: each pixel's value is the texture
 * integrated against the 2 × 2-pixel pyramid (1 − |x|)(1 − |y|) centred on
 * it, through the exact screen → (s, t) mapping, by stratified
 * supersampling: n × n strata over the footprint, one jittered sample per
 * stratum, each evaluated at its exact (s, t) (render_scene_texture_truth:
 * analytic for procedural textures, bilinear base level for images) or, on
 * a mirror, at its exact reflected direction (render_scene_env_truth: the
 * environment map's bilinear base level).
 *
 * Sharing samples. With n/2 strata per pixel the strata of neighbouring
 * pixels coincide (the footprints overlap by a whole pixel), so one global
 * grid of (W + 1)·n/2 × (H + 1)·n/2 samples serves every pixel and each
 * sample is evaluated once instead of four times. A stratum is weighted by
 * the pyramid at its centre, which makes the sum separable: a horizontal
 * pass per sample row, then a vertical pass per pixel.
 *
 * Silhouettes and occlusion edges (doc/comparison.md). A sample that
 * misses the surface counts as the background colour, so the truth image
 * shows the antialiased edge. The filters see one (s, t) per pixel and
 * cannot know about an edge, so a pixel enters the metrics (the mask) only
 * when every sample of its footprint lies on the surface seen at its
 * centre, continuing it: on the same object, and where the first-order
 * expansion of the centre's hit, P + dP/dx·Δx + dP/dy·Δy, says it should
 * be, within EDGE_TOL times the footprint's size on the surface
 * (|dP/dx| + |dP/dy|). Within one object that finds the edges where one
 * part covers another (the teapot's spout, handle and lid in front of its
 * body): there a sample lands on the part behind, tens of footprints away
 * along the ray, while on a smooth surface the expansion is off by a
 * second-order term, a small fraction of the footprint (on a plane seen in
 * perspective about 1/(d − 1) of it at a pixel d pixels from the horizon).
 */
#include "cmp_internal.h"
#include "cli.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A sample farther than this many footprint sizes from the centre's
 * surface continued to first order lies across an occlusion edge. */
#define EDGE_TOL 2.0

/* Flags of a horizontal pass (sample row l, pixel column i): the row's
 * samples continue the surface seen at the centre of pixel (i, l / per)
 * (ON_UPPER: the row is in the upper half of that pixel's footprint), of
 * pixel (i, l / per − 1) (ON_LOWER). */
enum { ON_UPPER = 1, ON_LOWER = 2 };

typedef struct truth_job {
    const cmp_view *v;
    int n, per;        /* samples per footprint axis, per pixel (n / 2) */
    int cols, rows;    /* global sample grid */
    double *w;         /* n pyramid weights of the strata along one axis */
    float *hrow;       /* rows × W × 4: horizontal pass */
    unsigned char *hon; /* rows × W: ON_UPPER | ON_LOWER */
    cmp_truth *t;
    unsigned char *failed; /* per sample row */
} truth_job;

/* splitmix64 finalizer: a fixed jitter per sample, independent of threads. */
static uint64_t mix64(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

static double unit(uint64_t z) { return (double)(z >> 11) * (1.0 / 9007199254740992.0); }

/* A sample: where it is on the screen, what it hit. */
typedef struct sample_pt {
    double x, y;
    double P[3];
    int object; /* −1: background */
} sample_pt;

/* The value and hit at screen point (x, y). */
static void truth_sample(const cmp_view *v, double x, double y, float out[4], sample_pt *pt)
{
    render_hit h;
    int tex, k;
    pt->x = x;
    pt->y = y;
    if (!render_cache_hit(v->cache, x, y, &h)) {
        for (k = 0; k < 4; ++k) out[k] = v->background[k];
        pt->object = -1;
        return;
    }
    tex = render_scene_material_texture(v->sc, h.material);
    if (v->env_tex >= 0 && render_scene_env_truth(v->sc, &h, out)) {
        /* A mirror: the environment's base level in the exact reflected
         * direction at this point (render.h). */
    } else if (tex >= 0)
        render_scene_texture_truth(v->sc, tex, h.s, h.t, h.P, out);
    else
        for (k = 0; k < 4; ++k) out[k] = 1.0f;
    for (k = 0; k < 3; ++k) pt->P[k] = h.P[k];
    pt->object = h.object;
}

/* Whether the sample continues the surface seen at the centre of pixel
 * (i, j): same object, and within EDGE_TOL footprints of the first-order
 * expansion of the centre's hit. */
static int continues(const cmp_view *v, int i, int j, const sample_pt *pt)
{
    const render_hit *c = render_cache_pixel(v->cache, i, j);
    double dx = pt->x - (i + 0.5), dy = pt->y - (j + 0.5), d2 = 0.0, gx = 0.0, gy = 0.0, tol;
    int k;
    if (c->object < 0 || pt->object != c->object) return 0;
    for (k = 0; k < 3; ++k) {
        double e = pt->P[k] - (c->P[k] + c->dPdx[k] * dx + c->dPdy[k] * dy);
        d2 += e * e;
        gx += c->dPdx[k] * c->dPdx[k];
        gy += c->dPdy[k] * c->dPdy[k];
    }
    tol = EDGE_TOL * (sqrt(gx) + sqrt(gy));
    return d2 <= tol * tol;
}

static void truth_sample_row(void *ctx, int l)
{
    truth_job *jb = ctx;
    const cmp_view *v = jb->v;
    float *f = malloc(sizeof *f * 4 * (size_t)jb->cols);
    sample_pt *pt = malloc(sizeof *pt * (size_t)jb->cols);
    int m, i, k, c, upper = l / jb->per, lower = upper - 1;
    if (!f || !pt) {
        jb->failed[l] = 1;
        free(f);
        free(pt);
        return;
    }
    /* Sample (m, l) lies in stratum [m, m + 1) / per − ½ on each axis. */
    for (m = 0; m < jb->cols; ++m) {
        uint64_t z = mix64(((uint64_t)(uint32_t)l << 32) ^ (uint64_t)(uint32_t)m ^ 0x9e3779b97f4a7c15ull);
        double x = (m + unit(z)) / jb->per - 0.5;
        double y = (l + unit(mix64(z))) / jb->per - 0.5;
        truth_sample(v, x, y, f + (size_t)m * 4, &pt[m]);
    }
    for (i = 0; i < v->w; ++i) {
        double acc[4] = {0, 0, 0, 0};
        int on = (upper < v->h ? ON_UPPER : 0) | (lower >= 0 ? ON_LOWER : 0);
        for (k = 0; k < jb->n; ++k) {
            const sample_pt *p = &pt[i * jb->per + k];
            const float *s = f + (size_t)(i * jb->per + k) * 4;
            for (c = 0; c < 4; ++c) acc[c] += jb->w[k] * s[c];
            if ((on & ON_UPPER) && !continues(v, i, upper, p)) on &= ~ON_UPPER;
            if ((on & ON_LOWER) && !continues(v, i, lower, p)) on &= ~ON_LOWER;
        }
        for (c = 0; c < 4; ++c) jb->hrow[((size_t)l * (size_t)v->w + (size_t)i) * 4 + (size_t)c] = (float)acc[c];
        jb->hon[(size_t)l * (size_t)v->w + (size_t)i] = (unsigned char)on;
    }
    free(f);
    free(pt);
}

static void truth_pixel_row(void *ctx, int j)
{
    truth_job *jb = ctx;
    const cmp_view *v = jb->v;
    double wsum = 0.0;
    int i, k, c;
    for (k = 0; k < jb->n; ++k) wsum += jb->w[k];
    wsum *= wsum;
    for (i = 0; i < v->w; ++i) {
        size_t px = (size_t)j * (size_t)v->w + (size_t)i;
        double acc[4] = {0, 0, 0, 0};
        int ok = v->tex[px] >= 0;
        for (k = 0; k < jb->n; ++k) {
            size_t r = (size_t)(j * jb->per + k) * (size_t)v->w + (size_t)i;
            for (c = 0; c < 4; ++c) acc[c] += jb->w[k] * jb->hrow[r * 4 + (size_t)c];
            /* Rows k < per are the upper half of this pixel's footprint. */
            if (!(jb->hon[r] & (k < jb->per ? ON_UPPER : ON_LOWER))) ok = 0;
        }
        for (c = 0; c < 4; ++c) jb->t->rgba[px * 4 + (size_t)c] = (float)(acc[c] / wsum);
        jb->t->mask[px] = (unsigned char)ok;
    }
}

int cmp_truth_build(const cmp_view *v, int n, int threads, cmp_truth *t, char *err, size_t errlen)
{
    truth_job jb;
    size_t npx = (size_t)v->w * (size_t)v->h, cells;
    double t0 = cmp_now();
    int k, failed = 0;
    memset(t, 0, sizeof *t);
    memset(&jb, 0, sizeof jb);
    if (n < 2 || n % 2 != 0 || n > 1024) {
        snprintf(err, errlen, "truth samples must be even, 2 to 1024 (got %d)", n);
        return 1;
    }
    jb.v = v;
    jb.t = t;
    jb.n = n;
    jb.per = n / 2;
    jb.cols = (v->w + 1) * jb.per;
    jb.rows = (v->h + 1) * jb.per;
    cells = (size_t)jb.rows * (size_t)v->w;
    jb.w = malloc(sizeof *jb.w * (size_t)n);
    jb.hrow = malloc(sizeof *jb.hrow * 4 * cells);
    jb.hon = malloc(cells);
    jb.failed = calloc((size_t)jb.rows, 1);
    t->rgba = malloc(sizeof *t->rgba * 4 * npx);
    t->mask = malloc(npx);
    t->samples = n;
    if (!jb.w || !jb.hrow || !jb.hon || !jb.failed || !t->rgba || !t->mask) {
        failed = 1;
    } else {
        /* Stratum k's centre is at offset (k + ½)/per − 1 from the pixel centre. */
        for (k = 0; k < n; ++k) jb.w[k] = 1.0 - fabs((k + 0.5) / jb.per - 1.0);
        render_parallel_rows(jb.rows, threads, truth_sample_row, &jb, cli_progress, "truth");
        for (k = 0; k < jb.rows; ++k) failed |= jb.failed[k];
        if (!failed) render_parallel_rows(v->h, threads, truth_pixel_row, &jb, NULL, NULL);
    }
    free(jb.w);
    free(jb.hrow);
    free(jb.hon);
    free(jb.failed);
    if (failed) {
        cmp_truth_free(t);
        snprintf(err, errlen, "out of memory for the ground truth (%d x %d samples per pixel)", n, n);
        return 1;
    }
    t->seconds = cmp_now() - t0;
    return 0;
}

void cmp_truth_free(cmp_truth *t)
{
    free(t->rgba);
    free(t->mask);
    t->rgba = NULL;
    t->mask = NULL;
}
