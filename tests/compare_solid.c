/*
 * Solid textures baked into 3D textures, through compare's own view, truth
 * and runs (doc/volumes.md, "Renderer"; doc/comparison.md, "solid"): a
 * tiny version of the solid scene (16³ and 24³ bakes, 32 × 32 pixels,
 * 8 × 8 truth samples per footprint).
 *
 *   - the scene parses; the solid textures are 3D textures and a pixel on
 *     them asks a 3D query whose point is the hit's P in the box and whose
 *     columns are dP/dx, dP/dy scaled by the box (exact, as jacobian.c);
 *   - the truth is the procedural function at the surface point, whatever
 *     (s, t) says;
 *   - the renderer's texture-only picture is that 3D lookup, bit for bit;
 *   - every filter gives finite values; trilinear, EWA, Blinn–Newell and
 *     anisotropic score below NEAREST (the aliasing the bake removes);
 *   - a "solid" block's bad keys and values are refused with a message.
 */
#include "check.h"
#include "cmp_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* What a failed check prints after the condition. */
static const char err_hint[] = "(see the condition)";

static const char scene[] =
    "{\"camera\":{\"eye\":[7.5,-9.5,4.2],\"look\":[1.6,1.2,0.9],\"up\":[0,0,1],\"fov\":40},"
    "\"textures\":["
    "{\"name\":\"wood\",\"type\":\"wood\",\"freq\":2,\"amount\":3,"
    "\"solid\":{\"min\":[-3.1,-2.1,-0.1],\"max\":[3.5,2.1,3.2],\"size\":24}},"
    "{\"name\":\"checker\",\"type\":\"checker\",\"freq\":1,"
    "\"solid\":{\"min\":[0,0,0],\"max\":[4,4,4],\"size\":16,\"wrap\":\"repeat\",\"samples\":1}}],"
    "\"materials\":[{\"name\":\"wood\",\"texture\":\"wood\"},{\"name\":\"checker\",\"texture\":\"checker\"}],"
    "\"objects\":[{\"type\":\"teapot\",\"material\":\"wood\"},"
    "{\"type\":\"plane\",\"material\":\"checker\",\"centre\":[0,0,-0.35],\"axis\":[0.12,0.2,1]}]}";

static double rmse_of(const cmp_view *v, const cmp_truth *t, const char *name)
{
    cmp_config cfg;
    cmp_result r;
    cmp_metrics m;
    tool_backend lib;
    char err[256];
    size_t k, n = (size_t)v->w * (size_t)v->h;
    CHECK(cmp_configs_parse(name, 0, &cfg, 1, err, sizeof err) == 1, "%s", err_hint);
    CHECK(tool_backend_libsample(&lib, NULL) == 0, "%s", err_hint);
    cfg.tb = &lib;
    CHECK(cmp_run_backend(v, &cfg, 2, 1, &r, err, sizeof err) == 0, "%s", err);
    tool_backend_close(&lib);
    for (k = 0; k < 4 * n; ++k) CHECK(isfinite(r.rgba[k]), "%s", err_hint);
    cmp_metrics_compute(r.rgba, t->rgba, t->mask, n, &m);
    CHECK(m.count > 100, "%s", err_hint);
    printf("%-14s rmse %.4f\n", name, m.rmse);
    cmp_result_free(&r);
    return m.rmse;
}

static void refused(const char *solid, const char *expect)
{
    char json[1024], err[512];
    render_scene *sc = NULL;
    snprintf(json, sizeof json,
             "{\"textures\":[{\"name\":\"w\",\"type\":\"wood\",%s}],"
             "\"objects\":[{\"type\":\"sphere\"}]}",
             solid);
    CHECK(render_scene_parse(json, strlen(json), 8, 8, &sc, err, sizeof err) != 0, "%s", err_hint);
    CHECK(sc == NULL, "%s", err_hint);
    if (!strstr(err, expect)) fprintf(stderr, "'%s': got '%s'\n", solid, err);
    CHECK(strstr(err, expect) != NULL, "%s", err_hint);
}

static void solid_scene(void)
{
    render_scene *sc = NULL;
    cmp_view v;
    cmp_truth t;
    char err[512];
    int i, j, checked = 0, k;
    double nearest;

    CHECK(render_scene_parse(scene, strlen(scene), 32, 32, &sc, err, sizeof err) == 0, "%s", err_hint);
    CHECK(render_scene_texture_solid(sc, 0) && render_scene_texture_solid(sc, 1), "%s", err_hint);
    {
        sample_texture_info info;
        sample_texture_info_get(render_scene_texture(sc, 0), &info);
        CHECK(info.kind == SAMPLE_TEXTURE_3D && info.width == 24 && info.depth == 24, "%s", err_hint);
    }
    memset(&v, 0, sizeof v);
    CHECK(cmp_view_build(sc, 2, &v, err, sizeof err) == 0, "%s", err_hint);
    CHECK(v.q3 != NULL, "%s", err_hint);
    /* The query of a pixel on the wood: P and dP/dx, dP/dy in the box. */
    for (j = 0; j < v.h; ++j)
        for (i = 0; i < v.w; ++i) {
            const render_hit *h = render_cache_pixel(v.cache, i, j);
            const sample_query3 *q = &v.q3[(size_t)j * (size_t)v.w + (size_t)i];
            static const double lo[3] = {-3.1, -2.1, -0.1}, ext[3] = {6.6, 4.2, 3.3};
            float exact[4], again[4];
            if (v.tex[(size_t)j * (size_t)v.w + (size_t)i] != 0) continue;
            CHECK(cmp_view_3d(&v, 0), "%s", err_hint);
            for (k = 0; k < 3; ++k) {
                CHECK(fabs(q->p[k] - (h->P[k] - lo[k]) / ext[k]) < 1e-6, "%s", err_hint);
                CHECK(fabs(q->dpdx[k] - h->dPdx[k] / ext[k]) < 1e-6 * (1 + fabs(q->dpdx[k])), "%s", err_hint);
                CHECK(fabs(q->dpdy[k] - h->dPdy[k] / ext[k]) < 1e-6 * (1 + fabs(q->dpdy[k])), "%s", err_hint);
            }
            /* The truth is the function at P, whatever (s, t) says. */
            CHECK(render_scene_texture_exact(sc, 0, h->s, h->t, h->P, exact), "%s", err_hint);
            CHECK(render_scene_texture_exact(sc, 0, 0.25, 0.75, h->P, again), "%s", err_hint);
            CHECK(memcmp(exact, again, sizeof exact) == 0, "%s", err_hint);
            ++checked;
        }
    CHECK(checked > 50, "%s", err_hint);
    {
        /* The renderer's own shading path (shade.c) asks the same query:
         * its texture-only picture is the 3D lookup, bit for bit. */
        render_options o;
        render_image img;
        sample_sampler smp;
        size_t px, same = 0;
        render_options_init(&o);
        o.shade = RENDER_SHADE_TEXTURE;
        render_scene_sampler(sc, &smp);
        CHECK(render_image_run(sc, &o, &img, err, sizeof err) == 0, "%s", err);
        for (px = 0; px < (size_t)v.w * (size_t)v.h; ++px) {
            float want[4];
            if (!cmp_view_3d(&v, v.tex[px])) continue;
            CHECK(render_scene_solid_sample(sc, v.tex[px], &smp, &v.q3[px], 1, want, NULL), "%s", err_hint);
            CHECK(memcmp(want, img.rgba + 4 * px, sizeof want) == 0, "pixel %zu", px);
            ++same;
        }
        CHECK(same > 200, "%zu pixels on solids", same);
        render_image_free(&img);
    }

    CHECK(cmp_truth_build(&v, 8, 2, &t, err, sizeof err) == 0, "%s", err_hint);
    nearest = rmse_of(&v, &t, "nearest");
    CHECK(rmse_of(&v, &t, "trilinear") < nearest, "%s", err_hint);
    CHECK(rmse_of(&v, &t, "ewa") < nearest, "%s", err_hint);
    CHECK(rmse_of(&v, &t, "blinn-newell") < nearest, "%s", err_hint);
    CHECK(rmse_of(&v, &t, "aniso16") < nearest, "%s", err_hint);
    cmp_truth_free(&t);
    cmp_view_free(&v);
    render_scene_destroy(sc);
}

static void refusals(void)
{
    render_scene *sc = NULL;
    char err[512];
    refused("\"solid\":{\"size\":8,\"colour\":1}", "unknown key 'colour'");
    refused("\"solid\":{\"min\":[0,0,0],\"max\":[1,0,1]}", "'max' must exceed 'min'");
    refused("\"solid\":{\"size\":0}", "'size' must be a number in [1, 512]");
    refused("\"solid\":{\"mip\":\"gauss\"}", "'mip' must name a mip filter");
    refused("\"solid\":{\"wrap\":\"tile\"}", "'wrap' must name a wrap mode");
    refused("\"solid\":7", "'solid' must be an object");
    refused("\"size\":8,\"solid\":{}", "bake is given in 'solid'");
    {
        /* Only the patterns of three coordinates are solids. */
        const char *bad = "{\"textures\":[{\"name\":\"g\",\"type\":\"grid\",\"solid\":{}}],"
                          "\"objects\":[{\"type\":\"sphere\"}]}";
        CHECK(render_scene_parse(bad, strlen(bad), 8, 8, &sc, err, sizeof err) != 0, "%s", err_hint);
        CHECK(strstr(err, "'solid' applies to") != NULL, "%s", err_hint);
    }
}

int main(void)
{
    RUN(solid_scene);
    RUN(refusals);
    return check_finish();
}
