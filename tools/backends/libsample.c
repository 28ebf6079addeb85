/* libsample as a backend (backend.h): sample_batch on the caller's texture
 * with the caller's sampler state, texels counted. */
#include "backend.h"
#include "sample/testing.h"

#include <stdlib.h>

struct tool_backend_tex {
    const sample_texture *tex;
    sample_sampler smp;
};

static int lib_prepare(tool_backend *b, const sample_texture *tex, const sample_sampler *smp,
                       tool_backend_tex **out, tool_backend_times *t, char *err, size_t errlen)
{
    tool_backend_tex *x;
    sample_status st = sample_sampler_validate(smp);
    (void)b;
    (void)t;
    if (st != SAMPLE_OK) {
        snprintf(err, errlen, "invalid sampler state: %s", sample_strerror(st));
        return TOOL_BACKEND_ERROR;
    }
    if (!(x = malloc(sizeof *x))) {
        snprintf(err, errlen, "out of memory");
        return TOOL_BACKEND_ERROR;
    }
    x->tex = tex;
    x->smp = *smp;
    *out = x;
    return 0;
}

static int lib_sample(tool_backend *b, tool_backend_tex *x, const sample_query *q, size_t n,
                      float *rgba, double *texels, tool_backend_times *t, char *err, size_t errlen)
{
    sample_batch_args a = {0};
    sample_stats *stats = NULL;
    sample_status st;
    size_t i;
    (void)t;
    /* Stats in the timed call: their cost is the same small per-query
     * store for every libsample filter (doc/frequency-tests.md §5). */
    if (texels && !(stats = malloc(n * sizeof *stats))) {
        snprintf(err, errlen, "out of memory");
        return TOOL_BACKEND_ERROR;
    }
    a.count = n;
    a.queries = q;
    a.rgba = rgba;
    a.stats = stats;
    st = (b->impl ? sample_batch_reference : sample_batch)(x->tex, &x->smp, &a);
    if (st != SAMPLE_OK) {
        snprintf(err, errlen, "sample_batch: %s", sample_strerror(st));
        free(stats);
        return TOOL_BACKEND_ERROR;
    }
    if (texels)
        for (i = 0; i < n; ++i) *texels += stats[i].texels;
    free(stats);
    return 0;
}

static void lib_release(tool_backend *b, tool_backend_tex *x)
{
    (void)b;
    free(x);
}

static void lib_close(tool_backend *b) { (void)b; }

static const tool_backend_ops lib_ops = {lib_prepare, lib_sample, lib_release, lib_close};

void tool_backend_libsample(tool_backend *b, int reference)
{
    b->ops = &lib_ops;
    snprintf(b->driver, sizeof b->driver, "libsample %s%s", SAMPLE_VERSION_STRING,
             reference ? ", reference path" : "");
    b->counts_texels = 1;
    /* impl is only a flag here: non-NULL selects the reference path. */
    b->impl = reference ? (void *)&lib_ops : NULL;
}
