/*
 * OpenImageIO's TextureSystem as a backend (backend.h), the industry
 * reference of compare, freq and bench: a registry entry's twin settings
 * (tools/filters.h: by default aniso16's, MipModeAniso with 16 probes) on
 * OpenImageIO's own mip file, made as maketx would from libsample's base
 * level (oiio_ts_make_texture: its own 2 × 2 box levels), asked the same
 * queries with the same derivatives as every other row.
 *
 * OpenImageIO reads textures from files, so prepare writes one into the
 * store's private folder. The backends opened on one store share its
 * TextureSystem and its files: a file is kept while any row holds it and
 * until a new one is written, so rows asked the same texels read the same
 * file, and a fresh file name per content keeps the cache from serving old
 * texels. Each new file is read once through (every tile of every level) so
 * that the timed lookups find it in the cache, as libsample finds its
 * texture in memory. Built into texsample where it has the OpenImageIO shim.
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */
#include "backend.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef TEXSAMPLE_HAVE_OIIO
#include <unistd.h>
#ifdef TEXSAMPLE_HAVE_IO
#include "sample/sample_io.h"
#endif

enum { STORE_FILES = 16 };

/* One file the store wrote, and what it holds. */
typedef struct store_file {
    char path[640];
    float *rgba; /* base level, w × h × 4: the key with the rest */
    int w, h, env;
    oiio_ts_format fmt; /* the file's texel format */
    sample_wrap wrap_s, wrap_t;
    oiio_ts_tex *handle;
    int refs; /* prepared textures using it */
    /* The texture last prepared on it: while refs > 0 that texture is
     * alive (a prepared texture is released before its texture is
     * destroyed) and unchanged (libsample's textures are immutable), so
     * the same pointer with the same key holds the same texels. */
    const sample_texture *src;
} store_file;

struct tool_oiio_store {
    oiio_ts *ts;
    char dir[512];
    unsigned serial;
    int native; /* tool_oiio_store_native_formats */
    store_file file[STORE_FILES];
};

struct tool_backend_tex {
    store_file *file;
    store_file own; /* file: an existing file (tool_backend_oiio_prepare_file) */
};

int tool_oiio_available(void) { return 1; }

tool_oiio_store *tool_oiio_store_open(double cache_mb, char *err, size_t errlen)
{
    return tool_oiio_store_open_in(cache_mb, NULL, err, errlen);
}

tool_oiio_store *tool_oiio_store_open_in(double cache_mb, const char *base, char *err, size_t errlen)
{
    tool_oiio_store *s = calloc(1, sizeof *s);
    if (!base || !*base) base = getenv("TMPDIR");
    if (!s) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    snprintf(s->dir, sizeof s->dir, "%s/texsample-oiio-XXXXXX", base && *base ? base : "/tmp");
    if (!mkdtemp(s->dir)) {
        snprintf(err, errlen, "cannot make a folder for OpenImageIO's files under %s",
                 base && *base ? base : "/tmp");
        free(s);
        return NULL;
    }
    if (!(s->ts = oiio_ts_create(cache_mb))) {
        snprintf(err, errlen, "OpenImageIO: cannot create a TextureSystem");
        rmdir(s->dir);
        free(s);
        return NULL;
    }
    return s;
}

void tool_oiio_store_native_formats(tool_oiio_store *s) { s->native = 1; }

/* The format a file of tex is written in (tool_oiio_store_native_formats). */
static oiio_ts_format file_format(const tool_oiio_store *s, const sample_texture_info *info, int env)
{
    if (!s->native || env) return OIIO_TS_FLOAT;
    switch (info->format) {
    case SAMPLE_FORMAT_F16: return OIIO_TS_HALF;
    case SAMPLE_FORMAT_UNORM8:
    case SAMPLE_FORMAT_SRGB8: return OIIO_TS_UINT8;
    default: return OIIO_TS_FLOAT;
    }
}

/* An sRGB texture's 256 decodings (sample_srgb_to_linear, which the
 * texture's exact decoding matches within an ulp, far less than half a gap
 * between codes) and, for each of SRGB_BUCKETS equal steps of [0, 1], the
 * last code whose decoding lies at or below the step's start: a value's
 * code is then a step or two past its bucket's. */
enum { SRGB_BUCKETS = 1024 };
typedef struct srgb_codes {
    float lin[256];
    unsigned char first[SRGB_BUCKETS];
} srgb_codes;

static void srgb_codes_init(srgb_codes *t)
{
    int b, c = 0;
    for (b = 0; b < 256; ++b) t->lin[b] = sample_srgb_to_linear((float)b / 255.0f);
    for (b = 0; b < SRGB_BUCKETS; ++b) {
        while (c < 255 && t->lin[c + 1] <= (float)b / SRGB_BUCKETS) ++c;
        t->first[b] = (unsigned char)c;
    }
}

/* The code whose decoding is nearest v, over 255. */
static float srgb_code(const srgb_codes *t, float v)
{
    float x = v * SRGB_BUCKETS;
    int lo = t->first[x <= 0.0f ? 0 : x >= SRGB_BUCKETS - 1 ? SRGB_BUCKETS - 1 : (int)x], hi;
    while (lo < 255 && t->lin[lo + 1] <= v) ++lo;
    hi = lo < 255 ? lo + 1 : 255;
    return (float)(v - t->lin[lo] <= t->lin[hi] - v ? lo : hi) / 255.0f;
}

/* The values OpenImageIO's file is made from for texel (linear RGBA, in
 * place): for an 8-bit texture its codes / 255 exactly — an sRGB
 * texture's colour channels by the code whose decoding is nearest, its
 * alpha linear (GL 4.6 §8.24). Exact quotients matter beyond the base
 * level: make_texture's 2 × 2 box averages land on half codes, where a
 * rounding error would pick the other code. */
static void file_values(sample_format fmt, oiio_ts_format ofmt, const srgb_codes *t, float rgba[4])
{
    int c;
    if (ofmt != OIIO_TS_UINT8) return;
    for (c = 0; c < 4; ++c)
        rgba[c] = c < 3 && fmt == SAMPLE_FORMAT_SRGB8 ? srgb_code(t, rgba[c])
                                                      : floorf(rgba[c] * 255.0f + 0.5f) / 255.0f;
}

static void file_drop(store_file *f)
{
    if (f->rgba) remove(f->path);
    free(f->rgba);
    memset(f, 0, sizeof *f);
}

void tool_oiio_store_close(tool_oiio_store *s)
{
    int k;
    if (!s) return;
    oiio_ts_destroy(s->ts);
    for (k = 0; k < STORE_FILES; ++k) file_drop(&s->file[k]);
    rmdir(s->dir);
    free(s);
}

/* Read every tile of every level once (see the top). */
static void warm_up(tool_oiio_store *s, store_file *f)
{
    enum { TILE = 64, MAXQ = 1024 };
    sample_query q[MAXQ];
    float out[4 * MAXQ];
    oiio_ts_opts o;
    int w = f->w, h = f->h;
    oiio_ts_opts_init(&o);
    o.mode = OIIO_TS_TRILINEAR;
    for (;;) {
        int tw = (w + TILE - 1) / TILE, th = (h + TILE - 1) / TILE, i, j, k = 0;
        for (j = 0; j < th; ++j)
            for (i = 0; i < tw && k < MAXQ; ++i, ++k) {
                q[k].s = (float)((i * TILE + 0.5) / w);
                q[k].t = (float)((j * TILE + 0.5) / h);
                q[k].dsdx = (float)(1.0 / w);
                q[k].dtdy = (float)(1.0 / h);
                q[k].dtdx = q[k].dsdy = 0.0f;
            }
        (void)oiio_ts_sample(s->ts, f->handle, &o, q, (size_t)k, out, NULL, 0);
        if (w == 1 && h == 1) break;
        w = w > 1 ? w / 2 : 1;
        h = h > 1 ? h / 2 : 1;
    }
}

/* Write the file: OpenImageIO's mip file of the base level, or its
 * lat-long environment map (the same texels and pyramid, with the
 * attributes that make OpenImageIO read it as a y-up lat-long map with
 * texel centres at (i + ½)/w: sample_io_write_env). */
static int file_write(tool_oiio_store *s, store_file *f, const sample_texture *tex, char *err,
                      size_t errlen)
{
    /* OpenImageIO 2.4's TIFF writer cannot hold half, nor OpenEXR 8-bit
     * (oiio_ts.h): in the texture's own format .tx (TIFF, as maketx
     * writes) for float and 8-bit, .exr for half; float files otherwise
     * .exr. */
    snprintf(f->path, sizeof f->path, "%s/%s%u.%s", s->dir, f->env ? "environment" : "texture",
             s->serial++, s->native && !f->env && f->fmt != OIIO_TS_HALF ? "tx" : "exr");
    if (f->env) {
#ifdef TEXSAMPLE_HAVE_IO
        sample_io_exr_options o;
        sample_error e;
        sample_io_exr_options_init(&o);
        o.use_float = 1;
        if (sample_io_write_env(f->path, tex, &o, &e) != SAMPLE_OK) {
            snprintf(err, errlen, "%s", e.message);
            return -1;
        }
#else
        (void)tex;
        snprintf(err, errlen, "this build has no libsample_io to write the environment map");
        return -1;
#endif
    } else if (oiio_ts_make_texture(f->rgba, f->w, f->h, f->fmt, f->wrap_s, f->wrap_t,
                                    f->path, err, errlen) != 0) {
        return -1;
    }
    if (!(f->handle = oiio_ts_open(s->ts, f->path, err, errlen))) {
        remove(f->path);
        return -1;
    }
    warm_up(s, f);
    return 0;
}

/* The store's file holding this texture (written if no file holds it). */
static store_file *store_get(tool_oiio_store *s, const sample_texture *tex, const sample_sampler *smp,
                             int env, char *err, size_t errlen)
{
    sample_texture_info info;
    store_file key, *f = NULL;
    srgb_codes codes;
    size_t bytes;
    int i, j, k;
    sample_texture_info_get(tex, &info);
    memset(&key, 0, sizeof key);
    key.w = info.width;
    key.h = info.height;
    key.env = env;
    key.fmt = file_format(s, &info, env);
    key.wrap_s = env ? SAMPLE_WRAP_REPEAT : smp->wrap_s;
    key.wrap_t = env ? SAMPLE_WRAP_REPEAT : smp->wrap_t;
    key.src = tex;
    /* A texture another row holds: no need to read its texels again (a
     * timing prepares a row per measurement on a texture of millions). */
    for (k = 0; k < STORE_FILES; ++k) {
        store_file *c = &s->file[k];
        if (c->refs > 0 && c->src == tex && c->env == env && c->fmt == key.fmt &&
            c->wrap_s == key.wrap_s && c->wrap_t == key.wrap_t)
            return c;
    }
    bytes = sizeof *key.rgba * 4 * (size_t)key.w * (size_t)key.h;
    if (!(key.rgba = malloc(bytes))) {
        snprintf(err, errlen, "out of memory for a %d x %d texture", key.w, key.h);
        return NULL;
    }
    if (info.format == SAMPLE_FORMAT_SRGB8 && key.fmt == OIIO_TS_UINT8) srgb_codes_init(&codes);
    for (j = 0; j < key.h; ++j)
        for (i = 0; i < key.w; ++i) {
            float *p = key.rgba + ((size_t)j * (size_t)key.w + (size_t)i) * 4;
            sample_texture_texel(tex, 0, i, j, p);
            file_values(info.format, key.fmt, &codes, p);
        }
    for (k = 0; k < STORE_FILES; ++k) {
        store_file *c = &s->file[k];
        if (c->rgba && c->w == key.w && c->h == key.h && c->env == env && c->fmt == key.fmt &&
            c->wrap_s == key.wrap_s && c->wrap_t == key.wrap_t && memcmp(c->rgba, key.rgba, bytes) == 0) {
            free(key.rgba);
            c->src = tex;
            return c;
        }
    }
    /* A new file: the files no row holds give way. */
    for (k = 0; k < STORE_FILES; ++k) {
        if (!s->file[k].refs) file_drop(&s->file[k]);
        if (!f && !s->file[k].rgba) f = &s->file[k];
    }
    if (!f) {
        free(key.rgba);
        snprintf(err, errlen, "more than %d OpenImageIO textures at once", STORE_FILES);
        return NULL;
    }
    *f = key;
    if (file_write(s, f, tex, err, errlen) != 0) {
        free(f->rgba);
        memset(f, 0, sizeof *f);
        return NULL;
    }
    return f;
}

typedef struct oiio_impl {
    tool_oiio_store *store;
    oiio_ts_opts opts;
} oiio_impl;

/* 1 (with the reason in err) where OpenImageIO has no equivalent of the
 * sampler's wrap modes: its black wrap is a zero border. */
static int wrap_na(const sample_sampler *smp, char *err, size_t errlen)
{
    if (oiio_ts_wrap_supported(smp->wrap_s) && oiio_ts_wrap_supported(smp->wrap_t) &&
        ((smp->wrap_s != SAMPLE_WRAP_CLAMP_TO_BORDER && smp->wrap_t != SAMPLE_WRAP_CLAMP_TO_BORDER) ||
         (smp->border_color[0] == 0.0f && smp->border_color[1] == 0.0f &&
          smp->border_color[2] == 0.0f && smp->border_color[3] == 0.0f)))
        return 0;
    snprintf(err, errlen, "OpenImageIO has no equivalent of wrap modes %s/%s",
             sample_wrap_name(smp->wrap_s), sample_wrap_name(smp->wrap_t));
    return 1;
}

static int prepare_as(tool_backend *b, const sample_texture *tex, const sample_sampler *smp, int env,
                      tool_backend_tex **out, char *err, size_t errlen)
{
    oiio_impl *o = b->impl;
    sample_texture_info info;
    tool_backend_tex *x;
    store_file *f;
    sample_texture_info_get(tex, &info);
    if (info.kind == SAMPLE_TEXTURE_3D) {
        /* texture3d() reads volume files and filters their base level only
         * (no mip filtering, no footprint): nothing to set beside these
         * rows (bench --volume times it). */
        snprintf(err, errlen, "OpenImageIO's texture3d has no mip or footprint filtering for a "
                              "solid texture's volume");
        return TOOL_BACKEND_NA;
    }
    if (env && info.kind == SAMPLE_TEXTURE_CUBE) {
        snprintf(err, errlen, "OpenImageIO's environment() reads lat-long maps only, not cube maps");
        return TOOL_BACKEND_NA;
    }
    if (!env && wrap_na(smp, err, errlen)) return TOOL_BACKEND_NA;
    if (!(x = malloc(sizeof *x))) {
        snprintf(err, errlen, "out of memory");
        return TOOL_BACKEND_ERROR;
    }
    if (!(f = store_get(o->store, tex, smp, env, err, errlen))) {
        free(x);
        return TOOL_BACKEND_ERROR;
    }
    ++f->refs;
    x->file = f;
    *out = x;
    return 0;
}

static int oiio_prepare(tool_backend *b, const sample_texture *tex, const sample_sampler *smp,
                        tool_backend_tex **out, tool_backend_times *t, char *err, size_t errlen)
{
    (void)t;
    return prepare_as(b, tex, smp, 0, out, err, errlen);
}

static int oiio_prepare_env(tool_backend *b, const sample_texture *tex, const sample_sampler *smp,
                            tool_backend_tex **out, tool_backend_times *t, char *err, size_t errlen)
{
    (void)t;
    return prepare_as(b, tex, smp, 1, out, err, errlen);
}

static int oiio_run(tool_backend *b, tool_backend_tex *x, const tool_backend_batch *a,
                    tool_backend_times *t, char *err, size_t errlen)
{
    oiio_impl *o = b->impl;
    oiio_ts_opts opts = o->opts;
    int rc;
    (void)t;
    if (a->u) {
        snprintf(err, errlen, "no stochastic draws through this interface");
        return TOOL_BACKEND_NA;
    }
    if ((a->q3 != NULL) != (x->file->env != 0)) {
        snprintf(err, errlen, x->file->env ? "an environment map takes direction queries"
                                           : "direction queries need an environment map");
        return TOOL_BACKEND_ERROR;
    }
    opts.wrap_s = x->file->wrap_s;
    opts.wrap_t = x->file->wrap_t;
    /* Exact corners are libsample's Blinn–Newell input; OpenImageIO filters
     * from the Jacobian alone. */
    rc = a->q3 ? oiio_ts_environment(o->store->ts, x->file->handle, &opts, a->q3, a->count, a->rgba,
                                     err, errlen)
               : oiio_ts_sample(o->store->ts, x->file->handle, &opts, a->q, a->count, a->rgba, err,
                                errlen);
    return rc == 0 ? 0 : TOOL_BACKEND_ERROR;
}

static void oiio_release(tool_backend *b, tool_backend_tex *x)
{
    (void)b;
    if (x->file != &x->own) --x->file->refs;
    free(x);
}

int tool_backend_oiio_prepare_file(tool_backend *b, const char *path, const sample_sampler *smp,
                                   tool_backend_tex **out, char *err, size_t errlen)
{
    oiio_impl *o = b->impl;
    tool_backend_tex *x;
    if (wrap_na(smp, err, errlen)) return TOOL_BACKEND_NA;
    if (!(x = calloc(1, sizeof *x))) {
        snprintf(err, errlen, "out of memory");
        return TOOL_BACKEND_ERROR;
    }
    snprintf(x->own.path, sizeof x->own.path, "%s", path);
    x->own.wrap_s = smp->wrap_s;
    x->own.wrap_t = smp->wrap_t;
    /* Not read through: such files may be larger than the cache. */
    if (!(x->own.handle = oiio_ts_open(o->store->ts, path, err, errlen))) {
        free(x);
        return TOOL_BACKEND_ERROR;
    }
    x->file = &x->own;
    *out = x;
    return 0;
}

oiio_ts *tool_oiio_store_ts(tool_oiio_store *s) { return s->ts; }

static void oiio_close(tool_backend *b) { free(b->impl); }

const char *tool_oiio_file(const tool_backend_tex *x) { return x->file->path; }

static const tool_backend_ops oiio_ops = {.prepare = oiio_prepare,
                                          .prepare_env = oiio_prepare_env,
                                          .run = oiio_run,
                                          .release = oiio_release,
                                          .close = oiio_close};

int tool_backend_oiio_open(tool_backend *b, tool_oiio_store *store, const oiio_ts_opts *opts,
                           char *err, size_t errlen)
{
    oiio_impl *o = malloc(sizeof *o);
    memset(b, 0, sizeof *b);
    if (!o) {
        snprintf(err, errlen, "out of memory");
        return TOOL_BACKEND_ERROR;
    }
    o->store = store;
    o->opts = *opts;
    b->ops = &oiio_ops;
    b->impl = o;
    b->thread_safe = 1;
    snprintf(b->driver, sizeof b->driver, "OpenImageIO TextureSystem");
    return 0;
}

#else

int tool_oiio_available(void) { return 0; }

tool_oiio_store *tool_oiio_store_open(double cache_mb, char *err, size_t errlen)
{
    return tool_oiio_store_open_in(cache_mb, NULL, err, errlen);
}

tool_oiio_store *tool_oiio_store_open_in(double cache_mb, const char *base, char *err, size_t errlen)
{
    (void)cache_mb;
    (void)base;
    snprintf(err, errlen, "this build has no OpenImageIO");
    return NULL;
}

void tool_oiio_store_close(tool_oiio_store *s) { (void)s; }

void tool_oiio_store_native_formats(tool_oiio_store *s) { (void)s; }

oiio_ts *tool_oiio_store_ts(tool_oiio_store *s)
{
    (void)s;
    return NULL;
}

int tool_backend_oiio_prepare_file(tool_backend *b, const char *path, const sample_sampler *smp,
                                   tool_backend_tex **out, char *err, size_t errlen)
{
    (void)b, (void)path, (void)smp, (void)out;
    snprintf(err, errlen, "this build has no OpenImageIO");
    return TOOL_BACKEND_ERROR;
}

const char *tool_oiio_file(const tool_backend_tex *x)
{
    (void)x;
    return "";
}

int tool_backend_oiio_open(tool_backend *b, tool_oiio_store *store, const oiio_ts_opts *opts,
                           char *err, size_t errlen)
{
    (void)store;
    (void)opts;
    memset(b, 0, sizeof *b);
    snprintf(err, errlen, "this build has no OpenImageIO");
    return TOOL_BACKEND_ERROR;
}

#endif
