/*
 * 3D textures (volume.c, volume_sample.c, volume_footprint.c; DESIGN §11,
 * doc/volumes.md): a volume's texel reads through the three wrap modes,
 * its level of detail with ρ over three components (GL 4.6 §8.14.1), one
 * level's reconstruction (eq. 8.11) and the footprint filters over the
 * flat patch a pixel covers inside the volume. Volumes run the reference
 * path only: one query at a time, texel by texel, through the same decodes
 * (tex_read_layer), wraps (ls_wrap_index) and arithmetic (recon_bilerp,
 * recon_blend, ls_recon_cubic_combine) as 2D textures.
 */
#ifndef SAMPLE_VOLUME_H
#define SAMPLE_VOLUME_H

#include "lod.h"
#include "recon.h"

/* Read texel (i, j, k) of level lv (k the slice) through the wrap modes
 * on s, t and r (ls_wrap_index; `linear` as for ctx_texel); the border
 * colour where any axis says so. Every volume filter reads through this. */
static inline void vol_texel(const sample_ctx *c, int lv, double i, double j, double k, int linear, float out[4])
{
    const struct sample_level *L = &c->tex->level[lv];
    int x, y, z;
    if (i >= 0.0 && i < (double)L->w && j >= 0.0 && j < (double)L->h && k >= 0.0 && k < (double)L->d) {
        tex_read_layer(c->tex, lv, (int)i, (int)j, (int)k, out);
        return;
    }
    x = ls_wrap_index(c->smp->wrap_s, i, L->w, linear);
    y = ls_wrap_index(c->smp->wrap_t, j, L->h, linear);
    z = ls_wrap_index(c->smp->wrap_r, k, L->d, linear);
    if (x < 0 || y < 0 || z < 0) {
        memcpy(out, c->border, sizeof c->border);
        return;
    }
    tex_read_layer(c->tex, lv, x, y, z, out);
}

/* A level's size per axis (w, h, d). */
static inline void vol_level_dims(const sample_ctx *c, int lv, int n[3])
{
    const struct sample_level *L = &c->tex->level[lv];
    n[0] = L->w;
    n[1] = L->h;
    n[2] = L->d;
}

/* log2 ρ of a volume query on level_base (GL 4.6 §8.14.1, eq. 8.7 with
 * the third terms: ρ = max(‖(∂u/∂x, ∂v/∂x, ∂w/∂x)‖, ‖(… /∂y)‖)), and the
 * squared column lengths in base texels (the anisotropic filter's Px²,
 * Py²). In double, as lod_log2_rho; −inf for a zero Jacobian. */
static inline double vol_log2_rho(const sample_ctx *c, const sample_query3 *q, double rho2[2])
{
    int n[3], a;
    vol_level_dims(c, c->base, n);
    rho2[0] = rho2[1] = 0.0;
    for (a = 0; a < 3; ++a) {
        double x = (double)q->dpdx[a] * n[a], y = (double)q->dpdy[a] * n[a];
        rho2[0] += x * x;
        rho2[1] += y * y;
    }
    return 0.5 * sample_log2(rho2[0] > rho2[1] ? rho2[0] : rho2[1]);
}

/* One level's reconstruction at p = (s, t, r): NEAREST (eq. 8.12 on three
 * axes), LINEAR (trilinear, eq. 8.11: the bilinear values of slices k0
 * and k0 + 1 blended by γ) or CUBIC (tricubic). Returns texels read. */
uint32_t ls_vol_recon_level(const sample_ctx *c, int lv, sample_filter kind, const float p[3], float out[4]);

/* The footprint filters in 3D (volume_footprint.c): query q (finite, GL
 * λ > 0) through the sampler's footprint filter; returns texels read (at
 * most SAMPLE_MAX_FOOTPRINT_TEXELS), fills out and st. */
uint32_t ls_vol_footprint(const sample_ctx *c, const sample_query3 *q, float call_bias, float out[4],
                          sample_stats *st);

#endif /* SAMPLE_VOLUME_H */
