/*
 * The industry reference: OpenImageIO's TextureSystem at a registry
 * entry's twin settings (by default aniso16's: MipModeAniso, 16 probes),
 * from its own mip file made as maketx would from the same base level,
 * asked the same queries with the same derivatives as libsample (view.c). OIIO reads the texture from a file, so each texture's
 * base level is written next to the results first. Without OIIO in the
 * build, the configuration is reported as unavailable.
 */
#include "cmp_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef TEXSAMPLE_HAVE_OIIO
#include "oiio_ts.h"
#ifdef TEXSAMPLE_HAVE_IO
#include "sample/sample_io.h"
#endif

typedef struct oiio_ctx {
    oiio_ts *ts;
    oiio_ts_tex **tex; /* per scene texture, NULL when not used */
    oiio_ts_opts opts;
} oiio_ctx;

static int oiio_fn(void *ctx, int texture, const sample_query *q, const sample_query3 *q3,
                   const sample_quad *quad, size_t n, float *rgba, sample_stats *stats)
{
    oiio_ctx *c = ctx;
    (void)quad;
    (void)stats;
    if (!c->tex[texture]) return 1;
    if (q3) return oiio_ts_environment(c->ts, c->tex[texture], &c->opts, q3, n, rgba, NULL, 0) == 0 ? 0 : 1;
    return oiio_ts_sample(c->ts, c->tex[texture], &c->opts, q, n, rgba, NULL, 0) == 0 ? 0 : 1;
}

/* The environment as OpenImageIO's own environment map: the same texels
 * and pyramid, written with the attributes that make OIIO read it as a
 * y-up lat-long map with texel centres at (i + ½)/w (sample_io_write_env).
 * OIIO's environment() samples lat-long maps only. */
static oiio_ts_tex *oiio_prepare_env(const cmp_view *v, oiio_ts *ts, const char *workdir, char *err,
                                     size_t errlen)
{
#ifdef TEXSAMPLE_HAVE_IO
    int cube = 0;
    const sample_texture *tex = render_scene_env(v->sc, &cube);
    sample_io_exr_options o;
    sample_error e;
    char path[1024];
    if (cube) {
        snprintf(err, errlen, "OpenImageIO's environment() reads lat-long maps only, not cube maps");
        return NULL;
    }
    sample_io_exr_options_init(&o);
    o.use_float = 1;
    snprintf(path, sizeof path, "%s/oiio_environment.exr", workdir);
    if (sample_io_write_env(path, tex, &o, &e) != SAMPLE_OK) {
        snprintf(err, errlen, "%.*s", (int)(errlen > 1 ? errlen - 1 : 0), e.message);
        return NULL;
    }
    return oiio_ts_open(ts, path, err, errlen);
#else
    (void)v, (void)ts, (void)workdir;
    snprintf(err, errlen, "this build has no libsample_io to write the environment map");
    return NULL;
#endif
}

/* Write texture k's base level as OIIO's own mip-mapped file. */
static oiio_ts_tex *oiio_prepare(const cmp_view *v, oiio_ts *ts, int k, const char *workdir,
                                 char *err, size_t errlen)
{
    const sample_texture *tex = render_scene_texture(v->sc, k);
    sample_texture_info info;
    char path[1024];
    float *rgba;
    int i, j, rc;
    sample_texture_info_get(tex, &info);
    rgba = malloc(sizeof *rgba * 4 * (size_t)info.width * (size_t)info.height);
    if (!rgba) {
        snprintf(err, errlen, "out of memory for a %d x %d texture", info.width, info.height);
        return NULL;
    }
    for (j = 0; j < info.height; ++j)
        for (i = 0; i < info.width; ++i)
            sample_texture_texel(tex, 0, i, j, rgba + ((size_t)j * (size_t)info.width + (size_t)i) * 4);
    snprintf(path, sizeof path, "%s/oiio_texture%d.exr", workdir, k);
    rc = oiio_ts_make_texture(rgba, info.width, info.height, OIIO_TS_FLOAT, v->sampler.wrap_s,
                              v->sampler.wrap_t, path, err, errlen);
    free(rgba);
    return rc == 0 ? oiio_ts_open(ts, path, err, errlen) : NULL;
}

int cmp_oiio_available(void) { return 1; }

int cmp_run_oiio(const cmp_view *v, const cmp_config *c, const char *workdir, int threads,
                 int runs, cmp_result *r, char *err, size_t errlen)
{
    oiio_ctx ctx;
    int ntex = render_scene_texture_count(v->sc), k, rc = 1;
    size_t px, n = (size_t)v->w * (size_t)v->h;
    memset(r, 0, sizeof *r);
    if (!oiio_ts_wrap_supported(v->sampler.wrap_s) || !oiio_ts_wrap_supported(v->sampler.wrap_t) ||
        ((v->sampler.wrap_s == SAMPLE_WRAP_CLAMP_TO_BORDER ||
          v->sampler.wrap_t == SAMPLE_WRAP_CLAMP_TO_BORDER) &&
         (v->sampler.border_color[0] != 0.0f || v->sampler.border_color[1] != 0.0f ||
          v->sampler.border_color[2] != 0.0f || v->sampler.border_color[3] != 0.0f))) {
        snprintf(err, errlen, "%s: OpenImageIO has no equivalent of wrap modes %s/%s", c->name,
                 sample_wrap_name(v->sampler.wrap_s), sample_wrap_name(v->sampler.wrap_t));
        return 1;
    }
    oiio_ts_opts_init(&ctx.opts);
    tool_filter_oiio_opts(c->pick.f, &ctx.opts);
    ctx.opts.wrap_s = v->sampler.wrap_s;
    ctx.opts.wrap_t = v->sampler.wrap_t;
    ctx.ts = oiio_ts_create(0.0);
    ctx.tex = calloc((size_t)ntex + 1, sizeof *ctx.tex); /* + the environment (env_tex = ntex) */
    if (!ctx.ts || !ctx.tex) {
        snprintf(err, errlen, "%s: cannot start OpenImageIO's TextureSystem", c->name);
        goto out;
    }
    /* Only the textures some pixel uses. */
    for (px = 0; px < n; ++px) {
        k = v->tex[px];
        if (k >= 0 && cmp_view_3d(v, k)) {
            /* OpenImageIO's texture3d() reads volume files and filters
             * their base level only (no mip filtering, no footprint):
             * nothing to set beside these rows (bench --volume times it). */
            snprintf(err, errlen, "%s: OpenImageIO's texture3d has no mip or footprint filtering "
                                  "for a solid texture's volume", c->name);
            goto out;
        }
        if (k >= 0 && k < ntex && !ctx.tex[k] &&
            !(ctx.tex[k] = oiio_prepare(v, ctx.ts, k, workdir, err, errlen)))
            goto out;
        if (k >= 0 && k == v->env_tex && !ctx.tex[k] &&
            !(ctx.tex[k] = oiio_prepare_env(v, ctx.ts, workdir, err, errlen)))
            goto out;
    }
    if (cmp_run(v, 0, oiio_fn, &ctx, 0, threads, runs, r)) {
        snprintf(err, errlen, "%s: an OpenImageIO lookup failed", c->name);
        goto out;
    }
    rc = 0;
out:
    free(ctx.tex);
    oiio_ts_destroy(ctx.ts);
    return rc;
}

#else

int cmp_oiio_available(void) { return 0; }

int cmp_run_oiio(const cmp_view *v, const cmp_config *c, const char *workdir, int threads,
                 int runs, cmp_result *r, char *err, size_t errlen)
{
    (void)v;
    (void)workdir;
    (void)threads;
    (void)runs;
    memset(r, 0, sizeof *r);
    snprintf(err, errlen, "%s: this build has no OpenImageIO", c->name);
    return 1;
}

#endif
