/* The backend that runs the engine's filter configurations under test
 * (DESIGN §9) through sample_batch; the configurations are the filter
 * registry's entries (tools/filters.h). */
#include "freq.h"

#include <stdio.h>
#include <stdlib.h>

typedef struct lib_ctx {
    const sample_texture *tex;
    sample_sampler smp;
} lib_ctx;

static void *lib_prepare(const fq_backend *b, const sample_texture *tex, const float *texels,
                         int n, int channels, char *err, size_t errlen)
{
    const tool_filter *f = (const tool_filter *)b->config;
    lib_ctx *c = (lib_ctx *)malloc(sizeof *c);
    (void)texels;
    (void)n;
    (void)channels;
    if (!c) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    c->tex = tex;
    sample_sampler_init(&c->smp);
    c->smp.wrap_s = c->smp.wrap_t = SAMPLE_WRAP_REPEAT;
    tool_filter_apply(f, &c->smp);
    return c;
}

static int lib_sample(void *ctx, const sample_query *q, size_t count, float *rgba,
                      double *texels, char *err, size_t errlen)
{
    lib_ctx *c = (lib_ctx *)ctx;
    sample_batch_args a = {0};
    sample_status st;
    size_t i;
    /* Stats are collected in the timed call: their cost is the same small
     * per-query store for every libsample filter (doc §5). */
    sample_stats *stats = (sample_stats *)malloc(count * sizeof *stats);
    if (!stats) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    a.count = count;
    a.queries = q;
    a.rgba = rgba;
    a.stats = stats;
    st = sample_batch(c->tex, &c->smp, &a);
    if (st != SAMPLE_OK) {
        snprintf(err, errlen, "sample_batch: %s", sample_strerror(st));
        free(stats);
        return -1;
    }
    for (i = 0; i < count; ++i) *texels += stats[i].texels;
    free(stats);
    return 0;
}

static void lib_release(void *ctx) { free(ctx); }

const char *const fq_default_filters[] = {
    "nearest", "bilinear", "nearest_mipmap_nearest", "trilinear", "aniso16",
    "cubic_mipmap_linear", "blinn-newell", "ewa", "oiio-trilinear", "oiio-aniso16", NULL,
};

void fq_libsample_backend(const tool_filter *f, fq_backend *out)
{
    out->name = tool_filter_name(f);
    out->label = f->label;
    out->prepare = lib_prepare;
    out->sample = lib_sample;
    out->release = lib_release;
    out->config = f;
    out->counts_texels = 1;
    out->driver = NULL;
}
