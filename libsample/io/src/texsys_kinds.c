/*
 * Cube maps and volumes in the texture system (doc/texture-system.md,
 * "Cube maps and volumes"). sample_texsys_open recognises them by the
 * rules of their whole-file readers: a volume as sample_io_read_volume
 * reads one (an image with a z extent, or subimages of one size), a cube
 * map as sample_io_read_env reads one, where the file says it is one
 * (textureformat "CubeFace Environment", which OpenEXR's envmap attribute
 * reads as): an image that does not say so is a 2D texture whatever its
 * shape, since a texture opened by name need not be an environment. A
 * lat-long environment is a 2D texture and opens as any other.
 *
 * Such a texture is read whole, when it is opened, by that reader with
 * the default pyramid (sample_mip_params_init: the box filter across the
 * cube's faces, or across a volume's slices), and held until the system
 * is destroyed: its faces' levels are built across face edges from the
 * whole cube, and a volume's levels from every slice, so no tile of either
 * can be made alone from its file. The texture the system hands out has
 * the held texture's levels and reads them through its texel source, one
 * layer per face or slice, so its samples are the held texture's bit for
 * bit. Its bytes count in stats.bytes_read, not against the tile limit.
 */
#include "texsys_internal.h"

#include <stdlib.h>

struct ts_whole {
    ts_head h; /* first */
    sample_texture *tex;  /* handed out: the held texture's levels, no texels */
    sample_texture *held; /* resident */
    char *path;
    const char *colorspace; /* the open's, or the system's option */
    char colorspace_own[TS_COLORSPACE_MAX];
    ts_whole *next;
};

static const unsigned char *whole_texel(const struct ls_texel_source *src, int lv, int i, int j, int layer)
{
    const ts_whole *w = (const ts_whole *)src;
    const struct sample_level *L = &w->held->level[lv];
    return L->data + (size_t)layer * L->slice + (size_t)j * L->stride + (size_t)i * w->held->texel_bytes;
}

/* The texture is freed with the system (io_ts_whole_free_all). */
static void whole_destroy(struct ls_texel_source *src) { (void)src; }

static void whole_free(ts_whole *w)
{
    if (!w) return;
    free(w->tex);
    sample_texture_destroy(w->held);
    free(w->path);
    free(w);
}

/* 1: a volume; 2: a cube map; 0: neither (a 2D texture); −1: failed. */
static int whole_kind(const char *path, const char *cs, sample_error *err)
{
    sample_io_options o;
    sample_io_file_info info;
    if (io_ts_probe_volume(path)) return 1;
    sample_io_options_init(&o);
    o.colorspace = cs;
    if (sample_io_describe(path, &o, &info, err) != SAMPLE_OK) return -1;
    /* sample_io_read_env refuses a named cube of another shape. */
    return strcmp(info.textureformat, "CubeFace Environment") == 0 ? 2 : 0;
}

sample_status io_ts_whole_open(sample_texsys *sys, const char *path, const char *cs, const sample_texture **out,
                               sample_error *err)
{
    sample_mip_params mip;
    sample_io_options o;
    sample_status st;
    ts_whole *w;
    int kind, k;
    if (!cs) cs = sys->colorspace;
    for (w = sys->wholes; w; w = w->next)
        if (!strcmp(w->path, path) && io_ts_same_colorspace(w->colorspace, cs)) {
            *out = w->tex;
            return SAMPLE_OK;
        }
    /* Neither, or not an image at all: the 2D path opens it or says why. */
    if (sample_io_check_regular_file(path, "texture", err) != SAMPLE_OK || io_preflight(path, NULL, 0, err) != SAMPLE_OK ||
        (kind = whole_kind(path, cs, err)) <= 0)
        return SAMPLE_OK;
    w = (ts_whole *)calloc(1, sizeof *w);
    if (!w || !(w->path = io_strdup(path)) || !(w->tex = (sample_texture *)calloc(1, sizeof *w->tex))) {
        whole_free(w);
        return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate a texture entry");
    }
    if (cs) {
        snprintf(w->colorspace_own, sizeof w->colorspace_own, "%s", cs);
        w->colorspace = w->colorspace_own;
    }
    sample_mip_params_init(&mip);
    sample_io_options_init(&o);
    o.colorspace = cs;
    st = kind == 1 ? sample_io_read_volume(path, &mip, &w->held, err) : sample_io_read_env(path, &o, &mip, &w->held, err);
    if (st != SAMPLE_OK) {
        whole_free(w);
        return st;
    }
    *w->tex = *w->held;
    for (k = 0; k < SAMPLE_MAX_LEVELS; ++k) w->tex->level[k].data = NULL;
    w->h.sys = sys;
    w->h.base.texel = whole_texel;
    w->h.base.destroy = whole_destroy;
    memcpy(w->h.base.fill, sys->o.fill, sizeof w->h.base.fill);
    w->tex->source = &w->h.base;
    pthread_mutex_lock(&sys->lock);
    sys->st.files_opened++;
    sys->st.tiles_read++;
    sys->st.bytes_read += w->held->bytes;
    sys->st.held_memory += w->held->bytes;
    w->next = sys->wholes;
    sys->wholes = w;
    pthread_mutex_unlock(&sys->lock);
    *out = w->tex;
    return SAMPLE_OK;
}

ts_whole *io_ts_whole_of(const sample_texsys *sys, const sample_texture *tex)
{
    const ts_whole *w;
    if (!sys || !tex || !tex->source || tex->source->texel != whole_texel) return NULL;
    w = (const ts_whole *)tex->source;
    return w->h.sys == sys ? (ts_whole *)(uintptr_t)w : NULL;
}

void io_ts_whole_info(const ts_whole *w, sample_texsys_info *info)
{
    int k, side = 0;
    for (k = 0; k < w->tex->nlevels; ++k) {
        const struct sample_level *L = &w->tex->level[k];
        if (L->w > side) side = L->w;
        if (L->h > side) side = L->h;
    }
    info->tile_size = side; /* one tile: the whole level */
    info->file_tiled = 0;
    info->wrap_s = info->wrap_t = SAMPLE_WRAP_REPEAT;
    snprintf(info->colorspace, sizeof info->colorspace, "%s", w->colorspace ? w->colorspace : "");
}

void io_ts_whole_free_all(sample_texsys *sys)
{
    ts_whole *w, *next;
    for (w = sys->wholes; w; w = next) {
        next = w->next;
        whole_free(w);
    }
    sys->wholes = NULL;
}
