/*
 * Image textures of scene files: read through libsample_io (any format
 * OpenImageIO reads, converted to linear by OpenColorIO), mip-mapped with
 * the texture's wrap modes. Without libsample_io in the build, a scene that
 * names an image is refused with a message instead.
 */
#define _POSIX_C_SOURCE 200809L
#include "rn_internal.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#ifdef TEXSAMPLE_HAVE_IO
#include "sample/sample_io.h"
#include "sample/texsys.h"

/* base_dir/file, or file alone when it is absolute or there is no base. */
static int resolve(const char *base_dir, const char *file, char *out, size_t outlen)
{
    int n = base_dir && base_dir[0] && file[0] != '/'
                ? snprintf(out, outlen, "%s/%s", base_dir, file)
                : snprintf(out, outlen, "%s", file);
    return n >= 0 && (size_t)n < outlen;
}

/* A grey (1-channel) or grey + alpha (2-channel) texture rebuilt as float
 * (Y, Y, Y) or (Y, Y, Y, A), every level as the file gave it. libsample
 * reads channels as OpenGL's R and RG formats do, (r, 0, 0, 1) and
 * (r, g, 0, 1), which is right for data but shows a grey picture red.
 * Float keeps the decoded values exactly; the texel budget already counts
 * every texture as float RGBA. */
static int broadcast_grey(rn_texture *t, char *err, size_t errlen)
{
    sample_texture_info info;
    sample_image lv[32];
    sample_texture *out = NULL;
    sample_error e;
    int k, ok = 1, ch;
    sample_texture_info_get(t->tex, &info);
    if (info.channels > 2) return 1;
    ch = info.channels == 1 ? 3 : 4;
    memset(lv, 0, sizeof lv);
    for (k = 0; k < info.levels && k < 32 && ok; ++k) {
        int w, h, i, j;
        float *px;
        sample_texture_level_size(t->tex, k, &w, &h);
        px = malloc(sizeof *px * (size_t)ch * (size_t)w * (size_t)h);
        if (!(ok = px != NULL)) break;
        for (j = 0; j < h; ++j)
            for (i = 0; i < w; ++i) {
                float c[4], *o = px + ((size_t)j * (size_t)w + (size_t)i) * (size_t)ch;
                sample_texture_texel(t->tex, k, i, j, c);
                o[0] = o[1] = o[2] = c[0];
                if (ch == 4) o[3] = c[1];
            }
        lv[k].width = w;
        lv[k].height = h;
        lv[k].channels = ch;
        lv[k].format = SAMPLE_FORMAT_F32;
        lv[k].data = px;
    }
    if (ok && sample_texture_create_levels(lv, k, &out, &e) != SAMPLE_OK) {
        rn_seterr(err, errlen, "image texture '%s': %s", t->path, e.message);
        out = NULL;
        ok = -1;
    }
    for (k = 0; k < 32; ++k) free((void *)lv[k].data);
    if (!out) {
        if (ok == 0) rn_seterr(err, errlen, "image texture '%s': out of memory", t->path);
        return 0;
    }
    /* A cached texture stays its system's; the copy is the scene's. */
    if (!t->cached) sample_texture_destroy(t->tex);
    t->tex = out;
    t->cached = 0;
    return 1;
}

/* Checks the file (a regular one: `what` names it in the message) and
 * sets the reading options every scene file shares. */
static int read_options(const rn_texture *t, const char *path, const char *what, double max_texels,
                        sample_io_options *o, char *err, size_t errlen)
{
    size_t size;
    int fd;
    /* Checked here so that a missing file (e.g. a built-in scene whose
     * testimages/ file is absent) says so plainly, not as a decoder error,
     * and so that no decoder ever opens a FIFO or a device. */
    if ((fd = rn_open_regular(path, what, SIZE_MAX, &size, err, errlen)) < 0) return 0;
    close(fd);
    sample_io_options_init(o);
    /* Data maps (bump, normal) hold numbers, not colours: raw unless the
     * scene names a space (the OCIO role "data" exists in every config). */
    o->colorspace = t->colorspace[0] ? t->colorspace : t->use == RN_USE_DATA ? "data" : NULL;
    /* The scene's texel budget, as float RGBA bytes (sample_io's measure):
     * a file claiming more is refused before its pixels are decoded. */
    o->max_bytes = max_texels * 16.0 >= (double)SIZE_MAX ? SIZE_MAX
                   : max_texels >= 1.0              ? (size_t)(max_texels * 16.0)
                                                    : 1;
    return 1;
}

/* The file through the scene's texture system: header now, tiles as
 * filters touch them. The texel budget is applied as sample_io applies
 * max_bytes (every level's texels as float RGBA), so that a scene refused
 * whole is refused cached too. */
static int open_cached(rn_texture *t, render_scene *sc, const char *path, const sample_io_options *o,
                       const char *what, char *err, size_t errlen)
{
    sample_texsys_options so;
    sample_texsys *sys = sc->texsys;
    const sample_texture *tex;
    sample_texture_info info;
    sample_error e;
    double bytes = 0.0;
    int k;
    if (!sys) {
        sample_texsys_options_init(&so);
        so.max_memory_mb = sc->cache_mb;
        if (sample_texsys_create(&so, &sys, &e) != SAMPLE_OK) {
            rn_seterr(err, errlen, "%s '%s': %s", what, t->path, e.message);
            return 0;
        }
        sc->texsys = sys;
    }
    if (sample_texsys_open_colorspace(sys, path, o->colorspace, &tex, &e) != SAMPLE_OK) {
        rn_seterr(err, errlen, "%s '%s': %s", what, t->path, e.message);
        return 0;
    }
    sample_texture_info_get(tex, &info);
    for (k = 0; k < info.levels; ++k) {
        int w, h;
        sample_texture_level_size(tex, k, &w, &h);
        bytes += 16.0 * (double)w * (double)h;
    }
    if (bytes > (double)o->max_bytes) {
        rn_seterr(err, errlen, "%s '%s': %d x %d with its levels is more than the scene's texel budget", what,
                  t->path, info.width, info.height);
        return 0;
    }
    t->tex = (sample_texture *)(uintptr_t)tex;
    t->cached = 1;
    return 1;
}

void image_texsys_destroy(void *texsys) { sample_texsys_destroy((sample_texsys *)texsys); }

int image_load(rn_texture *t, render_scene *sc, const char *base_dir, double max_texels, double *texels,
               char *err, size_t errlen)
{
    char path[4096], what[600];
    sample_io_options o;
    sample_mip_params mip;
    sample_texture_info info;
    sample_error e;
    if (!resolve(base_dir, t->path, path, sizeof path)) {
        rn_seterr(err, errlen, "image texture '%s': path too long", t->path);
        return 0;
    }
    snprintf(what, sizeof what, "image texture '%s' at", t->path);
    if (!read_options(t, path, what, max_texels, &o, err, errlen)) return 0;
    sample_mip_params_init(&mip);
    mip.wrap_s = t->wrap_s;
    mip.wrap_t = t->wrap_t;
    if (sc->cache_mb > 0.0) {
        /* The box pyramid a texture system builds for a file without
         * levels reads only in-range texels (libsample/src/mip.c,
         * fill_box), so the scene's wrap modes and the file's give the
         * same levels: the cached texture is the whole one, bit for bit. */
        if (!open_cached(t, sc, path, &o, "image texture", err, errlen)) return 0;
    } else if (sample_io_read_texture(path, &o, &mip, &t->tex, &e) != SAMPLE_OK) {
        t->tex = NULL;
        rn_seterr(err, errlen, "image texture '%s': %s", t->path, e.message);
        return 0;
    }
    if ((t->use & RN_USE_COLOUR) && !broadcast_grey(t, err, errlen)) return 0;
    sample_texture_info_get(t->tex, &info);
    *texels = (double)info.width * (double)info.height;
    return 1;
}

int env_image_load(const rn_texture *t, rn_env *e, render_scene *sc, const char *base_dir, double max_texels,
                   double *texels, char *err, size_t errlen)
{
    char path[4096], what[600];
    sample_io_options o;
    sample_mip_params mip;
    sample_texture_info info;
    sample_texture *conv = NULL;
    sample_error er;
    if (!resolve(base_dir, t->path, path, sizeof path)) {
        rn_seterr(err, errlen, "file '%s': path too long", t->path);
        return 0;
    }
    snprintf(what, sizeof what, "environment file '%s' at", t->path);
    if (!read_options(t, path, what, max_texels, &o, err, errlen)) return 0;
    sample_mip_params_init(&mip);
    if (sc->cache_mb > 0.0 && e->file_kind == RN_ENV_NONE && !e->file_size) {
        /* Through the texture system where it gives what
         * sample_io_read_env gives: a cube map (N x 6N), or a 2:1 lat-long
         * map as a 2D texture of the file's levels (a box pyramid, which
         * reads no texel past an edge, where it has none). Another shape
         * goes to sample_io_read_env, which applies the rest of its rule;
         * a map resampled into another layout or size is read whole. */
        rn_texture c = *t;
        if (!open_cached(&c, sc, path, &o, "file", err, errlen)) return 0;
        sample_texture_info_get(c.tex, &info);
        if (info.kind == SAMPLE_TEXTURE_CUBE || (info.kind == SAMPLE_TEXTURE_2D && info.width == 2 * info.height)) {
            e->tex = c.tex;
            e->cached = 1;
        }
    }
    if (!e->tex && sample_io_read_env(path, &o, &mip, &e->tex, &er) != SAMPLE_OK) {
        e->tex = NULL;
        rn_seterr(err, errlen, "file '%s': %s", t->path, er.message);
        return 0;
    }
    sample_texture_info_get(e->tex, &info);
    e->kind = info.kind == SAMPLE_TEXTURE_CUBE ? RN_ENV_CUBE : RN_ENV_LATLONG;
    if (info.channels <= 2) {
        /* Grey as for colour textures (libsample reads one channel as
         * red); a lat-long map only. */
        rn_texture g = *t;
        if (e->kind == RN_ENV_CUBE) {
            rn_seterr(err, errlen, "file '%s': a grey cube map is not read; give it three channels", t->path);
            return 0;
        }
        g.tex = e->tex;
        g.cached = e->cached;
        e->tex = NULL;
        if (!broadcast_grey(&g, err, errlen)) {
            if (!g.cached) sample_texture_destroy(g.tex);
            return 0;
        }
        e->tex = g.tex;
        e->cached = g.cached;
    }
    if ((e->file_kind != RN_ENV_NONE && e->file_kind != e->kind) || e->file_size) {
        rn_env_kind want = e->file_kind != RN_ENV_NONE ? e->file_kind : e->kind;
        if (sample_io_env_convert(e->tex, want == RN_ENV_CUBE ? SAMPLE_TEXTURE_CUBE : SAMPLE_TEXTURE_2D,
                                  e->file_size, &mip, &conv, &er) != SAMPLE_OK) {
            rn_seterr(err, errlen, "file '%s': %s", t->path, er.message);
            return 0;
        }
        sample_texture_destroy(e->tex);
        e->tex = conv;
        e->kind = want;
        sample_texture_info_get(e->tex, &info);
    }
    *texels = (double)info.width * (double)info.height * (info.kind == SAMPLE_TEXTURE_CUBE ? 6.0 : 1.0);
    return 1;
}

#else

void image_texsys_destroy(void *texsys) { (void)texsys; }

int image_load(rn_texture *t, render_scene *sc, const char *base_dir, double max_texels, double *texels,
               char *err, size_t errlen)
{
    (void)sc;
    (void)base_dir;
    (void)max_texels;
    *texels = 0;
    rn_seterr(err, errlen, "image texture '%s': this build has no image support (libsample_io)",
              t->path);
    return 0;
}

int env_image_load(const rn_texture *t, rn_env *e, render_scene *sc, const char *base_dir, double max_texels,
                   double *texels, char *err, size_t errlen)
{
    (void)e;
    (void)sc;
    (void)base_dir;
    (void)max_texels;
    *texels = 0;
    rn_seterr(err, errlen, "file '%s': this build has no image support (libsample_io)", t->path);
    return 0;
}

#endif
