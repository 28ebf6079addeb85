/*
 * The fast path of sample_batch for the OpenGL filters: NEAREST, LINEAR and
 * CUBIC per level, with or without mipmaps; with a footprint filter, the
 * magnified queries (λ ≤ 0, the mag filter); the anisotropic filter's
 * minified queries (their probes addressed and prefetched a few queries
 * ahead, aniso_address, and read from those addresses; the rare others
 * with this format's bilinear inlined); Blinn–Newell and EWA
 * planned one query ahead (ls_fp_footprint_plan: geometry, counting pass and
 * row prefetches) and accumulated by the filter (ls_filter_footprint_query). Also the
 * per-format readers the footprint filters use (tex_readers).
 *
 * It computes exactly what the general path (sampler.c's loop over
 * ls_recon_level / ctx_texel) computes, with the same operations in the same
 * order — the arithmetic itself is shared (tex_decode_v4, recon_bilerp,
 * recon_blend, ls_recon_cubic_combine in internal.h) — and differs only in how
 * it gets there:
 *
 *  - one loop per (format × channel count), chosen once per batch: the
 *    texel decode has no per-texel switch (zstd style: a generic static
 *    inline function instantiated by a small macro);
 *  - texel addresses are computed once per level and query as row pointers
 *    and column indices; a run of taps inside the level (most queries) needs
 *    no wrap at all, REPEAT uses an integer modulo, and only the rest goes
 *    through the double-valued ls_wrap_index;
 *  - queries are planned in blocks (λ, levels, addresses) and every cache
 *    line they will read is prefetched before the first texel is decoded:
 *    random queries into a large texture are bound by memory latency, and
 *    overlapping the misses of many queries is worth more than any
 *    arithmetic saving;
 *  - when the result cannot depend on λ (no mipmaps, the same per-level
 *    filter for magnification and minification, no stats wanted) λ is not
 *    computed at all;
 *  - with AVX2, 8-bit RGBA texels are decoded by gathers from the same
 *    tables tex_decode_v4 reads, and RGBA halves two texels at a time
 *    (texel_v4, texel_pair): the same values by fewer instructions.
 *
 * Identity with the reference path (sample_batch_reference, the testing
 * header) is tested for every format, channel count, wrap mode and filter
 * (tests/test_fastpath.c).
 */
#include "fast_texel.h"
#include "filter.h"
#include "footprint_feline.h"
#include "kernels.h"
#include "lod_lanes.h"

/* Queries planned (and prefetched) ahead of their evaluation. Larger blocks
 * keep more misses in flight; past about 32 the prefetches of one block
 * start to evict each other's lines from L1 (doc/performance.md). */
#ifndef FAST_BLOCK
#define FAST_BLOCK 32
#endif
/* How many anisotropic queries ahead of their reading their probes' lines
 * are asked for (fast_gl_batch). */
#ifndef FAST_AHEAD_FP
#define FAST_AHEAD_FP 16
#endif
#ifndef FAST_AHEAD_ANISO
#define FAST_AHEAD_ANISO 4
#endif

/* Texel addresses and fractions of one query on one level: taps
 * (col[x], row[y]) for x, y < 1, 2 or 4 (NEAREST, LINEAR, CUBIC). A
 * texture in tiles (texel.h, tile_side) has its taps in one tile, rows a
 * tile's row apart and col[] within the tile, or read through the source
 * (TAPS_SOURCE: col[] and ry[] the level's texel indices). */
typedef struct fast_taps {
    union {
        const unsigned char *row[4]; /* NULL: the row reads the border colour */
        int ry[4];                   /* TAPS_SOURCE: row index; −1: the border colour */
    };
    int col[4];                  /* texel index; −1: the border colour */
    float fu, fv;                /* α, β: the fractional parts (eq. 8.13) */
    int inside;                  /* 1: a block of consecutive taps in the level
                                  * (and tile; axis_index), no border; 0: rows
                                  * and columns; TAPS_SOURCE */
} fast_taps;

/* fast_taps.inside of taps read texel by texel through the source. */
#define TAPS_SOURCE (-1)

enum { PLAN_GL, PLAN_BORDER, PLAN_ANISO, PLAN_FOOTPRINT };

/* The probes of an anisotropic query, addressed when the query is planned
 * (aniso_address): at most ANISO_FAST_PROBES (a weighted probe set:
 * FP_PROBES_MAX), each with its 2 × 2 block inside both levels. */
#define ANISO_FAST_PROBES 16
#define ANISO_TAPS_MAX (FP_PROBES_MAX > ANISO_FAST_PROBES ? FP_PROBES_MAX : ANISO_FAST_PROBES)
/* Probes addressed together: the loops over them run on whole vectors
 * (8 floats: one AVX register, two SSE ones). */
#define ANISO_LANES 8

/* Blocks of a texture in tiles that cross a tile's edge, copied (at most
 * this many per query): a 2 × 2 block of texels of at most 16 bytes. */
#define ANISO_SCRATCH 8

typedef struct aniso_taps {
    int n; /* probes addressed; 0: fp_aniso_probes reads the query */
    const unsigned char *p[2][ANISO_TAPS_MAX]; /* each block's first texel on l0, l1 */
    size_t stride[2][ANISO_TAPS_MAX];          /* and the bytes from its first row to its second */
    float fu[2][ANISO_TAPS_MAX], fv[2][ANISO_TAPS_MAX];
    unsigned char scratch[ANISO_SCRATCH][4 * 16];
} aniso_taps;

typedef uint32_t (*aniso_fn)(const sample_ctx *c, const sample_query *q, const fp_aniso_setup *an,
                             const aniso_taps *at, float out[4], float dds[4], float ddt[4]);

typedef struct fast_plan {
    int kind; /* PLAN_GL: the taps below; PLAN_BORDER: non-finite input;
               * PLAN_ANISO: λ > 0, the probes of `an`; PLAN_FOOTPRINT: λ > 0
               * with Blinn–Newell or EWA (ls_filter_footprint_query) */
    float lam;
    lod_choice ch;
    union {
        fast_taps tp[2];    /* ch.level0, ch.level1 */
        fp_aniso_setup an;
    } u;
} fast_plan;

static int kind_taps(sample_filter kind)
{
    return kind == SAMPLE_NEAREST ? 1 : (kind == SAMPLE_LINEAR ? 2 : 4);
}

/* Indices (double)i0 + first + k, k < n, on an axis of len texels, exactly
 * as ls_wrap_index maps them. i0 is integral (a floor). A run inside the axis
 * maps to itself; REPEAT below 2^24 is an integer modulo (the same true
 * modulo as ls_wrap_index's exact fmod); anything else asks ls_wrap_index.
 * Returns 1 when the indices are consecutive, as a run inside the axis and
 * a repeated run not straddling the edge are (a repeating texture seen
 * from afar: the readers take the block whole), else 0. */
SAMPLE_FORCE_INLINE int axis_index(sample_wrap mode, float i0, int len, int n, int first, int linear,
                              int out[4])
{
    int k;
    if (i0 >= (float)-first && i0 <= (float)(len - n - first)) {
        int b = (int)i0 + first;
        for (k = 0; k < n; ++k) out[k] = b + k;
        return 1;
    }
    if (mode == SAMPLE_WRAP_REPEAT && fabsf(i0) < 16777216.0f) {
        int r = ((int)i0 + first) % len;
        if (r < 0) r += len;
        if (r <= len - n) {
            for (k = 0; k < n; ++k) out[k] = r + k;
            return 1;
        }
        for (k = 0; k < n; ++k) {
            out[k] = r;
            if (++r == len) r = 0;
        }
        return 0;
    }
    for (k = 0; k < n; ++k) out[k] = ls_wrap_index(mode, (double)i0 + (first + k), len, linear);
    return 0;
}

/* Prefetch the lines of the n texels c0 … c1 of a row (either may be −1,
 * the border): the first texel's first byte and the last one's last byte.
 * Both are asked for even when they share a line. Testing for that (a
 * second prefetch of a line in flight takes a slot in the miss queue) cost
 * more than it saved: the test depends on where the query falls, and its
 * mispredictions made trilinear 27 % slower (measured: doc/history/performance-passes.md). */
SAMPLE_FORCE_INLINE void prefetch_run(const unsigned char *r, int c0, int c1, int n, size_t tb)
{
    if (c0 >= 0) SAMPLE_PREFETCH(r + (size_t)c0 * tb);
    if (n > 1 && c1 >= 0) SAMPLE_PREFETCH(r + (size_t)c1 * tb + (tb - 1));
}

/* Taps whose n rows lie inside level L from row y0 on (one stride apart),
 * and, if `prefetch`, the lines of each row's run col[0] … col[n − 1]. */
SAMPLE_FORCE_INLINE void taps_rows_inside(const struct sample_level *L, int y0, int n, size_t tb, int prefetch,
                                          fast_taps *tp)
{
    const unsigned char *r = L->data + (size_t)y0 * L->stride;
    int k;
    for (k = 0; k < n; ++k, r += L->stride) {
        tp->row[k] = r;
        if (prefetch) prefetch_run(r, tp->col[0], tp->col[n - 1], n, tb);
    }
}

/* The first texel of the tile holding texel (i, j) of level lv (texel.h,
 * tile_side): the batch's memo's (ls_tile_memo), else the source's, then
 * remembered; NULL where the source lacks the tile or its level (tile_levels). */
SAMPLE_FORCE_INLINE const unsigned char *tile_origin(const sample_ctx *c, int lv, int i, int j)
{
    const struct ls_texel_source *src = c->tex->source;
    const int m = src->tile_side - 1, x = i & ~m, y = j & ~m;
    ls_tile_memo *memo = c->tiles;
    const unsigned char *p;
    if (memo && memo->x[lv] == x && memo->y[lv] == y) return memo->p[lv];
    p = tex_source_level_in_tiles(src, lv) ? src->texel(src, lv, x, y, 0) : NULL;
    if (memo && p) {
        memo->x[lv] = x;
        memo->y[lv] = y;
        memo->p[lv] = p;
    }
    return p;
}

/* Taps of a texture whose source holds its levels in tiles (texel.h,
 * tile_side), their indices col[] (the level's) and y[] made: an n × n
 * block inside the level (`in`) and inside one tile is addressed in that
 * tile (one texel() call; rows T texels apart) and then read exactly as a
 * resident level's block; any other — across a tile's edge (about 3 % of
 * bilinear blocks in 64² tiles), wrapped, or where tile_origin is NULL (a
 * tile the source lacks: the fill colour; a level not in tiles) — is read
 * texel by texel through the source (TAPS_SOURCE, tap_v4), as the reference path reads. */
SAMPLE_FORCE_INLINE void plan_tiles(const sample_ctx *c, int lv, int n, int in, const int y[4], size_t tb,
                                    int prefetch, fast_taps *tp)
{
    const int side = c->tex->source->tile_side, m = side - 1, x0 = tp->col[0] & m, y0 = y[0] & m;
    const unsigned char *p;
    int k;
    if (in && x0 + n <= side && y0 + n <= side && (p = tile_origin(c, lv, tp->col[0], y[0]))) {
        const size_t rs = (size_t)side * tb;
        p += (size_t)y0 * rs; /* the start of the block's first row in the tile */
        for (k = 0; k < n; ++k, p += rs) {
            tp->col[k] = x0 + k;
            tp->row[k] = p;
            if (prefetch) prefetch_run(p, x0, x0 + n - 1, n, tb);
        }
        tp->inside = 1;
        return;
    }
    tp->inside = TAPS_SOURCE;
    for (k = 0; k < n; ++k) tp->ry[k] = y[k];
}

/* Addresses of one query on level lv (ls_recon_level's coordinate rules) and,
 * if `prefetch`, prefetches of the lines they touch: the first and last
 * byte of each row's run cover it when the run is contiguous, as it almost
 * always is. */
SAMPLE_FORCE_INLINE void plan_level(const sample_ctx *c, int lv, sample_filter kind, float s, float t,
                              size_t tb, int prefetch, fast_taps *tp)
{
    const struct sample_level *L = &c->tex->level[lv];
    float u = recon_texel_coord(c->smp->wrap_s, s, L->w);
    float v = recon_texel_coord(c->smp->wrap_t, t, L->h);
    int n = kind_taps(kind), first = kind == SAMPLE_CUBIC ? -1 : 0, y[4], k;
    float i0, j0;
    if (kind == SAMPLE_NEAREST) {
        /* i = ⌊u⌋, j = ⌊v⌋ (eq. 8.12), NEAREST addressing rule. */
        i0 = floorf(u);
        j0 = floorf(v);
        tp->fu = tp->fv = 0.0f;
    } else {
        i0 = recon_linear_origin(u, &tp->fu);
        j0 = recon_linear_origin(v, &tp->fv);
    }
    tp->inside = axis_index(c->smp->wrap_s, i0, L->w, n, first, kind != SAMPLE_NEAREST, tp->col);
    if (axis_index(c->smp->wrap_t, j0, L->h, n, first, kind != SAMPLE_NEAREST, y)) {
        if (SAMPLE_LIKELY(tex_resident(c->tex)))
            taps_rows_inside(L, y[0], n, tb, prefetch, tp);
        else
            plan_tiles(c, lv, n, tp->inside, y, tb, prefetch, tp);
        return;
    }
    if (!tex_resident(c->tex)) {
        plan_tiles(c, lv, n, 0, y, tb, prefetch, tp);
        return;
    }
    tp->inside = 0;
    for (k = 0; k < n; ++k) {
        const unsigned char *r = y[k] < 0 ? NULL : L->data + (size_t)y[k] * L->stride;
        tp->row[k] = r;
        if (r && prefetch) prefetch_run(r, tp->col[0], tp->col[n - 1], n, tb);
    }
}

SAMPLE_FORCE_INLINE v4f fetch(const sample_ctx *c, sample_format fmt, int nc, size_t tb,
                        const unsigned char *row, int col)
{
    if (!row || col < 0) return v4_load(c->border);
    return texel_v4(fmt, nc, row + (size_t)col * tb);
}

/* Tap (x, y) of taps read through the source (TAPS_SOURCE): the border
 * colour where the wrap says so, else the texel as the reference path
 * reads it (tex_read_at: the fill colour where the source has none). */
static SAMPLE_NOINLINE v4f source_tap(const sample_ctx *c, int lv, int x, int y)
{
    float v[4];
    if (x < 0 || y < 0) return v4_load(c->border);
    tex_read_at(c->tex, c->tex->source->texel(c->tex->source, lv, x, y, 0), v);
    return v4_load(v);
}

/* Tap (col[x], row[y]) of planned taps, from wherever they are. */
SAMPLE_FORCE_INLINE v4f tap_v4(const sample_ctx *c, sample_format fmt, int nc, size_t tb, int lv,
                               const fast_taps *tp, int x, int y)
{
    if (SAMPLE_LIKELY(tp->inside != TAPS_SOURCE)) return fetch(c, fmt, nc, tb, tp->row[y], tp->col[x]);
    return source_tap(c, lv, tp->col[x], tp->ry[y]);
}

/* ls_recon_level on planned taps. Returns the texels read. */
SAMPLE_FORCE_INLINE uint32_t run_level(const sample_ctx *c, sample_format fmt, int nc, size_t tb,
                                 sample_filter kind, int lv, const fast_taps *tp, float out[4],
                                 float dds[4], float ddt[4])
{
    const struct sample_level *L = &c->tex->level[lv];
    uint32_t n;
    if (kind == SAMPLE_NEAREST) {
        v4_store(out, tap_v4(c, fmt, nc, tb, lv, tp, 0, 0));
        if (dds) v4_store(dds, v4_set1(0.0f));
        if (ddt) v4_store(ddt, v4_set1(0.0f));
        return 1;
    }
    if (kind == SAMPLE_LINEAR) {
        if (tp->inside > 0) {
            /* Most queries: the 2 × 2 block lies in the level (its rows
             * are then consecutive, plan_level), or in one tile. */
            bilerp_block(fmt, nc, tp->row[0] + (size_t)tp->col[0] * tb, (size_t)(tp->row[1] - tp->row[0]),
                         tp->fu, tp->fv, out, dds, ddt);
        } else {
            v4f T[4];
            T[0] = tap_v4(c, fmt, nc, tb, lv, tp, 0, 0);
            T[1] = tap_v4(c, fmt, nc, tb, lv, tp, 1, 0);
            T[2] = tap_v4(c, fmt, nc, tb, lv, tp, 0, 1);
            T[3] = tap_v4(c, fmt, nc, tb, lv, tp, 1, 1);
            recon_bilerp(T, tp->fu, tp->fv, out, dds, ddt);
        }
        n = 4;
    } else {
        double wx[4], wy[4], dwx[4], dwy[4];
        float T[16][4];
        int x, y;
        ls_cubic_weights(c->smp->cubic, tp->fu, wx, dwx);
        ls_cubic_weights(c->smp->cubic, tp->fv, wy, dwy);
        if (tp->inside > 0) {
            /* The 4 × 4 block lies in the level (or a tile): each row's
             * four texels are adjacent (plan_level), read as a level row. */
            for (y = 0; y < 4; ++y) decode_row(fmt, nc, tp->row[y] + (size_t)tp->col[0] * tb, tb, 4, T + 4 * y);
        } else {
            for (y = 0; y < 4; ++y)
                for (x = 0; x < 4; ++x) v4_store(T[4 * y + x], tap_v4(c, fmt, nc, tb, lv, tp, x, y));
        }
        ls_recon_cubic_combine(T, wx, wy, dwx, dwy, (c->smp->options & SAMPLE_OPT_CUBIC_CLAMP) != 0, tp->fu,
                               tp->fv, out, dds, ddt);
        n = 16;
    }
    /* ∂/∂s = ∂/∂u · w, as ls_recon_level. */
    if (dds) v4_store(dds, v4_mul(v4_load(dds), v4_set1((float)L->w)));
    if (ddt) v4_store(ddt, v4_mul(v4_load(ddt), v4_set1((float)L->h)));
    return n;
}

/* plan_query for a footprint sampler: λ, and when λ > 0 (sampler.c's
 * rule: a footprint filter minifies, the mag filter magnifies) the
 * filter's plan; returns 1 then. Out of line: the GL filters' planning
 * loop stays small. */
static SAMPLE_NOINLINE int plan_footprint(const sample_ctx *c, const sample_query *q, float bias, fast_plan *pl)
{
    double rho2[2], lr = lod_log2_rho(c, q, rho2);
    pl->lam = lod_lambda(c, (float)lr, bias);
    if (!(pl->lam > 0.0f)) return 0;
    pl->kind = PLAN_FOOTPRINT;
    if (c->smp->footprint == SAMPLE_FOOTPRINT_ANISOTROPIC) {
        /* The probes now (their addresses and prefetches: plan_aniso),
         * queries ahead of their reading (the other filters find their
         * spans only in their counting pass). */
        pl->kind = PLAN_ANISO;
        ls_fp_aniso_setup_of(c, q, rho2, lr, bias, &pl->u.an);
    } else if (c->smp->footprint == SAMPLE_FOOTPRINT_FELINE) {
        pl->kind = PLAN_ANISO; /* plan_aniso makes its probe set */
    }
    return 1;
}

/* λ of query i from its λ_base, and the level choice. */
SAMPLE_FORCE_INLINE void plan_gl_choose(const sample_ctx *c, const sample_batch_args *a, size_t i, float lam_base,
                                        fast_plan *pl)
{
    pl->kind = PLAN_GL;
    pl->lam = lod_lambda(c, lam_base, a->lod_bias ? a->lod_bias[i] : 0.0f);
    pl->ch = lod_select(c, pl->lam);
}

/* λ and the level choice of finite query i under the OpenGL filters
 * (eqs. 8.6–8.9, §8.14.2–8.14.3); `fixed`, if not NULL, is the choice
 * whatever λ is (fast_gl_batch). */
SAMPLE_FORCE_INLINE void plan_gl_lod(const sample_ctx *c, const sample_batch_args *a, size_t i,
                                     const lod_choice *fixed, fast_plan *pl)
{
    if (fixed) {
        pl->kind = PLAN_GL;
        pl->ch = *fixed;
        pl->lam = 0.0f;
        return;
    }
    plan_gl_choose(c, a, i, lod_lambda_base(c, &a->queries[i]), pl);
}

/* plan_gl_lod for queries i … i + m − 1 of a finite block, λ_base four
 * queries at a time where the build has the lanes (lod_lanes.h). */
SAMPLE_FORCE_INLINE void plan_gl_lods(const sample_ctx *c, const sample_batch_args *a, size_t i, size_t m,
                                      const lod_choice *fixed, fast_plan *pl)
{
    float lb[FAST_BLOCK];
    size_t k = 0;
    if (fixed) {
        for (k = 0; k < m; ++k) plan_gl_lod(c, a, i + k, fixed, &pl[k]);
        return;
    }
#if SAMPLE_VEC_AVX2
    for (; k + 4 <= m; k += 4) lod_lambda_base4(c, &a->queries[i + k], lb + k);
#endif
    for (; k < m; ++k) lb[k] = lod_lambda_base(c, &a->queries[i + k]);
    for (k = 0; k < m; ++k) plan_gl_choose(c, a, i + k, lb[k], &pl[k]);
}

/* The addresses of planned level `which` (0 or 1) of query q, if it has
 * that level. */
SAMPLE_FORCE_INLINE void plan_taps(const sample_ctx *c, const sample_query *q, size_t tb, int linear, int which,
                                   fast_plan *pl)
{
    int lv = which ? pl->ch.level1 : pl->ch.level0;
    if (lv >= 0) plan_level(c, lv, linear ? SAMPLE_LINEAR : pl->ch.kind, q->s, q->t, tb, 1, &pl->u.tp[which]);
}

#if SAMPLE_VEC_AVX2
/* plan_taps of four queries of a finite block (k = 0 … 3), their texel
 * coordinates in one vector of eight floats (u, v of each), where that is
 * plan_level to the bit: LINEAR taps on a wrap mode that uses s and t as
 * they are (recon_texel_coord's modes below CLAMP), and a 2 × 2 block that
 * lies inside the level on both axes (axis_index's first case: the same
 * indices for every wrap mode). The same float operations in the same
 * order — u = s·w, a = u − ½, ⌊a⌋, a − ⌊a⌋, the in-level test against
 * w − 2 — so the same bits; a u that recon_texel_coord would clamp is
 * ±inf here and fails the test. Any other query, or level, goes through
 * plan_taps. A texture in tiles (`resident` 0) has the block then addressed
 * in its tile (plan_tiles). Only where the build has AVX2 (256-bit integer
 * lanes; measured in doc/history/performance-passes.md). */

SAMPLE_FORCE_INLINE void plan_taps4(const sample_ctx *c, const sample_query *q, size_t tb, int linear, int which,
                                    int resident, fast_plan *pl)
{
    const struct sample_level *lev = c->tex->level;
    int lv[4], ok[4], k, in;
    int64_t ij[4];
    __m128 fq[4];
    __m256i wh, ii;
    __m256 st, a, i0, lim, f;
    for (k = 0; k < 4; ++k) {
        lv[k] = which ? pl[k].ch.level1 : pl[k].ch.level0;
        ok[k] = lv[k] >= 0 && (linear || pl[k].ch.kind == SAMPLE_LINEAR);
    }
    if (!(ok[0] | ok[1] | ok[2] | ok[3])) { /* e.g. no second level: nothing for the lanes */
        for (k = 0; k < 4; ++k) plan_taps(c, &q[k], tb, linear, which, &pl[k]);
        return;
    }
    {
        const struct sample_level *L0 = &lev[ok[0] ? lv[0] : 0], *L1 = &lev[ok[1] ? lv[1] : 0],
                                  *L2 = &lev[ok[2] ? lv[2] : 0], *L3 = &lev[ok[3] ? lv[3] : 0];
        wh = _mm256_setr_epi32(L0->w, L0->h, L1->w, L1->h, L2->w, L2->h, L3->w, L3->h);
    }
    /* s, t of each query: 8 bytes at the start of its 24. */
    st = _mm256_castsi256_ps(_mm256_set_m128i(
        _mm_unpacklo_epi64(_mm_loadl_epi64((const __m128i *)(const void *)&q[2].s),
                           _mm_loadl_epi64((const __m128i *)(const void *)&q[3].s)),
        _mm_unpacklo_epi64(_mm_loadl_epi64((const __m128i *)(const void *)&q[0].s),
                           _mm_loadl_epi64((const __m128i *)(const void *)&q[1].s))));
    a = _mm256_sub_ps(_mm256_mul_ps(st, _mm256_cvtepi32_ps(wh)), _mm256_set1_ps(0.5f));
    i0 = _mm256_round_ps(a, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
    lim = _mm256_cvtepi32_ps(_mm256_sub_epi32(wh, _mm256_set1_epi32(2)));
    in = _mm256_movemask_ps(_mm256_and_ps(_mm256_cmp_ps(i0, _mm256_setzero_ps(), _CMP_GE_OQ),
                                          _mm256_cmp_ps(i0, lim, _CMP_LE_OQ)));
    /* Each query's (fu, fv) and (i, j) taken from the registers (a store
     * and narrower reloads would wait on store forwarding). */
    f = _mm256_sub_ps(a, i0);
    fq[0] = _mm256_castps256_ps128(f);
    fq[2] = _mm256_extractf128_ps(f, 1);
    fq[1] = _mm_movehl_ps(fq[0], fq[0]);
    fq[3] = _mm_movehl_ps(fq[2], fq[2]);
    ii = _mm256_cvttps_epi32(i0);
    ij[0] = _mm_cvtsi128_si64(_mm256_castsi256_si128(ii));
    ij[1] = _mm_extract_epi64(_mm256_castsi256_si128(ii), 1);
    ij[2] = _mm_cvtsi128_si64(_mm256_extracti128_si256(ii, 1));
    ij[3] = _mm_extract_epi64(_mm256_extracti128_si256(ii, 1), 1);
    for (k = 0; k < 4; ++k) {
        fast_taps *tp = &pl[k].u.tp[which];
        int i = (int)(uint32_t)ij[k], j = (int)(uint32_t)((uint64_t)ij[k] >> 32);
        if (!ok[k] || ((in >> 2 * k) & 3) != 3) {
            plan_taps(c, &q[k], tb, linear, which, &pl[k]);
            continue;
        }
        tp->fu = _mm_cvtss_f32(fq[k]);
        tp->fv = _mm_cvtss_f32(_mm_shuffle_ps(fq[k], fq[k], 1));
        tp->col[0] = i;
        tp->col[1] = i + 1;
        tp->inside = 1;
        if (resident) {
            taps_rows_inside(&lev[lv[k]], j, 2, tb, 1, tp);
        } else {
            const int y[4] = {j, j + 1};
            plan_tiles(c, lv[k], 2, 1, y, tb, 1, tp);
        }
    }
}
#endif

/* plan_taps of level `which` for queries 0 … m − 1 of a finite block;
 * four at a time for float and half texels only: with 8-bit texels the
 * query is bound by their decode, and planning in lanes measured 1–2 %
 * slower there (measured: doc/history/performance-passes.md). */
SAMPLE_FORCE_INLINE void plan_taps_block(const sample_ctx *c, const sample_query *q, size_t m, sample_format fmt,
                                         size_t tb, int linear, int which, fast_plan *pl)
{
    size_t k = 0;
#if SAMPLE_VEC_AVX2
    const int resident = tex_resident(c->tex);
    if ((fmt == SAMPLE_FORMAT_F32 || fmt == SAMPLE_FORMAT_F16) && !wrap_transforms_coord(c->smp->wrap_s) &&
        !wrap_transforms_coord(c->smp->wrap_t))
        for (; k + 4 <= m; k += 4) plan_taps4(c, q + k, tb, linear, which, resident, pl + k);
#else
    (void)fmt;
#endif
    for (; k < m; ++k) plan_taps(c, &q[k], tb, linear, which, &pl[k]);
}

/* Constants of each instantiation: `gl`, the sampler has no footprint
 * filter (gl_blocks), so no query is handed to one; `linear`, the batch's
 * per-level filter is LINEAR whatever λ is, so the tap count and the
 * reconstruction are known at compile time. (`fixed` implies no footprint
 * filter.) */
SAMPLE_FORCE_INLINE void plan_query(const sample_ctx *c, const sample_batch_args *a, size_t i,
                              const lod_choice *fixed, size_t tb, int gl, int linear, fast_plan *pl)
{
    const sample_query *q = &a->queries[i];
    if (!batch_query_finite(a, i)) {
        pl->kind = PLAN_BORDER;
        return;
    }
    if (gl || c->smp->footprint == SAMPLE_FOOTPRINT_NONE) {
        plan_gl_lod(c, a, i, fixed, pl);
    } else {
        pl->kind = PLAN_GL;
        if (plan_footprint(c, q, a->lod_bias ? a->lod_bias[i] : 0.0f, pl)) return;
        pl->ch = lod_select(c, pl->lam);
    }
    plan_taps(c, q, tb, linear, 0, pl);
    plan_taps(c, q, tb, linear, 1, pl);
}

/* sampler.c's run_query + gl_apply for a planned query. */
SAMPLE_FORCE_INLINE void run_query(const sample_ctx *c, const sample_batch_args *a, size_t i,
                             const fast_plan *pl, const fp_plan *fpl, const aniso_taps *at,
                             sample_format fmt, int nc, size_t tb, int gl, int linear, aniso_fn aniso)
{
    const sample_filter kind = linear ? SAMPLE_LINEAR : pl->ch.kind;
    float *out = a->rgba + 4 * i;
    float *dds = a->drgba_ds ? a->drgba_ds + 4 * i : NULL;
    float *ddt = a->drgba_dt ? a->drgba_dt + 4 * i : NULL;
    uint32_t n;
    if (pl->kind == PLAN_BORDER) {
        batch_border(c, a, i);
        return;
    }
    if (!gl && pl->kind == PLAN_FOOTPRINT) {
        ls_filter_footprint_query(c, a, i, fpl);
        return;
    }
    if (!gl && pl->kind == PLAN_ANISO) {
        n = aniso(c, &a->queries[i], &pl->u.an, at, out, dds, ddt);
        if (a->stats) {
            fp_aniso_stats(&pl->u.an, &a->stats[i]);
            a->stats[i].texels = n;
        }
        return;
    }
    n = run_level(c, fmt, nc, tb, kind, pl->ch.level0, &pl->u.tp[0], out, dds, ddt);
    if (pl->ch.level1 >= 0) {
        float o1[4], ds1[4], dt1[4];
        n += run_level(c, fmt, nc, tb, kind, pl->ch.level1, &pl->u.tp[1], o1,
                       dds ? ds1 : NULL, ddt ? dt1 : NULL);
        recon_blend(out, o1, pl->ch.frac);
        if (dds) recon_blend(dds, ds1, pl->ch.frac);
        if (ddt) recon_blend(ddt, dt1, pl->ch.frac);
    }
    if (a->stats) {
        a->stats[i].texels = n;
        a->stats[i].level0 = (int16_t)pl->ch.level0;
        a->stats[i].level1 = (int16_t)pl->ch.level1;
        a->stats[i].level_frac = pl->ch.frac;
        a->stats[i].lod = pl->lam;
    }
}

/* ---- Readers for the footprint filters (tex_readers) --------------------- */

SAMPLE_FORCE_INLINE uint32_t bilinear_level(const sample_ctx *c, sample_format fmt, int nc, int lv,
                                            float s, float t, float out[4], float dds[4],
                                            float ddt[4])
{
    const size_t tb = texel_bytes(fmt, nc);
    fast_taps tp;
    /* No prefetch: the anisotropic filter asked for its probes' rows. */
    plan_level(c, lv, SAMPLE_LINEAR, s, t, tb, 0, &tp);
    return run_level(c, fmt, nc, tb, SAMPLE_LINEAR, lv, &tp, out, dds, ddt);
}

/* ---- Anisotropic probes addressed ahead ---------------------------------
 * plan_level's LINEAR addressing for all of a query's probes at once, as
 * loops of ANISO_LANES iterations without branches, which GCC turns into
 * vector code at -O2 and -O3 (lane-wise IEEE operations: the same bits as
 * one probe at a time). Only the common case is taken: both wraps without
 * a ls_wrap_coord transform and every block inside both levels, where
 * axis_index maps the block to itself whatever the wrap mode; the floor is
 * then a truncation (a ≥ 0), the inside test is 0 ≤ a < w − 1
 * (⌊a⌋ ≤ w − 2), and recon_texel_coord's clamp of u to ±FLT_MAX cannot
 * apply (an infinite u fails the test). Anything else returns 0 and the
 * query's probes are read by fp_aniso_probes. */

/* Before each loop over one vector's lanes: GCC -O3 would unroll the 8
 * iterations completely and then vectorize poorly across them. */
#if defined(__GNUC__)
#define ANISO_LANE_LOOP _Pragma("GCC unroll 1")
#else
#define ANISO_LANE_LOOP
#endif

/* x where in is 1, +0 where it is 0: a select written as a mask, because
 * GCC 12 does not if-convert `in ? x : 0.0f` in these loops. */
SAMPLE_FORCE_INLINE float keep_if(float x, int in)
{
    uint32_t b;
    memcpy(&b, &x, sizeof b);
    b &= (uint32_t)-in;
    memcpy(&x, &b, sizeof x);
    return x;
}

/* aniso_address's blocks (ii[k], jj[k]), k < n, on level lv of a texture
 * in tiles (texel.h, tile_side), as `which` (0: l0, 1: l1) of at: a block
 * inside one tile where it is (one texel() call), one across a tile's
 * edge copied texel by texel into at->scratch (rows 2 texels apart), the
 * same bytes, so bilerp_block reads the same values either way. Returns 0
 * where a block's tile_origin is NULL (a tile the source lacks, a level not
 * in tiles) or the scratch is full: fp_aniso_probes then
 * reads the query (plan_tiles, texel by texel where needed). */
static int aniso_address_tiles(const sample_ctx *c, int lv, int n, const int *ii, const int *jj, size_t tb,
                               int which, int *used, aniso_taps *at)
{
    const struct ls_texel_source *src = c->tex->source;
    const int side = src->tile_side, m = side - 1;
    const size_t rs = (size_t)side * tb;
    int k, d;
    for (k = 0; k < n; ++k) {
        const unsigned char *p;
        if ((ii[k] & m) + 2 <= side && (jj[k] & m) + 2 <= side) {
            if (!(p = tile_origin(c, lv, ii[k], jj[k]))) return 0;
            p += (size_t)(jj[k] & m) * rs + (size_t)(ii[k] & m) * tb;
            at->p[which][k] = p;
            at->stride[which][k] = rs;
            SAMPLE_PREFETCH(p);
            SAMPLE_PREFETCH(p + rs);
            SAMPLE_PREFETCH(p + 2 * tb - 1);
            SAMPLE_PREFETCH(p + rs + 2 * tb - 1);
            continue;
        }
        if (*used == ANISO_SCRATCH) return 0;
        for (d = 0; d < 4; ++d) {
            if (!(p = src->texel(src, lv, ii[k] + (d & 1), jj[k] + (d >> 1), 0))) return 0;
            memcpy(at->scratch[*used] + (size_t)d * tb, p, tb);
        }
        at->p[which][k] = at->scratch[*used];
        at->stride[which][k] = 2 * tb;
        ++*used;
    }
    return 1;
}

static int aniso_address(const sample_ctx *c, const sample_query *q, const fp_aniso_setup *an, size_t tb,
                         aniso_taps *at)
{
    float s[ANISO_TAPS_MAX], t[ANISO_TAPS_MAX];
    int ii[ANISO_TAPS_MAX], jj[ANISO_TAPS_MAX];
    const int n = an->n, lanes = (n + ANISO_LANES - 1) / ANISO_LANES * ANISO_LANES;
    int lv, k, b0, used = 0;
    at->n = 0;
    if (n > (an->set ? FP_PROBES_MAX : ANISO_FAST_PROBES) || wrap_transforms_coord(c->smp->wrap_s) ||
        wrap_transforms_coord(c->smp->wrap_t))
        return 0;
    /* Lanes past n hold probes beyond the footprint's end (a set's: its
     * last probe again): computed, never read. */
    if (an->set)
        for (k = 0; k < lanes; ++k) {
            s[k] = an->set->s[k < n ? k : n - 1];
            t[k] = an->set->t[k < n ? k : n - 1];
        }
    else
        for (b0 = 0; b0 < lanes; b0 += ANISO_LANES)
            ANISO_LANE_LOOP
            for (k = b0; k < b0 + ANISO_LANES; ++k) fp_aniso_probe(q, an, k + 1, &s[k], &t[k]);
    for (lv = 0; lv < 1 + (an->l1 != an->l0); ++lv) {
        const struct sample_level *L = &c->tex->level[lv ? an->l1 : an->l0];
        const float w = (float)L->w, h = (float)L->h, wm = w - 1.0f, hm = h - 1.0f;
        int out = 0;
        for (b0 = 0; b0 < lanes; b0 += ANISO_LANES)
            ANISO_LANE_LOOP
            for (k = b0; k < b0 + ANISO_LANES; ++k) {
                float a = s[k] * w - 0.5f, b = t[k] * h - 0.5f;
                int in = (a >= 0.0f) & (a < wm) & (b >= 0.0f) & (b < hm);
                a = keep_if(a, in);
                b = keep_if(b, in);
                ii[k] = (int)a;
                jj[k] = (int)b;
                at->fu[lv][k] = a - (float)ii[k];
                at->fv[lv][k] = b - (float)jj[k];
                out |= (in ^ 1) & (k < n);
            }
        if (out) return 0;
        /* Each block's lines, the first and last byte of both rows. No
         * test for a line asked for already (prefetch_run): which lines
         * repeat depends on the data, and the branches mispredicted so
         * often that the query took 45 % longer (measured: doc/history/performance-passes.md). */
        if (!tex_resident(c->tex)) {
            if (!aniso_address_tiles(c, lv ? an->l1 : an->l0, n, ii, jj, tb, lv, &used, at)) return 0;
            continue;
        }
        for (k = 0; k < n; ++k) {
            const unsigned char *p = L->data + (size_t)jj[k] * L->stride + (size_t)ii[k] * tb;
            at->p[lv][k] = p;
            at->stride[lv][k] = L->stride;
            SAMPLE_PREFETCH(p);
            SAMPLE_PREFETCH(p + L->stride);
            SAMPLE_PREFETCH(p + 2 * tb - 1);
            SAMPLE_PREFETCH(p + L->stride + 2 * tb - 1);
        }
    }
    at->n = n;
    return 1;
}

/* fp_aniso_probes on addressed probes, without derivatives. */
SAMPLE_FORCE_INLINE uint32_t aniso_read(const sample_ctx *c, sample_format fmt, int nc,
                                        const fp_aniso_setup *an, const aniso_taps *at, float out[4])
{
    const int two = an->l1 != an->l0;
    double acc[4] = {0, 0, 0, 0};
    int k;
    (void)c;
    for (k = 0; k < at->n; ++k) {
        float o0[4], o1[4];
        bilerp_block(fmt, nc, at->p[0][k], at->stride[0][k], at->fu[0][k], at->fv[0][k], o0, NULL, NULL);
        if (two)
            bilerp_block(fmt, nc, at->p[1][k], at->stride[1][k], at->fu[1][k], at->fv[1][k], o1, NULL, NULL);
        else
            memcpy(o1, o0, sizeof o1);
        if (an->set)
            fp_probe_add(acc, an->set->w[k], (double)an->f, o0, o1);
        else
            fp_aniso_add(acc, (double)an->f, o0, o1);
    }
    if (an->set)
        fp_probe_mean(acc, an->set->sw, out);
    else
        fp_aniso_mean(acc, an->n, out);
    return (uint32_t)(4 * at->n * (1 + two));
}

/* plan_query for the anisotropic filter's pipeline (and Feline's, whose
 * weighted probes go to `set`): a minified query's probes addressed and
 * their lines asked for. */
SAMPLE_FORCE_INLINE void plan_aniso(const sample_ctx *c, const sample_batch_args *a, size_t i, size_t tb,
                                    fast_plan *pl, aniso_taps *at, fp_probe_set *set)
{
    plan_query(c, a, i, NULL, tb, 0, 0, pl);
    at->n = 0;
    if (pl->kind != PLAN_ANISO) return;
    if (c->smp->footprint == SAMPLE_FOOTPRINT_FELINE)
        ls_fp_feline_setup(c, &a->queries[i], a->lod_bias ? a->lod_bias[i] : 0.0f, &pl->u.an, set);
    if (!aniso_address(c, &a->queries[i], &pl->u.an, tb, at) && !pl->u.an.set)
        ls_fp_aniso_prefetch(c, &a->queries[i], &pl->u.an);
}

/* A kernel set is generated for a texel format and channel count given as
 * the expressions FMT and NC: constants (SAMPLE_FORMAT_F32, 4) in the
 * kernels specialised for one format (the switches of tex_decode_v4 then
 * vanish), or the texture's own (fast_any) in the one generic set that
 * serves every other format and channel count. `name` names the set. In
 * the readers, FMT and NC may use fmt_/nc_, which every reader defines
 * from its arguments or its texture. */
#define FAST_TEXTURE_FORMAT(c)                                                 \
    const sample_format fmt_ = (c)->tex->format;                               \
    const int nc_ = (c)->tex->channels;                                        \
    (void)fmt_;                                                                \
    (void)nc_
#define TEX_READERS(name, FMT, NC)                                             \
    static void row_##name(sample_format fmt_, int nc_, const unsigned char *p, size_t pitch, int n, \
                           float (*out)[4])                                    \
    {                                                                          \
        (void)fmt_;                                                            \
        (void)nc_;                                                             \
        decode_row(FMT, NC, p, pitch, n, out);                                 \
    }                                                                          \
    SAMPLE_FORCE_INLINE uint32_t bilinear_inline_##name(const sample_ctx *c, int lv, float s, float t, \
                                                        float out[4], float dds[4], float ddt[4]) \
    {                                                                          \
        FAST_TEXTURE_FORMAT(c);                                                \
        return bilinear_level(c, FMT, NC, lv, s, t, out, dds, ddt);            \
    }                                                                          \
    static uint32_t bilinear_##name(const sample_ctx *c, int lv, float s, float t, float out[4], \
                                    float dds[4], float ddt[4])                \
    {                                                                          \
        return bilinear_inline_##name(c, lv, s, t, out, dds, ddt);             \
    }                                                                          \
    /* ls_fp_anisotropic's probes: those addressed ahead read from their      \
     * addresses, the others with this format's bilinear inlined. */         \
    static SAMPLE_NOINLINE uint32_t aniso_##name(const sample_ctx *c, const sample_query *q, \
                                                 const fp_aniso_setup *an, const aniso_taps *at, \
                                                 float out[4], float dds[4], float ddt[4]) \
    {                                                                          \
        FAST_TEXTURE_FORMAT(c);                                                \
        if (at->n && !dds && !ddt) return aniso_read(c, FMT, NC, an, at, out); \
        return fp_aniso_probes(c, q, an, bilinear_inline_##name, out, dds, ddt); \
    }

/* The filter's own plan of query i when plan_query handed it to the
 * footprint filter (Blinn–Newell, EWA). */
SAMPLE_FORCE_INLINE void plan_fp_query(const sample_ctx *c, const sample_batch_args *a, size_t i,
                                       const fast_plan *pl, fp_plan *fpl)
{
    if (pl->kind == PLAN_FOOTPRINT)
        ls_fp_footprint_plan(c, &a->queries[i], a->corners ? &a->corners[i] : NULL,
                          a->lod_bias ? a->lod_bias[i] : 0.0f, fpl);
}

/* The OpenGL filters' batch loop (no footprint filter): blocks of
 * FAST_BLOCK queries planned (and their lines prefetched), then run. The
 * sampler and context are copied into locals whose address never leaves
 * this function's inlined code: the compiler then knows that the result
 * stores (floats) cannot change the sampler's floats, and keeps the λ
 * clamps and level-selection state in registers across queries. With
 * gl = 1 run_query never reaches the anisotropic reader (NULL here). */
SAMPLE_FORCE_INLINE void gl_blocks(const sample_ctx *cp, const sample_batch_args *a, sample_format fmt,
                                   int nc, const lod_choice *fixed, int linear)
{
    const size_t tb = texel_bytes(fmt, nc);
    const sample_sampler smp = *cp->smp;
    sample_ctx ctx = *cp;
    const sample_ctx *c = &ctx;
    size_t i, k;
    ctx.smp = &smp;
    for (i = 0; i < a->count; i += FAST_BLOCK) {
        fast_plan plan[FAST_BLOCK];
        size_t m = a->count - i < FAST_BLOCK ? a->count - i : FAST_BLOCK;
        if (!batch_range_finite(a, i, m)) {
            for (k = 0; k < m; ++k) plan_query(c, a, i + k, fixed, tb, 1, linear, &plan[k]);
        } else {
            /* plan_query's steps, each for the whole block before the
             * next: short loops whose iterations the processor overlaps,
             * where plan_query's one long chain of dependent steps (λ, the
             * levels, each level's addresses) kept about one query in
             * flight (measured: doc/history/performance-passes.md). */
            plan_gl_lods(c, a, i, m, fixed, plan);
            plan_taps_block(c, a->queries + i, m, fmt, tb, linear, 0, plan);
            /* A fixed choice of one level has no second level's taps. */
            if (!fixed || fixed->level1 >= 0) plan_taps_block(c, a->queries + i, m, fmt, tb, linear, 1, plan);
        }
        for (k = 0; k < m; ++k) run_query(c, a, i + k, &plan[k], NULL, NULL, fmt, nc, tb, 1, linear, NULL);
    }
}

/* The batch loop, generic over the texel format and channel count; each
 * instantiation below has them as constants. */
SAMPLE_FORCE_INLINE void fast_gl_batch(const sample_ctx *cp, const sample_batch_args *a, sample_format fmt,
                                 int nc, aniso_fn aniso)
{
    const size_t tb = texel_bytes(fmt, nc);
    const sample_sampler *smp = cp->smp;
    const sample_ctx *c = cp;
    sample_ctx cm;
    ls_tile_memo memo;
    lod_choice mn = lod_select(c, 1.0f), mg = lod_select(c, -1.0f);
    /* λ only picks between two identical choices: a non-mipmapped min filter
     * whose per-level filter is the mag filter's (lod_select then returns
     * level_base and that filter for every λ). Stats report λ, so they need
     * it computed, and a footprint filter needs it for every query. */
    int fixed = !a->stats && smp->footprint == SAMPLE_FOOTPRINT_NONE &&
                (smp->min_filter == SAMPLE_NEAREST || smp->min_filter == SAMPLE_LINEAR ||
                 smp->min_filter == SAMPLE_CUBIC) &&
                mn.kind == mg.kind && mn.level0 == mg.level0 && mn.level1 < 0 && mg.level1 < 0;
    size_t i;
    if (!tex_resident(cp->tex)) { /* valid until the batch ends (ls_tile_memo) */
        for (i = 0; i < SAMPLE_MAX_LEVELS; ++i) memo.x[i] = memo.y[i] = -1;
        cm = *cp;
        cm.tiles = &memo;
        c = &cm;
    }
    if (smp->footprint == SAMPLE_FOOTPRINT_ANISOTROPIC || smp->footprint == SAMPLE_FOOTPRINT_FELINE) {
        /* A software pipeline FAST_AHEAD_ANISO queries deep: query i + D is
         * planned (its probes' lines asked for) right after query i ran, so
         * the misses of the next queries are in flight while this one
         * computes. A block of them planned at once would issue more
         * prefetches than the miss queue holds and then leave memory idle
         * while the block computes. */
        fast_plan ring[FAST_AHEAD_ANISO];
        aniso_taps taps[FAST_AHEAD_ANISO];
        fp_probe_set sets[FAST_AHEAD_ANISO];
        size_t ahead = a->count < FAST_AHEAD_ANISO ? a->count : FAST_AHEAD_ANISO;
        for (i = 0; i < ahead; ++i) plan_aniso(c, a, i, tb, &ring[i], &taps[i], &sets[i]);
        for (i = 0; i < a->count; ++i) {
            size_t r = i % FAST_AHEAD_ANISO;
            run_query(c, a, i, &ring[r], NULL, &taps[r], fmt, nc, tb, 0, 0, aniso);
            if (i + FAST_AHEAD_ANISO < a->count)
                plan_aniso(c, a, i + FAST_AHEAD_ANISO, tb, &ring[r], &taps[r], &sets[r]);
        }
        return;
    }
    if (smp->footprint == SAMPLE_FOOTPRINT_BLINN_NEWELL || smp->footprint == SAMPLE_FOOTPRINT_EWA) {
        /* Two pipelines: every query is planned FAST_AHEAD_FP ahead (the
         * magnified ones, read like any GL query, get their lines asked
         * for as in the blocks below); a minified one's filter plan — its
         * geometry and counting pass, which finds and prefetches its rows
         * — is made while the query before it runs, so its lines arrive
         * during that query's accumulation. Deeper filter plans measured
         * the same (doc/history/performance-passes.md) and each is FP_PLAN_BYTES. */
        fast_plan ring[FAST_AHEAD_FP];
        fp_plan fpl[2];
        size_t ahead = a->count < FAST_AHEAD_FP ? a->count : FAST_AHEAD_FP;
        for (i = 0; i < ahead; ++i) plan_query(c, a, i, NULL, tb, 0, 0, &ring[i]);
        if (ahead) plan_fp_query(c, a, 0, &ring[0], &fpl[0]);
        for (i = 0; i < a->count; ++i) {
            fast_plan *pl = &ring[i % FAST_AHEAD_FP];
            if (i + 1 < a->count) plan_fp_query(c, a, i + 1, &ring[(i + 1) % FAST_AHEAD_FP], &fpl[(i + 1) & 1]);
            run_query(c, a, i, pl, &fpl[i & 1], NULL, fmt, nc, tb, 0, 0, aniso);
            if (i + FAST_AHEAD_FP < a->count) plan_query(c, a, i + FAST_AHEAD_FP, NULL, tb, 0, 0, pl);
        }
        return;
    }
    if (lod_level_kind(smp->min_filter) == SAMPLE_LINEAR && lod_level_kind(smp->mag_filter) == SAMPLE_LINEAR)
        gl_blocks(c, a, fmt, nc, fixed ? &mg : NULL, 1);
    else
        gl_blocks(c, a, fmt, nc, fixed ? &mg : NULL, 0);
}

/* The batch loop of a kernel set (TEX_READERS). */
#define FAST_GL_KERNEL(name, FMT, NC)                                          \
    static void fast_gl_##name(const sample_ctx *c, const sample_batch_args *a) \
    {                                                                          \
        FAST_TEXTURE_FORMAT(c);                                                \
        fast_gl_batch(c, a, FMT, NC, aniso_##name);                            \
    }
#define FAST_KERNEL_SET(name, FMT, NC) TEX_READERS(name, FMT, NC) FAST_GL_KERNEL(name, FMT, NC)

/* Specialised only where it pays: RGBA float, half and sRGB8 — the
 * textures a renderer samples most and the bench measures
 * (doc/benchmarks.md). Each set costs a copy of the batch loop in every
 * instruction set's object (about 18 s of compile time each with GCC 12
 * at -O3, against 38 s for the generic set); every other format and
 * channel count runs the generic set, whose per-texel format and channel
 * switches predict perfectly within a batch. The scalar build on x86-64 (SAMPLE_FAST_SPECIALIZE 0)
 * exists for tests and comparisons only and has the generic set alone. */
#ifndef SAMPLE_FAST_SPECIALIZE
#define SAMPLE_FAST_SPECIALIZE 1
#endif
FAST_KERNEL_SET(any, fmt_, nc_)
#if SAMPLE_FAST_SPECIALIZE
FAST_KERNEL_SET(F32_4, SAMPLE_FORMAT_F32, 4)
FAST_KERNEL_SET(F16_4, SAMPLE_FORMAT_F16, 4)
FAST_KERNEL_SET(SRGB8_4, SAMPLE_FORMAT_SRGB8, 4)
#define FAST_RGBA(fmt) fmt##_4
#else
#define FAST_RGBA(fmt) any
#endif

/* ---- This build's table (isa.c) -----------------------------------------
 * The build compiles this file once per instruction set (scalar, SSE2,
 * AVX2, AVX-512; isa.c picks one at run time): the code is the same, only
 * simd.h's vector type and the compiler's target differ, and each object
 * exports its own table, named by SAMPLE_ISA_NAME. */

#ifndef SAMPLE_ISA
#error "fast_gl.c is built once per instruction set with SAMPLE_ISA set (libsample/CMakeLists.txt)"
#endif

#define ISA_CAT3_(a, b) a##b
#define ISA_CAT3(a, b) ISA_CAT3_(a, b)
/* Channels 1–3 in the generic set, 4 in the format's own (FAST_RGBA) or,
 * for a format without one (ISA_*_ANY_ROW), the generic set too. */
#define ISA_KERNELS_ROW(fmt)                                                   \
    [SAMPLE_FORMAT_##fmt] = {fast_gl_any, fast_gl_any, fast_gl_any, ISA_CAT3(fast_gl_, FAST_RGBA(fmt))}
#define ISA_KERNELS_ANY_ROW(fmt) [SAMPLE_FORMAT_##fmt] = {fast_gl_any, fast_gl_any, fast_gl_any, fast_gl_any}
#define ISA_READERS_ANY {row_any, bilinear_any}
#define ISA_READERS_ROW(fmt)                                                   \
    [SAMPLE_FORMAT_##fmt] = {ISA_READERS_ANY, ISA_READERS_ANY, ISA_READERS_ANY,  \
                             {ISA_CAT3(row_, FAST_RGBA(fmt)), ISA_CAT3(bilinear_, FAST_RGBA(fmt))}}
#define ISA_READERS_ANY_ROW(fmt)                                               \
    [SAMPLE_FORMAT_##fmt] = {ISA_READERS_ANY, ISA_READERS_ANY, ISA_READERS_ANY, ISA_READERS_ANY}
extern const fp_row_kernels SAMPLE_ISA_NAME(ls_fp_row_kernels); /* footprint_rows.c */
const isa_kernels SAMPLE_ISA_NAME(ls_isa_kernels) = {
    .fast_gl = {ISA_KERNELS_ROW(F32), ISA_KERNELS_ROW(F16), ISA_KERNELS_ANY_ROW(UNORM8), ISA_KERNELS_ROW(SRGB8)},
    .readers = {ISA_READERS_ROW(F32), ISA_READERS_ROW(F16), ISA_READERS_ANY_ROW(UNORM8), ISA_READERS_ROW(SRGB8)},
    .rows = &SAMPLE_ISA_NAME(ls_fp_row_kernels),
};
_Static_assert(SAMPLE_FORMAT_COUNT == 4, "one row of isa_kernels per format");
