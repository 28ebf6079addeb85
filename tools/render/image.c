/*
 * Whole-image rendering: one visible-surface query and one shading per pixel
 * centre, rows spread over threads. Every pixel depends only on its own
 * position, so the bytes do not depend on the thread count.
 */
#include "rn_internal.h"

#include <stdlib.h>

typedef struct image_job {
    const render_scene *sc;
    render_options opt;
    render_image *img;
} image_job;

static void put(float *buf, int n, size_t px, const double *v)
{
    int k;
    if (buf)
        for (k = 0; k < n; ++k) buf[px * (size_t)n + (size_t)k] = (float)v[k];
}

static void image_row(void *ctx, int j)
{
    image_job *jb = ctx;
    const render_scene *sc = jb->sc;
    render_image *img = jb->img;
    int i, k;
    for (i = 0; i < img->width; ++i) {
        size_t px = (size_t)j * img->width + i;
        double x = i + 0.5, y = j + 0.5, d[4];
        float *out = img->rgba + 4 * px;
        render_hit h;
        sample_stats st;
        memset(&st, 0, sizeof st);
        st.level0 = st.level1 = -1;
        if (!render_scene_hit(sc, x, y, &h)) {
            for (k = 0; k < 4; ++k) out[k] = jb->opt.background[k];
            d[0] = HUGE_VAL;
            put(img->depth, 1, px, d);
            d[0] = d[1] = -1.0;
            put(img->id, 2, px, d);
            continue;
        }
        {
            sample_quad q;
            int have_q = jb->opt.corners && render_scene_corners(sc, &h, x, y, &q);
            shade_hit(sc, &jb->opt, &h, have_q ? &q : NULL, out, &st);
        }
        d[0] = h.s; d[1] = h.t;
        put(img->st, 2, px, d);
        put(img->jacobian, 4, px, h.J);
        d[0] = st.lod;
        put(img->lod, 1, px, d);
        d[0] = st.texels;
        put(img->texels, 1, px, d);
        put(img->depth, 1, px, &h.depth);
        put(img->normal, 3, px, h.N);
        d[0] = h.object; d[1] = h.prim;
        put(img->id, 2, px, d);
    }
}

static float *buf_alloc(unsigned want, unsigned bit, size_t px, int n, int *ok)
{
    float *b;
    if (!(want & bit)) return NULL;
    b = calloc(px * (size_t)n, sizeof *b);
    if (!b) *ok = 0;
    return b;
}

int render_image_run(const render_scene *sc, const render_options *o, render_image *out,
                     char *err, size_t errlen)
{
    image_job jb;
    size_t px = (size_t)sc->cam.width * (size_t)sc->cam.height;
    int ok = 1, k;
    memset(out, 0, sizeof *out);
    jb.sc = sc;
    jb.opt = *o;
    jb.img = out;
    if (o->use_scene_sampler) jb.opt.sampler = sc->sampler;
    for (k = 0; k < 4; ++k) jb.opt.background[k] = sc->background[k];
    if (sample_sampler_validate(&jb.opt.sampler) != SAMPLE_OK) {
        rn_seterr(err, errlen, "invalid sampler state");
        return -1;
    }
    out->width = sc->cam.width;
    out->height = sc->cam.height;
    out->rgba = calloc(px * 4, sizeof *out->rgba);
    if (!out->rgba) ok = 0;
    out->st = buf_alloc(o->buffers, RENDER_BUF_ST, px, 2, &ok);
    out->jacobian = buf_alloc(o->buffers, RENDER_BUF_JACOBIAN, px, 4, &ok);
    out->lod = buf_alloc(o->buffers, RENDER_BUF_LOD, px, 1, &ok);
    out->texels = buf_alloc(o->buffers, RENDER_BUF_TEXELS, px, 1, &ok);
    out->depth = buf_alloc(o->buffers, RENDER_BUF_DEPTH, px, 1, &ok);
    out->normal = buf_alloc(o->buffers, RENDER_BUF_NORMAL, px, 3, &ok);
    out->id = buf_alloc(o->buffers, RENDER_BUF_ID, px, 2, &ok);
    if (!ok) {
        render_image_free(out);
        rn_seterr(err, errlen, "out of memory for a %d x %d image", sc->cam.width, sc->cam.height);
        return -1;
    }
    render_parallel_rows(out->height, o->threads, image_row, &jb, o->progress, "render");
    return 0;
}

void render_image_free(render_image *img)
{
    if (!img) return;
    free(img->rgba);
    free(img->st);
    free(img->jacobian);
    free(img->lod);
    free(img->texels);
    free(img->depth);
    free(img->normal);
    free(img->id);
    memset(img, 0, sizeof *img);
}
