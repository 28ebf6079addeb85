/*
 * 3D textures: creation from caller volumes, their pyramids (mip.c's
 * resampler with its third axis) and their level sizes (DESIGN §11,
 * doc/volumes.md). A slice is a layer of its level (texel.h), read by
 * sample_texture_texel_layer.
 */
#include "mip.h"
#include "volume.h"

#include <stdio.h>
#include <stdlib.h>

static int vol_dim(int n, int k) { return (n >> k) > 0 ? (n >> k) : 1; }

/* Slice 0 of a volume as a 2D image, for the checks 2D images get. */
static sample_image vol_slice_image(const sample_volume *v)
{
    sample_image im;
    im.width = v->width;
    im.height = v->height;
    im.channels = v->channels;
    im.format = v->format;
    im.data = v->data;
    im.row_stride = v->row_stride;
    return im;
}

/* A volume description: its slices as 2D images are (ls_tex_check_layers,
 * which also bounds the bytes of all slices), a depth in 1 … SAMPLE_MAX_SIZE
 * and a slice stride that holds a slice. */
static sample_status check_volume(const sample_volume *v, const char *what, sample_error *err)
{
    sample_image im;
    size_t row, slice;
    sample_status st;
    RETURN_ERROR_IF(!v, err, SAMPLE_E_INVALID_ARGUMENT, "%s: volume is NULL", what);
    RETURN_ERROR_IF(v->depth <= 0, err, SAMPLE_E_BAD_SIZE, "%s: size %d x %d x %d is not positive", what, v->width,
                    v->height, v->depth);
    RETURN_ERROR_IF(v->depth > SAMPLE_MAX_SIZE, err, SAMPLE_E_TOO_LARGE,
                    "%s: depth %d exceeds the limit of %d per side", what, v->depth, SAMPLE_MAX_SIZE);
    im = vol_slice_image(v);
    if ((st = ls_tex_check_layers(&im, v->depth, what, err)) != SAMPLE_OK) return st;
    /* Sizes are within the byte limit now, so these products fit. */
    row = v->row_stride ? v->row_stride : (size_t)v->width * (size_t)v->channels * sample_format_bytes(v->format);
    slice = row * (size_t)(v->height - 1) + (size_t)v->width * (size_t)v->channels * sample_format_bytes(v->format);
    RETURN_ERROR_IF(v->slice_stride != 0 && v->slice_stride < slice, err, SAMPLE_E_BAD_SIZE,
                    "%s: slice stride %zu is less than a slice (%zu bytes)", what, v->slice_stride, slice);
    return SAMPLE_OK;
}

/* Copy a volume into level k (allocated, of the volume's size), slice by
 * slice as layers. */
static void copy_volume(sample_texture *tex, int k, const sample_volume *v)
{
    sample_image im = vol_slice_image(v);
    size_t rs = v->row_stride ? v->row_stride : (size_t)v->width * tex->texel_bytes;
    size_t ss = v->slice_stride ? v->slice_stride : rs * (size_t)v->height;
    int z;
    for (z = 0; z < v->depth; ++z) {
        im.data = (const unsigned char *)v->data + (size_t)z * ss;
        ls_tex_copy_layer(tex, k, z, &im);
    }
}

static sample_texture *vol_new(const sample_volume *v)
{
    sample_texture *tex = ls_tex_new(SAMPLE_TEXTURE_3D, v->width, v->height, v->channels, v->format);
    if (tex) tex->depth = v->depth;
    return tex;
}

/* A 3D texture of `count` given levels and, when mip asks for one, the
 * pyramid below them (sample_texture_create_3d gives one level). */
static sample_status vol_create(const sample_volume *levels, int count, const sample_mip_params *mip,
                                sample_texture **out, sample_error *err)
{
    sample_texture *tex = vol_new(&levels[0]);
    sample_status st = SAMPLE_OK;
    int k;
    RETURN_ERROR_IF(!tex, err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate a texture object");
    for (k = 0; k < count && st == SAMPLE_OK; ++k)
        if ((st = ls_tex_alloc_level(tex, k, err)) == SAMPLE_OK) {
            tex->nlevels = k + 1;
            copy_volume(tex, k, &levels[k]);
        }
    if (st == SAMPLE_OK && mip && mip->filter != SAMPLE_MIPGEN_NONE) st = ls_mip_build(tex, mip, err);
    if (st != SAMPLE_OK) {
        sample_texture_destroy(tex);
        return st;
    }
    *out = tex;
    return SAMPLE_OK;
}

sample_status sample_texture_create_3d(const sample_volume *volume, const sample_mip_params *mip,
                                       sample_texture **out, sample_error *err)
{
    sample_status st;
    RETURN_ERROR_IF(!out, err, SAMPLE_E_INVALID_ARGUMENT, "output pointer is NULL");
    *out = NULL;
    if ((st = check_volume(volume, "volume", err)) != SAMPLE_OK) return st;
    if ((st = ls_tex_check_mip(mip, err)) != SAMPLE_OK) return st;
    RETURN_ERROR_IF(mip && (unsigned)mip->wrap_r >= SAMPLE_WRAP_COUNT, err, SAMPLE_E_INVALID_ARGUMENT,
                    "unknown wrap mode %d on r in mip parameters", (int)mip->wrap_r);
    return vol_create(volume, 1, mip, out, err);
}

sample_status sample_texture_create_3d_levels(const sample_volume *levels, int count, sample_texture **out,
                                              sample_error *err)
{
    sample_status st;
    int k, full = 1, m;
    RETURN_ERROR_IF(!out, err, SAMPLE_E_INVALID_ARGUMENT, "output pointer is NULL");
    *out = NULL;
    RETURN_ERROR_IF(!levels || count < 1, err, SAMPLE_E_INVALID_ARGUMENT, "need at least one level (got %d)",
                    count);
    if ((st = check_volume(&levels[0], "level 0", err)) != SAMPLE_OK) return st;
    m = levels[0].width > levels[0].height ? levels[0].width : levels[0].height;
    if (levels[0].depth > m) m = levels[0].depth;
    while (m > 1) {
        m >>= 1;
        ++full;
    }
    RETURN_ERROR_IF(count > full, err, SAMPLE_E_BAD_SIZE, "%d levels given but a %d x %d x %d volume has only %d",
                    count, levels[0].width, levels[0].height, levels[0].depth, full);
    for (k = 1; k < count; ++k) {
        const sample_volume *v = &levels[k], *b = &levels[0];
        char what[32];
        snprintf(what, sizeof what, "level %d", k);
        if ((st = check_volume(v, what, err)) != SAMPLE_OK) return st;
        RETURN_ERROR_IF(v->width != vol_dim(b->width, k) || v->height != vol_dim(b->height, k) ||
                            v->depth != vol_dim(b->depth, k),
                        err, SAMPLE_E_BAD_SIZE, "level %d is %d x %d x %d, expected %d x %d x %d", k, v->width,
                        v->height, v->depth, vol_dim(b->width, k), vol_dim(b->height, k), vol_dim(b->depth, k));
        RETURN_ERROR_IF(v->channels != b->channels || v->format != b->format, err, SAMPLE_E_INVALID_ARGUMENT,
                        "level %d has a different channel count or format from level 0", k);
    }
    return vol_create(levels, count, NULL, out, err);
}

int sample_texture_level_size3(const sample_texture *tex, int level, int *w, int *h, int *d)
{
    int ok = tex && level >= 0 && level < tex->nlevels;
    if (w) *w = ok ? tex->level[level].w : 0;
    if (h) *h = ok ? tex->level[level].h : 0;
    if (d) *d = ok ? tex->level[level].d : 0;
    return ok;
}
