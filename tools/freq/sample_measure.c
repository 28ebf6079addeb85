/* The frequency test as a C API (sample_measure.h): registry filters
 * through freq's libsample backend (filters.c), callbacks through a
 * backend of their own, the sweep and summary as texsample freq runs
 * them. */
#include "sample_measure.h"

#include "freq.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct sample_freq_result {
    fq_plan plan;
    double *lists; /* m, θ, r: the plan's copies */
    fq_sweep sweep;
};

typedef struct fn_ctx {
    const sample_measure_filter *filter;
    const sample_texture *tex;
} fn_ctx;

static void *fn_prepare(const fq_backend *b, const sample_texture *tex, const float *texels, int n,
                        int channels, char *err, size_t errlen)
{
    fn_ctx *c = (fn_ctx *)malloc(sizeof *c);
    (void)texels;
    (void)n;
    (void)channels;
    if (!c) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    c->filter = (const sample_measure_filter *)b->config;
    c->tex = tex;
    return c;
}

static int fn_sample(void *ctx, const sample_query *q, size_t count, float *rgba, double *texels, char *err,
                     size_t errlen)
{
    fn_ctx *c = (fn_ctx *)ctx;
    (void)texels;
    err[0] = '\0';
    if (c->filter->fn(c->filter->user, c->tex, q, count, rgba, err, errlen) == 0) return 0;
    if (!err[0]) snprintf(err, errlen, "filter %s failed", c->filter->name ? c->filter->name : "(callback)");
    return -1;
}

static void fn_release(void *ctx) { free(ctx); }

int sample_freq_run(const sample_freq_params *params, const sample_measure_filter *filters, int nfilters,
                    sample_freq_result **out, char *err, size_t errlen)
{
    sample_freq_result *res;
    fq_backend *backends;
    fq_tool_cfg *cfgs;
    const fq_backend **list;
    size_t nl;
    int k, rc;
    *out = NULL;
    if (!params || !filters || nfilters < 1 || params->nm < 1 || params->ntheta < 1 || params->nr < 1 ||
        params->n < 2 || (params->n & (params->n - 1)) != 0 || !(params->f_step > 0.0) ||
        !(params->f_max > 0.0) || params->width < 1 || params->rows < 1 || params->phases < 1) {
        snprintf(err, errlen, "sample_freq_run: every list needs an entry, n a power of two >= 2, "
                              "f_step, f_max, width, rows and phases > 0");
        return -1;
    }
    for (k = 0; k < params->nr; ++k)
        if (!(params->r[k] >= 1.0)) {
            snprintf(err, errlen, "sample_freq_run: r = %g; anisotropy ratios are >= 1", params->r[k]);
            return -1;
        }
    for (k = 0; k < params->nm; ++k)
        if (!(params->m[k] > 0.0)) {
            snprintf(err, errlen, "sample_freq_run: m = %g; minifications are > 0", params->m[k]);
            return -1;
        }
    nl = (size_t)params->nm + (size_t)params->ntheta + (size_t)params->nr;
    res = (sample_freq_result *)calloc(1, sizeof *res);
    backends = (fq_backend *)calloc((size_t)nfilters, sizeof *backends);
    cfgs = (fq_tool_cfg *)calloc((size_t)nfilters, sizeof *cfgs);
    list = (const fq_backend **)calloc((size_t)nfilters, sizeof *list);
    if (res) res->lists = (double *)malloc(nl * sizeof *res->lists);
    if (!res || !backends || !cfgs || !list || !res->lists) {
        snprintf(err, errlen, "out of memory");
        rc = -1;
        goto done;
    }
    for (k = 0; k < nfilters; ++k) {
        const sample_measure_filter *f = &filters[k];
        if (f->fn) {
            backends[k].name = backends[k].label = f->name ? f->name : "callback";
            backends[k].prepare = fn_prepare;
            backends[k].sample = fn_sample;
            backends[k].release = fn_release;
            backends[k].config = f;
            backends[k].counts_texels = 0;
        } else {
            const tool_filter *tf = f->name ? tool_filter_by_name(f->name) : NULL;
            if (!tf || tf->corners) {
                snprintf(err, errlen, "sample_freq_run: '%s' is not a filter of the registry that runs on "
                                      "Jacobians alone", f->name ? f->name : "(null)");
                rc = -1;
                goto done;
            }
            if (fq_libsample_backend(tf, &cfgs[k], &backends[k]) != 0) {
                snprintf(err, errlen, "out of memory");
                rc = -1;
                goto done;
            }
        }
        list[k] = &backends[k];
    }
    memcpy(res->lists, params->m, (size_t)params->nm * sizeof *res->lists);
    memcpy(res->lists + params->nm, params->theta_deg, (size_t)params->ntheta * sizeof *res->lists);
    memcpy(res->lists + params->nm + params->ntheta, params->r, (size_t)params->nr * sizeof *res->lists);
    res->plan.m = res->lists;
    res->plan.nm = params->nm;
    res->plan.theta_deg = res->lists + params->nm;
    res->plan.ntheta = params->ntheta;
    res->plan.r = res->lists + params->nm + params->ntheta;
    res->plan.nr = params->nr;
    res->plan.n = params->n;
    res->plan.f_step = params->f_step;
    res->plan.f_max = params->f_max;
    res->plan.width = params->width;
    res->plan.rows = params->rows;
    res->plan.phases = params->phases;
    res->plan.backends = list;
    res->plan.nbackends = nfilters;
    rc = fq_sweep_run(&res->plan, &res->sweep, err, errlen);
    /* The summary needs the plan's lists only, not the backends. */
    res->plan.backends = NULL;
done:
    for (k = 0; cfgs && k < nfilters; ++k) tool_backend_close(&cfgs[k].own);
    free(backends);
    free(cfgs);
    free(list);
    if (rc == 0)
        *out = res;
    else
        sample_freq_free(res);
    return rc;
}

size_t sample_freq_count(const sample_freq_result *res) { return res ? res->sweep.count : 0; }

void sample_freq_points(const sample_freq_result *res, sample_freq_point *out)
{
    size_t i;
    for (i = 0; res && i < res->sweep.count; ++i) {
        const fq_point *p = &res->sweep.pts[i];
        sample_freq_point *o = &out[i];
        o->filter = p->backend;
        o->im = p->im;
        o->itheta = p->itheta;
        o->ir = p->ir;
        o->p = p->wave.p;
        o->q = p->wave.q;
        o->f = p->wave.f;
        o->F = p->res.F;
        o->alias_F = p->res.alias_F;
        o->re = p->res.re;
        o->im_ = p->res.im;
        o->amp = p->res.amp;
        o->stderr_ = p->res.stderr_;
        o->residual = p->res.residual;
        o->texels = p->res.texels;
        o->ns = p->res.ns;
    }
}

sample_freq_summary sample_freq_summarize(const sample_freq_result *res, int filter, int im, int ir)
{
    sample_freq_summary s = {0};
    fq_stat st;
    if (!res || filter < 0 || filter >= res->plan.nbackends) return s;
    st = fq_summarize(&res->plan, &res->sweep, filter, im, ir);
    s.pass = st.pass;
    s.pass_worst = st.pass_worst;
    s.alias = st.alias;
    s.alias_worst = st.alias_worst;
    s.texels = st.texels;
    s.ns = st.ns;
    s.npass = st.npass;
    s.nstop = st.nstop;
    return s;
}

void sample_freq_free(sample_freq_result *res)
{
    if (!res) return;
    fq_sweep_free(&res->sweep);
    free(res->lists);
    free(res);
}
