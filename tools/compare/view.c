/*
 * One ray cast per pixel centre, shared by every configuration: each filter
 * answers exactly the same queries (the same (s, t), the same exact
 * Jacobian, the same corners), OpenImageIO included, and the timings measure
 * the filters, not the ray casting. The same per-pixel hits seed the ground
 * truth's supersampling (render_cache). A mirror of the scene's
 * environment asks for the reflected direction with its exact screen
 * derivatives instead (render_scene_env_query).
 */
#include "cmp_internal.h"

#include <stdio.h>
#include <stdlib.h>

static void view_row(void *ctx, int j)
{
    cmp_view *v = ctx;
    int i;
    for (i = 0; i < v->w; ++i) {
        size_t px = (size_t)j * (size_t)v->w + (size_t)i;
        const render_hit *h = render_cache_pixel(v->cache, i, j);
        sample_query *q = &v->q[px];
        v->object[px] = h->object;
        v->quad_ok[px] = 0;
        if (h->object < 0) {
            v->tex[px] = -2;
            continue;
        }
        /* A mirror answers one question, the environment's, whatever
         * texture its material also has. */
        if (v->env_tex >= 0 && render_scene_env_query(v->sc, h, &v->q3[px])) {
            v->tex[px] = v->env_tex;
            continue;
        }
        v->tex[px] = render_scene_material_texture(v->sc, h->material);
        /* A solid texture asks for the surface point in its volume. */
        if (v->q3 && render_scene_solid_query(v->sc, v->tex[px], h, &v->q3[px])) continue;
        q->s = (float)h->s;
        q->t = (float)h->t;
        q->dsdx = (float)h->J[0];
        q->dtdx = (float)h->J[1];
        q->dsdy = (float)h->J[2];
        q->dtdy = (float)h->J[3];
        if (v->tex[px] >= 0)
            v->quad_ok[px] =
                (unsigned char)render_scene_corners(v->sc, h, i + 0.5, j + 0.5, &v->quad[px]);
    }
}

int cmp_view_3d(const cmp_view *v, int texture)
{
    return render_scene_texture_solid(v->sc, texture);
}

int cmp_view_build(const render_scene *sc, int threads, cmp_view *v, char *err, size_t errlen)
{
    size_t n;
    /* Background: not a filtering question, so one neutral colour for every
     * scene, the same in the images and in the ground truth. */
    static const float bg[4] = {0.18f, 0.2f, 0.24f, 1.0f};
    int k, want3;
    v->sc = sc;
    render_scene_size(sc, &v->w, &v->h);
    render_scene_sampler(sc, &v->sampler);
    for (k = 0; k < 4; ++k) v->background[k] = bg[k];
    n = (size_t)v->w * (size_t)v->h;
    v->cache = render_cache_build(sc, threads);
    v->tex = malloc(n * sizeof *v->tex);
    v->object = malloc(n * sizeof *v->object);
    v->q = calloc(n, sizeof *v->q);
    v->env_tex = render_scene_env(sc, NULL) ? render_scene_texture_count(sc) : -1;
    for (k = 0; k < render_scene_texture_count(sc) && !cmp_view_3d(v, k); ++k) {}
    want3 = v->env_tex >= 0 || k < render_scene_texture_count(sc);
    v->q3 = want3 ? calloc(n, sizeof *v->q3) : NULL;
    v->quad = calloc(n, sizeof *v->quad);
    v->quad_ok = calloc(n, 1);
    if (!v->cache || !v->tex || !v->object || !v->q || !v->quad || !v->quad_ok || (want3 && !v->q3)) {
        cmp_view_free(v);
        snprintf(err, errlen, "out of memory for a %d x %d view", v->w, v->h);
        return 1;
    }
    render_parallel_rows(v->h, threads, view_row, v, NULL, NULL);
    return 0;
}

void cmp_view_free(cmp_view *v)
{
    render_cache_destroy(v->cache);
    free(v->tex);
    free(v->object);
    free(v->q);
    free(v->q3);
    free(v->quad);
    free(v->quad_ok);
    v->cache = NULL;
    v->tex = v->object = NULL;
    v->q = NULL;
    v->q3 = NULL;
    v->quad = NULL;
    v->quad_ok = NULL;
}
