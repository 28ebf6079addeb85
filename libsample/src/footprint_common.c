/*
 * Footprint geometry and the level loop shared by the Blinn–Newell and EWA
 * filters (DESIGN §7, doc/footprint-filters.md).
 */
#include "footprint.h"

#include "cube.h"

#include <float.h>

void ls_fp_shape_of(double J[2][2], fp_shape *o)
{
    /* Blinn's closed-form 2 × 2 SVD ("Consider the lowly 2×2 matrix",
     * 1996): J = R(φ)·diag(σ0, ±σ1)·R(θ) with E, F, G, H the symmetric and
     * antisymmetric parts, Q = |(E, H)|, R = |(F, G)|, σ0 = Q + R ≥
     * σ1 = |Q − R|; the rotations are never formed (ls_fp_shape_reshape). */
    o->E = 0.5 * (J[0][0] + J[1][1]);
    o->F = 0.5 * (J[0][0] - J[1][1]);
    o->G = 0.5 * (J[1][0] + J[0][1]);
    o->H = 0.5 * (J[1][0] - J[0][1]);
    o->Q = sample_hypot(o->E, o->H);
    o->R = sample_hypot(o->F, o->G);
    ls_fp_shape_finish(o);
}

void ls_fp_shape_sigma(fp_shape *o)
{
    o->s[0] = o->Q + o->R;
    o->s[1] = fabs(o->Q - o->R);
    o->clamped = 0;
}

void ls_fp_shape_finish(fp_shape *o)
{
    double lo;
    ls_fp_shape_sigma(o);
    /* Eccentricity clamp: lengthen the minor axis rather than shorten the
     * major one (pbrt's "clamp ellipse eccentricity"): the filter may blur
     * across, never alias along. */
    lo = o->s[0] / FP_MAX_ECCENTRICITY;
    o->clamped = o->s[1] < lo;
    if (o->clamped) o->s[1] = lo;
}

void ls_fp_shape_scaled(const fp_shape *b, double J[2][2], double r, fp_shape *o)
{
    /* Scaling J by a power of two scales E … H exactly, and Q, R and σ with
     * them (the hypot calls are the costly part, not these products). */
    o->E = 0.5 * (J[0][0] + J[1][1]);
    o->F = 0.5 * (J[0][0] - J[1][1]);
    o->G = 0.5 * (J[1][0] + J[0][1]);
    o->H = 0.5 * (J[1][0] - J[0][1]);
    o->Q = b->Q * r;
    o->R = b->R * r;
    ls_fp_shape_finish(o);
}

double ls_fp_shape_reshape(const fp_shape *d, double wid, double out[2][2])
{
    /* J = R(φ)·diag(σ0, ±σ1)·R(θ) (ls_fp_shape_of) = Q·R(φ + θ) + R·Ref(φ − θ),
     * with Q·R(φ + θ) = [[E, −H], [H, E]] and R·Ref(φ − θ) = [[F, G], [G, −F]]
     * (Blinn, "Consider the lowly 2×2 matrix", 1996). The same rotations
     * with new singular values t0, ±t1 are then
     *   J″ = (t0 ± t1)/(2Q)·[[E, −H], [H, E]] + (t0 ∓ t1)/(2R)·[[F, G], [G, −F]]
     * (upper signs where σ1's sign is +, i.e. Q ≥ R): no angles, no trig.
     * The coefficient over the smaller of Q, R is written without the
     * cancellation of t0 − t1: t0² − t1² = σ0² − σ1c², which is 4QR when the
     * clamp did not act (σ0 ± σ1 = 2·max, 2·min). */
    double sx = d->s[0], s1 = d->s[1], t0 = sqrt(sx * sx + wid), t1 = sqrt(s1 * s1 + wid);
    double big = d->Q >= d->R ? d->Q : d->R, small = d->Q >= d->R ? d->R : d->Q, kb, ks, kc, ka;
    if (!(big > 0.0)) { /* J = 0: take U = V = I */
        out[0][0] = t0;
        out[0][1] = out[1][0] = 0.0;
        out[1][1] = t1;
        return t0 * t1;
    }
    kb = (t0 + t1) / (2.0 * big);
    ks = d->clamped ? (sx - s1) * (sx + s1) / ((t0 + t1) * 2.0 * small) : 2.0 * big / (t0 + t1);
    kc = d->Q >= d->R ? kb : ks;
    ka = d->Q >= d->R ? ks : kb;
    out[0][0] = kc * d->E + ka * d->F;
    out[0][1] = ka * d->G - kc * d->H;
    out[1][0] = kc * d->H + ka * d->G;
    out[1][1] = kc * d->E - ka * d->F;
    return d->Q >= d->R ? t0 * t1 : -(t0 * t1);
}

void ls_fp_level_jacobian(const sample_ctx *c, int lv, const double J[2][2], int flip_s, int flip_t,
                       double out[2][2])
{
    double ku, kv;
    fp_level_scale(c, lv, flip_s, flip_t, &ku, &kv);
    out[0][0] = J[0][0] * ku;
    out[0][1] = J[0][1] * ku;
    out[1][0] = J[1][0] * kv;
    out[1][1] = J[1][1] * kv;
}

void ls_fp_level_shape(const sample_ctx *c, int lv, const fp_shape *base, double J[2][2], int flipped,
                    fp_shape *o)
{
    const struct sample_level *L = &c->tex->level[lv], *B = &c->tex->level[c->base];
    int q = L->w > 0 ? B->w / L->w : 0;
    /* A level that halves both axes k times has the base Jacobian times
     * 2^−k (the same singular vectors, σ scaled); a mirror-clamp flip or an
     * axis that stopped halving (non-power-of-two sizes, 1 × n levels)
     * takes the full computation. */
    if (!flipped && q > 0 && (q & (q - 1)) == 0 && B->w == L->w * q && B->h == L->h * q)
        ls_fp_shape_scaled(base, J, 1.0 / q, o);
    else
        ls_fp_shape_of(J, o);
}

void ls_fp_accum_init(fp_accum *a) { memset(a, 0, sizeof *a); }

/* Normalized result and its derivatives: R = ΣwT / Σw and, by the quotient
 * rule at fixed footprint, ∂R = (Σ∂w·T − R·Σ∂w) / Σw. */
static int accum_result(const fp_accum *a, double r[4], double rs[4], double rt[4])
{
    int k;
    if (!(a->sw > 0.0)) return 0;
    for (k = 0; k < 4; ++k) r[k] = a->sT[k] / a->sw;
    if (a->deriv)
        for (k = 0; k < 4; ++k) {
            rs[k] = (a->sTdu[k] - r[k] * a->sdu) / a->sw;
            rt[k] = (a->sTdv[k] - r[k] * a->sdv) / a->sw;
        }
    return 1;
}

static int mirror_clamp(sample_wrap m)
{
    return m == SAMPLE_WRAP_MIRROR_CLAMP || m == SAMPLE_WRAP_MIRROR_CLAMP_TO_BORDER;
}

/* A periodic wrap reads the same texels one period further on; bringing the
 * centre into the first period keeps i − u0 exact for coordinates like 1e6
 * (where the texel index and the offset would otherwise share 53 bits). */
static double reduce_period(sample_wrap m, double u, int n)
{
    double p = m == SAMPLE_WRAP_REPEAT ? (double)n : (m == SAMPLE_WRAP_MIRRORED_REPEAT ? 2.0 * n : 0.0);
    return p > 0.0 ? u - p * fp_floor(u / p) : u;
}

double ls_fp_center_axis(sample_wrap m, float s, int n, int *flip)
{
    *flip = mirror_clamp(m) && s < 0.0f;
    /* A float times an int below 2^17 is exact in double. Texel centres sit
     * at integers after the −½ (DESIGN §2). */
    if (wrap_transforms_coord(m)) s = ls_wrap_coord(m, s, n);
    return reduce_period(m, (double)s * n, n) - 0.5;
}

void ls_fp_center(const sample_ctx *c, int lv, float s, float t, double *u0, double *v0, int *flip_s,
               int *flip_t)
{
    const struct sample_level *L = &c->tex->level[lv];
    *u0 = ls_fp_center_axis(c->smp->wrap_s, s, L->w, flip_s);
    *v0 = ls_fp_center_axis(c->smp->wrap_t, t, L->h, flip_t);
}

static void store(float *dst, const double *v)
{
    int k;
    if (dst)
        for (k = 0; k < 4; ++k) dst[k] = (float)v[k];
}

void ls_fp_run_count(const sample_ctx *c, const void *geom, fp_level_fn level, double minor_base, float s,
                  float t, float call_bias, fp_run_state *rs)
{
    /* Four texels stay in reserve for the bilinear fallback below. */
    const double cap = (double)SAMPLE_MAX_FOOTPRINT_TEXELS - 4.0;
    /* λ of the level where the minor semi-axis spans FP_MINOR_TEXELS:
     * log2(minor) − log2(FP_MINOR_TEXELS), then the biases and the min/max
     * LOD clamps as for any λ (GL 4.6 §8.14.1). */
    double lb = sample_log2(minor_base) - sample_log2(FP_MINOR_TEXELS);
    float lam = lod_lambda(c, lb < -1e4 ? -1e4f : (float)lb, call_bias);
    int l0, l1, ok = 0;
    float f;

    ls_lod_split(c, lam, &l0, &l1, &f);
    if (f == 0.0f) l1 = l0;
    /* Texel cap (SAMPLE_MAX_FOOTPRINT_TEXELS): a footprint too large for its
     * levels moves one level coarser at a time (at most SAMPLE_MAX_LEVELS
     * steps; each count is itself bounded). */
    for (;;) {
        double n0 = level(c, geom, l0, NULL, 1);
        double n1 = l1 != l0 ? level(c, geom, l1, NULL, 1) : 0.0;
        if (n0 + n1 <= cap) {
            ok = 1;
            break;
        }
        if (l0 >= c->maxlev) break;
        ++l0;
        if (l1 < c->maxlev) ++l1;
        if (l0 == l1) f = 0.0f;
    }
    rs->geom = geom;
    rs->level = level;
    rs->s = s;
    rs->t = t;
    rs->lam = lam;
    rs->f = f;
    rs->l0 = l0;
    rs->l1 = l1;
    rs->ok = ok;
    rs->fallback = NULL;
}

uint32_t ls_fp_run_read(const sample_ctx *c, const fp_run_state *rs, float out[4], float dds[4], float ddt[4],
                     sample_stats *st)
{
    const void *geom = rs->geom;
    fp_level_fn level = rs->level;
    int l0 = rs->l0, l1 = rs->l1, k, ok = rs->ok;
    float f = rs->f;
    uint32_t n = 0;
    fp_accum a0, a1;
    double r0[4], s0[4], t0[4], r1[4], s1[4], t1[4];

    if (ok) {
        ls_fp_accum_init(&a0);
        a0.deriv = dds || ddt;
        n = (uint32_t)level(c, geom, l0, &a0, 0);
        ok = accum_result(&a0, r0, s0, t0);
        if (ok && l1 != l0) {
            ls_fp_accum_init(&a1);
            a1.deriv = a0.deriv;
            n += (uint32_t)level(c, geom, l1, &a1, 0);
            ok = accum_result(&a1, r1, s1, t1);
            /* Blend in double: (1 − f)·T + f·T is then T exactly in float. */
            for (k = 0; k < 4 && ok; ++k) r0[k] = (1.0 - f) * r0[k] + f * r1[k];
            for (k = 0; k < 4 && ok && a0.deriv; ++k) {
                s0[k] = (1.0 - f) * s0[k] + f * s1[k];
                t0[k] = (1.0 - f) * t0[k] + f * t1[k];
            }
        }
    }
    if (st) {
        st->level0 = (int16_t)l0;
        st->level1 = (int16_t)(l1 != l0 ? l1 : -1);
        st->level_frac = l1 != l0 ? f : 0.0f;
        st->lod = rs->lam;
    }
    if (!ok) {
        /* Wider than the whole budget even on the coarsest level (or an
         * empty sum, which the unit-variance term rules out for finite
         * input): the bilinear value of the coarsest level at the centre —
         * what the footprint tends to as it covers the whole texture. */
        if (st) {
            st->level0 = (int16_t)c->maxlev;
            st->level1 = -1;
            st->level_frac = 0.0f;
        }
        if (rs->fallback) return n + rs->fallback(c, geom, c->maxlev, out);
        return n + ls_recon_level(c, c->maxlev, SAMPLE_LINEAR, rs->s, rs->t, out, dds, ddt);
    }
    store(out, r0);
    store(dds, s0);
    store(ddt, t0);
    return n;
}

void ls_fp_footprint_plan(const sample_ctx *c, const sample_query *q, const sample_quad *corners, float call_bias,
                       fp_plan *pl)
{
    if (c->smp->footprint == SAMPLE_FOOTPRINT_BLINN_NEWELL)
        ls_fp_blinn_newell_plan(c, q, corners, call_bias, pl);
    else
        ls_fp_ewa_plan(c, q, call_bias, pl);
}

uint32_t ls_fp_footprint_run(const sample_ctx *c, const fp_plan *pl, float out[4], float dds[4], float ddt[4],
                          sample_stats *st)
{
    return ls_fp_run_read(c, &pl->rs, out, dds, ddt, st);
}

/* ---- Spans of a texture in tiles ---------------------------------------- */

static inline int min_int(int a, int b) { return a < b ? a : b; }

/* Texels i … i + m − 1 of walk row j through ctx_texel into out: the
 * border, another face, a tile the source cannot supply. Out of line: a
 * rare case whose inlined reads would crowd the common one's registers. */
static SAMPLE_NOINLINE void span_by_texel(const fp_level_rows *lr, double j, double i, int m, float (*out)[4])
{
    int t;
    for (t = 0; t < m; ++t) ctx_texel(lr->c, lr->lv, lr->tr ? j : i + t, lr->tr ? i + t : j, 1, out[t]);
}

/* A piece of a walk row outside the level along it (wrapped, env NONE):
 * its first texel x = the wrap mode's index of i (−1: the border colour)
 * and how many of the next texels follow it, x + 1, x + 2, … inside one
 * tile of `side` and the level's `along` texels, at most `rest` (REPEAT
 * up to its seam; a mirror's reflected run has 1). */
static SAMPLE_NOINLINE int wrapped_piece(sample_wrap mode, double i, int along, int side, int rest, int *x)
{
    int m = 1, lim;
    *x = ls_wrap_index(mode, i, along, 1);
    if (*x < 0) return 1;
    lim = min_int(min_int(rest, side - (*x & (side - 1))), along - *x);
    while (m < lim && ls_wrap_index(mode, i + m, along, 1) == *x + m) ++m;
    return m;
}

const unsigned char *ls_fp_span_tiles(const fp_level_rows *lr, double j, double ilo, int n, float (*buf)[4],
                                      size_t *pitch)
{
    const sample_ctx *c = lr->c;
    const sample_texture *tex = c->tex;
    const struct ls_texel_source *src = tex->source;
    const struct sample_level *L = &tex->level[lr->lv];
    const int side = src->tile_side, tr = lr->tr;
    /* Along a walk row and across it: a level row's s and t, or a level
     * column's t and s. In a tile, texels along a row are one texel apart,
     * along a column `side` texels (texel.h, tile_side). */
    const int along = tr ? L->h : L->w, across = tr ? L->w : L->h;
    const size_t step = tr ? (size_t)side * tex->texel_bytes : tex->texel_bytes;
    const int in_j = j >= 0.0 && j < (double)across, wraps = c->env == LS_ENV_NONE;
    /* ctx_texel's mapping of the walk row: itself inside the level, the
     * wrap mode's index outside (−1: the border colour) unless an
     * environment map finds it (then every texel goes through ctx_texel:
     * −1 here too). */
    const int jj = in_j ? (int)j : wraps ? ls_wrap_index(tr ? c->smp->wrap_s : c->smp->wrap_t, j, across, 1) : -1;
    int k = 0;
    *pitch = 16;
    if (jj < 0) {
        span_by_texel(lr, j, ilo, n, buf);
        return (const unsigned char *)buf;
    }
    while (k < n) {
        const double i = ilo + k;
        const int in_i = i >= 0.0 && i < (double)along;
        const unsigned char *p = NULL;
        int x = -1, m = 1;
        /* The texels x, x + 1, … up to the tile's edge or the level's:
         * inside the level along the row, all of them. */
        if (in_i) {
            x = (int)i;
            m = min_int(min_int(n - k, side - (x & (side - 1))), along - x);
        } else if (wraps) {
            m = wrapped_piece(tr ? c->smp->wrap_t : c->smp->wrap_s, i, along, side, n - k, &x);
        }
        /* ctx_texel's layer: the query's face inside the level, the first
         * layer through the wrap modes (tex_read). */
        if (x >= 0) p = src->texel(src, lr->lv, tr ? jj : x, tr ? x : jj, in_i && in_j ? c->face : 0);
        if (!p) span_by_texel(lr, j, i, m, buf + k);
        else if (m == n && lr->in_place) {
            *pitch = step;
            return p;
        } else
            tex_readers_in(lr->k, tex)->row(tex->format, tex->channels, p, step, m, buf + k);
        k += m;
    }
    return (const unsigned char *)buf;
}

/* ---- Cube maps: a footprint over several faces -------------------------- */

/* The faces a cube-map query's footprint is read on (ls_fp_cube_read): the
 * face of its centre first, then up to two neighbours, each with its
 * context (the face) and its plan's geometry and level function. */
typedef struct fp_cube_faces {
    int n;
    sample_ctx c[3];
    const fp_run_state *rs[3];
} fp_cube_faces;

/* One level of a cube-map footprint (an fp_level_fn): every face's walk,
 * each reading only its own face (ls_env_face_clip), into one sum. The
 * centre's face was counted by its plan on these levels; a neighbour is
 * counted here (count_only: the count finds the rows that its walk then
 * reads), and one whose footprint would exceed the cap on this level adds
 * nothing. */
static double cube_faces_level(const sample_ctx *c, const void *gp, int lv, fp_accum *acc, int count_only)
{
    const fp_cube_faces *g = (const fp_cube_faces *)gp;
    double total = g->rs[0]->level(&g->c[0], g->rs[0]->geom, lv, acc, count_only);
    int k;
    (void)c;
    for (k = 1; k < g->n; ++k) {
        const fp_run_state *r = g->rs[k];
        double n = r->level(&g->c[k], r->geom, lv, NULL, 1);
        if (!(n <= (double)SAMPLE_MAX_FOOTPRINT_TEXELS)) continue;
        total += count_only ? n : r->level(&g->c[k], r->geom, lv, acc, 0);
    }
    return total;
}

/* Whether the footprint of a query centred at face coordinate x ∈ [0, 1]
 * may reach the face's edge at `edge` (0 or 1) on level lv or the next:
 * within 4·‖J‖ (the Frobenius norm, ≥ the largest singular value: the
 * footprint's semi-major axis in face units) plus 12 texels of level lv.
 * Either filter reaches less: EWA's ellipse, widened, to a·√(σ² + rc)
 * texels of the level it walks, a the radial kernel's support (at most 3
 * pixels) and rc ≤ 2 (footprint_kernels.c), that is at most
 * 3·(σ + 1.5 texels), and a texel of level lv + 1 is two of lv;
 * Blinn–Newell's parallelogram, widened by one texel, to the sum of its
 * two columns. */
static int cube_reaches(const sample_ctx *c, const sample_query *q, int lv, double x, double edge)
{
    double norm = sqrt((double)q->dsdx * q->dsdx + (double)q->dsdy * q->dsdy + (double)q->dtdx * q->dtdx +
                       (double)q->dtdy * q->dtdy);
    return fabs(edge - x) < 4.0 * norm + 12.0 / c->tex->level[lv].w;
}

uint32_t ls_fp_cube_read(const sample_ctx *c, float call_bias, const fp_plan *pl0, float out[4], float dds[4],
                         float ddt[4], sample_stats *st)
{
    const sample_query3 *q3 = c->q3;
    const double r[3] = {q3->p[0], q3->p[1], q3->p[2]};
    fp_plan pl[2];
    fp_cube_faces g;
    fp_run_state rs = pl0->rs;
    sample_query q0;
    int f;
    g.n = 1;
    g.c[0] = *c;
    g.rs[0] = &pl0->rs;
    ls_cube_query_on(q3, c->face, &q0);
    /* The neighbours sharing an edge with the centre's face (not it, not
     * its opposite) on whose side the direction lies (r·axis > 0: their
     * plane holds it), where the footprint may reach that edge: U or V of
     * the centre's face is the neighbour's axis, ±1 in sc or tc its edge. */
    for (f = 0; f < 6 && rs.ok; ++f) {
        const double a[3] = {ls_cube_frame[f][0][0], ls_cube_frame[f][0][1], ls_cube_frame[f][0][2]};
        double du, dv, x, edge;
        sample_query qf;
        if ((f >> 1) == (c->face >> 1) || !(cube_dot(f, 0, r) > 0.0)) continue;
        du = cube_dot(c->face, 1, a); /* ±1 or 0: the edge at s = 1 or 0 */
        dv = cube_dot(c->face, 2, a); /* likewise t */
        x = du != 0.0 ? q0.s : q0.t;
        edge = du + dv > 0.0 ? 1.0 : 0.0;
        if (!cube_reaches(c, &q0, rs.l0, x, edge) || !ls_cube_query_on(q3, f, &qf)) continue;
        g.c[g.n] = *c;
        g.c[g.n].face = f;
        ls_fp_footprint_plan(&g.c[g.n], &qf, NULL, call_bias, &pl[g.n - 1]);
        g.rs[g.n] = &pl[g.n - 1].rs;
        ++g.n;
    }
    rs.geom = &g;
    rs.level = cube_faces_level;
    return ls_fp_run_read(c, &rs, out, dds, ddt, st);
}
