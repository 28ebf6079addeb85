/* freq's rows on the backends of tools/backend.h: registry entries on
 * libsample, their OpenImageIO and OpenGL twins, and outside programs,
 * each asked the same gratings and queries. Only the interface is called
 * here, so the texsample_freq library stays free of EGL and OpenImageIO
 * (texsample opens those backends). */
#include "backend.h"
#include "freq.h"

#include <stdio.h>
#include <stdlib.h>

/* The row's sampler: freq's REPEAT, the entry's filter settings. */
static void row_sampler(const fq_tool_cfg *c, sample_sampler *s)
{
    sample_sampler_init(s);
    s->wrap_s = s->wrap_t = SAMPLE_WRAP_REPEAT;
    if (c->f) tool_filter_apply(c->f, s);
}

/* What the sweep holds between prepare and release. */
typedef struct tb_ctx {
    tool_backend *tb;
    tool_backend_tex *x;
} tb_ctx;

static void *tb_prepare(const fq_backend *b, const sample_texture *tex, const float *texels, int n,
                        int channels, char *err, size_t errlen)
{
    const fq_tool_cfg *c = (const fq_tool_cfg *)b->config;
    tb_ctx *ctx = malloc(sizeof *ctx);
    sample_sampler s;
    (void)texels;
    (void)n;
    (void)channels;
    if (!ctx) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    row_sampler(c, &s);
    ctx->tb = c->tb;
    if (tool_backend_prepare(c->tb, tex, &s, &ctx->x, NULL, err, errlen) != 0) {
        free(ctx);
        return NULL;
    }
    return ctx;
}

static int tb_sample(void *ctx, const sample_query *q, size_t count, float *rgba, double *texels,
                     char *err, size_t errlen)
{
    tb_ctx *c = ctx;
    return tool_backend_sample(c->tb, c->x, q, count, rgba, texels, NULL, err, errlen) == 0 ? 0 : -1;
}

static void tb_release(void *ctx)
{
    tb_ctx *c = ctx;
    tool_backend_release(c->tb, c->x);
    free(c);
}

void fq_tool_backend(tool_backend *tb, const tool_filter *f, const char *name, const char *label,
                     const char *driver, fq_tool_cfg *cfg, fq_backend *out)
{
    cfg->tb = tb;
    cfg->f = f;
    snprintf(cfg->name, sizeof cfg->name, "%s", name);
    snprintf(cfg->label, sizeof cfg->label, "%s", label);
    out->name = cfg->name;
    out->label = cfg->label;
    out->prepare = tb_prepare;
    out->sample = tb_sample;
    out->release = tb_release;
    out->config = cfg;
    out->counts_texels = tb->counts_texels;
    out->driver = driver;
}

int fq_libsample_backend(const tool_filter *f, fq_tool_cfg *cfg, fq_backend *out)
{
    if (tool_backend_libsample(&cfg->own, NULL) != 0) return -1;
    fq_tool_backend(&cfg->own, f, tool_filter_name(f), f->label, NULL, cfg, out);
    return 0;
}

int fq_tool_probe(const fq_backend *b, char *err, size_t errlen)
{
    enum { N = 16 };
    const fq_tool_cfg *c = (const fq_tool_cfg *)b->config;
    static float texels[N * N];
    sample_query q = {0.5f, 0.5f, 1.0f / N, 0.0f, 0.0f, 1.0f / N};
    sample_texture *tex = NULL;
    sample_error serr;
    sample_sampler s;
    tool_backend_tex *x = NULL;
    float rgba[4];
    int rc;
    if (fq_texture_create(texels, N, 1, &tex, &serr) != SAMPLE_OK) {
        snprintf(err, errlen, "%s", serr.message);
        return TOOL_BACKEND_ERROR;
    }
    row_sampler(c, &s);
    rc = tool_backend_prepare(c->tb, tex, &s, &x, NULL, err, errlen);
    if (rc == 0) {
        rc = tool_backend_sample(c->tb, x, &q, 1, rgba, NULL, NULL, err, errlen);
        tool_backend_release(c->tb, x);
    }
    sample_texture_destroy(tex);
    return rc;
}
