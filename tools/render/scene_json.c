/*
 * Scene files (JSON, read by json.c). The built-in scenes are JSON texts too
 * (scene.c), so this is the only scene builder. Every member is checked:
 * an unknown or repeated key, a value of the wrong type or out of range, a
 * repeated name, or text after the scene is an error whose message names
 * the member, its line and column, and for an unknown key the closest valid
 * one (doc/renderer.md, "Scene file").
 */
#include "rn_internal.h"
#include "rn_json.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

typedef struct jctx {
    const rn_json *j;
    render_scene *sc;
    char *err;
    size_t errlen;
    uint32_t at; /* the node an error is about (RN_JNONE: none yet) */
    uint32_t textures, materials; /* the lists, RN_JNONE if absent */
    render_parse_options po;
    double work, texels; /* spent so far of po.max_bake_work, po.max_texels */
    int teapots;
} jctx;

/* Record an error about node n (its line and column are added at the end). */
static int jfail(jctx *c, uint32_t n, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
static int jfail(jctx *c, uint32_t n, const char *fmt, ...)
{
    va_list ap;
    if (c->at == RN_JNONE) c->at = n;
    if (c->err && c->errlen) {
        va_start(ap, fmt);
        vsnprintf(c->err, c->errlen, fmt, ap);
        va_end(ap);
    }
    return 0;
}

/* ---- Keys --------------------------------------------------------------- */

/* Optimal-string-alignment distance (Levenshtein plus adjacent
 * transpositions, Damerau 1964): "texure" → "texture" is 1, "reflekt" →
 * "reflect" 1, "colour" → "color" 1. b is a known key (short); a may be long. */
static size_t edit_distance(const char *a, const char *b)
{
    size_t nb = strlen(b), i, k, rows[3][40], *pp, *p, *cur;
    if (nb >= 40) return (size_t)-1;
    pp = rows[0];
    p = rows[1];
    cur = rows[2];
    for (k = 0; k <= nb; ++k) p[k] = k;
    for (i = 1; a[i - 1]; ++i) {
        cur[0] = i;
        for (k = 1; k <= nb; ++k) {
            size_t sub = p[k - 1] + (a[i - 1] != b[k - 1]), v = sub;
            if (p[k] + 1 < v) v = p[k] + 1;
            if (cur[k - 1] + 1 < v) v = cur[k - 1] + 1;
            if (i > 1 && k > 1 && a[i - 1] == b[k - 2] && a[i - 2] == b[k - 1] && pp[k - 2] + 1 < v)
                v = pp[k - 2] + 1;
            cur[k] = v;
        }
        {
            size_t *t = pp;
            pp = p;
            p = cur;
            cur = t;
        }
    }
    return p[nb];
}

static int in_list(const char *const *list, const char *key)
{
    for (; list && *list; ++list)
        if (strcmp(*list, key) == 0) return 1;
    return 0;
}

/* Check the members of object o: each key in `keys`, none twice. A key of
 * `others` (valid for another kind of the same thing) is refused as not
 * applying to `what`; any other unknown key is named with the closest valid
 * one. The duplicate scan stops at the first repeat, so it costs at most
 * |keys|² comparisons whatever the object holds. */
static int jkeys(jctx *c, uint32_t o, const char *const *keys, const char *const *others,
                 const char *what)
{
    uint32_t e, f;
    for (e = rn_json_first(c->j, o); e != RN_JNONE; e = rn_json_next(c->j, o, e)) {
        const char *key = rn_json_key(c->j, e);
        if (!in_list(keys, key)) {
            const char *const *k, *best = keys[0];
            size_t bd = (size_t)-1;
            if (in_list(others, key))
                return jfail(c, e, "'%.40s' does not apply to %s", key, what);
            for (k = keys; *k; ++k) {
                size_t d = edit_distance(key, *k);
                if (d < bd) {
                    bd = d;
                    best = *k;
                }
            }
            return jfail(c, e, "unknown key '%.40s' (did you mean '%s'?)", key, best);
        }
        for (f = rn_json_first(c->j, o); f != e; f = rn_json_next(c->j, o, f))
            if (strcmp(rn_json_key(c->j, f), key) == 0) {
                int line, col;
                rn_json_where(c->j, f, &line, &col);
                return jfail(c, e, "duplicate key '%s' (first at line %d, column %d)", key, line,
                             col);
            }
    }
    return 1;
}

/* ---- Values ------------------------------------------------------------- */

/* Charge a bake to the scene's budgets before it is made: 0 (error set)
 * if it would exceed them. Counted in double: 8192² · 16² overflows 32 bits. */
static int budget(jctx *c, uint32_t n, const char *what, double texels, double work)
{
    if (c->texels + texels > c->po.max_texels || c->work + work > c->po.max_bake_work)
        return jfail(c, n, "%s: the scene's textures exceed the limits (%.0f texels, %.0f bake samples)",
                     what, c->po.max_texels, c->po.max_bake_work);
    c->texels += texels;
    c->work += work;
    return 1;
}

/* Optional number: 1 if absent or valid, 0 (error set) if wrong. */
static int jnum(jctx *c, uint32_t o, const char *key, double lo, double hi, double *out)
{
    uint32_t v = rn_json_get(c->j, o, key);
    double d;
    if (v == RN_JNONE) return 1;
    d = rn_json_number(c->j, v);
    if (rn_json_type(c->j, v) != RN_JNUMBER || !(d >= lo && d <= hi))
        return jfail(c, v, "'%s' must be a number in [%g, %g]", key, lo, hi);
    *out = d;
    return 1;
}

static int jint(jctx *c, uint32_t o, const char *key, int lo, int hi, int *out)
{
    double d = *out;
    if (!jnum(c, o, key, lo, hi, &d)) return 0;
    if (d != floor(d)) return jfail(c, rn_json_get(c->j, o, key), "'%s' must be an integer", key);
    *out = (int)d;
    return 1;
}

/* Array a of n finite numbers (|x| ≤ 1e12) into out; what names it. */
static int jnumbers(jctx *c, uint32_t a, const char *what, int n, double *out)
{
    uint32_t e;
    int k = 0;
    if (rn_json_type(c->j, a) != RN_JARRAY || rn_json_size(c->j, a) != (uint32_t)n)
        return jfail(c, a, "'%s' must be an array of %d numbers", what, n);
    for (e = rn_json_first(c->j, a); e != RN_JNONE; e = rn_json_next(c->j, a, e), ++k) {
        double d = rn_json_number(c->j, e);
        if (rn_json_type(c->j, e) != RN_JNUMBER || !(fabs(d) <= 1e12))
            return jfail(c, e, "'%s'[%d] must be a finite number", what, k);
        out[k] = d;
    }
    return 1;
}

/* Optional array of n finite numbers. */
static int jvec(jctx *c, uint32_t o, const char *key, int n, double *out)
{
    uint32_t v = rn_json_get(c->j, o, key);
    return v == RN_JNONE || jnumbers(c, v, key, n, out);
}

static int jcolor(jctx *c, uint32_t o, const char *key, int n, float *out)
{
    double d[4];
    int k;
    for (k = 0; k < n; ++k) d[k] = out[k];
    if (!jvec(c, o, key, n, d)) return 0;
    for (k = 0; k < n; ++k) out[k] = (float)d[k];
    return 1;
}

/* Optional string: 1 with *out NULL if absent, 0 (error set) if not a string. */
static int jstr(jctx *c, uint32_t o, const char *key, const char **out)
{
    uint32_t v = rn_json_get(c->j, o, key);
    *out = NULL;
    if (v == RN_JNONE) return 1;
    if (!(*out = rn_json_string(c->j, v))) return jfail(c, v, "'%s' must be a string", key);
    return 1;
}

/* Optional object member: *out RN_JNONE if absent. */
static int jobj(jctx *c, uint32_t o, const char *key, uint32_t *out)
{
    *out = rn_json_get(c->j, o, key);
    if (*out != RN_JNONE && rn_json_type(c->j, *out) != RN_JOBJECT)
        return jfail(c, *out, "'%s' must be an object", key);
    return 1;
}

/* The "name" of list element e, NULL if it has none (checked by jname). */
static const char *name_of(const rn_json *j, uint32_t e)
{
    return rn_json_string(j, rn_json_get(j, e, "name"));
}

/* Index of the element of `list` whose "name" is name, or −1. */
static int find_named(const rn_json *j, uint32_t list, const char *name)
{
    uint32_t e;
    int k = 0;
    if (list == RN_JNONE) return -1;
    for (e = rn_json_first(j, list); e != RN_JNONE; e = rn_json_next(j, list, e), ++k) {
        const char *n = name_of(j, e);
        if (n && strcmp(n, name) == 0) return k;
    }
    return -1;
}

/* Element e's optional "name": a non-empty string that no earlier element
 * of list has (references by name must be unambiguous). */
static int jname(jctx *c, uint32_t list, uint32_t e, const char *what)
{
    const char *name;
    uint32_t f;
    int k = 0;
    if (!jstr(c, e, "name", &name)) return 0;
    if (!name) return 1;
    if (!name[0]) return jfail(c, rn_json_get(c->j, e, "name"), "'name' must not be empty");
    for (f = rn_json_first(c->j, list); f != e; f = rn_json_next(c->j, list, f), ++k) {
        const char *n = name_of(c->j, f);
        if (n && strcmp(n, name) == 0)
            return jfail(c, rn_json_get(c->j, e, "name"), "%s name '%.40s' is already used by %s[%d]",
                         what, name, what, k);
    }
    return 1;
}

/* An optional reference by name; −1 if absent, −2 (error set) if unknown. */
static int jref(jctx *c, uint32_t o, const char *key, uint32_t list, const char *what)
{
    uint32_t v = rn_json_get(c->j, o, key);
    const char *name = rn_json_string(c->j, v);
    int k;
    if (v == RN_JNONE) return -1;
    if (!name || (k = find_named(c->j, list, name)) < 0) {
        jfail(c, v, "'%s' names no %s", key, what);
        return -2;
    }
    return k;
}

/* ---- Scene parts ---------------------------------------------------------- */

static int parse_camera(jctx *c, uint32_t cam, int w, int h)
{
    static const char *const keys[] = {"eye", "look", "up", "fov", NULL};
    double eye[3] = {0, -5, 2}, look[3] = {0, 0, 0}, up[3] = {0, 0, 1}, fov = 45.0;
    if (cam != RN_JNONE &&
        (!jkeys(c, cam, keys, NULL, "the camera") || !jvec(c, cam, "eye", 3, eye) ||
         !jvec(c, cam, "look", 3, look) || !jvec(c, cam, "up", 3, up) ||
         !jnum(c, cam, "fov", 1e-3, 179, &fov)))
        return 0;
    if (!cam_init(&c->sc->cam, eye, look, up, fov, w, h))
        return jfail(c, cam, "camera: eye equals look, or up is parallel to the view");
    return 1;
}

static int parse_sampler(jctx *c, uint32_t o)
{
    static const char *const keys[] = {"wrap_s", "wrap_t", "min",    "mag",      "filter",
                                       "cubic",  "aniso",  "lod_bias", NULL};
    sample_sampler *s = &c->sc->sampler;
    double aniso = s->max_anisotropy, bias = s->lod_bias;
    size_t k;
    if (o == RN_JNONE) return 1;
    if (!jkeys(c, o, keys, NULL, "the sampler")) return 0;
    for (k = 0; k < 6; ++k) {
        const char *v;
        int e;
        if (!jstr(c, o, keys[k], &v)) return 0;
        if (!v) continue;
        switch (k) {
        case 0: case 1: e = sample_wrap_parse(v); break;
        case 2: case 3: e = sample_filter_parse(v); break;
        case 4: e = sample_footprint_parse(v); break;
        default: e = sample_cubic_parse(v); break;
        }
        if (e < 0)
            return jfail(c, rn_json_get(c->j, o, keys[k]), "sampler: unknown %s '%.40s'", keys[k], v);
        switch (k) {
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
    if (sample_sampler_validate(s) != SAMPLE_OK)
        return jfail(c, o, "sampler: invalid combination (e.g. a mipmap mag filter)");
    return 1;
}

/* Optional wrap mode by name; 1 if absent or valid. */
static int jwrap(jctx *c, uint32_t o, const char *key, sample_wrap *out)
{
    const char *v;
    int e;
    if (!jstr(c, o, key, &v)) return 0;
    if (!v) return 1;
    if ((e = sample_wrap_parse(v)) < 0)
        return jfail(c, rn_json_get(c->j, o, key), "'%s' must name a wrap mode", key);
    *out = (sample_wrap)e;
    return 1;
}

/* An image file's "file" and "colorspace" (image textures, environments). */
static int jfile(jctx *c, uint32_t o, rn_texture *t)
{
    const char *file, *cs;
    if (!c->po.images) return jfail(c, o, "image files are not allowed here");
    if (!jstr(c, o, "file", &file) || !jstr(c, o, "colorspace", &cs)) return 0;
    if (!file || !file[0] || strlen(file) >= sizeof t->path)
        return jfail(c, o, "an image needs a 'file' (a path of at most %zu bytes)",
                     sizeof t->path - 1);
    strcpy(t->path, file);
    if (cs && (!cs[0] || strlen(cs) >= sizeof t->colorspace))
        return jfail(c, rn_json_get(c->j, o, "colorspace"),
                     "'colorspace' must be an OCIO name of at most %zu bytes",
                     sizeof t->colorspace - 1);
    if (cs) strcpy(t->colorspace, cs);
    return 1;
}

static const char *const image_keys[] = {"name", "type", "file", "colorspace", "wrap_s", "wrap_t",
                                         NULL};
static const char *const proc_keys[] = {"name",    "type", "freq",  "width", "octaves",
                                        "amount",  "seed", "size",  "samples", "terms",
                                        "a",       "b",    "solid", NULL};

/* A procedural texture's "solid" block (doc/volumes.md, "Renderer"): the
 * pattern as a function of the surface point, baked into a 3D texture over
 * the box [min, max] of world space, size³ texels of samples³ box samples
 * each, its pyramid built by "mip", read with "wrap" on all three axes. */
static int parse_solid(jctx *c, uint32_t tex, rn_texture *t)
{
    static const char *const keys[] = {"min", "max", "size", "samples", "mip", "wrap", NULL};
    uint32_t o;
    rn_solid *so = &t->solid;
    const char *mip;
    double n, cost;
    int k, size = 64, e;
    if (!jobj(c, tex, "solid", &o)) return 0;
    if (t->kind != RN_TEX_CHECKER && t->kind != RN_TEX_NOISE && t->kind != RN_TEX_TURBULENCE &&
        t->kind != RN_TEX_MARBLE && t->kind != RN_TEX_SOLID)
        return jfail(c, o, "'solid' applies to checker, noise, turbulence, marble and wood textures");
    if (rn_json_get(c->j, tex, "size") != RN_JNONE || rn_json_get(c->j, tex, "samples") != RN_JNONE)
        return jfail(c, o, "a solid texture's bake is given in 'solid' ('size', 'samples')");
    solid_defaults(so);
    so->on = 1;
    if (!jkeys(c, o, keys, NULL, "'solid'") || !jvec(c, o, "min", 3, so->lo) ||
        !jvec(c, o, "max", 3, so->hi) || !jint(c, o, "size", 1, 512, &size) ||
        !jint(c, o, "samples", 1, 8, &so->samples) || !jstr(c, o, "mip", &mip) ||
        !jwrap(c, o, "wrap", &so->wrap))
        return 0;
    for (k = 0; k < 3; ++k) {
        if (!(so->hi[k] > so->lo[k]))
            return jfail(c, o, "'solid': 'max' must exceed 'min' on every axis");
        so->size[k] = size;
    }
    if (mip) {
        if ((e = sample_mipgen_parse(mip)) < 0)
            return jfail(c, rn_json_get(c->j, o, "mip"), "'mip' must name a mip filter (box, ...)");
        so->mip = (sample_mipgen)e;
    }
    /* Noise evaluations per sample: one, or one per octave of turbulence. */
    cost = t->kind == RN_TEX_TURBULENCE || t->kind == RN_TEX_MARBLE ? t->octaves : 1;
    n = (double)size * size * size;
    if (!budget(c, o, "solid texture", n, n * so->samples * so->samples * so->samples * cost))
        return 0;
    return scene_add_texture(c->sc, t) ? 1 : jfail(c, tex, "out of memory");
}

static int parse_texture(jctx *c, uint32_t o)
{
    rn_texture t;
    const char *type;
    double d;
    int k, kind = -1;
    if (!jstr(c, o, "type", &type)) return 0;
    for (k = 0; type && k < RN_TEX_KIND_COUNT; ++k)
        if (strcmp(type, rn_tex_kind_names[k]) == 0) kind = k;
    if (type && strcmp(type, "wood") == 0) kind = RN_TEX_SOLID; /* the solid kind's own name */
    if (kind < 0)
        return jfail(c, type ? rn_json_get(c->j, o, "type") : o, "texture type '%.40s' unknown",
                     type ? type : "(missing)");
    if (!jname(c, c->textures, o, "textures")) return 0;
    proc_defaults(&t, (rn_tex_kind)kind);
    if (kind == RN_TEX_IMAGE) {
        /* Wrap modes default to the scene sampler's, so that the ground
         * truth's bilinear lookup and the pyramid treat the edges as the
         * render does. */
        t.wrap_s = c->sc->sampler.wrap_s;
        t.wrap_t = c->sc->sampler.wrap_t;
        if (!jkeys(c, o, image_keys, proc_keys, "image textures") || !jfile(c, o, &t) ||
            !jwrap(c, o, "wrap_s", &t.wrap_s) || !jwrap(c, o, "wrap_t", &t.wrap_t))
            return 0;
        return scene_add_texture(c->sc, &t) ? 1 : jfail(c, o, "out of memory");
    }
    if (!jkeys(c, o, proc_keys, image_keys, "procedural textures")) return 0;
    d = t.seed;
    if (!jnum(c, o, "freq", 1, 256, &t.freq) || !jnum(c, o, "width", 0, 1, &t.width) ||
        !jint(c, o, "octaves", 1, 12, &t.octaves) || !jnum(c, o, "amount", 0, 1e4, &t.amount) ||
        !jnum(c, o, "seed", 0, 4294967295.0, &d) || !jint(c, o, "size", 1, 8192, &t.bake_size) ||
        !jint(c, o, "samples", 1, 16, &t.bake_samples) ||
        !jint(c, o, "terms", 1, RN_FOURIER_MAX, &t.nfourier) || !jcolor(c, o, "a", 4, t.a) ||
        !jcolor(c, o, "b", 4, t.b))
        return 0;
    t.seed = (uint32_t)d;
    if (rn_json_get(c->j, o, "solid") != RN_JNONE) return parse_solid(c, o, &t);
    if (kind == RN_TEX_NOISE || kind == RN_TEX_TURBULENCE || kind == RN_TEX_MARBLE ||
        kind == RN_TEX_FOURIER)
        t.freq = floor(t.freq); /* integer periods: seamless tiling */
    {
        /* A Fourier texture's sample sums `terms` cosines (proc.c). */
        double n2 = (double)t.bake_size * t.bake_size, m2 = (double)t.bake_samples * t.bake_samples;
        double cost = kind == RN_TEX_FOURIER ? (t.nfourier > 0 ? t.nfourier : 24) : 1;
        if (!budget(c, o, "texture", n2, n2 * m2 * cost)) return 0;
    }
    return scene_add_texture(c->sc, &t) ? 1 : jfail(c, o, "out of memory");
}

/* Texture reference `key` of a material, marking how the texture is used:
 * image textures are decoded by that use (colour: by file and rule; data:
 * raw), so one texture cannot serve both unless its colour space is given. */
static int jtexref(jctx *c, uint32_t o, const char *key, unsigned use, int *out)
{
    rn_texture *t;
    if ((*out = jref(c, o, key, c->textures, "texture")) == -2) return 0;
    if (*out < 0) return 1;
    t = &c->sc->tex[*out];
    t->use |= use;
    if (t->solid.on && use == RN_USE_DATA)
        return jfail(c, rn_json_get(c->j, o, key),
                     "a solid texture is a colour texture, not a bump or normal map");
    if (t->kind == RN_TEX_IMAGE && !t->colorspace[0] && t->use == (RN_USE_COLOUR | RN_USE_DATA))
        return jfail(c, rn_json_get(c->j, o, key),
                     "image texture '%.40s' is used as colour and as data (bump, normal_map): "
                     "give it a 'colorspace' or use two textures",
                     t->path);
    return 1;
}

static int parse_material(jctx *c, uint32_t o)
{
    static const char *const keys[] = {"name",  "texture", "bump",     "normal_map", "bump_scale",
                                       "diffuse", "ambient", "gloss", "exponent",   "reflect",
                                       NULL};
    rn_material m;
    double d[3];
    material_defaults(&m);
    d[0] = m.ambient;
    d[1] = m.gloss;
    d[2] = m.reflect;
    if (!jkeys(c, o, keys, NULL, "materials") || !jname(c, c->materials, o, "materials") ||
        !jtexref(c, o, "texture", RN_USE_COLOUR, &m.texture) ||
        !jtexref(c, o, "bump", RN_USE_DATA, &m.bump) ||
        !jtexref(c, o, "normal_map", RN_USE_DATA, &m.normal_map) ||
        !jcolor(c, o, "diffuse", 3, m.diffuse) || !jnum(c, o, "ambient", 0, 100, &d[0]) ||
        !jnum(c, o, "gloss", 0, 100, &d[1]) || !jnum(c, o, "reflect", 0, 100, &d[2]) ||
        !jnum(c, o, "exponent", 0, 1e4, &m.exponent) ||
        !jnum(c, o, "bump_scale", -1e3, 1e3, &m.bump_scale))
        return 0;
    m.ambient = (float)d[0];
    m.gloss = (float)d[1];
    m.reflect = (float)d[2];
    return scene_add_material(c->sc, &m) ? 1 : jfail(c, o, "out of memory");
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

static int parse_polygon(jctx *c, uint32_t p, rn_poly *pg)
{
    static const char *const keys[] = {"v", "st", NULL};
    uint32_t V = rn_json_get(c->j, p, "v"), ST = rn_json_get(c->j, p, "st"), a, b;
    int nv = (int)rn_json_size(c->j, V), i;
    if (!jkeys(c, p, keys, NULL, "polygons")) return 0;
    if (rn_json_type(c->j, p) != RN_JOBJECT || V == RN_JNONE ||
        rn_json_type(c->j, V) != RN_JARRAY || (nv != 3 && nv != 4) || ST == RN_JNONE ||
        rn_json_type(c->j, ST) != RN_JARRAY || rn_json_size(c->j, ST) != (uint32_t)nv)
        return jfail(c, p, "'v' needs 3 or 4 points and 'st' as many");
    pg->n = nv;
    a = rn_json_first(c->j, V);
    b = rn_json_first(c->j, ST);
    for (i = 0; i < nv; ++i) {
        if (!jnumbers(c, a, "v", 3, pg->V[i]) || !jnumbers(c, b, "st", 2, pg->st[i])) return 0;
        a = rn_json_next(c->j, V, a);
        b = rn_json_next(c->j, ST, b);
    }
    if (!poly_prepare(pg)) return jfail(c, p, "degenerate (collinear points or st)");
    return 1;
}

static int parse_polygons(jctx *c, uint32_t j, rn_object *o)
{
    uint32_t list = rn_json_get(c->j, j, "polygons"), p;
    uint32_t n = rn_json_size(c->j, list);
    int k = 0;
    if (list == RN_JNONE || rn_json_type(c->j, list) != RN_JARRAY || n < 1 || n > RN_MAX_POLYGONS)
        return jfail(c, list == RN_JNONE ? j : list,
                     "'polygons' must be an array of 1 to %d polygons", RN_MAX_POLYGONS);
    if (!(o->polys = calloc(n, sizeof *o->polys))) return jfail(c, list, "out of memory");
    o->count = (int)n;
    for (p = rn_json_first(c->j, list); p != RN_JNONE; p = rn_json_next(c->j, list, p), ++k)
        if (rn_json_type(c->j, p) != RN_JOBJECT || !parse_polygon(c, p, &o->polys[k])) {
            char inner[200];
            if (rn_json_type(c->j, p) != RN_JOBJECT) jfail(c, p, "must be an object");
            snprintf(inner, sizeof inner, "%s", c->err ? c->err : "");
            return jfail(c, p, "polygon %d: %s", k, inner);
        }
    return 1;
}

static int parse_object(jctx *c, uint32_t j)
{
    /* Per kind; each also takes type, material, st_scale, st_offset. */
    static const char *const kinds[] = {"teapot", "polygons", "sphere", "cylinder", "plane"};
    static const char *const keys[5][10] = {
        {"type", "material", "st_scale", "st_offset", "scale", "offset", NULL},
        {"type", "material", "st_scale", "st_offset", "polygons", NULL},
        {"type", "material", "st_scale", "st_offset", "centre", "axis", "radius", NULL},
        {"type", "material", "st_scale", "st_offset", "centre", "axis", "radius", "height", NULL},
        {"type", "material", "st_scale", "st_offset", "centre", "axis", "size", NULL}};
    static const char *const all[] = {"scale",  "offset", "polygons", "centre",
                                      "axis",   "radius", "height",   "size", NULL};
    static const char *const what[] = {"a teapot", "polygons", "a sphere", "a cylinder", "a plane"};
    rn_object o;
    const char *type;
    double axis[3] = {0, 0, 1}, scale = 1.0, offset[3] = {0, 0, 0};
    int ok = 1, kind = -1, k;
    if (!jstr(c, j, "type", &type)) return 0;
    for (k = 0; type && k < 5; ++k)
        if (strcmp(type, kinds[k]) == 0) kind = k;
    if (kind < 0)
        return jfail(c, type ? rn_json_get(c->j, j, "type") : j, "object type '%.40s' unknown",
                     type ? type : "(missing)");
    if (!jkeys(c, j, keys[kind], all, what[kind])) return 0;
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
    if (o.st_scale[0] == 0.0 || o.st_scale[1] == 0.0)
        return jfail(c, rn_json_get(c->j, j, "st_scale"), "'st_scale' must not be zero");
    if (!axis_frame(&o, axis)) return jfail(c, rn_json_get(c->j, j, "axis"), "'axis' must not be zero");
    if (kind == RN_PATCHES && ++c->teapots > RN_MAX_TEAPOTS)
        return jfail(c, j, "at most %d teapots (%d patches each)", RN_MAX_TEAPOTS, TEAPOT_PATCHES);
    if (kind == RN_PATCHES) ok = scene_teapot_object(&o, scale, offset);
    else if (kind == RN_POLYGONS) ok = parse_polygons(c, j, &o);
    if (!ok) {
        if (c->at == RN_JNONE) jfail(c, j, "out of memory");
        free(o.polys);
        if (o.patches)
            for (k = 0; k < o.count; ++k) patch_release(&o.patches[k]);
        free(o.patches);
        return 0;
    }
    return scene_add_object(c->sc, &o) ? 1 : jfail(c, j, "out of memory");
}

typedef int (*jlist_fn)(jctx *c, uint32_t o);

/* A list of at most max elements, each an object parsed by fn. The caps
 * keep the scene's memory and the per-sample search cost (linear in
 * objects, and in polygons) bounded whatever the file says. */
static int parse_list(jctx *c, uint32_t root, const char *key, jlist_fn fn, int required, int max)
{
    uint32_t list = rn_json_get(c->j, root, key), e;
    int k = 0;
    if (list == RN_JNONE) return required ? jfail(c, root, "'%s' is missing", key) : 1;
    if (rn_json_type(c->j, list) != RN_JARRAY || rn_json_size(c->j, list) > (uint32_t)max)
        return jfail(c, list, "'%s' must be an array of at most %d", key, max);
    for (e = rn_json_first(c->j, list); e != RN_JNONE; e = rn_json_next(c->j, list, e), ++k) {
        if (rn_json_type(c->j, e) != RN_JOBJECT || !fn(c, e)) {
            char inner[200];
            if (rn_json_type(c->j, e) != RN_JOBJECT) jfail(c, e, "must be an object");
            snprintf(inner, sizeof inner, "%s", c->err ? c->err : "");
            return jfail(c, e, "%s[%d]: %s", key, k, inner);
        }
    }
    return 1;
}

static int parse_light(jctx *c, uint32_t o)
{
    static const char *const keys[] = {"dir", "color", NULL};
    rn_light *L;
    double d[3] = {0, 0, 1};
    if (c->sc->nlight >= RN_MAX_LIGHTS) return jfail(c, o, "at most %d lights", RN_MAX_LIGHTS);
    L = &c->sc->light[c->sc->nlight];
    L->color[0] = L->color[1] = L->color[2] = 1.0f;
    if (!jkeys(c, o, keys, NULL, "lights") || !jvec(c, o, "dir", 3, d) ||
        !jcolor(c, o, "color", 3, L->color))
        return 0;
    if (!(v3_normalize(d) > 0.0)) return jfail(c, rn_json_get(c->j, o, "dir"), "'dir' must not be zero");
    v3_copy(L->dir, d);
    c->sc->nlight++;
    return 1;
}

/* "environment": the procedural sky baked as a lat-long or cube map, or an
 * environment file (a lat-long map or OpenEXR's cube layout, read in
 * scene_finish by sample_io_read_env), resampled into "type" at "size"
 * where those are given. */
static int parse_env(jctx *c, uint32_t o)
{
    static const char *const sky_keys[] = {"type", "size", "radius", "centre", "strength", NULL};
    static const char *const file_keys[] = {"type", "size", "file", "colorspace", "radius", "centre",
                                            "strength", NULL};
    rn_env *e = &c->sc->env;
    const char *type;
    int size = 0, file = rn_json_get(c->j, o, "file") != RN_JNONE;
    double strength = 1.0;
    rn_env_kind kind;
    if (!jstr(c, o, "type", &type)) return 0;
    if (!type) kind = file ? RN_ENV_NONE : RN_ENV_LATLONG;
    else if (strcmp(type, "latlong") == 0) kind = RN_ENV_LATLONG;
    else if (strcmp(type, "cube") == 0) kind = RN_ENV_CUBE;
    else return jfail(c, rn_json_get(c->j, o, "type"), "environment type must be latlong or cube");
    if (!jkeys(c, o, file ? file_keys : sky_keys, file ? sky_keys : file_keys,
               file ? "an environment file" : "the procedural environment"))
        return 0;
    if (!file) size = kind == RN_ENV_CUBE ? 128 : 512;
    if (!jint(c, o, "size", 2, 8192, &size) || !jnum(c, o, "radius", 0, 1e9, &e->radius) ||
        !jvec(c, o, "centre", 3, e->centre) || !jnum(c, o, "strength", 0, 1e6, &strength))
        return 0;
    e->strength = (float)strength;
    if (file) {
        rn_texture *t = &c->sc->env_image;
        proc_defaults(t, RN_TEX_IMAGE);
        t->use = RN_USE_COLOUR;
        e->file_kind = kind;
        e->file_size = size;
        if (size) {
            /* The resampled map counts against the budget as a baked one. */
            double n = kind == RN_ENV_CUBE ? 6.0 * size * size : (double)size * 2 * size;
            if (!budget(c, o, "environment", n, 4.0 * n)) return 0;
        }
        return jfile(c, o, t);
    }
    {
        /* Lat-long is size × size/2, a cube six size²; 2 × 2 samples each. */
        double n = kind == RN_ENV_LATLONG ? (double)size * (size / 2) : 6.0 * size * size;
        if (!budget(c, o, "environment", n, 4.0 * n)) return 0;
    }
    if (!env_build_sky(e, kind, size, c->err, c->errlen)) return jfail(c, o, "%s", c->err);
    return 1;
}

static int parse_root(jctx *c, uint32_t root, int width, int height)
{
    static const char *const keys[] = {"width",     "height",    "background", "camera",
                                       "sampler",   "textures",  "materials",  "lights",
                                       "environment", "objects", NULL};
    uint32_t cam, smp, env;
    int w = 512, h = 512;
    if (rn_json_type(c->j, root) != RN_JOBJECT) return jfail(c, root, "the scene must be a JSON object");
    if (!jkeys(c, root, keys, NULL, "the scene") || !jint(c, root, "width", 1, 16384, &w) ||
        !jint(c, root, "height", 1, 16384, &h) ||
        !jcolor(c, root, "background", 4, c->sc->background) || !jobj(c, root, "camera", &cam) ||
        !jobj(c, root, "sampler", &smp) || !jobj(c, root, "environment", &env))
        return 0;
    if (width > 0) w = width;
    if (height > 0) h = height;
    c->textures = rn_json_get(c->j, root, "textures");
    c->materials = rn_json_get(c->j, root, "materials");
    if (!parse_camera(c, cam, w, h) || !parse_sampler(c, smp) ||
        !parse_list(c, root, "textures", parse_texture, 0, RN_MAX_TEXTURES) ||
        !parse_list(c, root, "materials", parse_material, 0, RN_MAX_MATERIALS) ||
        !parse_list(c, root, "lights", parse_light, 0, RN_MAX_LIGHTS) ||
        !parse_list(c, root, "objects", parse_object, 1, RN_MAX_OBJECTS))
        return 0;
    if (c->sc->nmat == 0) {
        rn_material m;
        material_defaults(&m);
        if (!scene_add_material(c->sc, &m)) return jfail(c, root, "out of memory");
    }
    if (env != RN_JNONE && !parse_env(c, env)) {
        char inner[200];
        snprintf(inner, sizeof inner, "%s", c->err ? c->err : "");
        return jfail(c, env, "environment: %s", inner);
    }
    return 1;
}

void render_parse_options_init(render_parse_options *po)
{
    memset(po, 0, sizeof *po);
    po->images = 1;
    po->max_bake_work = RENDER_MAX_BAKE_WORK;
    po->max_texels = RENDER_MAX_TEXELS;
    po->max_values = RENDER_MAX_JSON_VALUES;
    po->cache_mb = RENDER_CACHE_MB;
}

int render_scene_parse_ex(const char *json, size_t len, int width, int height,
                          const render_parse_options *po, render_scene **out, char *err,
                          size_t errlen)
{
    rn_json j;
    jctx c;
    size_t k = 0;
    int ok;
    *out = NULL;
    if (err && errlen) err[0] = '\0';
    memset(&c, 0, sizeof c);
    if (po) c.po = *po;
    else render_parse_options_init(&c.po);
    if (c.po.max_values < 1 || c.po.max_values > RENDER_MAX_JSON_VALUES)
        c.po.max_values = RENDER_MAX_JSON_VALUES;
    /* Fail before reading the rest when the text cannot be a scene (a
     * megabyte array would otherwise be parsed in full first). */
    if (len >= 3 && memcmp(json, "\xEF\xBB\xBF", 3) == 0) k = 3;
    while (k < len && (json[k] == ' ' || json[k] == '\t' || json[k] == '\n' || json[k] == '\r')) ++k;
    if (k < len && json[k] != '{') {
        int line, col;
        rn_json_line_col(json, len, k, &line, &col);
        rn_seterr(err, errlen, "line %d, column %d: the scene must be a JSON object", line, col);
        return -1;
    }
    if (!rn_json_parse(&j, json, len, (uint32_t)c.po.max_values, err, errlen)) return -1;
    c.j = &j;
    c.at = RN_JNONE;
    c.textures = c.materials = RN_JNONE;
    c.err = err;
    c.errlen = errlen;
    if (!(c.sc = scene_new())) {
        rn_json_free(&j);
        rn_seterr(err, errlen, "out of memory");
        return -1;
    }
    ok = parse_root(&c, 0, width, height);
    if (!ok && c.at != RN_JNONE && err && errlen) {
        char inner[512];
        int line, col;
        rn_json_where(&j, c.at, &line, &col);
        snprintf(inner, sizeof inner, "%s", err);
        rn_seterr(err, errlen, "line %d, column %d: %s", line, col, inner);
    }
    rn_json_free(&j);
    if (ok)
        ok = scene_finish(c.sc, &c.po, c.po.max_texels - c.texels, err, errlen);
    if (!ok) {
        render_scene_destroy(c.sc);
        return -1;
    }
    *out = c.sc;
    return 0;
}

int render_scene_parse(const char *json, size_t len, int width, int height, render_scene **out,
                       char *err, size_t errlen)
{
    return render_scene_parse_ex(json, len, width, height, NULL, out, err, errlen);
}
