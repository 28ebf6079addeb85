/*
 * The texture system (sample/texsys.h, doc/texture-system.md): options,
 * opening a name, info, stats and errors. The cache is texsys_cache.c,
 * UDIM sets texsys_udim.c.
 */
#include "texsys_internal.h"

#include <stdlib.h>

void sample_texsys_options_init(sample_texsys_options *o)
{
    if (!o) return;
    memset(o, 0, sizeof *o);
    /* OpenImageIO's ImageCache defaults (max_memory_MB, max_open_files). */
    o->max_memory_mb = 1024.0;
    o->max_open_files = 100;
}

sample_status sample_texsys_create(const sample_texsys_options *o, sample_texsys **out, sample_error *err)
{
    sample_texsys_options defaults;
    sample_texsys *sys;
    sample_status st;
    if (!out) return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "sample_texsys_create: out is NULL");
    *out = NULL;
    if (!o) {
        sample_texsys_options_init(&defaults);
        o = &defaults;
    }
    if (!(o->max_memory_mb > 0.0) || o->max_memory_mb > 1048576.0)
        return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "max_memory_mb %g is not in (0, 1048576]",
                                o->max_memory_mb);
    if (o->max_open_files < 1)
        return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "max_open_files %d is less than 1", o->max_open_files);
    sys = (sample_texsys *)calloc(1, sizeof *sys);
    if (!sys) return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate a texture system");
    sys->o = *o;
    sys->ocio_config = io_strdup(o->ocio_config);
    sys->colorspace = io_strdup(o->colorspace);
    sys->o.ocio_config = sys->o.colorspace = NULL;
    sys->limit = (size_t)(o->max_memory_mb * 1048576.0);
    pthread_mutex_init(&sys->lock, NULL);
    pthread_mutex_init(&sys->open_lock, NULL);
    if ((o->ocio_config && !sys->ocio_config) || (o->colorspace && !sys->colorspace)) {
        sample_texsys_destroy(sys);
        return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate a texture system");
    }
    st = io_colour_open(sys->ocio_config, &sys->col, err);
    if (st == SAMPLE_OK && sys->colorspace) st = io_colour_require(sys->col, sys->colorspace, err);
    if (st != SAMPLE_OK) {
        sample_texsys_destroy(sys);
        return st;
    }
    *out = sys;
    return SAMPLE_OK;
}

void sample_texsys_destroy(sample_texsys *sys)
{
    ts_file *f, *next;
    if (!sys) return;
    io_ts_udim_free_all(sys);
    io_ts_whole_free_all(sys);
    for (f = sys->files; f; f = next) {
        next = f->next;
        io_ts_file_free(f);
    }
    io_ts_cache_drain(sys);
    io_colour_close(sys->col);
    pthread_mutex_destroy(&sys->lock);
    pthread_mutex_destroy(&sys->open_lock);
    free(sys->ocio_config);
    free(sys->colorspace);
    free(sys);
}

static int level_dim(int n, int k) { return (n >> k) > 0 ? n >> k : 1; }

/* Levels sample_io_read_texture takes from the file: the prefix that
 * follows libsample's size rule (1 when only the base does). */
static sample_status file_levels(io_reader *r, const io_reader_info *inf, int *count, sample_error *err)
{
    int k;
    *count = 1;
    for (k = 1; k < inf->nlevels && k < SAMPLE_MAX_LEVELS; ++k) {
        int w, h;
        sample_status st = io_reader_level_size(r, k, &w, &h, err);
        if (st != SAMPLE_OK) return st;
        if (w != level_dim(inf->width, k) || h != level_dim(inf->height, k)) break;
        *count = k + 1;
        if (w == 1 && h == 1) break;
    }
    return SAMPLE_OK;
}

static int is_tile_side(int w, int h, int *log2)
{
    int b;
    if (w != h) return 0;
    for (b = 2; b <= 12; ++b)
        if (w == 1 << b) {
            *log2 = b;
            return 1;
        }
    return 0;
}

/* The texture (no texels) that f's header describes, and how its tiles
 * are had (texsys.h, section 2). */
static sample_status describe(ts_file *f, io_reader *r, sample_error *err)
{
    const io_reader_info *inf = &f->inf;
    sample_io_options o;
    sample_texture *tex;
    sample_status st;
    int count, levels, k, m;
    if (inf->width <= 0 || inf->height <= 0 || inf->channels <= 0)
        return sample_error_set(err, SAMPLE_E_CORRUPT, "'%s' claims %d x %d pixels with %d channels", f->path,
                                inf->width, inf->height, inf->channels);
    if (inf->width > SAMPLE_MAX_SIZE || inf->height > SAMPLE_MAX_SIZE)
        return sample_error_set(err, SAMPLE_E_TOO_LARGE, "'%s' is %d x %d; the largest texture side is %d", f->path,
                                inf->width, inf->height, SAMPLE_MAX_SIZE);
    sample_io_options_init(&o);
    o.colorspace = f->colorspace;
    if ((st = io_read_plan(f->h.sys->col, inf, &o, &f->plan, err)) != SAMPLE_OK) return st;
    if ((st = file_levels(r, inf, &count, err)) != SAMPLE_OK) return st;
    f->file_tiled = count > 1 && is_tile_side(inf->tile_w, inf->tile_h, &f->log2);
    if (!f->file_tiled) f->log2 = TS_AUTOTILE_LOG2;
    levels = count;
    if (count == 1) /* the box pyramid sample_io_read_texture builds */
        for (m = inf->width > inf->height ? inf->width : inf->height; m > 1; m >>= 1) ++levels;
    f->has_wrap = inf->wrapmodes[0] && io_wrapmodes_parse(inf->wrapmodes, &f->wrap_s, &f->wrap_t);
    tex = (sample_texture *)calloc(1, sizeof *tex);
    if (!tex) return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate a texture");
    tex->kind = SAMPLE_TEXTURE_2D;
    tex->width = inf->width;
    tex->height = inf->height;
    tex->depth = 1;
    tex->channels = f->plan.nchan;
    tex->format = f->plan.format;
    tex->texel_bytes = (size_t)f->plan.nchan * sample_format_bytes(f->plan.format);
    tex->nlevels = levels;
    for (k = 0; k < levels; ++k) {
        tex->level[k].w = level_dim(inf->width, k);
        tex->level[k].h = level_dim(inf->height, k);
        tex->level[k].d = 1;
        tex->bytes += (size_t)tex->level[k].w * (size_t)tex->level[k].h * tex->texel_bytes;
    }
    tex->source = &f->h.base;
    f->tex = tex;
    return io_ts_file_source_init(f, err);
}

/* A new file entry for path: header read, reader closed again (tiles
 * reopen it under the open-file limit). */
static sample_status open_new(sample_texsys *sys, const char *path, const char *cs, ts_file **out,
                              sample_error *err)
{
    ts_file *f = (ts_file *)calloc(1, sizeof *f);
    io_reader *r = NULL;
    sample_status st;
    if (!f || !(f->path = io_strdup(path))) {
        free(f);
        return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate a texture entry");
    }
    f->h.sys = sys;
    if (cs) {
        snprintf(f->colorspace_own, sizeof f->colorspace_own, "%s", cs);
        f->colorspace = f->colorspace_own;
    } else {
        f->colorspace = sys->colorspace;
    }
    io_ts_lock_init(&f->io_lock);
    st = sample_io_check_regular_file(path, "texture", err);
    if (st == SAMPLE_OK) st = io_preflight(path, NULL, 0, err);
    if (st == SAMPLE_OK) st = io_reader_open(path, NULL, 0, NULL, &r, err);
    if (st == SAMPLE_OK) {
        io_reader_info_get(r, &f->inf);
        st = describe(f, r, err);
    }
    io_reader_close(r);
    if (st != SAMPLE_OK) {
        pthread_mutex_lock(&sys->lock);
        io_ts_file_free(f);
        pthread_mutex_unlock(&sys->lock);
        return st;
    }
    pthread_mutex_lock(&sys->lock);
    sys->st.files_opened++;
    f->next = sys->files;
    sys->files = f;
    pthread_mutex_unlock(&sys->lock);
    *out = f;
    return SAMPLE_OK;
}

int io_ts_same_colorspace(const char *a, const char *b)
{
    return a == b || (a && b && !strcmp(a, b));
}

/* The file open as path in colour space cs (NULL: the system's), or NULL.
 * open_lock held. */
static ts_file *find_file(sample_texsys *sys, const char *path, const char *cs)
{
    ts_file *f;
    if (!cs) cs = sys->colorspace;
    for (f = sys->files; f; f = f->next)
        if (!strcmp(f->path, path) && io_ts_same_colorspace(f->colorspace, cs)) return f;
    return NULL;
}

/* open_lock held. */
sample_status io_ts_open_file(sample_texsys *sys, const char *path, const char *cs, ts_file **out,
                              sample_error *err)
{
    if ((*out = find_file(sys, path, cs)) != NULL) return SAMPLE_OK;
    return open_new(sys, path, cs ? cs : sys->colorspace, out, err);
}

sample_status sample_texsys_open_colorspace(sample_texsys *sys, const char *filename, const char *colorspace,
                                            const sample_texture **tex, sample_error *err)
{
    ts_file *f = NULL;
    sample_status st = SAMPLE_OK;
    if (!tex) return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "sample_texsys_open: tex is NULL");
    *tex = NULL;
    if (!sys || !filename || !*filename)
        return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "sample_texsys_open: no system or no name");
    if (colorspace && strlen(colorspace) >= TS_COLORSPACE_MAX)
        return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "colour space name '%.40s...' is too long",
                                colorspace);
    pthread_mutex_lock(&sys->open_lock);
    if (colorspace) st = io_colour_require(sys->col, colorspace, err);
    if (st == SAMPLE_OK && io_ts_udim_pattern(filename)) {
        st = io_ts_udim_open(sys, filename, colorspace, tex, err);
    } else if (st == SAMPLE_OK) {
        /* A cube map or a volume (texsys_kinds.c), else a 2D texture. */
        if (!(f = find_file(sys, filename, colorspace))) st = io_ts_whole_open(sys, filename, colorspace, tex, err);
        if (st == SAMPLE_OK && !*tex) st = io_ts_open_file(sys, filename, colorspace, &f, err);
        if (st == SAMPLE_OK && f) *tex = f->tex;
    }
    pthread_mutex_unlock(&sys->open_lock);
    return st;
}

sample_status sample_texsys_open(sample_texsys *sys, const char *filename, const sample_texture **tex,
                                 sample_error *err)
{
    return sample_texsys_open_colorspace(sys, filename, NULL, tex, err);
}

/* The file `tex` is, or NULL (a UDIM set, or not this system's). */
static ts_file *file_of(const sample_texsys *sys, const sample_texture *tex)
{
    const ts_head *h;
    if (!sys || !tex || !tex->source || tex->source->reads_begin != io_ts_reads_begin) return NULL;
    h = (const ts_head *)tex->source;
    return h->sys == sys && !h->udim ? (ts_file *)(uintptr_t)h : NULL;
}

sample_status sample_texsys_texture_info(sample_texsys *sys, const sample_texture *tex, sample_texsys_info *info,
                                         sample_error *err)
{
    ts_file *f = file_of(sys, tex);
    ts_udim *u = f ? NULL : io_ts_udim_of(sys, tex);
    ts_whole *w = f || u ? NULL : io_ts_whole_of(sys, tex);
    if (!info) return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "sample_texsys_texture_info: info is NULL");
    memset(info, 0, sizeof *info);
    if (!f && !u && !w) return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "not a texture of this texture system");
    sample_texture_info_get(tex, &info->texture);
    if (w) {
        io_ts_whole_info(w, info);
        return SAMPLE_OK;
    }
    if (u) {
        io_ts_udim_info(u, info);
        return SAMPLE_OK;
    }
    info->tile_size = 1 << f->log2;
    info->file_tiled = f->file_tiled;
    info->has_wrap = f->has_wrap;
    info->wrap_s = f->has_wrap ? f->wrap_s : SAMPLE_WRAP_REPEAT;
    info->wrap_t = f->has_wrap ? f->wrap_t : SAMPLE_WRAP_REPEAT;
    snprintf(info->colorspace, sizeof info->colorspace, "%s", f->plan.colorspace ? f->plan.colorspace : "");
    return SAMPLE_OK;
}

void sample_texsys_sampler_init(sample_texsys *sys, const sample_texture *tex, sample_sampler *s)
{
    ts_file *f = file_of(sys, tex);
    sample_sampler_init(s);
    if (!s) return;
    if (f && f->has_wrap) {
        s->wrap_s = f->wrap_s;
        s->wrap_t = f->wrap_t;
    } else if (!f && io_ts_udim_of(sys, tex)) {
        s->wrap_s = s->wrap_t = SAMPLE_WRAP_CLAMP_TO_BORDER;
        memcpy(s->border_color, sys->o.fill, sizeof s->border_color);
    }
}

sample_status io_ts_batch_chunks(const sample_texture *tex, const sample_sampler *s, const sample_batch_args *a,
                              void (*map)(void *ctx, sample_batch_args *b, size_t i0), void *ctx)
{
    size_t i0;
    sample_status st = SAMPLE_OK;
    if (!a || a->count == 0) return sample_batch(tex, s, a);
    for (i0 = 0; i0 < a->count && st == SAMPLE_OK; i0 += TS_CHUNK) {
        sample_batch_args b = *a;
        b.count = a->count - i0 < TS_CHUNK ? a->count - i0 : TS_CHUNK;
        b.queries = a->queries ? a->queries + i0 : NULL;
        b.corners = a->corners ? a->corners + i0 : NULL;
        b.lod_bias = a->lod_bias ? a->lod_bias + i0 : NULL;
        b.rgba = a->rgba ? a->rgba + 4 * i0 : NULL;
        b.drgba_ds = a->drgba_ds ? a->drgba_ds + 4 * i0 : NULL;
        b.drgba_dt = a->drgba_dt ? a->drgba_dt + 4 * i0 : NULL;
        b.stats = a->stats ? a->stats + i0 : NULL;
        if (map) map(ctx, &b, i0);
        st = sample_batch(tex, s, &b);
        if (map && st == SAMPLE_OK) map(ctx, &b, (size_t)-1);
    }
    return st;
}

sample_status sample_texsys_batch(sample_texsys *sys, const sample_texture *tex, const sample_sampler *s,
                                  const sample_batch_args *args)
{
    ts_udim *u;
    if (file_of(sys, tex)) return io_ts_batch_chunks(tex, s, args, NULL, NULL);
    if (io_ts_whole_of(sys, tex)) return sample_batch(tex, s, args);
    if ((u = io_ts_udim_of(sys, tex)) != NULL) return io_ts_udim_batch(u, s, args);
    return SAMPLE_E_INVALID_ARGUMENT;
}

unsigned long sample_texsys_texture_error(sample_texsys *sys, const sample_texture *tex, sample_error *first)
{
    ts_file *f = file_of(sys, tex);
    ts_udim *u = f ? NULL : io_ts_udim_of(sys, tex);
    unsigned long n = 0;
    if (first) memset(first, 0, sizeof *first);
    if (!f && !u) return 0;
    pthread_mutex_lock(&sys->lock);
    if (u) {
        n = io_ts_udim_errors(u, first);
    } else {
        n = f->nerrors;
        if (first && n) *first = f->first_error;
    }
    pthread_mutex_unlock(&sys->lock);
    return n;
}

void sample_texsys_stats_get(sample_texsys *sys, sample_texsys_stats *stats)
{
    if (!stats) return;
    memset(stats, 0, sizeof *stats);
    if (!sys) return;
    pthread_mutex_lock(&sys->lock);
    *stats = sys->st;
    stats->memory = sys->resident + sys->retired_bytes;
    stats->open_files = sys->open_files;
    pthread_mutex_unlock(&sys->lock);
}
