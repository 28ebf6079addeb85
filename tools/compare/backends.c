/*
 * A row through its backend (tools/backend.h): libsample, OpenImageIO's
 * TextureSystem, OpenGL or an outside program, all asked the same queries
 * (view.c) on the same textures. Every texture a pixel uses is prepared
 * first, so that a backend that cannot do one of them (OpenImageIO and a
 * solid texture's volume, OpenGL and an environment map) makes the row
 * "n/a" before anything runs. A backend that serves many threads at once
 * (libsample, OpenImageIO) runs on compare's threads through cmp_run, in
 * batches of pixels that share a texture; the others (a GL context, a
 * program) get one batch per texture on one thread, which keeps the draws
 * and process starts few.
 */
#include "cmp_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int cmp_prepare(const cmp_view *v, const cmp_config *c, cmp_prepared *p, char *err, size_t errlen)
{
    int ntex = render_scene_texture_count(v->sc), k, rc = 0;
    size_t px, n = (size_t)v->w * (size_t)v->h;
    sample_sampler scene;
    memset(p, 0, sizeof *p);
    p->tb = c->tb;
    p->ntex = ntex + 1; /* + the environment (env_tex = ntex) */
    if (!(p->tex = calloc((size_t)p->ntex, sizeof *p->tex))) {
        snprintf(err, errlen, "out of memory");
        return TOOL_BACKEND_ERROR;
    }
    cmp_config_sampler(c, &v->sampler, &scene);
    /* Only the textures some pixel uses. */
    for (px = 0; px < n && rc == 0; ++px) {
        sample_sampler smp = scene;
        k = v->tex[px];
        if (k < 0 || p->tex[k]) continue;
        if (k == v->env_tex) {
            rc = tool_backend_prepare_env(c->tb, render_scene_env(v->sc, NULL), &smp, &p->tex[k],
                                          NULL, err, errlen);
            continue;
        }
        /* A solid texture's box has its own wrap (render_scene_solid_wrap). */
        if (render_scene_texture_solid(v->sc, k))
            smp.wrap_s = smp.wrap_t = smp.wrap_r = render_scene_solid_wrap(v->sc, k);
        rc = tool_backend_prepare(c->tb, render_scene_texture(v->sc, k), &smp, &p->tex[k], NULL,
                                  err, errlen);
    }
    if (rc != 0) cmp_prepared_release(p);
    return rc;
}

void cmp_prepared_release(cmp_prepared *p)
{
    int k;
    for (k = 0; p->tex && k < p->ntex; ++k) tool_backend_release(p->tb, p->tex[k]);
    free(p->tex);
    memset(p, 0, sizeof *p);
}

int cmp_prepared_batch(const cmp_prepared *p, int texture, const sample_query *q,
                       const sample_query3 *q3, const sample_quad *quad, const float *u,
                       unsigned draws, size_t n, float *rgba, sample_stats *stats,
                       tool_backend_times *t, char *err, size_t errlen)
{
    tool_backend_batch a;
    tool_backend_batch_init(&a, n, q, q3, rgba, p->tb->counts_texels ? stats : NULL);
    a.corners = quad;
    a.u = u;
    a.draws = draws;
    return tool_backend_run(p->tb, p->tex[texture], &a, t, err, errlen);
}

/* cmp_run's engine on a thread-safe backend. */
static int batch_fn(void *ctx, int texture, const size_t *px, const sample_query *q,
                    const sample_query3 *q3, const sample_quad *quad, size_t n, float *rgba,
                    sample_stats *stats)
{
    char err[256];
    (void)px;
    return cmp_prepared_batch(ctx, texture, q, q3, quad, NULL, 0, n, rgba, stats, NULL, err,
                              sizeof err) != 0;
}

/* One caller at a time: texture k's pixels (their indices in px) as one
 * batch, `runs` times. */
static int run_texture(const cmp_view *v, const cmp_prepared *p, int k, const size_t *px, size_t n,
                       sample_query *q, float *out, int runs, double *sample_s, cmp_result *r,
                       char *err, size_t errlen)
{
    size_t i;
    int run, rc = 0;
    for (i = 0; i < n; ++i) q[i] = v->q[px[i]];
    for (run = 0; run < runs && rc == 0; ++run) {
        tool_backend_times t = {0, 0, 0};
        rc = cmp_prepared_batch(p, k, q, NULL, NULL, NULL, 0, n, out, NULL, &t, err, errlen);
        sample_s[run] += t.sample;
    }
    for (i = 0; rc == 0 && i < n; ++i) memcpy(r->rgba + 4 * px[i], out + 4 * i, 4 * sizeof *out);
    return rc;
}

/* The row on one thread, ns_per_sample the sampling alone (the backend's
 * upload and read-back left out). */
static int run_serial(const cmp_view *v, const cmp_prepared *p, int runs, cmp_result *r, char *err,
                      size_t errlen)
{
    size_t npx = (size_t)v->w * (size_t)v->h, i, n;
    int k, rc = 0;
    size_t *px = malloc(npx * sizeof *px);
    sample_query *q = malloc(npx * sizeof *q);
    float *out = malloc(npx * 4 * sizeof *out);
    double *sample_s = calloc((size_t)runs, sizeof *sample_s), t0 = cmp_now();
    r->rgba = malloc(npx * 4 * sizeof *r->rgba);
    if (!px || !q || !out || !sample_s || !r->rgba) {
        snprintf(err, errlen, "out of memory for %zu pixels", npx);
        rc = TOOL_BACKEND_ERROR;
        goto done;
    }
    cmp_fill_untextured(v, r->rgba);
    for (k = 0; k < p->ntex && rc == 0; ++k) {
        if (!p->tex[k]) continue;
        if (k == v->env_tex || cmp_view_3d(v, k)) {
            snprintf(err, errlen, "direction or volume queries on one thread");
            rc = TOOL_BACKEND_NA;
            break;
        }
        for (i = 0, n = 0; i < npx; ++i)
            if (v->tex[i] == k) px[n++] = i;
        if (n) rc = run_texture(v, p, k, px, n, q, out, runs, sample_s, r, err, errlen);
        r->queries += n;
    }
    if (rc == 0) {
        for (k = 0; k < runs; ++k) sample_s[k] = r->queries ? 1e9 * sample_s[k] / (double)r->queries : 0.0;
        r->runs = runs;
        r->seconds = (cmp_now() - t0) / runs;
        r->ns_per_sample = cmp_median(sample_s, runs);
        r->texels = -1.0;
    }
done:
    free(px);
    free(q);
    free(out);
    free(sample_s);
    if (rc != 0) cmp_result_free(r);
    return rc;
}

int cmp_run_backend(const cmp_view *v, const cmp_config *c, int threads, int runs, cmp_result *r,
                    char *err, size_t errlen)
{
    cmp_prepared p;
    int rc;
    if (runs < 1) runs = 1;
    memset(r, 0, sizeof *r);
    if ((rc = cmp_prepare(v, c, &p, err, errlen)) != 0) return rc;
    if (!c->tb->thread_safe) {
        rc = run_serial(v, &p, runs, r, err, errlen);
    } else if (cmp_run(v, c->pick.f && c->pick.f->corners && !c->pick.oiio, batch_fn, &p,
                       c->tb->counts_texels, threads, runs, r)) {
        snprintf(err, errlen, "sampling failed");
        rc = TOOL_BACKEND_ERROR;
    }
    cmp_prepared_release(&p);
    return rc;
}
