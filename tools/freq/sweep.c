/*
 * The sweep (DESIGN §9): for each orientation, the gratings that the
 * frequency grid of every minification needs; each grating texture is built
 * once and measured at every (m, r) that uses it with every filter.
 */
#include "freq.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* A grating the sweep needs, and the minification it is needed at. */
typedef struct need {
    fq_wave wave;
    int im;
} need;

typedef struct need_list {
    need *v;
    size_t count, cap;
} need_list;

static int push_need(need_list *l, const fq_wave *w, int im)
{
    if (l->count == l->cap) {
        size_t cap = l->cap ? 2 * l->cap : 256;
        need *v = (need *)realloc(l->v, cap * sizeof *v);
        if (!v) return -1;
        l->v = v;
        l->cap = cap;
    }
    l->v[l->count].wave = *w;
    l->v[l->count].im = im;
    l->count++;
    return 0;
}

static int push_point(fq_sweep *s, const fq_point *p)
{
    if (s->count == s->cap) {
        size_t cap = s->cap ? 2 * s->cap : 1024;
        fq_point *v = (fq_point *)realloc(s->pts, cap * sizeof *v);
        if (!v) return -1;
        s->pts = v;
        s->cap = cap;
    }
    s->pts[s->count++] = *p;
    return 0;
}

static int by_wave(const void *a, const void *b)
{
    const need *x = (const need *)a, *y = (const need *)b;
    if (x->wave.p != y->wave.p) return x->wave.p < y->wave.p ? -1 : 1;
    if (x->wave.q != y->wave.q) return x->wave.q < y->wave.q ? -1 : 1;
    return x->im - y->im;
}

static int by_curve(const void *a, const void *b)
{
    const fq_point *x = (const fq_point *)a, *y = (const fq_point *)b;
    if (x->backend != y->backend) return x->backend - y->backend;
    if (x->im != y->im) return x->im - y->im;
    if (x->itheta != y->itheta) return x->itheta - y->itheta;
    if (x->ir != y->ir) return x->ir - y->ir;
    return (x->res.F > y->res.F) - (x->res.F < y->res.F);
}

/* The gratings for orientation θ: for each m, the grid F = 0, step, … up to
 * f_max, each moved to the nearest tiling wave vector; a grid point whose
 * grating the base level cannot hold (f ≥ ½ cycle/texel) ends the curve,
 * and one that rounds to the previous point's wave vector is dropped. */
static int plan_waves(const fq_plan *plan, int itheta, need_list *out)
{
    double theta = plan->theta_deg[itheta] * FQ_PI / 180.0;
    int im, i;
    for (im = 0; im < plan->nm; ++im) {
        int last_p = -1, last_q = -1;
        for (i = 0; i * plan->f_step <= plan->f_max + 1e-9; ++i) {
            fq_wave w = fq_wave_nearest(plan->n, i * plan->f_step / plan->m[im], theta);
            if (w.f >= 0.5) break;
            if (w.p == last_p && w.q == last_q) continue;
            last_p = w.p;
            last_q = w.q;
            if (push_need(out, &w, im) != 0) return -1;
        }
    }
    qsort(out->v, out->count, sizeof *out->v, by_wave);
    return 0;
}

/* Measure one grating with every backend at every (m, r) that needs it:
 * needs[0 … count) share the wave vector. */
static int run_wave(const fq_plan *plan, int itheta, const need *needs, size_t count,
                    fq_sweep *out, char *err, size_t errlen)
{
    const fq_wave *w = &needs[0].wave;
    sample_texture *tex = NULL;
    sample_error serr;
    float *texels = fq_grating_texels(w);
    int ib, rc = 0;
    if (!texels) {
        snprintf(err, errlen, "out of memory for a %d x %d grating", w->n, w->n);
        return -1;
    }
    if (fq_texture_create(texels, w->n, 2, &tex, &serr) != SAMPLE_OK) {
        snprintf(err, errlen, "grating texture: %s", serr.message);
        free(texels);
        return -1;
    }
    for (ib = 0; ib < plan->nbackends && rc == 0; ++ib) {
        const fq_backend *b = plan->backends[ib];
        void *ctx = b->prepare(b, tex, texels, w->n, 2, err, errlen);
        size_t k;
        int ir;
        if (!ctx) {
            rc = -1;
            break;
        }
        for (k = 0; k < count && rc == 0; ++k)
            for (ir = 0; ir < plan->nr && rc == 0; ++ir) {
                fq_layout l;
                fq_point pt;
                fq_layout_init(&l, plan->m[needs[k].im], plan->r[ir]);
                l.width = plan->width;
                l.rows = plan->rows;
                l.phases = plan->phases;
                pt.backend = ib;
                pt.im = needs[k].im;
                pt.itheta = itheta;
                pt.ir = ir;
                pt.wave = *w;
                rc = fq_measure(b, ctx, w, &l, &pt.res, err, errlen);
                if (rc == 0 && push_point(out, &pt) != 0) {
                    snprintf(err, errlen, "out of memory for the results");
                    rc = -1;
                }
            }
        b->release(ctx);
    }
    sample_texture_destroy(tex);
    free(texels);
    return rc;
}

int fq_sweep_run(const fq_plan *plan, fq_sweep *out, char *err, size_t errlen)
{
    need_list *lists;
    size_t total = 0, done = 0;
    int it, rc = 0;
    out->pts = NULL;
    out->count = out->cap = 0;
    lists = (need_list *)calloc((size_t)plan->ntheta, sizeof *lists);
    if (!lists) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    for (it = 0; it < plan->ntheta && rc == 0; ++it) {
        if (plan_waves(plan, it, &lists[it]) != 0) {
            snprintf(err, errlen, "out of memory");
            rc = -1;
        }
        total += lists[it].count;
    }
    for (it = 0; it < plan->ntheta && rc == 0; ++it) {
        size_t a = 0, b;
        while (a < lists[it].count && rc == 0) {
            for (b = a + 1; b < lists[it].count && lists[it].v[b].wave.p == lists[it].v[a].wave.p &&
                            lists[it].v[b].wave.q == lists[it].v[a].wave.q;
                 ++b)
                ;
            rc = run_wave(plan, it, lists[it].v + a, b - a, out, err, errlen);
            done += b - a;
            if (plan->progress) plan->progress(done, total);
            a = b;
        }
    }
    for (it = 0; it < plan->ntheta; ++it) free(lists[it].v);
    free(lists);
    if (out->count) qsort(out->pts, out->count, sizeof *out->pts, by_curve);
    return rc;
}

void fq_sweep_free(fq_sweep *s)
{
    free(s->pts);
    s->pts = NULL;
    s->count = s->cap = 0;
}

size_t fq_curve(const fq_sweep *s, int backend, int im, int itheta, int ir, const fq_point **first)
{
    /* Points are sorted by curve (by_curve), so a curve is one run: find
     * its first point by bisection on the curve key. */
    fq_point key;
    size_t lo = 0, hi = s->count, n = 0;
    key.backend = backend;
    key.im = im;
    key.itheta = itheta;
    key.ir = ir;
    key.res.F = -1.0;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (by_curve(&s->pts[mid], &key) < 0)
            lo = mid + 1;
        else
            hi = mid;
    }
    *first = s->pts + lo;
    while (lo + n < s->count && s->pts[lo + n].backend == backend && s->pts[lo + n].im == im &&
           s->pts[lo + n].itheta == itheta && s->pts[lo + n].ir == ir)
        n++;
    return n;
}
