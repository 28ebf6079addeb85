/* libsample as a backend (backend.h): sample_batch on the caller's texture
 * with the caller's sampler state, texels counted; direction queries
 * through sample_batch_env, volume queries through sample_batch_3d; or a
 * caller's batch function with its context (a texture system's batch). One
 * prepared texture serves any number of threads (sample.h: the batch
 * calls only read the texture and the sampler). */
#include "backend.h"

#include <stdlib.h>
#include <string.h>

struct tool_backend_tex {
    const sample_texture *tex;
    sample_sampler smp;
    int volume; /* a 3D texture: q3 are volume queries (sample_batch_3d) */
};

static int lib_prepare(tool_backend *b, const sample_texture *tex, const sample_sampler *smp,
                       tool_backend_tex **out, tool_backend_times *t, char *err, size_t errlen)
{
    tool_backend_tex *x;
    sample_texture_info info;
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
    sample_texture_info_get(tex, &info);
    x->tex = tex;
    x->smp = *smp;
    x->volume = info.kind == SAMPLE_TEXTURE_3D;
    *out = x;
    return 0;
}

typedef struct lib_impl {
    tool_batch_fn batch;
    tool_batch_ctx_fn batch_ctx; /* with ctx, instead of batch */
    void *ctx;
} lib_impl;

static int lib_run(tool_backend *b, tool_backend_tex *x, const tool_backend_batch *a,
                   tool_backend_times *t, char *err, size_t errlen)
{
    const lib_impl *l = b->impl;
    sample_status st;
    (void)t;
    if (a->q3 && l->batch_ctx) {
        snprintf(err, errlen, "no direction or volume queries through %s", b->driver);
        return TOOL_BACKEND_NA;
    }
    if (a->q3 && a->u) {
        /* sample_batch3_args has no u: the 3D and environment paths are
         * deterministic. */
        snprintf(err, errlen, "no stochastic draws for direction or volume queries");
        return TOOL_BACKEND_NA;
    }
    if (a->q3) {
        sample_batch3_args a3 = {0};
        a3.count = a->count;
        a3.queries = a->q3;
        a3.rgba = a->rgba;
        a3.stats = a->stats;
        st = (x->volume ? sample_batch_3d : sample_batch_env)(x->tex, &x->smp, &a3);
    } else {
        sample_batch_args a2 = {0};
        a2.count = a->count;
        a2.queries = a->q;
        a2.corners = a->corners;
        a2.rgba = a->rgba;
        a2.stats = a->stats;
        a2.u = a->u;
        a2.draws = a->draws;
        st = l->batch_ctx ? l->batch_ctx(l->ctx, x->tex, &x->smp, &a2) : l->batch(x->tex, &x->smp, &a2);
    }
    if (st != SAMPLE_OK) {
        snprintf(err, errlen, "sample_batch: %s", sample_strerror(st));
        return TOOL_BACKEND_ERROR;
    }
    return 0;
}

static void lib_release(tool_backend *b, tool_backend_tex *x)
{
    (void)b;
    free(x);
}

static void lib_close(tool_backend *b) { free(b->impl); }

static const tool_backend_ops lib_ops = {.prepare = lib_prepare,
                                         .prepare_env = lib_prepare,
                                         .run = lib_run,
                                         .release = lib_release,
                                         .close = lib_close};

/* Both openings: batch or batch_ctx set. */
static int lib_open(tool_backend *b, tool_batch_fn batch, tool_batch_ctx_fn batch_ctx, void *ctx)
{
    lib_impl *l = calloc(1, sizeof *l);
    memset(b, 0, sizeof *b);
    if (!l) return TOOL_BACKEND_ERROR;
    l->batch = batch;
    l->batch_ctx = batch_ctx;
    l->ctx = ctx;
    b->ops = &lib_ops;
    b->counts_texels = 1;
    b->thread_safe = 1;
    b->impl = l;
    return 0;
}

int tool_backend_libsample(tool_backend *b, tool_batch_fn batch)
{
    if (lib_open(b, batch ? batch : sample_batch, NULL, NULL) != 0) return TOOL_BACKEND_ERROR;
    snprintf(b->driver, sizeof b->driver, "libsample %s%s", SAMPLE_VERSION_STRING,
             batch && batch != sample_batch ? ", reference path" : "");
    return 0;
}

int tool_backend_libsample_ctx(tool_backend *b, tool_batch_ctx_fn batch, void *ctx,
                               const char *driver)
{
    if (lib_open(b, NULL, batch, ctx) != 0) return TOOL_BACKEND_ERROR;
    snprintf(b->driver, sizeof b->driver, "libsample %s, %s", SAMPLE_VERSION_STRING, driver);
    return 0;
}
