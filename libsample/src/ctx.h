/*
 * The per-batch context (sampler.c, ls_ctx_init): texture, sampler state,
 * level_base and q (GL 4.6 §8.14.3), border colour and the batch's
 * kernels; texel reads through the wrap modes (ctx_texel), and the
 * finiteness test that sends bad input to the border colour (DESIGN §10).
 */
#ifndef SAMPLE_CTX_H
#define SAMPLE_CTX_H

#include "env_addr.h"
#include "texel.h"
#include "wrap.h"

struct isa_kernels;

/* The tile each level's texels were last addressed in, for a texture whose
 * source holds its levels in tiles (texel.h, tile_side): texel (x, y) of
 * level lv, the first of its tile, is at p[lv]; x[lv] = −1: none yet. A
 * memo of one batch only, which is as long as texel()'s pointers stay
 * valid (texel.h, struct ls_texel_source). Consecutive queries of a
 * coherent batch (a renderer's scanlines, the bench's plane) mostly fall in
 * the tile the query before them read, and then skip the source's call. */
typedef struct ls_tile_memo {
    int x[SAMPLE_MAX_LEVELS], y[SAMPLE_MAX_LEVELS];
    const unsigned char *p[SAMPLE_MAX_LEVELS];
} ls_tile_memo;

typedef struct sample_ctx {
    const sample_texture *tex;
    const sample_sampler *smp;
    float border[4];
    int base;      /* effective base level */
    int maxlev;    /* q: last level that may be used (GL 4.6 §8.14.3) */
    /* The kernels of this batch, chosen once when the batch starts (as
     * zstd's dctx->bmi2): every loop below reads this, never a global. */
    const struct isa_kernels *isa;
    /* Environment maps (env_addr.h): how texels past an edge are found
     * instead of the wrap modes, and the cube face a query selected (the
     * layer every read of the query is on; 0 for other kinds). */
    ls_env_mode env;
    int face;
    /* A cube-map query's own direction and derivatives (NULL for other
     * kinds): the anisotropic filter places probes that leave the face
     * by direction (footprint_aniso.c). */
    const sample_query3 *q3;
    /* The fast path's tile memo for this batch (fast_gl.c); NULL: none. */
    ls_tile_memo *tiles;
} sample_ctx;

/* The context of a batch: level_base and q (GL 4.6 §8.14.3) from the
 * sampler and the levels present, the border colour, and the kernels k
 * (ls_isa_kernels_active(), or ls_isa_kernels_reference). */
void ls_ctx_init(sample_ctx *c, const sample_texture *tex, const sample_sampler *smp,
              const struct isa_kernels *k);

/* Read texel (i, j) of level `lv` through the wrap modes; border colour where
 * the wrap says so. Every filter reads texels through this. */
static inline void ctx_texel(const sample_ctx *c, int lv, double i, double j, int linear,
                             float out[4])
{
    const struct sample_level *L = &c->tex->level[lv];
    int x, y;
    /* Every wrap mode maps an in-range index to itself (ls_wrap_index's own
     * first test); checking here saves two calls on most reads. */
    if (i >= 0.0 && i < (double)L->w && j >= 0.0 && j < (double)L->h) {
        tex_read_layer(c->tex, lv, (int)i, (int)j, c->face, out);
        return;
    }
    if (c->env != LS_ENV_NONE) {
        ls_env_texel(c->tex, lv, c->face, c->env, i, j, linear, out);
        return;
    }
    x = ls_wrap_index(c->smp->wrap_s, i, L->w, linear);
    y = ls_wrap_index(c->smp->wrap_t, j, L->h, linear);
    if (x < 0 || y < 0) {
        out[0] = c->border[0]; out[1] = c->border[1];
        out[2] = c->border[2]; out[3] = c->border[3];
        return;
    }
    tex_read(c->tex, lv, x, y, out);
}

/* Whether the n floats stored at p are all finite. A float is ±inf or NaN
 * when its magnitude bits are ≥ 0x7f800000; adding 0x00800000 carries
 * exactly those into bit 31, so one OR over the words and one test decide
 * (a loop the compiler vectorizes, no branch per float). The words are
 * read with memcpy: p may be a struct of floats (sample_query). */
static inline int floats_finite(const void *p, size_t n)
{
    const unsigned char *b = (const unsigned char *)p;
    uint32_t bad = 0, w;
    size_t k;
    for (k = 0; k < n; ++k) {
        memcpy(&w, b + 4 * k, 4);
        bad |= (w & 0x7fffffffu) + 0x00800000u;
    }
    return !(bad & 0x80000000u);
}

_Static_assert(sizeof(sample_query) == 6 * sizeof(float) && sizeof(sample_quad) == 8 * sizeof(float),
               "queries and corners are plain arrays of floats");

/* Whether queries first … first + n − 1 of a batch can all be filtered:
 * DESIGN §10, non-finite coordinates, Jacobian, bias or corners give the
 * border colour, decided before any arithmetic could turn them into an
 * index. The fast path asks once for a block of queries, whose planning
 * steps then run as passes over the block with no border case
 * (fast_gl.c, gl_blocks). */
static inline int batch_range_finite(const sample_batch_args *a, size_t first, size_t n)
{
    return floats_finite(a->queries + first, 6 * n) && (!a->lod_bias || floats_finite(a->lod_bias + first, n)) &&
           (!a->corners || floats_finite(a->corners + first, 8 * n));
}

/* Whether query k of a batch can be filtered (batch_range_finite). */
static inline int batch_query_finite(const sample_batch_args *a, size_t k)
{
    return batch_range_finite(a, k, 1);
}

/* Prefetch the 2 × 2 block a bilinear read at texel coordinates (u, v)
 * (after the −½) on level L of a resident texture needs (nothing for
 * another source). Wrapping is ignored (a hint), but the
 * address is kept inside the level so that no invalid pointer is ever
 * formed. The pair's first and last byte (they may straddle a line) are
 * asked for without testing whether they share one: that test mispredicts
 * (fast_gl.c, prefetch_run). */
SAMPLE_FORCE_INLINE void ctx_prefetch_block(const sample_ctx *c, const struct sample_level *L, float u, float v)
{
    int i = u > 0.0f ? (u < (float)(L->w - 1) ? (int)u : L->w - 1) : 0;
    int j = v > 0.0f ? (v < (float)(L->h - 1) ? (int)v : L->h - 1) : 0;
    size_t tb = c->tex->texel_bytes;
    const unsigned char *p;
    size_t e = i + 1 < L->w ? 2 * tb - 1 : tb - 1;
    if (!tex_resident(c->tex)) return;
    p = L->data + (size_t)j * L->stride + (size_t)i * tb;
    SAMPLE_PREFETCH(p);
    SAMPLE_PREFETCH(p + e);
    if (j + 1 < L->h) {
        SAMPLE_PREFETCH(p + L->stride);
        SAMPLE_PREFETCH(p + L->stride + e);
    }
}

/* The stats of a query before (or without) any level: none chosen, λ 0,
 * no texel read. */
static inline void stats_clear(sample_stats *st)
{
    st->texels = 0;
    st->level0 = st->level1 = -1;
    st->level_frac = 0.0f;
    st->lod = 0.0f;
}

/* Query i of a batch where DESIGN §10 gives the border colour (non-finite
 * input): the colour, zero derivatives, empty stats. */
static inline void batch_border(const sample_ctx *c, const sample_batch_args *a, size_t i)
{
    memcpy(a->rgba + 4 * i, c->border, sizeof c->border);
    if (a->drgba_ds) memset(a->drgba_ds + 4 * i, 0, 4 * sizeof(float));
    if (a->drgba_dt) memset(a->drgba_dt + 4 * i, 0, 4 * sizeof(float));
    if (a->stats) stats_clear(&a->stats[i]);
}

#endif /* SAMPLE_CTX_H */
