/* The comparison against the ground truth as a C API (sample_measure.h):
 * the view, truth, runs and metrics of texsample compare (cmd_compare.c
 * runs the same functions), with filters as registry names or callbacks. */
#include "sample_measure.h"

#include "cmp_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct sample_compare_result {
    int w, h, nfilters;
    cmp_truth truth;
    float **images;
    sample_compare_metrics *metrics;
};

typedef struct fn_ctx {
    const sample_measure_filter *f;
    const render_scene *sc;
    char err[256];
} fn_ctx;

static int fn_batch(void *ctx, int texture, const size_t *px, const sample_query *q, const sample_query3 *q3,
                    const sample_quad *quad, size_t n, float *rgba, sample_stats *stats)
{
    fn_ctx *c = (fn_ctx *)ctx;
    (void)px;
    (void)quad;
    (void)stats;
    if (q3) {
        /* An environment map's or a solid texture's 3D queries: a
         * filter callback takes 2D queries (sample_measure.h). */
        snprintf(c->err, sizeof c->err, "a filter callback takes 2D queries; this scene's environment map or "
                                        "solid textures take 3D queries");
        return 1;
    }
    return c->f->fn(c->f->user, render_scene_texture(c->sc, texture), q, n, rgba, c->err, sizeof c->err) != 0;
}

/* Run filter k over the view into res. Returns 0, or −1 with a message. */
static int run_filter(const sample_compare_params *p, const cmp_view *v, const sample_measure_filter *f, int k,
                      sample_compare_result *res, char *err, size_t errlen)
{
    cmp_result r;
    cmp_metrics m;
    size_t n = (size_t)v->w * (size_t)v->h;
    sample_compare_metrics *o = &res->metrics[k];
    if (f->fn) {
        fn_ctx c;
        c.f = f;
        c.sc = v->sc;
        c.err[0] = '\0';
        /* One thread: a callback into an interpreter runs one call at a time. */
        if (cmp_run(v, 0, fn_batch, &c, 0, 1, 1, &r)) {
            snprintf(err, errlen, "%s", c.err[0] ? c.err : "a filter callback failed");
            return -1;
        }
    } else {
        cmp_config cfg;
        tool_backend lib;
        char perr[256];
        /* libsample's entries, corner mode included; not OpenImageIO's twins. */
        if (!f->name || cmp_configs_parse(f->name, TOOL_PICK_CORNERS, &cfg, 1, perr, sizeof perr) != 1) {
            snprintf(err, errlen, "sample_compare_run: '%s' is not a libsample filter of the registry",
                     f->name ? f->name : "(null)");
            return -1;
        }
        int rc;
        if (tool_backend_libsample(&lib, NULL) != 0) {
            snprintf(err, errlen, "out of memory");
            return -1;
        }
        cfg.tb = &lib;
        rc = cmp_run_backend(v, &cfg, p->threads, 1, &r, err, errlen);
        tool_backend_close(&lib);
        if (rc) return -1;
    }
    cmp_metrics_compute(r.rgba, res->truth.rgba, res->truth.mask, n, &m);
    o->rmse = m.rmse;
    o->psnr = m.psnr;
    o->max_err = m.max_err;
    o->count = (double)m.count;
    o->seconds = r.seconds;
    o->ns_per_sample = r.ns_per_sample;
    o->texels = r.texels;
    res->images[k] = r.rgba;
    return 0;
}

int sample_compare_run(const sample_compare_params *p, const sample_measure_filter *filters, int nfilters,
                       sample_compare_result **out, char *err, size_t errlen)
{
    render_scene *sc = NULL;
    sample_compare_result *res;
    cmp_view v;
    char label[64];
    int k, rc = -1;
    *out = NULL;
    if (!p || !p->scene || !filters || nfilters < 1 || p->size < 1 || p->truth < 2 || p->truth % 2 != 0 ||
        p->threads < 1) {
        snprintf(err, errlen, "sample_compare_run: a scene, one filter or more, size >= 1, truth even "
                              "and >= 2, threads >= 1");
        return -1;
    }
    memset(&v, 0, sizeof v);
    res = (sample_compare_result *)calloc(1, sizeof *res);
    if (res) {
        res->images = (float **)calloc((size_t)nfilters, sizeof *res->images);
        res->metrics = (sample_compare_metrics *)calloc((size_t)nfilters, sizeof *res->metrics);
        res->nfilters = nfilters;
    }
    if (!res || !res->images || !res->metrics) {
        snprintf(err, errlen, "out of memory");
        goto done;
    }
    if (cmp_scene_open(p->scene, p->size, RENDER_CACHE_MB, &sc, label, sizeof label, err, errlen)) goto done;
    if (cmp_view_build(sc, p->threads, &v, err, errlen)) goto done;
    res->w = v.w;
    res->h = v.h;
    if (cmp_truth_build(&v, p->truth, p->threads, &res->truth, err, errlen)) goto done;
    for (k = 0; k < nfilters; ++k)
        if (run_filter(p, &v, &filters[k], k, res, err, errlen)) goto done;
    rc = 0;
done:
    cmp_view_free(&v);
    render_scene_destroy(sc);
    if (rc == 0)
        *out = res;
    else
        sample_compare_free(res);
    return rc;
}

void sample_compare_size(const sample_compare_result *res, int *w, int *h)
{
    *w = res ? res->w : 0;
    *h = res ? res->h : 0;
}

const float *sample_compare_truth(const sample_compare_result *res) { return res ? res->truth.rgba : NULL; }

const unsigned char *sample_compare_mask(const sample_compare_result *res) { return res ? res->truth.mask : NULL; }

const float *sample_compare_image(const sample_compare_result *res, int filter)
{
    return res && filter >= 0 && filter < res->nfilters ? res->images[filter] : NULL;
}

sample_compare_metrics sample_compare_metrics_get(const sample_compare_result *res, int filter)
{
    sample_compare_metrics m = {0};
    if (res && filter >= 0 && filter < res->nfilters) m = res->metrics[filter];
    return m;
}

void sample_compare_free(sample_compare_result *res)
{
    int k;
    if (!res) return;
    for (k = 0; res->images && k < res->nfilters; ++k) free(res->images[k]);
    free(res->images);
    free(res->metrics);
    cmp_truth_free(&res->truth);
    free(res);
}
