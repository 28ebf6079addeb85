/*
 * Sampling 3D textures (DESIGN §11, doc/volumes.md): one level's
 * reconstruction (GL 4.6 §8.14.2 on three axes), the OpenGL filters' level
 * choice and blend (§8.14.3, lod_select as for 2D) and the batch entry
 * point. One query at a time, texel by texel (vol_texel): the reference
 * path's structure (sampler.c), with the 2D arithmetic reused per slice.
 */
#include "filter.h"
#include "kernels.h"
#include "volume.h"

/* NEAREST: texel (⌊u⌋, ⌊v⌋, ⌊w⌋) (eq. 8.12 with the third coordinate). */
static uint32_t vol_nearest(const sample_ctx *c, int lv, const float u[3], float out[4])
{
    vol_texel(c, lv, floorf(u[0]), floorf(u[1]), floorf(u[2]), 0, out);
    return 1;
}

/* The bilinear value of slice k at the block (i0, j0) with fractions α, β:
 * recon_bilerp on the slice's 2 × 2 texels, as a 2D level would give. */
static void vol_slice_bilerp(const sample_ctx *c, int lv, float i0, float j0, double k, float al, float be,
                             float out[4])
{
    float T[4][4];
    v4f V[4];
    int n;
    vol_texel(c, lv, i0, j0, k, 1, T[0]);
    vol_texel(c, lv, (double)i0 + 1.0, j0, k, 1, T[1]);
    vol_texel(c, lv, i0, (double)j0 + 1.0, k, 1, T[2]);
    vol_texel(c, lv, (double)i0 + 1.0, (double)j0 + 1.0, k, 1, T[3]);
    for (n = 0; n < 4; ++n) V[n] = v4_load(T[n]);
    recon_bilerp(V, al, be, out, NULL, NULL);
}

/* LINEAR (eq. 8.11): i0 = ⌊u − ½⌋, α = frac(u − ½) on each axis
 * (recon_linear_origin); the weights (1 − γ) and γ of slices k0 and k0 + 1
 * times the bilinear weights of each are the eight products of eq. 8.11,
 * computed as two bilinear values and one blend (recon_blend). */
static uint32_t vol_linear(const sample_ctx *c, int lv, const float u[3], float out[4])
{
    float al, be, ga, i0 = recon_linear_origin(u[0], &al), j0 = recon_linear_origin(u[1], &be);
    float k0 = recon_linear_origin(u[2], &ga), upper[4];
    vol_slice_bilerp(c, lv, i0, j0, k0, al, be, out);
    vol_slice_bilerp(c, lv, i0, j0, (double)k0 + 1.0, al, be, upper);
    recon_blend(out, upper, ga);
    return 8;
}

/* CUBIC: the bicubic value of slices k0 − 1 … k0 + 2 (ls_recon_cubic_combine,
 * with SAMPLE_OPT_CUBIC_CLAMP applying within each slice), combined across
 * slices with the same kernel's weights, in double. */
static uint32_t vol_cubic(const sample_ctx *c, int lv, const float u[3], float out[4])
{
    float al, be, ga, i0 = recon_linear_origin(u[0], &al), j0 = recon_linear_origin(u[1], &be);
    float k0 = recon_linear_origin(u[2], &ga);
    double wx[4], wy[4], wz[4], dwx[4], dwy[4], dwz[4], acc[4] = {0, 0, 0, 0};
    float T[16][4], sl[4];
    int x, y, z, n;
    ls_cubic_weights(c->smp->cubic, al, wx, dwx);
    ls_cubic_weights(c->smp->cubic, be, wy, dwy);
    ls_cubic_weights(c->smp->cubic, ga, wz, dwz);
    for (z = 0; z < 4; ++z) {
        for (y = 0; y < 4; ++y)
            for (x = 0; x < 4; ++x)
                vol_texel(c, lv, (double)i0 + (x - 1), (double)j0 + (y - 1), (double)k0 + (z - 1), 1, T[4 * y + x]);
        ls_recon_cubic_combine(T, wx, wy, dwx, dwy, (c->smp->options & SAMPLE_OPT_CUBIC_CLAMP) != 0, al, be, sl,
                               NULL, NULL);
        for (n = 0; n < 4; ++n) acc[n] += wz[z] * sl[n];
    }
    for (n = 0; n < 4; ++n) out[n] = (float)acc[n];
    return 64;
}

uint32_t ls_vol_recon_level(const sample_ctx *c, int lv, sample_filter kind, const float p[3], float out[4])
{
    int n[3];
    float u[3];
    vol_level_dims(c, lv, n);
    /* u = s'·n per axis, after the wraps that transform the coordinate,
     * kept finite (recon_texel_coord); wrap_r is r's. */
    u[0] = recon_texel_coord(c->smp->wrap_s, p[0], n[0]);
    u[1] = recon_texel_coord(c->smp->wrap_t, p[1], n[1]);
    u[2] = recon_texel_coord(c->smp->wrap_r, p[2], n[2]);
    switch (kind) {
    case SAMPLE_NEAREST: return vol_nearest(c, lv, u, out);
    case SAMPLE_CUBIC: return vol_cubic(c, lv, u, out);
    case SAMPLE_LINEAR:
    default: return vol_linear(c, lv, u, out);
    }
}

/* The levels an OpenGL filter chose for λ (lod_select), reconstructed and
 * blended by eq. 8.18 (recon_blend), as ls_filter_gl_levels does for 2D. */
static uint32_t vol_gl_levels(const sample_ctx *c, const sample_query3 *q, float lam, const lod_choice *ch,
                              float out[4], sample_stats *st)
{
    uint32_t n = ls_vol_recon_level(c, ch->level0, ch->kind, q->p, out);
    if (ch->level1 >= 0) {
        float o1[4];
        n += ls_vol_recon_level(c, ch->level1, ch->kind, q->p, o1);
        recon_blend(out, o1, ch->frac);
    }
    st->level0 = (int16_t)ch->level0;
    st->level1 = (int16_t)ch->level1;
    st->level_frac = ch->frac;
    st->lod = lam;
    return n;
}

_Static_assert(sizeof(sample_query3) == 9 * sizeof(float), "a volume query is 9 floats");

/* One query: the border colour for non-finite input (DESIGN §10), else λ
 * with ρ over three components, then the footprint filter when one is set
 * and λ > 0, else the OpenGL filters (the order of sampler.c's
 * reference_query). */
static void vol_query(const sample_ctx *c, const sample_batch3_args *a, size_t i)
{
    const sample_query3 *q = &a->queries[i];
    float *out = a->rgba + 4 * i, bias = a->lod_bias ? a->lod_bias[i] : 0.0f;
    sample_stats local, *st = a->stats ? &a->stats[i] : &local;
    double rho2[2];
    float lam;
    lod_choice ch;

    stats_clear(st);
    if (!floats_finite(q, 9) || !floats_finite(&bias, 1)) {
        memcpy(out, c->border, sizeof c->border);
        return;
    }
    lam = lod_lambda(c, (float)vol_log2_rho(c, q, rho2), bias);
    if (c->smp->footprint != SAMPLE_FOOTPRINT_NONE && lam > 0.0f) {
        st->texels = ls_vol_footprint(c, q, bias, out, st);
        return;
    }
    ch = lod_select(c, lam);
    st->texels = vol_gl_levels(c, q, lam, &ch, out, st);
}

sample_status sample_batch_3d(const sample_texture *tex, const sample_sampler *smp, const sample_batch3_args *a)
{
    sample_ctx c;
    sample_status st;
    uintptr_t ticket;
    size_t i;
    int run;
    if (!a) return SAMPLE_E_INVALID_ARGUMENT;
    if ((st = ls_batch_check(tex, SAMPLE_TEXTURE_3D, smp, a->count, a->queries, a->rgba, &run)) != SAMPLE_OK || !run)
        return st;
    /* The reference kernels: volumes have no fast path, and the footprint
     * filters' readers below are the texel-by-texel ones. */
    ls_ctx_init(&c, tex, smp, &ls_isa_kernels_reference);
    ticket = tex_reads_begin(tex); /* a texel source that evicts (texel.h) */
    for (i = 0; i < a->count; ++i) vol_query(&c, a, i);
    tex_reads_end(tex, ticket);
    return SAMPLE_OK;
}
