/*
 * Scene files (JSON, via cJSON). The built-in scenes are JSON texts too
 * (scene.c), so this is the only scene builder. Every field is checked;
 * a bad file gives a message naming the field, never a crash.
 */
#include "rn_internal.h"

#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>

typedef struct jctx {
    render_scene *sc;
    char *err;
    size_t errlen;
    const cJSON *textures, *materials;
    render_parse_options po;
    double work, texels; /* spent so far of po.max_bake_work, po.max_texels */
    int teapots;
} jctx;

/* Charge a bake to the scene's budgets before it is made: 0 (error set)
 * if it would exceed them. Counted in double: 8192² · 16² overflows 32 bits. */
static int budget(jctx *c, const char *what, double texels, double work)
{
    if (c->texels + texels > c->po.max_texels || c->work + work > c->po.max_bake_work) {
        rn_seterr(c->err, c->errlen,
                  "%s: the scene's textures exceed the limits (%.0f texels, %.0f bake samples)",
                  what, c->po.max_texels, c->po.max_bake_work);
        return 0;
    }
    c->texels += texels;
    c->work += work;
    return 1;
}

/* Optional number: 1 if absent or valid, 0 (error set) if wrong. */
static int jnum(jctx *c, const cJSON *o, const char *key, double lo, double hi, double *out)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    if (!v) return 1;
    if (!cJSON_IsNumber(v) || !(v->valuedouble >= lo && v->valuedouble <= hi)) {
        rn_seterr(c->err, c->errlen, "'%s' must be a number in [%g, %g]", key, lo, hi);
        return 0;
    }
    *out = v->valuedouble;
    return 1;
}

static int jint(jctx *c, const cJSON *o, const char *key, int lo, int hi, int *out)
{
    double d = *out;
    if (!jnum(c, o, key, lo, hi, &d)) return 0;
    if (d != floor(d)) {
        rn_seterr(c->err, c->errlen, "'%s' must be an integer", key);
        return 0;
    }
    *out = (int)d;
    return 1;
}

/* Optional array of n finite numbers. */
static int jvec(jctx *c, const cJSON *o, const char *key, int n, double *out)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    int k;
    if (!v) return 1;
    if (!cJSON_IsArray(v) || cJSON_GetArraySize(v) != n) {
        rn_seterr(c->err, c->errlen, "'%s' must be an array of %d numbers", key, n);
        return 0;
    }
    for (k = 0; k < n; ++k) {
        const cJSON *e = cJSON_GetArrayItem(v, k);
        if (!cJSON_IsNumber(e) || !isfinite(e->valuedouble) || fabs(e->valuedouble) > 1e12) {
            rn_seterr(c->err, c->errlen, "'%s'[%d] must be a finite number", key, k);
            return 0;
        }
        out[k] = e->valuedouble;
    }
    return 1;
}

static int jcolor(jctx *c, const cJSON *o, const char *key, int n, float *out)
{
    double d[4];
    int k;
    for (k = 0; k < n; ++k) d[k] = out[k];
    if (!jvec(c, o, key, n, d)) return 0;
    for (k = 0; k < n; ++k) out[k] = (float)d[k];
    return 1;
}

static const char *jstr(const cJSON *o, const char *key)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    return cJSON_IsString(v) ? v->valuestring : NULL;
}

/* Index of the element of `list` whose "name" is name, or −1. */
static int find_named(const cJSON *list, const char *name)
{
    int k = 0;
    const cJSON *e;
    cJSON_ArrayForEach(e, list) {
        const char *n = jstr(e, "name");
        if (n && strcmp(n, name) == 0) return k;
        ++k;
    }
    return -1;
}

/* An optional reference by name; −1 if absent, −2 (error set) if unknown. */
static int jref(jctx *c, const cJSON *o, const char *key, const cJSON *list, const char *what)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, key);
    int k;
    if (!v) return -1;
    if (!cJSON_IsString(v) || (k = find_named(list, v->valuestring)) < 0) {
        rn_seterr(c->err, c->errlen, "'%s' names no %s", key, what);
        return -2;
    }
    return k;
}

static int parse_sampler(jctx *c, const cJSON *o)
{
    sample_sampler *s = &c->sc->sampler;
    static const struct { const char *key; int kind; } names[] = {
        {"wrap_s", 0}, {"wrap_t", 1}, {"min", 2}, {"mag", 3}, {"filter", 4}, {"cubic", 5}};
    double aniso = s->max_anisotropy, bias = s->lod_bias;
    size_t k;
    if (!o) return 1;
    for (k = 0; k < sizeof names / sizeof names[0]; ++k) {
        const char *v = jstr(o, names[k].key);
        int e;
        if (!v) continue;
        switch (names[k].kind) {
        case 0: case 1: e = sample_wrap_parse(v); break;
        case 2: case 3: e = sample_filter_parse(v); break;
        case 4: e = sample_footprint_parse(v); break;
        default: e = sample_cubic_parse(v); break;
        }
        if (e < 0) {
            rn_seterr(c->err, c->errlen, "sampler: unknown %s '%s'", names[k].key, v);
            return 0;
        }
        switch (names[k].kind) {
        case 0: s->wrap_s = (sample_wrap)e; break;
        case 1: s->wrap_t = (sample_wrap)e; break;
        case 2: s->min_filter = (sample_filter)e; break;
        case 3: s->mag_filter = (sample_filter)e; break;
        case 4: s->footprint = (sample_footprint)e; break;
        default: s->cubic = (sample_cubic)e; break;
        }
    }
    if (!jnum(c, o, "aniso", 1, 1024, &aniso) || !jnum(c, o, "lod_bias", -16, 16, &bias)) return 0;
    s->max_anisotropy = (float)aniso;
    s->lod_bias = (float)bias;
    if (sample_sampler_validate(s) != SAMPLE_OK) {
        rn_seterr(c->err, c->errlen, "sampler: invalid combination (e.g. a mipmap mag filter)");
        return 0;
    }
    return 1;
}

/* Optional wrap mode by name; 1 if absent or valid. */
static int jwrap(jctx *c, const cJSON *o, const char *key, sample_wrap *out)
{
    const char *v = jstr(o, key);
    int e;
    if (!cJSON_GetObjectItemCaseSensitive(o, key)) return 1;
    if (!v || (e = sample_wrap_parse(v)) < 0) {
        rn_seterr(c->err, c->errlen, "'%s' must name a wrap mode", key);
        return 0;
    }
    *out = (sample_wrap)e;
    return 1;
}

/* An image texture's own fields: file, colorspace, wrap modes (default: the
 * scene sampler's, so that the ground truth's bilinear lookup and the pyramid
 * treat the edges as the render does). */
static int parse_image_fields(jctx *c, const cJSON *o, rn_texture *t)
{
    const char *file = jstr(o, "file"), *cs = jstr(o, "colorspace");
    if (!c->po.images) {
        rn_seterr(c->err, c->errlen, "image textures are not allowed here");
        return 0;
    }
    if (!file || !file[0] || strlen(file) >= sizeof t->path) {
        rn_seterr(c->err, c->errlen, "image texture needs a 'file' (a path of at most %zu bytes)",
                  sizeof t->path - 1);
        return 0;
    }
    strcpy(t->path, file);
    if (cJSON_GetObjectItemCaseSensitive(o, "colorspace") &&
        (!cs || !cs[0] || strlen(cs) >= sizeof t->colorspace)) {
        rn_seterr(c->err, c->errlen, "'colorspace' must be an OCIO name of at most %zu bytes",
                  sizeof t->colorspace - 1);
        return 0;
    }
    if (cs) strcpy(t->colorspace, cs);
    t->wrap_s = c->sc->sampler.wrap_s;
    t->wrap_t = c->sc->sampler.wrap_t;
    return jwrap(c, o, "wrap_s", &t->wrap_s) && jwrap(c, o, "wrap_t", &t->wrap_t);
}

static int parse_texture(jctx *c, const cJSON *o)
{
    rn_texture t;
    const char *type = jstr(o, "type");
    double d;
    int k, kind = -1;
    for (k = 0; type && k < RN_TEX_KIND_COUNT; ++k)
        if (strcmp(type, rn_tex_kind_names[k]) == 0) kind = k;
    if (kind < 0) {
        rn_seterr(c->err, c->errlen, "texture type '%s' unknown", type ? type : "(missing)");
        return 0;
    }
    proc_defaults(&t, (rn_tex_kind)kind);
    if (kind == RN_TEX_IMAGE && !parse_image_fields(c, o, &t)) return 0;
    d = t.seed;
    if (!jnum(c, o, "freq", 1, 256, &t.freq) || !jnum(c, o, "width", 0, 1, &t.width) ||
        !jint(c, o, "octaves", 1, 12, &t.octaves) || !jnum(c, o, "amount", 0, 1e4, &t.amount) ||
        !jnum(c, o, "seed", 0, 4294967295.0, &d) || !jint(c, o, "size", 1, 8192, &t.bake_size) ||
        !jint(c, o, "samples", 1, 16, &t.bake_samples) ||
        !jint(c, o, "terms", 1, RN_FOURIER_MAX, &t.nfourier) || !jcolor(c, o, "a", 4, t.a) ||
        !jcolor(c, o, "b", 4, t.b))
        return 0;
    t.seed = (uint32_t)d;
    if (kind == RN_TEX_NOISE || kind == RN_TEX_TURBULENCE || kind == RN_TEX_MARBLE ||
        kind == RN_TEX_FOURIER)
        t.freq = floor(t.freq); /* integer periods: seamless tiling */
    if (kind != RN_TEX_IMAGE) {
        double n2 = (double)t.bake_size * t.bake_size, m2 = (double)t.bake_samples * t.bake_samples;
        if (!budget(c, "texture", n2, n2 * m2)) return 0;
    }
    return scene_add_texture(c->sc, &t) ? 1 : (rn_seterr(c->err, c->errlen, "out of memory"), 0);
}

static int parse_material(jctx *c, const cJSON *o)
{
    rn_material m;
    double d[3];
    float f;
    material_defaults(&m);
    d[0] = m.ambient; d[1] = m.gloss; d[2] = m.reflect;
    if ((m.texture = jref(c, o, "texture", c->textures, "texture")) == -2 ||
        (m.bump = jref(c, o, "bump", c->textures, "texture")) == -2 ||
        (m.normal_map = jref(c, o, "normal_map", c->textures, "texture")) == -2 ||
        !jcolor(c, o, "diffuse", 3, m.diffuse) || !jnum(c, o, "ambient", 0, 100, &d[0]) ||
        !jnum(c, o, "gloss", 0, 100, &d[1]) || !jnum(c, o, "reflect", 0, 100, &d[2]) ||
        !jnum(c, o, "exponent", 0, 1e4, &m.exponent) ||
        !jnum(c, o, "bump_scale", -1e3, 1e3, &m.bump_scale))
        return 0;
    f = (float)d[0]; m.ambient = f;
    m.gloss = (float)d[1];
    m.reflect = (float)d[2];
    return scene_add_material(c->sc, &m) ? 1 : (rn_seterr(c->err, c->errlen, "out of memory"), 0);
}

/* Orthonormal frame with Z along axis. */
static int axis_frame(rn_object *o, const double axis[3])
{
    static const double ey[3] = {0, 1, 0}, ex[3] = {1, 0, 0};
    v3_copy(o->Z, axis);
    if (!(v3_normalize(o->Z) > 0.0)) return 0;
    v3_cross(o->X, fabs(o->Z[1]) < 0.9 ? ey : ex, o->Z);
    v3_normalize(o->X);
    v3_cross(o->Y, o->Z, o->X);
    return 1;
}

static int parse_polygons(jctx *c, const cJSON *list, rn_object *o)
{
    const cJSON *p;
    int n = cJSON_GetArraySize(list), k = 0;
    if (!cJSON_IsArray(list) || n < 1 || n > RN_MAX_POLYGONS) {
        rn_seterr(c->err, c->errlen, "'polygons' must be an array of 1 to %d polygons",
                  RN_MAX_POLYGONS);
        return 0;
    }
    o->polys = calloc((size_t)n, sizeof *o->polys);
    if (!o->polys) return 0;
    o->count = n;
    cJSON_ArrayForEach(p, list) {
        const cJSON *V = cJSON_GetObjectItemCaseSensitive(p, "v");
        const cJSON *ST = cJSON_GetObjectItemCaseSensitive(p, "st");
        rn_poly *pg = &o->polys[k];
        int nv = cJSON_GetArraySize(V), i;
        if (!cJSON_IsArray(V) || (nv != 3 && nv != 4) || !cJSON_IsArray(ST) ||
            cJSON_GetArraySize(ST) != nv) {
            rn_seterr(c->err, c->errlen, "polygon %d: 'v' needs 3 or 4 points and 'st' as many", k);
            return 0;
        }
        pg->n = nv;
        for (i = 0; i < nv; ++i) {
            const cJSON *a = cJSON_GetArrayItem(V, i), *b = cJSON_GetArrayItem(ST, i);
            int j;
            if (cJSON_GetArraySize(a) != 3 || cJSON_GetArraySize(b) != 2) {
                rn_seterr(c->err, c->errlen, "polygon %d: bad vertex %d", k, i);
                return 0;
            }
            for (j = 0; j < 3; ++j) {
                const cJSON *e = cJSON_GetArrayItem(a, j);
                if (!cJSON_IsNumber(e) || !isfinite(e->valuedouble)) {
                    rn_seterr(c->err, c->errlen, "polygon %d: bad vertex %d", k, i);
                    return 0;
                }
                pg->V[i][j] = e->valuedouble;
            }
            for (j = 0; j < 2; ++j) {
                const cJSON *e = cJSON_GetArrayItem(b, j);
                if (!cJSON_IsNumber(e) || !isfinite(e->valuedouble)) {
                    rn_seterr(c->err, c->errlen, "polygon %d: bad st %d", k, i);
                    return 0;
                }
                pg->st[i][j] = e->valuedouble;
            }
        }
        if (!poly_prepare(pg)) {
            rn_seterr(c->err, c->errlen, "polygon %d is degenerate (collinear points or st)", k);
            return 0;
        }
        ++k;
    }
    return 1;
}

static int parse_object(jctx *c, const cJSON *j)
{
    rn_object o;
    const char *type = jstr(j, "type");
    double axis[3] = {0, 0, 1}, scale = 1.0, offset[3] = {0, 0, 0};
    int ok = 1;
    static const char *const kinds[] = {"teapot", "polygons", "sphere", "cylinder", "plane"};
    int kind = -1, k;
    for (k = 0; type && k < 5; ++k)
        if (strcmp(type, kinds[k]) == 0) kind = k;
    if (kind < 0) {
        rn_seterr(c->err, c->errlen, "object type '%s' unknown", type ? type : "(missing)");
        return 0;
    }
    object_defaults(&o, (rn_kind)kind);
    o.material = jref(c, j, "material", c->materials, "material");
    if (o.material == -2) return 0;
    if (o.material == -1) o.material = 0;
    if (!jvec(c, j, "st_scale", 2, o.st_scale) || !jvec(c, j, "st_offset", 2, o.st_offset) ||
        !jvec(c, j, "centre", 3, o.centre) || !jvec(c, j, "axis", 3, axis) ||
        !jnum(c, j, "radius", 1e-9, 1e9, &o.radius) || !jnum(c, j, "height", 1e-9, 1e9, &o.height) ||
        !jnum(c, j, "size", 1e-9, 1e9, &o.radius) || !jnum(c, j, "scale", 1e-9, 1e9, &scale) ||
        !jvec(c, j, "offset", 3, offset))
        return 0;
    if (o.st_scale[0] == 0.0 || o.st_scale[1] == 0.0) {
        rn_seterr(c->err, c->errlen, "'st_scale' must not be zero");
        return 0;
    }
    if (!axis_frame(&o, axis)) {
        rn_seterr(c->err, c->errlen, "'axis' must not be zero");
        return 0;
    }
    if (kind == RN_PATCHES && ++c->teapots > RN_MAX_TEAPOTS) {
        rn_seterr(c->err, c->errlen, "at most %d teapots (%d patches each)", RN_MAX_TEAPOTS,
                  TEAPOT_PATCHES);
        return 0;
    }
    if (kind == RN_PATCHES) ok = scene_teapot_object(&o, scale, offset);
    else if (kind == RN_POLYGONS)
        ok = parse_polygons(c, cJSON_GetObjectItemCaseSensitive(j, "polygons"), &o);
    if (!ok) {
        if (!c->err || !c->err[0]) rn_seterr(c->err, c->errlen, "out of memory");
        free(o.polys);
        if (o.patches)
            for (k = 0; k < o.count; ++k) patch_release(&o.patches[k]);
        free(o.patches);
        return 0;
    }
    if (!scene_add_object(c->sc, &o)) {
        rn_seterr(c->err, c->errlen, "out of memory");
        return 0;
    }
    return 1;
}

typedef int (*jlist_fn)(jctx *c, const cJSON *o);

/* A list of at most max elements, each parsed by fn. The caps keep the
 * scene's memory and the per-sample search cost (linear in objects, and
 * in polygons) bounded whatever the file says. */
static int parse_list(jctx *c, const cJSON *root, const char *key, jlist_fn fn, int required,
                      int max)
{
    const cJSON *list = cJSON_GetObjectItemCaseSensitive(root, key), *e;
    int k = 0;
    if (!list) {
        if (required) rn_seterr(c->err, c->errlen, "'%s' is missing", key);
        return !required;
    }
    if (!cJSON_IsArray(list) || cJSON_GetArraySize(list) > max) {
        rn_seterr(c->err, c->errlen, "'%s' must be an array of at most %d", key, max);
        return 0;
    }
    cJSON_ArrayForEach(e, list) {
        if (!cJSON_IsObject(e) || !fn(c, e)) {
            char inner[200];
            snprintf(inner, sizeof inner, "%s", c->err && c->err[0] ? c->err : "must be an object");
            rn_seterr(c->err, c->errlen, "%s[%d]: %s", key, k, inner);
            return 0;
        }
        ++k;
    }
    return 1;
}

static int parse_light(jctx *c, const cJSON *o)
{
    rn_light *L;
    double d[3] = {0, 0, 1};
    if (c->sc->nlight >= RN_MAX_LIGHTS) {
        rn_seterr(c->err, c->errlen, "at most %d lights", RN_MAX_LIGHTS);
        return 0;
    }
    L = &c->sc->light[c->sc->nlight];
    L->color[0] = L->color[1] = L->color[2] = 1.0f;
    if (!jvec(c, o, "dir", 3, d) || !jcolor(c, o, "color", 3, L->color)) return 0;
    if (!(v3_normalize(d) > 0.0)) {
        rn_seterr(c->err, c->errlen, "'dir' must not be zero");
        return 0;
    }
    v3_copy(L->dir, d);
    c->sc->nlight++;
    return 1;
}

static int parse_env(jctx *c, const cJSON *o)
{
    rn_env *e = &c->sc->env;
    const char *type = jstr(o, "type");
    int size = 512;
    double strength = 1.0;
    rn_env_kind kind;
    if (!type || strcmp(type, "latlong") == 0) kind = RN_ENV_LATLONG;
    else if (strcmp(type, "cube") == 0) kind = RN_ENV_CUBE;
    else {
        rn_seterr(c->err, c->errlen, "environment type must be latlong or cube");
        return 0;
    }
    if (kind == RN_ENV_CUBE) size = 128;
    if (!jint(c, o, "size", 2, 8192, &size) || !jnum(c, o, "radius", 0, 1e9, &e->radius) ||
        !jvec(c, o, "centre", 3, e->centre) || !jnum(c, o, "strength", 0, 1e6, &strength))
        return 0;
    {
        /* Lat-long is size × size/2, a cube six size²; 2 × 2 samples each. */
        double n = kind == RN_ENV_LATLONG ? (double)size * (size / 2) : 6.0 * size * size;
        if (!budget(c, "environment", n, 4.0 * n)) return 0;
    }
    e->strength = (float)strength;
    return env_build_sky(e, kind, size, c->err, c->errlen);
}

static int parse_root(jctx *c, const cJSON *root, int width, int height)
{
    const cJSON *cam = cJSON_GetObjectItemCaseSensitive(root, "camera");
    const cJSON *env = cJSON_GetObjectItemCaseSensitive(root, "environment");
    double eye[3] = {0, -5, 2}, look[3] = {0, 0, 0}, up[3] = {0, 0, 1}, fov = 45.0;
    int w = 512, h = 512;
    if (!cJSON_IsObject(root)) {
        rn_seterr(c->err, c->errlen, "the scene must be a JSON object");
        return 0;
    }
    if (!jint(c, root, "width", 1, 16384, &w) || !jint(c, root, "height", 1, 16384, &h) ||
        !jcolor(c, root, "background", 4, c->sc->background))
        return 0;
    if (width > 0) w = width;
    if (height > 0) h = height;
    if (cam && (!jvec(c, cam, "eye", 3, eye) || !jvec(c, cam, "look", 3, look) ||
                !jvec(c, cam, "up", 3, up) || !jnum(c, cam, "fov", 1e-3, 179, &fov)))
        return 0;
    if (!cam_init(&c->sc->cam, eye, look, up, fov, w, h)) {
        rn_seterr(c->err, c->errlen, "camera: eye equals look, or up is parallel to the view");
        return 0;
    }
    c->textures = cJSON_GetObjectItemCaseSensitive(root, "textures");
    c->materials = cJSON_GetObjectItemCaseSensitive(root, "materials");
    if (!parse_sampler(c, cJSON_GetObjectItemCaseSensitive(root, "sampler")) ||
        !parse_list(c, root, "textures", parse_texture, 0, RN_MAX_TEXTURES) ||
        !parse_list(c, root, "materials", parse_material, 0, RN_MAX_MATERIALS) ||
        !parse_list(c, root, "lights", parse_light, 0, RN_MAX_LIGHTS) ||
        !parse_list(c, root, "objects", parse_object, 1, RN_MAX_OBJECTS))
        return 0;
    if (c->sc->nmat == 0) {
        rn_material m;
        material_defaults(&m);
        if (!scene_add_material(c->sc, &m)) return 0;
    }
    if (env && (!cJSON_IsObject(env) || !parse_env(c, env))) {
        if (!c->err || !c->err[0]) rn_seterr(c->err, c->errlen, "bad 'environment'");
        return 0;
    }
    return scene_finish(c->sc, c->po.base_dir, c->po.max_texels - c->texels, c->err, c->errlen);
}

void render_parse_options_init(render_parse_options *po)
{
    memset(po, 0, sizeof *po);
    po->images = 1;
    po->max_bake_work = RENDER_MAX_BAKE_WORK;
    po->max_texels = RENDER_MAX_TEXELS;
}

int render_scene_parse_ex(const char *json, size_t len, int width, int height,
                          const render_parse_options *po, render_scene **out, char *err,
                          size_t errlen)
{
    cJSON *root;
    const char *end = NULL;
    jctx c;
    *out = NULL;
    if (err && errlen) err[0] = '\0';
    /* The end pointer, not cJSON_GetErrorPtr(): that one is a global, which
     * another thread's parse may overwrite (and then points into its text). */
    root = cJSON_ParseWithLengthOpts(json, len, &end, 0);
    if (!root) {
        rn_seterr(err, errlen, "not valid JSON (near byte %ld)",
                  end && end >= json && end <= json + len ? (long)(end - json) : -1L);
        return -1;
    }
    memset(&c, 0, sizeof c);
    if (po) c.po = *po;
    else render_parse_options_init(&c.po);
    c.sc = scene_new();
    c.err = err;
    c.errlen = errlen;
    if (!c.sc) {
        cJSON_Delete(root);
        rn_seterr(err, errlen, "out of memory");
        return -1;
    }
    if (!parse_root(&c, root, width, height)) {
        cJSON_Delete(root);
        render_scene_destroy(c.sc);
        return -1;
    }
    cJSON_Delete(root);
    *out = c.sc;
    return 0;
}

int render_scene_parse(const char *json, size_t len, int width, int height, render_scene **out,
                       char *err, size_t errlen)
{
    return render_scene_parse_ex(json, len, width, height, NULL, out, err, errlen);
}
