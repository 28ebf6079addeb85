/* OpenImageIO's TextureSystem as a backend of the sweep (tools/oiio shim),
 * at the settings of a filter registry entry's twin (tools/filters.h).
 * Each grating goes through a mip-mapped file that oiio_ts_make_texture
 * writes as maketx would (its own 2 × 2 box levels), one file shared by
 * every OpenImageIO configuration, in one TextureSystem private to the run
 * (oiio_file). Built only when texsample has the shim. */
#define _POSIX_C_SOURCE 200809L
#include "freq_cli.h"

#ifdef TEXSAMPLE_HAVE_OIIO
#include "oiio_ts.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct oiio_ctx {
    fq_oiio_file *file;
    oiio_ts_opts opts;
} oiio_ctx;

void fq_oiio_file_clear(fq_oiio_file *file)
{
    if (file->texels) remove(file->path);
    free(file->texels);
    file->texels = NULL;
    file->count = 0;
    oiio_ts_destroy(file->ts);
    file->ts = NULL;
    file->handle = NULL;
}

/* Read every tile of every level once, so that the timed lookups find the
 * file in the cache, as libsample finds its texture in memory, and the
 * first configuration measured does not pay the file reads for both. */
static void warm_up(fq_oiio_file *file, int n)
{
    enum { TILE = 64, MAXQ = 1024 };
    sample_query q[MAXQ];
    float out[4 * MAXQ];
    oiio_ts_opts o;
    int lv, size;
    oiio_ts_opts_init(&o);
    o.mode = OIIO_TS_TRILINEAR;
    for (lv = 0, size = n; size >= 1; ++lv, size /= 2) {
        int tiles = (size + TILE - 1) / TILE, i, j, k = 0;
        for (j = 0; j < tiles; ++j)
            for (i = 0; i < tiles && k < MAXQ; ++i, ++k) {
                q[k].s = (float)((i * TILE + 0.5) / size);
                q[k].t = (float)((j * TILE + 0.5) / size);
                q[k].dsdx = q[k].dtdy = (float)(1.0 / size);
                q[k].dtdx = q[k].dsdy = 0.0f;
            }
        (void)oiio_ts_sample(file->ts, file->handle, &o, q, (size_t)k, out, NULL, 0);
    }
}

/* Make sure file->handle is a file holding these texels (N × N of
 * `channels` floats). One TextureSystem serves the whole run: creating one
 * per grating grows the process by about a megabyte each time (OpenImageIO
 * keeps per-system state), while a fresh file name per grating keeps its
 * cache from ever serving an old grating; the 64 MB cache bounds memory. */
static int oiio_file(fq_oiio_file *file, const float *texels, int n, int channels, char *err,
                     size_t errlen)
{
    size_t count = (size_t)n * n * (size_t)channels, k;
    float *rgba;
    int rc;
    if (file->handle && file->count == count &&
        memcmp(file->texels, texels, count * sizeof *texels) == 0)
        return 0;
    if (file->texels) remove(file->path);
    free(file->texels);
    file->texels = NULL;
    file->handle = NULL;
    if (!file->ts) file->ts = oiio_ts_create(64.0);
    if (!file->ts) {
        snprintf(err, errlen, "OpenImageIO: cannot create a TextureSystem");
        return -1;
    }
    rgba = (float *)malloc((size_t)n * n * 4 * sizeof *rgba);
    file->texels = (float *)malloc(count * sizeof *texels);
    if (!rgba || !file->texels) {
        free(rgba);
        free(file->texels);
        file->texels = NULL;
        snprintf(err, errlen, "OpenImageIO backend: out of memory");
        return -1;
    }
    for (k = 0; k < (size_t)n * n; ++k) {
        rgba[4 * k] = texels[channels * k];
        rgba[4 * k + 1] = channels > 1 ? texels[channels * k + 1] : 0.0f;
        rgba[4 * k + 2] = 0.0f;
        rgba[4 * k + 3] = 1.0f;
    }
    snprintf(file->path, sizeof file->path, "%s/grating_%u.exr", file->dir, file->serial++);
    rc = oiio_ts_make_texture(rgba, n, n, OIIO_TS_FLOAT, SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_REPEAT,
                              file->path, err, errlen);
    free(rgba);
    if (rc == 0) file->handle = oiio_ts_open(file->ts, file->path, err, errlen);
    if (!file->handle) {
        if (rc == 0) remove(file->path);
        free(file->texels);
        file->texels = NULL;
        return -1;
    }
    memcpy(file->texels, texels, count * sizeof *texels);
    file->count = count;
    warm_up(file, n);
    return 0;
}

static void *oiio_prepare(const fq_backend *b, const sample_texture *tex, const float *texels,
                          int n, int channels, char *err, size_t errlen)
{
    const fq_oiio_cfg *cfg = (const fq_oiio_cfg *)b->config;
    oiio_ctx *c;
    (void)tex;
    if (!texels) {
        snprintf(err, errlen, "OpenImageIO backend: no texels");
        return NULL;
    }
    if (oiio_file(cfg->file, texels, n, channels, err, errlen) != 0) return NULL;
    c = (oiio_ctx *)calloc(1, sizeof *c);
    if (!c) {
        snprintf(err, errlen, "OpenImageIO backend: out of memory");
        return NULL;
    }
    c->file = cfg->file;
    oiio_ts_opts_init(&c->opts);
    tool_filter_oiio_opts(cfg->f, &c->opts);
    c->opts.wrap_s = c->opts.wrap_t = SAMPLE_WRAP_REPEAT;
    return c;
}

static int oiio_sample(void *ctx, const sample_query *q, size_t count, float *rgba,
                       double *texels, char *err, size_t errlen)
{
    oiio_ctx *c = (oiio_ctx *)ctx;
    (void)texels;
    return oiio_ts_sample(c->file->ts, c->file->handle, &c->opts, q, count, rgba, err, errlen);
}

static void oiio_release(void *ctx) { free(ctx); }

int fq_oiio_available(void) { return 1; }

void fq_oiio_file_init(fq_oiio_file *file, const char *tmp)
{
    memset(file, 0, sizeof *file);
    snprintf(file->dir, sizeof file->dir, "%s", tmp);
}

void fq_oiio_backend(const tool_pick *p, fq_oiio_file *file, fq_oiio_cfg *cfg, fq_backend *out)
{
    cfg->f = p->f;
    cfg->file = file;
    out->name = tool_pick_name(p, cfg->name, sizeof cfg->name);
    out->label = tool_pick_label(p, cfg->label, sizeof cfg->label);
    out->prepare = oiio_prepare;
    out->sample = oiio_sample;
    out->release = oiio_release;
    out->config = cfg;
    out->counts_texels = 0;
    out->driver = NULL;
}

#else

#include <string.h>

int fq_oiio_available(void) { return 0; }

void fq_oiio_file_init(fq_oiio_file *file, const char *tmp)
{
    (void)tmp;
    memset(file, 0, sizeof *file);
}

/* Never called: without the shim no OIIO pick is accepted (cmd_freq.c). */
void fq_oiio_backend(const tool_pick *p, fq_oiio_file *file, fq_oiio_cfg *cfg, fq_backend *out)
{
    (void)p;
    (void)file;
    (void)cfg;
    memset(out, 0, sizeof *out);
}

void fq_oiio_file_clear(fq_oiio_file *file) { (void)file; }

#endif
