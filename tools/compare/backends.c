/*
 * A row through a backend of tools/backend.h: OpenGL's twin of a registry
 * entry, or an outside program. The same queries as every other row
 * (view.c), one batch per texture, on one thread: a GL context or a
 * program is one sampler, and gathering a texture's pixels into one batch
 * keeps the draws and process starts few.
 */
#include "cmp_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Sample texture k's pixels (their indices in px) into r->rgba. */
static int run_texture(const cmp_view *v, const cmp_config *c, const sample_sampler *smp, int k,
                       const size_t *px, size_t n, sample_query *q, float *out, int runs,
                       double *sample_s, cmp_result *r, char *err, size_t errlen)
{
    tool_backend_tex *x = NULL;
    size_t i;
    int run, rc;
    for (i = 0; i < n; ++i) q[i] = v->q[px[i]];
    rc = tool_backend_prepare(c->tb, render_scene_texture(v->sc, k), smp, &x, NULL, err, errlen);
    for (run = 0; run < runs && rc == 0; ++run) {
        tool_backend_times t = {0, 0, 0};
        rc = tool_backend_sample(c->tb, x, q, n, out, NULL, &t, err, errlen);
        sample_s[run] += t.sample;
    }
    tool_backend_release(c->tb, x);
    for (i = 0; rc == 0 && i < n; ++i) memcpy(r->rgba + 4 * px[i], out + 4 * i, 4 * sizeof *out);
    return rc;
}

int cmp_run_backend(const cmp_view *v, const cmp_config *c, int runs, cmp_result *r, char *err,
                    size_t errlen)
{
    size_t npx = (size_t)v->w * (size_t)v->h, i, n;
    int ntex = render_scene_texture_count(v->sc), k, rc = 0;
    size_t *px = malloc(npx * sizeof *px);
    sample_query *q = malloc(npx * sizeof *q);
    float *out = malloc(npx * 4 * sizeof *out);
    double *sample_s = calloc((size_t)(runs < 1 ? 1 : runs), sizeof *sample_s), t0 = cmp_now();
    sample_sampler smp;
    if (runs < 1) runs = 1;
    memset(r, 0, sizeof *r);
    r->rgba = malloc(npx * 4 * sizeof *r->rgba);
    if (!px || !q || !out || !sample_s || !r->rgba) {
        snprintf(err, errlen, "out of memory for %zu pixels", npx);
        rc = TOOL_BACKEND_ERROR;
        goto done;
    }
    cmp_config_sampler(c, &v->sampler, &smp);
    cmp_fill_untextured(v, r->rgba);
    for (k = 0; k < ntex && rc == 0; ++k) {
        for (i = 0, n = 0; i < npx; ++i)
            if (v->tex[i] == k) px[n++] = i;
        if (n) rc = run_texture(v, c, &smp, k, px, n, q, out, runs, sample_s, r, err, errlen);
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
