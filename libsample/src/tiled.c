/*
 * A texel source that holds each level as square tiles in memory of their
 * own, as a tile cache holds them (OpenEXR and TIFF tiles, OpenImageIO's
 * 64 × 64 default): texel (i, j) of level lv lies in tile (i >> b, j >> b)
 * at (i mod 2^b, j mod 2^b), 2^b texels a side, row after row. A missing
 * tile (NULL; sample_texture_tile_drop) reads as the fill colour, as a
 * tile that failed to load will. The filters do not know the difference
 * (texel.h, struct ls_texel_source): tests/test_source.c checks that every
 * filter gives a tiled copy's texture the resident texture's bits.
 */
#include "texel.h"

#include "sample/testing.h"

#include <stdlib.h>

typedef struct tiled_source {
    struct ls_texel_source base; /* first: the texture points at it */
    int log2;                    /* tiles are 2^log2 texels a side */
    size_t texel_bytes;
    int ntx[SAMPLE_MAX_LEVELS], nty[SAMPLE_MAX_LEVELS]; /* tiles across, down */
    unsigned char **tiles[SAMPLE_MAX_LEVELS];           /* row-major grid; NULL: missing */
} tiled_source;

static const unsigned char *tiled_texel(const struct ls_texel_source *src, int lv, int i, int j, int layer)
{
    const tiled_source *t = (const tiled_source *)src;
    const int b = t->log2, m = (1 << b) - 1;
    const unsigned char *tile;
    (void)layer; /* 2D textures only (sample_texture_tiled_copy) */
    tile = t->tiles[lv][(size_t)(j >> b) * (size_t)t->ntx[lv] + (size_t)(i >> b)];
    if (!tile) return NULL;
    return tile + (((size_t)(j & m) << b) + (size_t)(i & m)) * t->texel_bytes;
}

static void tiled_destroy(struct ls_texel_source *src)
{
    tiled_source *t = (tiled_source *)src;
    int lv;
    size_t k;
    for (lv = 0; lv < SAMPLE_MAX_LEVELS; ++lv) {
        if (!t->tiles[lv]) continue;
        for (k = 0; k < (size_t)t->ntx[lv] * (size_t)t->nty[lv]; ++k) free(t->tiles[lv][k]);
        free(t->tiles[lv]);
    }
    free(t);
}

/* Level lv of `from` copied into tiles of t (sized for `to`'s level). */
static sample_status tile_level(tiled_source *t, const sample_texture *from, sample_texture *to, int lv,
                                sample_error *err)
{
    const struct sample_level *L = &from->level[lv];
    const int side = 1 << t->log2;
    const size_t tile_bytes = (size_t)side * (size_t)side * t->texel_bytes;
    int tx, ty, j;
    t->ntx[lv] = (L->w + side - 1) / side;
    t->nty[lv] = (L->h + side - 1) / side;
    t->tiles[lv] = (unsigned char **)calloc((size_t)t->ntx[lv] * (size_t)t->nty[lv], sizeof *t->tiles[lv]);
    RETURN_ERROR_IF(!t->tiles[lv], err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate the tile table of level %d", lv);
    to->level[lv].w = L->w;
    to->level[lv].h = L->h;
    to->level[lv].d = L->d;
    for (ty = 0; ty < t->nty[lv]; ++ty)
        for (tx = 0; tx < t->ntx[lv]; ++tx) {
            /* Texels past the level's edge in a tile are never read; zero
             * them so that the copy is deterministic. */
            unsigned char *tile = (unsigned char *)calloc(1, tile_bytes);
            const int i0 = tx * side, j0 = ty * side;
            const int w = L->w - i0 < side ? L->w - i0 : side, h = L->h - j0 < side ? L->h - j0 : side;
            RETURN_ERROR_IF(!tile, err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate a tile of %zu bytes", tile_bytes);
            t->tiles[lv][(size_t)ty * (size_t)t->ntx[lv] + (size_t)tx] = tile;
            for (j = 0; j < h; ++j)
                memcpy(tile + (size_t)j * (size_t)side * t->texel_bytes, tex_level_addr(from, L, i0, j0 + j),
                       (size_t)w * t->texel_bytes);
            to->bytes += tile_bytes;
        }
    return SAMPLE_OK;
}

sample_status sample_texture_tiled_copy(const sample_texture *tex, int tile_log2, sample_texture **out,
                                        sample_error *err)
{
    sample_texture *copy;
    tiled_source *t;
    sample_status st = SAMPLE_OK;
    int lv;
    RETURN_ERROR_IF(!out, err, SAMPLE_E_INVALID_ARGUMENT, "output pointer is NULL");
    *out = NULL;
    RETURN_ERROR_IF(!tex || !tex_resident(tex) || tex->kind != SAMPLE_TEXTURE_2D, err, SAMPLE_E_INVALID_ARGUMENT,
                    "tiled copy: the texture must be resident and 2D");
    RETURN_ERROR_IF(tile_log2 < 0 || tile_log2 > 12, err, SAMPLE_E_INVALID_ARGUMENT,
                    "tiled copy: tiles of 2^%d texels a side (0 to 12)", tile_log2);
    copy = ls_tex_new(tex->kind, tex->width, tex->height, tex->channels, tex->format);
    t = (tiled_source *)calloc(1, sizeof *t);
    if (!copy || !t) {
        free(copy);
        free(t);
        return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate a tiled texture");
    }
    t->base.texel = tiled_texel;
    t->base.destroy = tiled_destroy;
    t->base.tile_side = 1 << tile_log2; /* tiled_texel's layout (texel.h) */
    t->log2 = tile_log2;
    t->texel_bytes = tex->texel_bytes;
    copy->source = &t->base;
    for (lv = 0; lv < tex->nlevels && st == SAMPLE_OK; ++lv) {
        st = tile_level(t, tex, copy, lv, err);
        copy->nlevels = lv + 1;
    }
    if (st != SAMPLE_OK) {
        sample_texture_destroy(copy);
        return st;
    }
    *out = copy;
    return SAMPLE_OK;
}

sample_status sample_texture_tile_drop(sample_texture *tex, int level, int tx, int ty, const float fill[4])
{
    tiled_source *t;
    unsigned char **slot;
    if (!tex || tex_resident(tex) || tex->source->texel != tiled_texel || !fill) return SAMPLE_E_INVALID_ARGUMENT;
    t = (tiled_source *)tex->source;
    if (level < 0 || level >= tex->nlevels || tx < 0 || ty < 0 || tx >= t->ntx[level] || ty >= t->nty[level])
        return SAMPLE_E_INVALID_ARGUMENT;
    slot = &t->tiles[level][(size_t)ty * (size_t)t->ntx[level] + (size_t)tx];
    free(*slot);
    *slot = NULL;
    memcpy(t->base.fill, fill, sizeof t->base.fill);
    return SAMPLE_OK;
}
