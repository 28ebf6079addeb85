/*
 * Solid textures baked into 3D textures (doc/volumes.md, "Renderer").
 *
 * A solid texture is a function of the surface point (Peachey 1985,
 * Perlin 1985: the object is "carved" from the material). Evaluated at
 * the visible point alone it aliases like any unfiltered texture; baked
 * into a 3D texture over a box of space it can be filtered: a pixel's
 * footprint on the surface is the parallelogram P + x·dP/dx + y·dP/dy
 * inside the volume, and libsample's 3D filters integrate over it
 * (sample_batch_3d). dP/dx and dP/dy are the renderer's exact ray
 * differentials (jacobian.c: [Pu Pv] times the inverse of d(x, y)/d(u, v),
 * no differencing), so the query is exact to float rounding.
 *
 * The bake is a box filter of samples³ stratified points per texel (the
 * texel's mean, so that the base level does not alias either), then the
 * pyramid of libsample's mip generator on linear values.
 */
#include "rn_internal.h"

#include <stdlib.h>

void solid_defaults(rn_solid *s)
{
    int k;
    memset(s, 0, sizeof *s);
    for (k = 0; k < 3; ++k) {
        s->lo[k] = -1.0;
        s->hi[k] = 1.0;
        s->size[k] = 64;
    }
    s->samples = 2;
    s->mip = SAMPLE_MIPGEN_BOX;
    s->wrap = SAMPLE_WRAP_CLAMP_TO_EDGE;
}

int solid_bake(rn_texture *t, char *err, size_t errlen)
{
    const rn_solid *so = &t->solid;
    const int w = so->size[0], h = so->size[1], d = so->size[2], m = so->samples;
    size_t n = (size_t)w * (size_t)h * (size_t)d, at = 0;
    float *px = malloc(sizeof *px * 4 * n);
    sample_volume vol;
    sample_mip_params mip;
    sample_error e;
    int i, j, k, a, b, c, ch;
    if (!px) {
        rn_seterr(err, errlen, "out of memory baking a %d x %d x %d solid texture", w, h, d);
        return 0;
    }
    for (k = 0; k < d; ++k)
        for (j = 0; j < h; ++j)
            for (i = 0; i < w; ++i, at += 4) {
                double acc[4] = {0, 0, 0, 0}, X[3];
                for (c = 0; c < m; ++c)
                    for (b = 0; b < m; ++b)
                        for (a = 0; a < m; ++a) {
                            float v[4];
                            double f[3] = {(i + (a + 0.5) / m) / w, (j + (b + 0.5) / m) / h,
                                           (k + (c + 0.5) / m) / d};
                            for (ch = 0; ch < 3; ++ch)
                                X[ch] = so->lo[ch] + f[ch] * (so->hi[ch] - so->lo[ch]);
                            proc_eval(t, 0.0, 0.0, X, v);
                            for (ch = 0; ch < 4; ++ch) acc[ch] += v[ch];
                        }
                for (ch = 0; ch < 4; ++ch) px[at + (size_t)ch] = (float)(acc[ch] / (m * m * m));
            }
    memset(&vol, 0, sizeof vol);
    vol.width = w;
    vol.height = h;
    vol.depth = d;
    vol.channels = 4;
    vol.format = SAMPLE_FORMAT_F32;
    vol.data = px;
    sample_mip_params_init(&mip);
    mip.filter = so->mip;
    mip.wrap_s = mip.wrap_t = mip.wrap_r = so->wrap;
    if (sample_texture_create_3d(&vol, &mip, &t->tex, &e) != SAMPLE_OK) {
        rn_seterr(err, errlen, "baking a solid texture: %s", e.message);
        free(px);
        return 0;
    }
    free(px);
    return 1;
}

int solid_query(const rn_texture *t, const render_hit *h, sample_query3 *q)
{
    int k;
    if (!t->solid.on || !t->tex) return 0;
    for (k = 0; k < 3; ++k) {
        /* The box maps affinely onto [0, 1]³, so the Jacobian's columns
         * scale by the same factor as the point. */
        double inv = 1.0 / (t->solid.hi[k] - t->solid.lo[k]);
        q->p[k] = (float)((h->P[k] - t->solid.lo[k]) * inv);
        q->dpdx[k] = (float)(h->dPdx[k] * inv);
        q->dpdy[k] = (float)(h->dPdy[k] * inv);
    }
    return 1;
}

int solid_sample(const rn_texture *t, const sample_sampler *smp, const sample_query3 *q, size_t n,
                 float *rgba, sample_stats *stats)
{
    sample_sampler s = *smp;
    sample_batch3_args a;
    /* The box's wrap belongs to the solid (a periodic pattern repeats, a
     * carved object's box clamps), not to the scene's 2D textures. */
    s.wrap_s = s.wrap_t = s.wrap_r = t->solid.wrap;
    memset(&a, 0, sizeof a);
    a.count = n;
    a.queries = q;
    a.rgba = rgba;
    a.stats = stats;
    return sample_batch_3d(t->tex, &s, &a) == SAMPLE_OK;
}

int render_scene_solid_query(const render_scene *sc, int texture, const render_hit *h,
                             sample_query3 *q)
{
    return texture >= 0 && texture < sc->ntex && solid_query(&sc->tex[texture], h, q);
}

int render_scene_texture_solid(const render_scene *sc, int texture)
{
    return texture >= 0 && texture < sc->ntex && sc->tex[texture].solid.on;
}

sample_wrap render_scene_solid_wrap(const render_scene *sc, int texture)
{
    return render_scene_texture_solid(sc, texture) ? sc->tex[texture].solid.wrap : SAMPLE_WRAP_REPEAT;
}

int render_scene_solid_sample(const render_scene *sc, int texture, const sample_sampler *smp,
                              const sample_query3 *q, size_t n, float *rgba, sample_stats *stats)
{
    return render_scene_texture_solid(sc, texture) &&
           solid_sample(&sc->tex[texture], smp, q, n, rgba, stats);
}
