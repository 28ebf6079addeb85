/* Texture storage: validation, copies, texel encode, level allocation. */
#if defined(__linux__)
#define _DEFAULT_SOURCE /* posix_memalign, madvise: before any system header */
#include <sys/mman.h>
#endif
#include "mip.h"

#include <stdio.h>
#include <stdlib.h>

/* Refuse textures whose texel memory (all levels) would exceed this, even if
 * malloc might grant it: 16 GiB. */
#define SAMPLE_MAX_TEXTURE_BYTES ((uint64_t)1 << 34)

static const size_t format_bytes[] = {
    [SAMPLE_FORMAT_F32] = 4, [SAMPLE_FORMAT_F16] = 2,
    [SAMPLE_FORMAT_UNORM8] = 1, [SAMPLE_FORMAT_SRGB8] = 1,
};
_Static_assert(sizeof format_bytes / sizeof format_bytes[0] == SAMPLE_FORMAT_COUNT, "one size per format");

size_t sample_format_bytes(sample_format f)
{
    return ((unsigned)f < SAMPLE_FORMAT_COUNT) ? format_bytes[f] : 0;
}

/* Level storage. Random texel reads into a large level miss the TLB on
 * almost every row (a 2048-texel RGBA float row is 32 KiB, eight 4 KiB
 * pages); on Linux, levels of 4 MiB and more are aligned to 2 MiB and
 * offered to the kernel as transparent huge pages, which keeps the whole
 * level in a few TLB entries. Elsewhere (or if the kernel declines) this is
 * plain memory; free() releases either. */
#if defined(__linux__) && defined(MADV_HUGEPAGE)
static void *tex_level_malloc(size_t bytes)
{
    const size_t huge = (size_t)2 << 20;
    void *p;
    if (bytes < 2 * huge) return malloc(bytes);
    if (posix_memalign(&p, huge, (bytes + huge - 1) / huge * huge) != 0) return NULL;
    (void)madvise(p, (bytes + huge - 1) / huge * huge, MADV_HUGEPAGE);
    return p;
}
#else
static void *tex_level_malloc(size_t bytes) { return malloc(bytes); }
#endif

static int level_dim(int n, int k) { return (n >> k) > 0 ? (n >> k) : 1; }

/* Checks an image description (of `layers` layers); sizes are checked in
 * 64-bit so that no product can overflow before it is compared with the
 * limit. */
sample_status ls_tex_check_layers(const sample_image *im, int layers, const char *what, sample_error *err)
{
    uint64_t row, total;
    RETURN_ERROR_IF(!im, err, SAMPLE_E_INVALID_ARGUMENT, "%s: image is NULL", what);
    RETURN_ERROR_IF(im->width <= 0 || im->height <= 0, err, SAMPLE_E_BAD_SIZE,
                    "%s: size %d x %d is not positive", what, im->width, im->height);
    RETURN_ERROR_IF(im->width > SAMPLE_MAX_SIZE || im->height > SAMPLE_MAX_SIZE, err,
                    SAMPLE_E_TOO_LARGE, "%s: size %d x %d exceeds the limit of %d per side",
                    what, im->width, im->height, SAMPLE_MAX_SIZE);
    RETURN_ERROR_IF(im->channels < 1 || im->channels > 4, err, SAMPLE_E_INVALID_ARGUMENT,
                    "%s: %d channels (must be 1 to 4)", what, im->channels);
    RETURN_ERROR_IF((unsigned)im->format >= SAMPLE_FORMAT_COUNT, err, SAMPLE_E_INVALID_ARGUMENT,
                    "%s: unknown texel format %d", what, (int)im->format);
    RETURN_ERROR_IF(!im->data, err, SAMPLE_E_INVALID_ARGUMENT, "%s: data is NULL", what);
    row = (uint64_t)im->width * (uint64_t)im->channels * format_bytes[im->format];
    RETURN_ERROR_IF(im->row_stride != 0 && im->row_stride < row, err, SAMPLE_E_BAD_SIZE,
                    "%s: row stride %zu is less than a row (%llu bytes)", what,
                    im->row_stride, (unsigned long long)row);
    total = row * (uint64_t)im->height * (uint64_t)(layers > 0 ? layers : 1);
    /* A full pyramid adds at most a third of the base level. */
    RETURN_ERROR_IF(total + total / 3 + 64 > SAMPLE_MAX_TEXTURE_BYTES, err, SAMPLE_E_TOO_LARGE,
                    "%s: %llu bytes of texels exceeds the limit of %llu", what,
                    (unsigned long long)total, (unsigned long long)SAMPLE_MAX_TEXTURE_BYTES);
    return SAMPLE_OK;
}

static sample_status check_image(const sample_image *im, const char *what, sample_error *err)
{
    return ls_tex_check_layers(im, 1, what, err);
}

sample_status ls_tex_alloc_level(sample_texture *tex, int k, sample_error *err)
{
    struct sample_level *L = &tex->level[k];
    size_t bytes;
    L->w = level_dim(tex->width, k);
    L->h = level_dim(tex->height, k);
    L->d = tex_level_layers(tex, k);
    L->stride = (size_t)L->w * tex->texel_bytes;
    L->slice = L->stride * (size_t)L->h;
    bytes = L->slice * (size_t)L->d;
    L->data = (unsigned char *)tex_level_malloc(bytes);
    RETURN_ERROR_IF(!L->data, err, SAMPLE_E_OUT_OF_MEMORY,
                    "cannot allocate %zu bytes for level %d (%d x %d x %d)", bytes, k, L->w, L->h, L->d);
    tex->bytes += bytes;
    return SAMPLE_OK;
}

static void copy_image(struct sample_level *L, size_t texel_bytes, const sample_image *im)
{
    size_t row = (size_t)L->w * texel_bytes;
    size_t src_stride = im->row_stride ? im->row_stride : row;
    int j;
    for (j = 0; j < L->h; ++j)
        memcpy(L->data + (size_t)j * L->stride, (const unsigned char *)im->data + (size_t)j * src_stride, row);
}

sample_status ls_tex_check_image(const sample_image *im, const char *what, sample_error *err)
{
    return check_image(im, what, err);
}

sample_status ls_tex_check_mip(const sample_mip_params *mip, sample_error *err)
{
    if (!mip) return SAMPLE_OK;
    RETURN_ERROR_IF((unsigned)mip->filter >= SAMPLE_MIPGEN_COUNT, err, SAMPLE_E_INVALID_ARGUMENT,
                    "unknown mip filter %d", (int)mip->filter);
    RETURN_ERROR_IF((unsigned)mip->wrap_s >= SAMPLE_WRAP_COUNT || (unsigned)mip->wrap_t >= SAMPLE_WRAP_COUNT,
                    err, SAMPLE_E_INVALID_ARGUMENT, "unknown wrap mode in mip parameters");
    RETURN_ERROR_IF(mip->max_levels < 0, err, SAMPLE_E_INVALID_ARGUMENT, "max_levels %d is negative",
                    mip->max_levels);
    return SAMPLE_OK;
}

void ls_tex_copy_layer(sample_texture *tex, int k, int layer, const sample_image *im)
{
    struct sample_level L = tex->level[k];
    L.data += (size_t)layer * L.slice;
    copy_image(&L, tex->texel_bytes, im);
}

sample_texture *ls_tex_new(sample_texture_kind kind, int width, int height, int channels, sample_format format)
{
    sample_texture *tex = (sample_texture *)calloc(1, sizeof *tex);
    if (!tex) return NULL;
    tex->kind = kind;
    tex->width = width;
    tex->height = height;
    tex->depth = 1;
    tex->channels = channels;
    tex->format = format;
    tex->texel_bytes = (size_t)channels * format_bytes[format];
    return tex;
}

static sample_texture *tex_new(const sample_image *base)
{
    return ls_tex_new(SAMPLE_TEXTURE_2D, base->width, base->height, base->channels, base->format);
}

sample_status sample_texture_create(const sample_image *image, const sample_mip_params *mip,
                                    sample_texture **out, sample_error *err)
{
    sample_texture *tex;
    sample_status st;
    RETURN_ERROR_IF(!out, err, SAMPLE_E_INVALID_ARGUMENT, "output pointer is NULL");
    *out = NULL;
    if ((st = check_image(image, "texture", err)) != SAMPLE_OK) return st;
    if ((st = ls_tex_check_mip(mip, err)) != SAMPLE_OK) return st;
    tex = tex_new(image);
    RETURN_ERROR_IF(!tex, err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate a texture object");
    if ((st = ls_tex_alloc_level(tex, 0, err)) != SAMPLE_OK) {
        free(tex);
        return st;
    }
    tex->nlevels = 1;
    copy_image(&tex->level[0], tex->texel_bytes, image);
    if (mip && mip->filter != SAMPLE_MIPGEN_NONE) {
        if ((st = ls_mip_build(tex, mip, err)) != SAMPLE_OK) {
            sample_texture_destroy(tex);
            return st;
        }
    }
    *out = tex;
    return SAMPLE_OK;
}

sample_status sample_texture_create_levels(const sample_image *levels, int count,
                                           sample_texture **out, sample_error *err)
{
    sample_texture *tex;
    sample_status st;
    int k;
    RETURN_ERROR_IF(!out, err, SAMPLE_E_INVALID_ARGUMENT, "output pointer is NULL");
    *out = NULL;
    RETURN_ERROR_IF(!levels || count < 1, err, SAMPLE_E_INVALID_ARGUMENT,
                    "need at least one level (got %d)", count);
    if ((st = check_image(&levels[0], "level 0", err)) != SAMPLE_OK) return st;
    {
        int full = 1, m = levels[0].width > levels[0].height ? levels[0].width : levels[0].height;
        while (m > 1) { m >>= 1; ++full; }
        RETURN_ERROR_IF(count > full, err, SAMPLE_E_BAD_SIZE,
                        "%d levels given but a %d x %d texture has only %d", count,
                        levels[0].width, levels[0].height, full);
    }
    for (k = 1; k < count; ++k) {
        char what[32];
        snprintf(what, sizeof what, "level %d", k);
        if ((st = check_image(&levels[k], what, err)) != SAMPLE_OK) return st;
        RETURN_ERROR_IF(levels[k].width != level_dim(levels[0].width, k) ||
                            levels[k].height != level_dim(levels[0].height, k),
                        err, SAMPLE_E_BAD_SIZE, "level %d is %d x %d, expected %d x %d", k,
                        levels[k].width, levels[k].height, level_dim(levels[0].width, k),
                        level_dim(levels[0].height, k));
        RETURN_ERROR_IF(levels[k].channels != levels[0].channels || levels[k].format != levels[0].format,
                        err, SAMPLE_E_INVALID_ARGUMENT,
                        "level %d has a different channel count or format from level 0", k);
    }
    tex = tex_new(&levels[0]);
    RETURN_ERROR_IF(!tex, err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate a texture object");
    for (k = 0; k < count; ++k) {
        if ((st = ls_tex_alloc_level(tex, k, err)) != SAMPLE_OK) {
            sample_texture_destroy(tex);
            return st;
        }
        tex->nlevels = k + 1;
        copy_image(&tex->level[k], tex->texel_bytes, &levels[k]);
    }
    *out = tex;
    return SAMPLE_OK;
}

void sample_texture_destroy(sample_texture *tex)
{
    int k;
    if (!tex) return;
    for (k = 0; k < SAMPLE_MAX_LEVELS; ++k) free(tex->level[k].data);
    if (tex->source) tex->source->destroy(tex->source);
    free(tex);
}

void sample_texture_info_get(const sample_texture *tex, sample_texture_info *info)
{
    if (!info) return;
    memset(info, 0, sizeof *info);
    if (!tex) return;
    info->width = tex->width;
    info->height = tex->height;
    info->channels = tex->channels;
    info->levels = tex->nlevels;
    info->format = tex->format;
    info->bytes = tex->bytes;
    info->kind = tex->kind;
    info->depth = tex->depth;
}

int sample_texture_level_size(const sample_texture *tex, int level, int *w, int *h)
{
    int ok = tex && level >= 0 && level < tex->nlevels;
    if (w) *w = ok ? tex->level[level].w : 0;
    if (h) *h = ok ? tex->level[level].h : 0;
    return ok;
}

void sample_texture_texel(const sample_texture *tex, int level, int i, int j, float rgba[4])
{
    uintptr_t ticket;
    if (!tex || level < 0 || level >= tex->nlevels || i < 0 || j < 0 ||
        i >= tex->level[level].w || j >= tex->level[level].h) {
        rgba[0] = rgba[1] = rgba[2] = rgba[3] = 0.0f;
        return;
    }
    ticket = tex_reads_begin(tex);
    tex_read(tex, level, i, j, rgba);
    tex_reads_end(tex, ticket);
}

void sample_texture_texel_layer(const sample_texture *tex, int level, int layer, int i, int j, float rgba[4])
{
    if (!tex || level < 0 || level >= tex->nlevels || layer < 0 || layer >= tex->level[level].d || i < 0 ||
        j < 0 || i >= tex->level[level].w || j >= tex->level[level].h) {
        rgba[0] = rgba[1] = rgba[2] = rgba[3] = 0.0f;
        return;
    }
    tex_read_layer(tex, level, i, j, layer, rgba);
}

static unsigned char to_u8(float v)
{
    /* NaN → 0; rounding as GL's conversion to normalized fixed point
     * (GL 4.6 §2.3.5.2: round to nearest). */
    if (!(v > 0.0f)) return 0;
    if (v >= 1.0f) return 255;
    return (unsigned char)(v * 255.0f + 0.5f);
}

void ls_tex_encode(const sample_texture *tex, const float in[4], unsigned char *dst)
{
    int c;
    for (c = 0; c < tex->channels; ++c) {
        switch (tex->format) {
        case SAMPLE_FORMAT_F32: memcpy(dst + 4 * c, &in[c], 4); break;
        case SAMPLE_FORMAT_F16: {
            uint16_t h = sample_float_to_half(in[c]);
            memcpy(dst + 2 * c, &h, 2);
            break;
        }
        case SAMPLE_FORMAT_UNORM8: dst[c] = to_u8(in[c]); break;
        case SAMPLE_FORMAT_SRGB8:
            dst[c] = c < 3 ? ls_srgb_encode8(in[c]) : to_u8(in[c]);
            break;
        default: break;
        }
    }
}
