/*
 * Scene objects: creation helpers, the built-in scenes (JSON texts, so the
 * scene-file parser is the only builder), finishing (baking, tessellation),
 * accessors of the public API, destruction.
 */
#define _POSIX_C_SOURCE 200809L
#include "rn_internal.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

void rn_seterr(char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;
    if (!err || !errlen) return;
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
}

/* The paper's Figure 10: a glazed, patterned teapot with a highlight and
 * the room reflected in it (environment at a finite radius: the
 * position-corrected lookup). The pattern is the paper's Figure 2 grid of
 * parametric lines, one texture per patch. */
static const char scene_teapot[] =
    "{\"camera\":{\"eye\":[6.5,-8.5,5.2],\"look\":[0.15,0,1.35],\"up\":[0,0,1],\"fov\":28},"
    "\"background\":[0.02,0.02,0.03,1],"
    "\"sampler\":{\"min\":\"linear_mipmap_linear\",\"mag\":\"linear\"},"
    "\"textures\":[{\"name\":\"grid\",\"type\":\"grid\",\"freq\":4,\"width\":0.12,"
    "\"a\":[0.85,0.8,0.65,1],\"b\":[0.08,0.15,0.55,1]}],"
    "\"materials\":[{\"name\":\"glaze\",\"texture\":\"grid\",\"diffuse\":[0.9,0.9,0.9],"
    "\"ambient\":0.15,\"gloss\":0.8,\"exponent\":60,\"reflect\":0.25}],"
    "\"lights\":[{\"dir\":[0.6,-0.5,0.8],\"color\":[1,1,1]}],"
    "\"environment\":{\"type\":\"latlong\",\"size\":512,\"radius\":12,\"centre\":[0,0,1.5]},"
    "\"objects\":[{\"type\":\"teapot\",\"material\":\"glaze\"}]}";

/* A checkerboard ground plane to the horizon: eye 1 above z = 0 looking at
 * (0, 10, 0), so the horizon is tan⁻¹(0.1) above the image centre. */
static const char scene_plane[] =
    "{\"camera\":{\"eye\":[0,0,1],\"look\":[0,10,0],\"up\":[0,0,1],\"fov\":60},"
    "\"background\":[0.5,0.6,0.8,1],"
    "\"sampler\":{\"min\":\"linear_mipmap_linear\",\"mag\":\"linear\"},"
    "\"textures\":[{\"name\":\"checker\",\"type\":\"checker\",\"freq\":8}],"
    "\"materials\":[{\"name\":\"m\",\"texture\":\"checker\",\"ambient\":1,\"gloss\":0}],"
    "\"objects\":[{\"type\":\"plane\",\"centre\":[0,0,0],\"axis\":[0,0,1],\"size\":1}]}";

/* A zone plate quad seen head-on, filling the image: every frequency up to
 * the texture's Nyquist rate at once. */
static const char scene_zoneplate[] =
    "{\"camera\":{\"eye\":[0.5,0.5,1.2071067811865475],\"look\":[0.5,0.5,0],\"up\":[0,1,0],"
    "\"fov\":45},"
    "\"sampler\":{\"min\":\"linear_mipmap_linear\",\"mag\":\"linear\"},"
    "\"textures\":[{\"name\":\"zp\",\"type\":\"zoneplate\",\"amount\":160}],"
    "\"materials\":[{\"name\":\"m\",\"texture\":\"zp\",\"ambient\":1,\"gloss\":0}],"
    "\"objects\":[{\"type\":\"polygons\",\"polygons\":[{\"v\":[[0,0,0],[1,0,0],[1,1,0],[0,1,0]],"
    "\"st\":[[0,0],[1,0],[1,1],[0,1]]}]}]}";

static const char scene_cylinder[] =
    "{\"camera\":{\"eye\":[0,-6,3],\"look\":[0,0,1],\"up\":[0,0,1],\"fov\":40},"
    "\"background\":[0.05,0.05,0.05,1],"
    "\"sampler\":{\"min\":\"linear_mipmap_linear\",\"mag\":\"linear\"},"
    "\"textures\":[{\"name\":\"bricks\",\"type\":\"bricks\",\"freq\":8,\"width\":0.1,"
    "\"a\":[0.8,0.78,0.7,1],\"b\":[0.6,0.2,0.12,1]}],"
    "\"materials\":[{\"name\":\"m\",\"texture\":\"bricks\",\"ambient\":0.2,\"gloss\":0.2,"
    "\"exponent\":20}],"
    "\"lights\":[{\"dir\":[0.3,-1,0.6]}],"
    "\"objects\":[{\"type\":\"cylinder\",\"centre\":[0,0,0],\"axis\":[0,0,1],\"radius\":1,"
    "\"height\":2,\"st_scale\":[2,1]}]}";

static const char scene_sphere[] =
    "{\"camera\":{\"eye\":[0,-4,1.5],\"look\":[0,0,0],\"up\":[0,0,1],\"fov\":40},"
    "\"sampler\":{\"min\":\"linear_mipmap_linear\",\"mag\":\"linear\"},"
    "\"textures\":[{\"name\":\"c\",\"type\":\"checker\",\"freq\":16}],"
    "\"materials\":[{\"name\":\"m\",\"texture\":\"c\",\"ambient\":0.2,\"gloss\":0.5,"
    "\"exponent\":40,\"reflect\":0.2}],"
    "\"lights\":[{\"dir\":[0.5,-1,1]}],"
    "\"environment\":{\"type\":\"cube\",\"size\":128},"
    "\"objects\":[{\"type\":\"sphere\",\"centre\":[0,0,0],\"radius\":1}]}";

/* The teapot of Fig. 10 with the photograph instead of the grid: each
 * patch carries the whole picture (REPEAT across patch seams). */
static const char scene_teapot_image[] =
    "{\"camera\":{\"eye\":[6.5,-8.5,5.2],\"look\":[0.15,0,1.35],\"up\":[0,0,1],\"fov\":28},"
    "\"background\":[0.02,0.02,0.03,1],"
    "\"sampler\":{\"min\":\"linear_mipmap_linear\",\"mag\":\"linear\"},"
    "\"textures\":[{\"name\":\"photo\",\"type\":\"image\",\"file\":\"photo.jpg\"}],"
    "\"materials\":[{\"name\":\"glaze\",\"texture\":\"photo\",\"diffuse\":[0.9,0.9,0.9],"
    "\"ambient\":0.15,\"gloss\":0.8,\"exponent\":60,\"reflect\":0.25}],"
    "\"lights\":[{\"dir\":[0.6,-0.5,0.8],\"color\":[1,1,1]}],"
    "\"environment\":{\"type\":\"latlong\",\"size\":512,\"radius\":12,\"centre\":[0,0,1.5]},"
    "\"objects\":[{\"type\":\"teapot\",\"material\":\"glaze\"}]}";

/* The photograph on a 2 × 4.7 quad lying on z = 0, seen from 0.75 above
 * its near part: minification grows, and grows anisotropic, towards the far
 * edge. t = 0 (the picture's top row) is the far edge, so it stands upright;
 * CLAMP_TO_EDGE, as a photograph does not tile. The camera is that of the
 * stand-in texsample compare had before this scene (compare now uses this
 * one), but the near edge is at y = −1.2, below the view, so that the
 * bottom rows show the photograph and not the background (the bottom ray
 * meets z = 0 at y ≈ −0.71). */
static const char scene_photo_plane[] =
    "{\"camera\":{\"eye\":[0,-1.6,0.75],\"look\":[0,1.2,0],\"up\":[0,0,1],\"fov\":50},"
    "\"background\":[0.5,0.6,0.8,1],"
    "\"sampler\":{\"min\":\"linear_mipmap_linear\",\"mag\":\"linear\","
    "\"wrap_s\":\"clamp_to_edge\",\"wrap_t\":\"clamp_to_edge\"},"
    "\"textures\":[{\"name\":\"photo\",\"type\":\"image\",\"file\":\"photo.jpg\"}],"
    "\"materials\":[{\"name\":\"m\",\"texture\":\"photo\",\"ambient\":1,\"gloss\":0}],"
    "\"objects\":[{\"type\":\"polygons\",\"material\":\"m\",\"polygons\":[{\"v\":[[-1,-1.2,0],"
    "[1,-1.2,0],[1,3.5,0],[-1,3.5,0]],\"st\":[[0,1],[1,1],[1,0],[0,0]]}]}]}";

const char *const render_builtin_names[] = {"teapot",   "plane",        "zoneplate",   "cylinder",
                                            "sphere",   "teapot-image", "photo-plane", NULL};
static const char *const builtin_json[] = {scene_teapot,   scene_plane,        scene_zoneplate,
                                           scene_cylinder, scene_sphere,       scene_teapot_image,
                                           scene_photo_plane};
_Static_assert(sizeof builtin_json / sizeof builtin_json[0] ==
                   sizeof render_builtin_names / sizeof render_builtin_names[0] - 1,
               "one JSON text per built-in name");

/* Image files of the built-in scenes: testimages/ of the source tree (the
 * build defines TEXSAMPLE_SOURCE_DIR), else of the working directory. */
#ifdef TEXSAMPLE_SOURCE_DIR
#define RN_BUILTIN_IMAGES TEXSAMPLE_SOURCE_DIR "/testimages"
#else
#define RN_BUILTIN_IMAGES "testimages"
#endif

int render_scene_builtin(const char *name, int width, int height, render_scene **out, char *err,
                         size_t errlen)
{
    return render_scene_builtin_ex(name, width, height, NULL, out, err, errlen);
}

int render_scene_builtin_ex(const char *name, int width, int height, const render_parse_options *pin,
                            render_scene **out, char *err, size_t errlen)
{
    render_parse_options po;
    int k;
    *out = NULL;
    if (pin) po = *pin;
    else render_parse_options_init(&po);
    po.base_dir = RN_BUILTIN_IMAGES;
    for (k = 0; render_builtin_names[k]; ++k)
        if (strcmp(name, render_builtin_names[k]) == 0) {
            int r = render_scene_parse_ex(builtin_json[k], strlen(builtin_json[k]), width, height,
                                          &po, out, err, errlen);
            if (r != 0) {
                char inner[200];
                snprintf(inner, sizeof inner, "%s", err ? err : "");
                rn_seterr(err, errlen, "built-in scene '%s': %s", name, inner);
            }
            return r;
        }
    rn_seterr(err, errlen,
              "no built-in scene '%s' (teapot, plane, zoneplate, cylinder, sphere, teapot-image, "
              "photo-plane)",
              name);
    return -1;
}

render_scene *scene_new(void)
{
    render_scene *sc = calloc(1, sizeof *sc);
    if (!sc) return NULL;
    sample_sampler_init(&sc->sampler);
    sc->sampler.min_filter = SAMPLE_LINEAR_MIPMAP_LINEAR;
    sc->background[3] = 1.0f;
    return sc;
}

#define GROW(arr, n, item)                                                                 \
    do {                                                                                   \
        void *p_ = realloc((arr), sizeof *(arr) * (size_t)((n) + 1));                      \
        if (!p_) return 0;                                                                 \
        (arr) = p_;                                                                        \
        (arr)[(n)++] = *(item);                                                            \
    } while (0)

int scene_add_object(render_scene *sc, const rn_object *o) { GROW(sc->obj, sc->nobj, o); return 1; }
int scene_add_material(render_scene *sc, const rn_material *m) { GROW(sc->mat, sc->nmat, m); return 1; }
int scene_add_texture(render_scene *sc, const rn_texture *t) { GROW(sc->tex, sc->ntex, t); return 1; }

void material_defaults(rn_material *m)
{
    m->texture = m->bump = m->normal_map = -1;
    m->bump_scale = 1.0;
    m->diffuse[0] = m->diffuse[1] = m->diffuse[2] = 1.0f;
    m->ambient = 0.1f;
    m->gloss = 0.0f;
    m->exponent = 60.0;
    m->reflect = 0.0f;
}

void object_defaults(rn_object *o, rn_kind kind)
{
    memset(o, 0, sizeof *o);
    o->kind = kind;
    o->st_scale[0] = o->st_scale[1] = 1.0;
    o->radius = 1.0;
    o->height = 1.0;
    v3_set(o->X, 1, 0, 0);
    v3_set(o->Y, 0, 1, 0);
    v3_set(o->Z, 0, 0, 1);
}

int scene_teapot_object(rn_object *o, double scale, const double offset[3])
{
    int p, i, j, k;
    o->kind = RN_PATCHES;
    o->count = TEAPOT_PATCHES;
    o->patches = calloc(TEAPOT_PATCHES, sizeof *o->patches);
    if (!o->patches) return 0;
    for (p = 0; p < TEAPOT_PATCHES; ++p) {
        for (i = 0; i < 4; ++i)
            for (j = 0; j < 4; ++j)
                for (k = 0; k < 3; ++k)
                    o->patches[p].cp[i][j][k] =
                        teapot_point[teapot_index[p][4 * i + j] - 1][k] * scale + offset[k];
        if (!patch_prepare(&o->patches[p])) return 0;
    }
    return 1;
}

int scene_finish(render_scene *sc, const render_parse_options *po, double texels_left, char *err,
                 size_t errlen)
{
    const char *base_dir = po->base_dir;
    int k;
    sc->cache_mb = po->cache_mb;
    for (k = 0; k < sc->ntex; ++k) {
        rn_texture *t = &sc->tex[k];
        double n = 0.0;
        if (t->kind != RN_TEX_IMAGE) {
            if (!proc_bake(t, err, errlen)) return 0;
            continue;
        }
        if (!image_load(t, sc, base_dir, texels_left, &n, err, errlen)) return 0;
        texels_left -= n;
    }
    if (sc->env_image.path[0]) {
        double n = 0.0;
        char inner[400];
        if (!env_image_load(&sc->env_image, &sc->env, sc, base_dir, texels_left, &n, err, errlen)) {
            snprintf(inner, sizeof inner, "%s", err ? err : "");
            rn_seterr(err, errlen, "environment: %s", inner);
            return 0;
        }
    }
    for (k = 0; k < sc->nobj; ++k)
        if (sc->obj[k].material < 0 || sc->obj[k].material >= sc->nmat) sc->obj[k].material = 0;
    return 1;
}

void render_scene_destroy(render_scene *sc)
{
    int k, p;
    if (!sc) return;
    for (k = 0; k < sc->nobj; ++k) {
        if (sc->obj[k].patches)
            for (p = 0; p < sc->obj[k].count; ++p) patch_release(&sc->obj[k].patches[p]);
        free(sc->obj[k].patches);
        free(sc->obj[k].polys);
    }
    for (k = 0; k < sc->ntex; ++k)
        if (!sc->tex[k].cached) sample_texture_destroy(sc->tex[k].tex);
    sample_texture_destroy(sc->env_image.tex);
    env_release(&sc->env);
    image_texsys_destroy(sc->texsys);
    free(sc->obj);
    free(sc->mat);
    free(sc->tex);
    free(sc);
}

int render_scene_load(const char *path, int width, int height, render_scene **out, char *err,
                      size_t errlen)
{
    return render_scene_load_ex(path, width, height, NULL, out, err, errlen);
}

int render_scene_load_ex(const char *path, int width, int height, const render_parse_options *pin,
                         render_scene **out, char *err, size_t errlen)
{
    const char *slash = strrchr(path, '/');
    char dir[4096], inner[512];
    render_parse_options po;
    char *buf;
    size_t n, got = 0;
    int r, fd;
    *out = NULL;
    if ((fd = rn_open_regular(path, "scene file", RENDER_MAX_SCENE_BYTES, &n, err, errlen)) < 0)
        return -1;
    /* One byte more than fstat said, to notice a file that grew since. */
    buf = malloc(n + 1);
    while (buf && got <= n) {
        ssize_t k = read(fd, buf + got, n + 1 - got);
        if (k <= 0) {
            if (k < 0 && errno == EINTR) continue;
            break;
        }
        got += (size_t)k;
    }
    close(fd);
    if (!buf || got != n) {
        free(buf);
        rn_seterr(err, errlen, "scene file '%s': %s", path,
                  !buf ? "out of memory" : "changed or unreadable while being read");
        return -1;
    }
    /* Image files are relative to the scene file's folder (as a scene
     * written next to its textures expects), not to the working directory. */
    if (pin) po = *pin;
    else render_parse_options_init(&po);
    po.base_dir = NULL;
    if (slash && (size_t)(slash - path) < sizeof dir) {
        size_t len = slash == path ? 1 : (size_t)(slash - path);
        memcpy(dir, path, len);
        dir[len] = '\0';
        po.base_dir = dir;
    }
    r = render_scene_parse_ex(buf, n, width, height, &po, out, err, errlen);
    free(buf);
    if (r != 0 && err && errlen) {
        snprintf(inner, sizeof inner, "%s", err);
        rn_seterr(err, errlen, "scene file '%s': %s", path, inner);
    }
    return r;
}

void render_scene_size(const render_scene *sc, int *width, int *height)
{
    *width = sc->cam.width;
    *height = sc->cam.height;
}

void render_scene_sampler(const render_scene *sc, sample_sampler *out) { *out = sc->sampler; }

int render_scene_material_texture(const render_scene *sc, int material)
{
    return material >= 0 && material < sc->nmat ? sc->mat[material].texture : -1;
}

int render_scene_texture_count(const render_scene *sc) { return sc->ntex; }

const sample_texture *render_scene_texture(const render_scene *sc, int texture)
{
    return texture >= 0 && texture < sc->ntex ? sc->tex[texture].tex : NULL;
}

int render_scene_texture_exact(const render_scene *sc, int texture, double s, double t,
                               const double P[3], float out[4])
{
    if (texture < 0 || texture >= sc->ntex || sc->tex[texture].kind == RN_TEX_IMAGE) return 0;
    proc_eval(&sc->tex[texture], s, t, P, out);
    return 1;
}

void render_scene_texture_truth(const render_scene *sc, int texture, double s, double t,
                                const double P[3], float out[4])
{
    sample_sampler smp;
    sample_query q = {(float)s, (float)t, 0, 0, 0, 0};
    if (render_scene_texture_exact(sc, texture, s, t, P, out)) return;
    out[0] = out[1] = out[2] = 0.0f;
    out[3] = 1.0f;
    if (texture < 0 || texture >= sc->ntex) return;
    sample_sampler_init(&smp);
    smp.wrap_s = sc->tex[texture].wrap_s;
    smp.wrap_t = sc->tex[texture].wrap_t;
    smp.min_filter = SAMPLE_LINEAR;
    smp.mag_filter = SAMPLE_LINEAR;
    sample_one(sc->tex[texture].tex, &smp, &q, out);
}

void render_options_init(render_options *o)
{
    memset(o, 0, sizeof *o);
    sample_sampler_init(&o->sampler);
    o->sampler.min_filter = SAMPLE_LINEAR_MIPMAP_LINEAR;
    o->use_scene_sampler = 1;
    o->threads = 1;
    o->shade = RENDER_SHADE_FULL;
    o->background[3] = 1.0f;
}
