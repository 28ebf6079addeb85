/*
 * Stochastic filters as error against samples per pixel
 * (doc/comparison.md, "Stochastic filters"): a renderer averages many
 * samples per pixel anyway, so a filter that answers each lookup with one
 * random estimate (sample_batch_args.u; doc/footprint-filters.md,
 * "Stochastic filtering") is scored by the mean of spp lookups per pixel,
 * each with its own uniform u, against the same ground truth as every row.
 * The means are nested (the first spp of the largest count's lookups), so
 * the sweep costs as many lookups as its largest spp. u comes from a hash of
 * (pixel, lookup), not from a stream, so the images are the same for any
 * thread count and on every run.
 */
#include "cmp_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A fixed seed: the sweep is reproducible. */
#define SPP_SEED 0x5eed2024u

int cmp_config_stochastic(const cmp_config *c, const sample_sampler *scene)
{
    sample_sampler s;
    if (!c->pick.f || c->pick.oiio || c->pick.gl) return 0;
    cmp_config_sampler(c, scene, &s);
    /* Where u changes the result: a footprint filter, or a blend of two
     * levels (DESIGN §7). */
    return s.footprint != SAMPLE_FOOTPRINT_NONE || s.min_filter == SAMPLE_LINEAR_MIPMAP_LINEAR ||
           s.min_filter == SAMPLE_NEAREST_MIPMAP_LINEAR;
}

float cmp_spp_u(size_t pixel, int lookup)
{
    /* SplitMix64's finaliser (Steele, Lea & Flood 2014) of (seed, pixel,
     * lookup): independent-looking uniforms from any index. */
    unsigned long long z = ((unsigned long long)SPP_SEED << 32) ^
                           ((unsigned long long)pixel * 0x9e3779b97f4a7c15ull) ^ (unsigned long long)lookup;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return (float)(z >> 40) * (1.0f / 16777216.0f); /* 24 bits: exact in float, < 1 */
}

typedef struct spp_ctx {
    const cmp_prepared *p;
    int lookup;
    unsigned draws;
} spp_ctx;

static int spp_fn(void *ctx, int texture, const size_t *px, const sample_query *q,
                  const sample_query3 *q3, const sample_quad *quad, size_t n, float *rgba,
                  sample_stats *stats)
{
    const spp_ctx *c = ctx;
    char err[256];
    float *u = malloc(n * sizeof *u);
    size_t i;
    int rc;
    (void)stats;
    if (!u) return 1;
    for (i = 0; i < n; ++i) u[i] = cmp_spp_u(px[i], c->lookup);
    rc = cmp_prepared_batch(c->p, texture, q, q3, quad, u, c->draws, n, rgba, NULL, NULL, err,
                            sizeof err);
    free(u);
    return rc != 0;
}

int cmp_spp_sweep(const cmp_view *v, const cmp_config *c, const cmp_truth *t, const int *spp, int nspp,
                  unsigned draws, int threads, cmp_spp_row *out, char *err, size_t errlen)
{
    size_t n = (size_t)v->w * (size_t)v->h, i;
    int most = spp[nspp - 1], j, k = 0, rc;
    double *sum = calloc(n * 4, sizeof *sum), *ns = malloc((size_t)most * sizeof *ns);
    float *mean = malloc(n * 4 * sizeof *mean);
    cmp_prepared p;
    spp_ctx ctx;
    memset(out, 0, sizeof *out);
    out->cfg = c;
    if (!sum || !ns || !mean) {
        snprintf(err, errlen, "out of memory");
        rc = TOOL_BACKEND_ERROR;
        goto done;
    }
    if ((rc = cmp_prepare(v, c, &p, err, errlen)) != 0) goto done;
    for (j = 0; j < p.ntex && rc == 0; ++j)
        if (p.tex[j] && (j == v->env_tex || cmp_view_3d(v, j))) {
            /* sample_batch3_args has no u. */
            snprintf(err, errlen, "direction and volume queries (%s) take no stochastic draws",
                     j == v->env_tex ? "an environment map" : "a solid texture");
            rc = TOOL_BACKEND_NA;
        }
    if (rc != 0) {
        cmp_prepared_release(&p);
        goto done;
    }
    ctx.p = &p;
    ctx.draws = draws;
    for (j = 0; j < most && rc == 0; ++j) {
        cmp_result r;
        cmp_metrics m;
        ctx.lookup = j;
        if (cmp_run(v, c->pick.f->corners, spp_fn, &ctx, 0, threads, 1, &r)) {
            snprintf(err, errlen, "a stochastic lookup failed");
            rc = TOOL_BACKEND_ERROR;
            break;
        }
        ns[j] = r.ns_per_sample;
        for (i = 0; i < n * 4; ++i) sum[i] += r.rgba[i];
        cmp_result_free(&r);
        if (j + 1 != spp[k]) continue;
        for (i = 0; i < n * 4; ++i) mean[i] = (float)(sum[i] / (j + 1));
        cmp_metrics_compute(mean, t->rgba, t->mask, n, &m);
        out->rmse[k++] = m.rmse;
    }
    cmp_prepared_release(&p);
    if (rc == 0) {
        out->ok = 1;
        out->ns_per_sample = cmp_median(ns, most);
    }
done:
    free(sum);
    free(ns);
    free(mean);
    return rc;
}

int cmp_spp_plot(const char *dir, const cmp_scene_result *s)
{
    cmp_series series[2 * CMP_MAX_CONFIGS];
    double x[CMP_MAX_SPP];
    char rel[512], path[1024], title[128], labels[CMP_MAX_CONFIGS][TOOL_FILTER_LABEL_MAX + 24];
    cmp_plot pl = {0};
    int r, k, n = 0;
    for (k = 0; k < s->nspp; ++k) x[k] = s->spp[k];
    for (r = 0; r < s->nspp_rows; ++r) {
        const cmp_spp_row *w = &s->spp_rows[r];
        if (!w->ok) continue;
        series[n].label = w->cfg->label;
        series[n].colour = r;
        series[n].n = s->nspp;
        series[n].x = x;
        series[n].y = w->rmse;
        series[n].hline = -1.0;
        ++n;
        /* The deterministic filter's RMSE, a dashed line of the same colour. */
        snprintf(labels[r], sizeof labels[r], "%s, deterministic", w->cfg->label);
        series[n].label = labels[r];
        series[n].colour = r;
        series[n].n = 0;
        series[n].hline = w->det_rmse;
        ++n;
    }
    if (!n || s->nspp < 1) return 0;
    snprintf(title, sizeof title, "%s: RMSE against samples per pixel (stochastic filters)", s->label);
    pl.title = title;
    pl.xlabel = "samples per pixel (log scale)";
    pl.xticks = x;
    pl.nxticks = s->nspp;
    pl.series = series;
    pl.nseries = n;
    cmp_pic_path(rel, sizeof rel, s, "spp", "");
    snprintf(path, sizeof path, "%s/%s", dir, rel);
    return cmp_plot_write(path, &pl);
}
