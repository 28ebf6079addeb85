/*
 * What Blinn–Newell and EWA share (footprint_common.c, footprint_rows.c and the two filters'
 * files) — the footprint's shape and level, the weighted sums, the
 * counting pass's row spans, the walk over a level's rows and the level
 * loop split into plan and run. DESIGN §7, doc/footprint-filters.md,
 * doc/performance.md and doc/history/performance-passes.md.
 */
#ifndef SAMPLE_FOOTPRINT_H
#define SAMPLE_FOOTPRINT_H

#include "kernels.h"
#include "lod.h"
#include "recon.h"

/* The two filters (footprint_blinn_newell.c, footprint_ewa.c; DESIGN §7):
 * each returns texels read, fills out (and dds/ddt if non-NULL) and stats
 * (if non-NULL), reads at most SAMPLE_MAX_FOOTPRINT_TEXELS texels, and
 * applies the sampler's and the call's bias itself (lod_lambda). */
uint32_t ls_fp_blinn_newell(const sample_ctx *c, const sample_query *q, const sample_quad *corners,
                         float call_bias, float out[4], float dds[4], float ddt[4],
                         sample_stats *st);
uint32_t ls_fp_ewa(const sample_ctx *c, const sample_query *q, float call_bias, float out[4],
                float dds[4], float ddt[4], sample_stats *st);


/* ---- Footprint geometry shared by the filters (footprint_common.c) ----- */

/* Blinn–Newell and EWA run on the level where the footprint's minor
 * semi-axis (smaller singular value of the Jacobian, in texels) is
 * FP_MINOR_TEXELS, i.e. the minor axis of the 2 × 2-pixel region spans four
 * texels; eccentricity (major / minor) is clamped to FP_MAX_ECCENTRICITY by
 * lengthening the minor axis (doc/footprint-filters.md). */
#define FP_MINOR_TEXELS 2.0
#define FP_MAX_ECCENTRICITY 16.0

/* A 2 × 2 Jacobian J = [[a, b], [c, d]] in Blinn's closed-form SVD,
 * J = R(φ)·diag(σ0, ±σ1)·R(θ) = U·diag(σ)·Vᵀ: its symmetric and
 * antisymmetric parts E, F, G, H, Q = |(E, H)|, R = |(F, G)|, the singular
 * values σ0 = Q + R ≥ σ1 = |Q − R|, σ1 raised to σ0 / FP_MAX_ECCENTRICITY
 * where it was below (`clamped`). Enough to rebuild J with new singular
 * values and the same rotations without any trigonometry (no libm: the
 * same bits on any machine, portable_math.h). */
typedef struct fp_shape {
    double E, F, G, H, Q, R, s[2];
    int clamped;
} fp_shape;
void ls_fp_shape_of(double J[2][2], fp_shape *o);
/* ls_fp_shape_of(J) given that J = r·(the Jacobian of b), r a power of two:
 * Q and R come from b (no hypot). */
void ls_fp_shape_scaled(const fp_shape *b, double J[2][2], double r, fp_shape *o);
void ls_fp_shape_finish(fp_shape *o); /* s and the clamp from Q, R */
void ls_fp_shape_sigma(fp_shape *o);  /* s from Q, R without the clamp */
/* out = U·diag(√(σ0² + wid), √(σ1² + wid))·Vᵀ, with J = U·diag(σ)·Vᵀ as
 * ls_fp_shape_of factors it and σ1 after the clamp: wid = 0 is the clamped
 * Jacobian (EWA), wid = 1 the unit-variance widening (Blinn–Newell).
 * Returns det(out). */
double ls_fp_shape_reshape(const fp_shape *d, double wid, double out[2][2]);

/* ∂u0/∂s and ∂v0/∂t on level lv: its width and height, negated on an axis
 * a mirror-clamp reflected (ls_fp_center's flips). */
static inline void fp_level_scale(const sample_ctx *c, int lv, int flip_s, int flip_t, double *ku, double *kv)
{
    const struct sample_level *L = &c->tex->level[lv];
    *ku = flip_s ? -(double)L->w : (double)L->w;
    *kv = flip_t ? -(double)L->h : (double)L->h;
}

/* The normalized Jacobian J (rows s, t; columns x, y) in texel units of level
 * lv, its rows scaled by fp_level_scale. */
void ls_fp_level_jacobian(const sample_ctx *c, int lv, const double J[2][2], int flip_s, int flip_t,
                       double out[2][2]);

/* The shape of J (level lv's Jacobian, ls_fp_level_jacobian; `flipped` if a
 * mirror-clamp negated a row) from `base`, the shape of the same query's
 * Jacobian on the base level c->base, when that is a power-of-two scaling;
 * ls_fp_shape_of(J) otherwise. */
void ls_fp_level_shape(const sample_ctx *c, int lv, const fp_shape *base, double J[2][2], int flipped,
                    fp_shape *o);

/* Weighted sums of one level: Σw, Σw·T and, for ∂/∂(u0, v0) of the centre at
 * fixed footprint, Σ∂w and Σ∂w·T. In double so that a constant texture comes
 * back exactly and sums over a thousand texels keep float precision. */
typedef struct fp_accum {
    double sw, sdu, sdv;
    double sT[4], sTdu[4], sTdv[4];
    uint32_t texels;
    int deriv; /* 0: the ∂ sums are not wanted (they stay 0) */
    /* Stochastic draws (fp_stochastic.c): Σ|w|, and when `draw` is set
     * the texels where the running Σ|w| (cum) first passes each of the
     * `draws` ascending targets at[], added with the sign of their weight
     * into sD; the last texel of nonzero weight in lastT (a target the
     * rounding left beyond the end takes it). A level walks its texels one
     * by one (fp_accum_add) when `draw` is set. */
    double sabs, cum, sD[4], lastT[4], lastsign;
    const double *at;
    int draw, draws, drawn;
} fp_accum;

/* One texel of weight w into the draws of a (fp_accum.draw). */
static inline void fp_accum_draw(fp_accum *a, double w, const float T[4])
{
    const double sg = w < 0.0 ? -1.0 : 1.0;
    int k;
    a->cum += fabs(w);
    for (k = 0; k < 4; ++k) a->lastT[k] = T[k];
    a->lastsign = sg;
    while (a->drawn < a->draws && a->cum > a->at[a->drawn]) {
        for (k = 0; k < 4; ++k) a->sD[k] += sg * T[k];
        a->drawn++;
    }
}

void ls_fp_accum_init(fp_accum *a);

static inline void fp_accum_add(fp_accum *a, double w, double dwdu, double dwdv, const float T[4])
{
    int k;
    if (a->draw && w != 0.0) fp_accum_draw(a, w, T);
    a->sabs += fabs(w);
    a->sw += w;
    for (k = 0; k < 4; ++k) a->sT[k] += w * T[k];
    if (a->deriv) {
        a->sdu += dwdu;
        a->sdv += dwdv;
        for (k = 0; k < 4; ++k) {
            a->sTdu[k] += dwdu * T[k];
            a->sTdv[k] += dwdv * T[k];
        }
    }
    a->texels++;
}

/* The sums of fp_accum without the derivative ones, for the filters' inner
 * loops when no derivatives are asked for: a local the compiler keeps in
 * registers (the 4 channels as two double pairs), folded into the level's
 * fp_accum once (fp_accum_fold). Same additions in the same order as
 * fp_accum_add, so the same bits. */
typedef struct fp_sums {
    double sw, sT[4];
    uint32_t n;
} fp_sums;

SAMPLE_FORCE_INLINE void fp_sums_add(fp_sums *s, double w, const float T[4])
{
    int k;
    s->sw += w;
    for (k = 0; k < 4; ++k) s->sT[k] += w * T[k];
    s->n++;
}

/* The two filters' weights (DESIGN §7), each written once as an
 * expression that serves a double (the derivative passes in
 * footprint_blinn_newell.c and footprint_ewa.c) and footprint_rows.c's
 * vector lanes alike, so that both round the same way.
 *
 * Blinn–Newell's pyramid (1 − |x|)₊·(1 − |y|)₊ at a texel's position
 * (x, y) in the pyramid's frame; ABS and POS are |·| and max(·, +0) of
 * the operand type. */
#define FP_BN_PYRAMID(x, y, ABS, POS) (POS(1.0 - ABS(x)) * POS(1.0 - ABS(y)))
/* EWA's r² = A·du² + B·du·dv + C·dv² of the texel (du, dv) from the
 * centre, with the row's constant term C·dv² given as cdv2. */
#define FP_EWA_R2(A, B, cdv2, du, dv) ((A) * (du) * (du) + (B) * (du) * (dv) + (cdv2))
/* EWA's table read at x = 128·r², e = ⌊x⌋: linear between lo = lut[e] and
 * hi = lut[e + 1]. */
#define FP_EWA_LERP(lo, hi, x, e) ((lo) + ((x) - (e)) * ((hi) - (lo)))

/* max(x, +0) of a double (FP_BN_PYRAMID's POS). */
static inline double fp_pos(double x) { return x > 0.0 ? x : 0.0; }

/* EWA's weight, e^(−2r²) − e^(−2), interpolated in ls_fp_ewa_lut
 * (footprint_ewa.c) at r² ∈ [0, 1); its slope dw/dr² in *dwdr2 if asked
 * for. */
extern const double ls_fp_ewa_lut[129];
SAMPLE_FORCE_INLINE double fp_ewa_weight(double r2, double *dwdr2)
{
    double x = r2 * 128.0;
    int e = (int)x;
    if (e > 127) e = 127;
    if (dwdr2) *dwdr2 = (ls_fp_ewa_lut[e + 1] - ls_fp_ewa_lut[e]) * 128.0;
    return FP_EWA_LERP(ls_fp_ewa_lut[e], ls_fp_ewa_lut[e + 1], x, e);
}

/* a ← a + s for an fp_accum that received nothing else (a level's sums
 * start at 0, so this is the sums themselves). */
SAMPLE_FORCE_INLINE void fp_accum_fold(fp_accum *a, const fp_sums *s)
{
    int k;
    a->sw += s->sw;
    a->sabs += s->sw; /* the row kernels' weights are ≥ +0 */
    for (k = 0; k < 4; ++k) a->sT[k] += s->sT[k];
    a->texels += s->n;
}

/* A query's Jacobian as the footprint filters hold it: rows s, t; columns
 * x, y (J[0] = (ds/dx, ds/dy), J[1] = (dt/dx, dt/dy)). */
static inline void fp_query_jacobian(const sample_query *q, double J[2][2])
{
    J[0][0] = q->dsdx;
    J[0][1] = q->dsdy;
    J[1][0] = q->dtdx;
    J[1][1] = q->dtdy;
}

/* A level's rows as the footprint filters walk them. A walk row is a row of
 * the level, or, when the footprint is taller than it is wide, a column
 * (`tr`): the walk costs per row about as much as per texel (the span, its
 * memo, the loop; measured in doc/history/performance-passes.md), and an ellipse steeper
 * than 45° has fewer columns than rows. In the walk's frame everything is
 * named as for rows: walk row j (jlo … jlo + nrows − 1) holds texels ilo,
 * ilo + 1, … `pitch` bytes apart, walk rows are `lstride` bytes apart,
 * `wlim` texels long and there are `hlim` of them in the level; the
 * centre is (u0, v0) along and across walk rows. Spans come from the
 * counting pass (sp; span and lg find those past FP_SPAN_MEMO again,
 * fp_row_span). */
typedef double (*fp_span_fn)(const void *level_geom, double dv, double *ilo);
typedef struct fp_level_rows {
    const sample_ctx *c;
    const struct fp_spans *sp;
    fp_span_fn span;
    const void *lg;
    int lv, nrows, tr;
    int in_place; /* float RGBA: texels inside the level are read where they are */
    /* hlim is 0 unless the texture is resident: the in-level tests
     * (fp_span_at, the counting passes, the prefetches) then fail without
     * a test of their own, and every span is read through the source
     * (fp_span_texels). */
    double jlo, u0, v0, wlim, hlim;
    const unsigned char *data; /* the level's texel (0, 0); NULL unless resident */
    const isa_kernels *k;      /* the batch's kernels (sample_ctx.isa) */
    size_t pitch, lstride;
} fp_level_rows;

/* Whether a footprint extending ±√u2 texels in u and ±√v2 in v is walked
 * by columns: where that saves a quarter of the lines or more. Near round
 * footprints keep the rows, whose prefetches cover a line at a time and
 * whose texels other formats decode in one go (doc/history/performance-passes.md). */
static inline int fp_walk_columns(double u2, double v2) { return u2 < 0.5625 * v2; }

/* lr for level lv walked by rows (tr = 0) or by columns (tr = 1), the
 * footprint centred at (u0, v0) (the level's own frame) and reaching from
 * lo to hi across the walk rows (offsets from the centre, walk frame).
 * Returns the walk rows it crosses, as a double (+inf or NaN for a
 * footprint no cap can hold: the caller tests it against the cap; lr then
 * walks none). */
SAMPLE_FORCE_INLINE double fp_level_rows_init(fp_level_rows *lr, const sample_ctx *c, const struct fp_spans *sp,
                                              fp_span_fn span, const void *lg, int lv, int tr, double u0, double v0,
                                              double lo, double hi)
{
    const struct sample_level *L = &c->tex->level[lv];
    const size_t tb = c->tex->texel_bytes;
    const double uw = tr ? v0 : u0, vw = tr ? u0 : v0, jlo = fp_ceil(vw + lo), nrows = fp_floor(vw + hi) - jlo + 1.0;
    lr->c = c;
    lr->sp = sp;
    lr->span = span;
    lr->lg = lg;
    lr->lv = lv;
    lr->nrows = nrows <= (double)SAMPLE_MAX_FOOTPRINT_TEXELS ? (int)nrows : 0;
    lr->tr = tr;
    lr->in_place = c->tex->format == SAMPLE_FORMAT_F32 && c->tex->channels == 4;
    lr->jlo = jlo;
    lr->u0 = uw;
    lr->v0 = vw;
    lr->wlim = (double)(tr ? L->h : L->w);
    lr->hlim = tex_resident(c->tex) ? (double)(tr ? L->w : L->h) : 0.0;
    /* A cube map's query reads its face (sample_ctx.face): in-face spans
     * are addressed in that layer, the rest through ctx_texel. */
    lr->data = tex_resident(c->tex) ? L->data + (size_t)c->face * L->slice : NULL;
    lr->k = c->isa;
    lr->pitch = tr ? L->stride : tb;
    lr->lstride = tr ? tb : L->stride;
    return nrows;
}

/* Texel i of walk row j, both inside the level (integers in double). */
SAMPLE_FORCE_INLINE const unsigned char *fp_texel_at(const fp_level_rows *lr, double j, double i)
{
    return lr->data + (size_t)(long)j * lr->lstride + (size_t)(long)i * lr->pitch;
}

/* Prefetch texels ilo … ilo + ncol − 1 of walk row j (the part inside the
 * level; wrapped parts are left to the hardware). The footprint filters
 * call it from their counting pass, which finds every row's span before
 * any texel is read: the rows' misses then overlap instead of arriving one
 * row at a time. Only a hint: results unchanged. Along a level row every
 * line, along a column every texel. */
SAMPLE_FORCE_INLINE void fp_prefetch_texels(const fp_level_rows *lr, const unsigned char *at, double ncol)
{
    if (lr->tr) {
        size_t k;
        for (k = 0; k < (size_t)ncol; ++k) SAMPLE_PREFETCH(at + k * lr->pitch);
    } else {
        /* The first texel's line, then every line start up to the last
         * byte. */
        uintptr_t o = ((uintptr_t)at & ~(uintptr_t)63) + 64, end = (uintptr_t)at + (size_t)ncol * lr->pitch;
        SAMPLE_PREFETCH(at);
        for (; o < end; o += 64) SAMPLE_PREFETCH((const void *)o);
    }
}

SAMPLE_FORCE_INLINE void fp_prefetch_span(const fp_level_rows *lr, double j, double ilo, double ncol)
{
    double lo = ilo < 0.0 ? 0.0 : ilo, hi = ilo + ncol - 1.0;
    if (!(j >= 0.0 && j < lr->hlim) || !(ncol > 0.0)) return;
    if (hi > lr->wlim - 1.0) hi = lr->wlim - 1.0;
    if (!(lo <= hi)) return;
    fp_prefetch_texels(lr, fp_texel_at(lr, j, lo), hi - lo + 1.0);
}

/* A level's row spans, found by the counting pass and kept for the
 * accumulating pass (the first FP_SPAN_MEMO rows; the rare taller
 * footprints recompute the rest): each row's bounds cost a few divisions,
 * a square root for EWA, and two rounding steps, and its address a few
 * more steps. */
#define FP_SPAN_MEMO 96
typedef struct fp_spans {
    int n; /* rows stored by the last complete count */
    double ilo[FP_SPAN_MEMO], ncol[FP_SPAN_MEMO];
    const unsigned char *at[FP_SPAN_MEMO]; /* fp_span_at */
} fp_spans;

/* The address of texels ilo … ilo + ncol − 1 of walk row j when they all
 * lie inside a resident level (then every wrap mode reads them there,
 * ctx_texel's own shortcut), NULL otherwise (read through ctx_texel). */
SAMPLE_FORCE_INLINE const unsigned char *fp_span_at(const fp_level_rows *lr, double j, double ilo, double ncol)
{
    if (j >= 0.0 && j < lr->hlim && ilo >= 0.0 && ilo + ncol <= lr->wlim) return fp_texel_at(lr, j, ilo);
    return NULL;
}

/* Keep row r's span (walk row j, texels ilo … ilo + ncol − 1, address at
 * or NULL: fp_span_at) for the accumulating pass and prefetch it. */
SAMPLE_FORCE_INLINE void fp_span_keep(const fp_level_rows *lr, fp_spans *sp, int r, double j, double ilo,
                                      double ncol, const unsigned char *at)
{
    if (r < FP_SPAN_MEMO) {
        sp->ilo[r] = ilo;
        sp->ncol[r] = ncol;
        sp->at[r] = at;
    }
    if (at) fp_prefetch_texels(lr, at, ncol);
    else fp_prefetch_span(lr, j, ilo, ncol);
}

/* The counting pass of a level (every row: its span, kept and prefetched,
 * fp_span_keep); returns the texels, or INFINITY once over the cap: every
 * row is bounded by the cap before any texel is read. Generic over the
 * filter's span function, inlined with it (zstd style). */
SAMPLE_FORCE_INLINE double fp_count_rows(const fp_level_rows *lr, fp_spans *sp, double cap)
{
    double total = 0.0;
    int r;
    sp->n = 0;
    for (r = 0; r < lr->nrows; ++r) {
        double j = lr->jlo + r, ilo = 0.0, ncol = lr->span(lr->lg, j - lr->v0, &ilo);
        fp_span_keep(lr, sp, r, j, ilo, ncol, ncol > 0.0 && ncol <= cap ? fp_span_at(lr, j, ilo, ncol) : NULL);
        total += ncol;
        if (total > cap) return INFINITY;
    }
    sp->n = lr->nrows < FP_SPAN_MEMO ? lr->nrows : FP_SPAN_MEMO;
    return total;
}

/* Row r's span in the accumulating pass: the one the count stored, or
 * (past FP_SPAN_MEMO rows) found again; its address in *at (fp_span_at). */
SAMPLE_FORCE_INLINE double fp_row_span(const fp_level_rows *lr, int r, double j, double dv, double cap, double *ilo,
                                       const unsigned char **at)
{
    double ncol;
    if (r < lr->sp->n) {
        *ilo = lr->sp->ilo[r];
        *at = lr->sp->at[r];
        return lr->sp->ncol[r];
    }
    ncol = lr->span(lr->lg, dv, ilo);
    *at = ncol > 0.0 && ncol <= cap ? fp_span_at(lr, j, *ilo, ncol) : NULL;
    return ncol;
}

/* Texels ilo … ilo + n − 1 of walk row j of a texture whose source holds
 * its levels in tiles (texel.h, tile_side), as fp_span_texels returns
 * them, bit for bit what ctx_texel reads (footprint_common.c). The span,
 * wrapped as ctx_texel wraps each texel, is cut where it leaves a tile or
 * where the wrapped texels stop following each other; each piece is one
 * texel() call and one run of the format's row reader (tex_readers) into
 * buf. A float RGBA span in one tile is returned in place. A tile the
 * source cannot supply (NULL), a border texel and a texel an environment
 * map finds on another face are read through ctx_texel. The row's sums
 * are then made over buf in one go, in the order a resident span's are:
 * the same bits (footprint_rows.c). */
const unsigned char *ls_fp_span_tiles(const fp_level_rows *lr, double j, double ilo, int n, float (*buf)[4],
                                      size_t *pitch);

/* ls_fp_span_tiles with its common case inline: a span inside the level
 * and inside one tile (nearly every row in 64² tiles) is one texel() call
 * and one run of the row reader; out of line it cost about 100
 * instructions a row (doc/texture-system.md, "The fast path reads the
 * tiles"). */
SAMPLE_FORCE_INLINE const unsigned char *fp_span_tile(const fp_level_rows *lr, double j, double ilo, int n,
                                                      float (*buf)[4], size_t *pitch)
{
    const sample_texture *tex = lr->c->tex;
    const struct ls_texel_source *src = tex->source;
    const struct sample_level *L = &tex->level[lr->lv];
    const int edge = ~(src->tile_side - 1);
    if (j >= 0.0 && j < (double)(lr->tr ? L->w : L->h) && ilo >= 0.0 && ilo + n <= lr->wlim &&
        ((int)ilo & edge) == (((int)ilo + n - 1) & edge)) {
        const int i0 = (int)ilo, jj = (int)j;
        const unsigned char *p = src->texel(src, lr->lv, lr->tr ? jj : i0, lr->tr ? i0 : jj, lr->c->face);
        if (p) {
            const size_t step = lr->tr ? (size_t)src->tile_side * tex->texel_bytes : tex->texel_bytes;
            if (lr->in_place) {
                *pitch = step;
                return p;
            }
            tex_readers_in(lr->k, tex)->row(tex->format, tex->channels, p, step, n, buf);
            *pitch = 16;
            return (const unsigned char *)buf;
        }
    }
    return ls_fp_span_tiles(lr, j, ilo, n, buf, pitch);
}

/* The n ≤ SAMPLE_MAX_FOOTPRINT_TEXELS texels ilo … ilo + n − 1 of walk row
 * j as float RGBA, *pitch bytes apart from the returned pointer, exactly as
 * ctx_texel reads them (linear rule): a float RGBA span inside the level
 * (at, fp_span_at) in place (nothing to decode), another span inside the
 * level decoded in one go by the format's reader (tex_readers) into buf, a
 * span of a texture in tiles piece by piece (ls_fp_span_tiles), anything
 * else texel by texel through ctx_texel into buf (pitch 16). Load with
 * memcpy. */
SAMPLE_FORCE_INLINE const unsigned char *fp_span_texels(const fp_level_rows *lr, double j, double ilo, int n,
                                                        const unsigned char *at, float (*buf)[4], size_t *pitch)
{
    const sample_ctx *c = lr->c;
    int k;
    *pitch = 16;
    if (at) {
        if (lr->in_place) {
            *pitch = lr->pitch;
            return at;
        }
        tex_readers_in(lr->k, c->tex)->row(c->tex->format, c->tex->channels, at, lr->pitch, n, buf);
    } else if (c->tex->source && c->tex->source->tile_side > 0 && tex_source_level_in_tiles(c->tex->source, lr->lv)) {
        return fp_span_tile(lr, j, ilo, n, buf, pitch);
    } else if (!lr->tr) {
        for (k = 0; k < n; ++k) ctx_texel(c, lr->lv, ilo + k, j, 1, buf[k]);
    } else {
        for (k = 0; k < n; ++k) ctx_texel(c, lr->lv, j, ilo + k, 1, buf[k]);
    }
    return (const unsigned char *)buf;
}

/* The accumulating pass's walk over a level's rows: each row with texels
 * (fp_row_span) handed to row() with its texels as float RGBA `pitch`
 * bytes apart (fp_span_texels, decoded into buf where needed), their
 * count, the first one's column ilo and the row's offset dv = (jlo + r) −
 * v0 from the centre, all in the walk's frame. Generic over row(), inlined
 * with it (zstd style). */
typedef void (*fp_row_fn)(void *ctx, const unsigned char *p, size_t pitch, int n, double ilo, double dv);
SAMPLE_FORCE_INLINE void fp_level_walk(const fp_level_rows *lr, float (*buf)[4], void *ctx, fp_row_fn row)
{
    const double cap = (double)SAMPLE_MAX_FOOTPRINT_TEXELS;
    int r;
    for (r = 0; r < lr->nrows; ++r) {
        double j = lr->jlo + r, dv = j - lr->v0, ilo = 0.0, ncol;
        const unsigned char *at, *p;
        size_t pitch;
        ncol = fp_row_span(lr, r, j, dv, cap, &ilo, &at);
        if (ncol > cap) break; /* unreachable after a successful count */
        /* A cube map's walk reads its own face only (ls_env_face_clip);
         * tested only for spans not inside the level, so 2D bits and the
         * in-level rows are untouched. */
        if (!at && lr->c->env == LS_ENV_CUBE) ncol = ls_env_face_clip(lr->wlim, j, &ilo, ncol);
        if (!(ncol > 0.0)) continue;
        p = fp_span_texels(lr, j, ilo, (int)ncol, at, buf, &pitch);
        row(ctx, p, pitch, (int)ncol, ilo, dv);
    }
}

/* A pass of fp_accum_add over a level (the filters' derivative passes,
 * Blinn–Newell's quad pass): what every filter's row function needs, the
 * first member of the filter's own state (so that a pointer to one is a
 * pointer to the other): the sums, the centre's u0 along a walk row, the
 * derivatives of the walk frame's centre (u0, v0) by the query's own
 * coordinates (ku, kv: the level's size, negative where mirrored; swapped
 * when the walk rows are columns), whether they are (tr) and the texels
 * added. fp_pass_run walks the level with row() and returns them. */
typedef struct fp_pass {
    fp_accum *acc;
    double u0, ku, kv, total;
    int tr;
} fp_pass;

/* ku, kv: ∂u0/∂s and ∂v0/∂t of the level's own (row-major) centre. */
SAMPLE_FORCE_INLINE double fp_pass_run(fp_pass *ps, const fp_level_rows *lr, float (*buf)[4], fp_accum *acc,
                                       double ku, double kv, fp_row_fn row)
{
    ps->acc = acc;
    ps->u0 = lr->u0;
    ps->tr = lr->tr;
    ps->ku = lr->tr ? kv : ku;
    ps->kv = lr->tr ? ku : kv;
    ps->total = 0.0;
    fp_level_walk(lr, buf, ps, row);
    return ps->total;
}

/* A row function's texel: weight w, its derivatives by the walk frame's
 * u and v (dwdu, dwdv: ∂w/∂(centre) already times ps->ku, ps->kv), added
 * as ∂/∂s and ∂/∂t. */
SAMPLE_FORCE_INLINE void fp_pass_add(fp_pass *ps, double w, double dwdu, double dwdv, const float T[4])
{
    if (ps->tr) fp_accum_add(ps->acc, w, dwdv, dwdu, T);
    else fp_accum_add(ps->acc, w, dwdu, dwdv, T);
    ps->total += 1.0;
}

/* The weights alone over a level (no derivatives), by the batch's row
 * kernel `level` (fp_row_kernels: bn_level, ewa_level) with the filter's
 * parameters par: sums kept in registers for the whole level, then folded
 * into acc. Returns the texels added. */
SAMPLE_FORCE_INLINE double fp_level_sums(fp_accum *acc, const fp_level_rows *lr,
                                         void (*level)(struct fp_sums *, const struct fp_level_rows *, const double *),
                                         const double *par)
{
    fp_sums sm = {0.0, {0.0, 0.0, 0.0, 0.0}, 0};
    level(&sm, lr, par);
    fp_accum_fold(acc, &sm);
    return sm.n;
}

/* A filter's weight at texel offset (du, dv) from the centre, in the walk
 * frame, and its gradient (wu, wv) = ∂w/∂(du, dv); 0 where the texel
 * adds nothing (outside the footprint). `pass` is the filter's pass state,
 * whose first member is the fp_pass. */
typedef int (*fp_weight_fn)(const void *pass, double du, double dv, double *w, double *wu, double *wv);

/* One row of a derivative pass (fp_pass_run's row, for every filter):
 * each texel's weight and gradient from weight(), added with the centre's
 * motion — du = c − u0, so ∂w/∂u0 = −wu, times ku (and likewise v). Texel
 * positions du = (ilo + k) − u0 are the other passes' to the bit. Generic
 * over weight(), inlined with it (zstd style). */
SAMPLE_FORCE_INLINE void fp_pass_row(void *pass, fp_weight_fn weight, const unsigned char *p, size_t pitch, int n,
                                     double ilo, double dv)
{
    fp_pass *ps = (fp_pass *)pass;
    int k;
    for (k = 0; k < n; ++k) {
        double w, wu, wv;
        float t4[4];
        if (!weight(pass, (ilo + k) - ps->u0, dv, &w, &wu, &wv)) continue;
        memcpy(t4, p + pitch * (size_t)k, sizeof t4);
        fp_pass_add(ps, w, -wu * ps->ku, -wv * ps->kv, t4);
    }
}

/* One level of a footprint filter: when `count_only`, returns (as a double,
 * +inf if unbounded) how many texels the level would visit, reading none;
 * otherwise accumulates into `acc` and returns the texels read. */
typedef double (*fp_level_fn)(const sample_ctx *c, const void *geom, int lv, fp_accum *acc,
                              int count_only);

/* The level loop shared by Blinn–Newell and EWA, in two halves.
 * ls_fp_run_count: levels from the minor semi-axis (base texels, after the
 * eccentricity clamp) and the bias, the counting pass (every row's span
 * found, kept and prefetched; no texel read), moved coarser while the two
 * levels together would exceed SAMPLE_MAX_FOOTPRINT_TEXELS. ls_fp_run_read:
 * the accumulating pass on those levels, blended in double; bilinear at
 * the coarsest level if even that did not fit. Fills out/dds/ddt/st;
 * returns texels. The halves may run apart (another query's work in
 * between) as long as geom stays where it is. */
typedef struct fp_run_state {
    const void *geom;
    fp_level_fn level;
    float s, t, lam, f;
    int l0, l1, ok;
    /* The value at the centre on level lv when no level fits (NULL: the
     * bilinear value at (s, t)); a kind whose levels are not 2D (a
     * volume's trilinear) sets it after ls_fp_run_count. */
    uint32_t (*fallback)(const sample_ctx *c, const void *geom, int lv, float out[4]);
} fp_run_state;
void ls_fp_run_count(const sample_ctx *c, const void *geom, fp_level_fn level, double minor_base, float s,
                  float t, float call_bias, fp_run_state *rs);
uint32_t ls_fp_run_read(const sample_ctx *c, const fp_run_state *rs, float out[4], float dds[4], float ddt[4],
                     sample_stats *st);
/* ls_fp_run_read's stochastic estimate (fp_stochastic.c) from a uniform u
 * in [0, 1): a level chosen with its blend weight, then `draws` texels of
 * it drawn in proportion to |w| (stratified: targets (j + u′)/draws of
 * Σ|w|), their values with the signs of their weights times Σ|w|/Σw,
 * averaged. Its expectation over u is ls_fp_run_read's value. Fills out
 * and st; returns the texels visited (both passes). */
uint32_t ls_fp_run_draw(const sample_ctx *c, const fp_run_state *rs, double u, int draws, float out[4],
                        sample_stats *st);

/* A Blinn–Newell or EWA query split at fp_run's halves, for a batch loop
 * that plans query i + 1 (its rows' lines then on their way) before it
 * runs query i: ls_fp_footprint_plan does the geometry and the counting pass
 * into *pl, ls_fp_footprint_run the accumulating pass, with the results of
 * ls_fp_blinn_newell / ls_fp_ewa bit for bit (they are these two calls). A plan
 * holds the filter's geometry and both levels' row spans (FP_PLAN_BYTES)
 * and must not be moved between the calls. */
#define FP_PLAN_BYTES 5632
typedef struct fp_plan {
    fp_run_state rs;
    union {
        double align;
        void *palign;
        unsigned char bytes[FP_PLAN_BYTES];
    } geom;
} fp_plan;
void ls_fp_footprint_plan(const sample_ctx *c, const sample_query *q, const sample_quad *corners, float call_bias,
                       fp_plan *pl);
uint32_t ls_fp_footprint_run(const sample_ctx *c, const fp_plan *pl, float out[4], float dds[4], float ddt[4],
                          sample_stats *st);
/* A Blinn–Newell or EWA query on a cube map (c->env == LS_ENV_CUBE, c->q3
 * its direction query), planned on the face its centre selects (pl0): the
 * texels of that face weighted by its footprint, and those of each
 * neighbouring face the footprint reaches by that face's own footprint
 * (the same query's (s, t) and Jacobian on its plane), one weighted sum
 * over all, on pl0's levels (footprint_common.c;
 * doc/environment-maps.md, "Footprint filters"). */
uint32_t ls_fp_cube_read(const sample_ctx *c, float call_bias, const fp_plan *pl0, float out[4], float dds[4],
                         float ddt[4], sample_stats *st);
void ls_fp_blinn_newell_plan(const sample_ctx *c, const sample_query *q, const sample_quad *corners, float call_bias,
                          fp_plan *pl);
void ls_fp_ewa_plan(const sample_ctx *c, const sample_query *q, float call_bias, fp_plan *pl);

/* The footprint centre on level lv in texel units with texel centres at
 * integers (u0 = s·w − ½), after the coordinate transform of the wrap modes
 * that have one (ls_wrap_coord); `flip_s`/`flip_t` say whether a mirror-clamp
 * reflected the centre, which mirrors the footprint too. */
void ls_fp_center(const sample_ctx *c, int lv, float s, float t, double *u0, double *v0, int *flip_s,
               int *flip_t);
/* One axis of ls_fp_center: the centre u0 on an axis of n texels under
 * wrap mode m, *flip set where a mirror-clamp reflected it. */
double ls_fp_center_axis(sample_wrap m, float s, int n, int *flip);

#endif /* SAMPLE_FOOTPRINT_H */
