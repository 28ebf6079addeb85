/*
 * Cross-check of libsample's 3D textures against Mesa's softpipe
 * (doc/volumes.md, "What matches Mesa").
 *
 * A GL_TEXTURE_3D of random RGBA32F texels with explicit levels
 * (libsample's box pyramid, uploaded level by level, so that both sides
 * read the same texels) is sampled by textureGrad(sampler3D, ...) and
 * textureLod in an OSMesa context (mesa_gl.h), one fragment per query, and
 * by sample_batch_3d on the same state: every wrap mode on s, t and r
 * (mixed across the axes), mag NEAREST and LINEAR × the six min filters,
 * and trilinear with lod clamps, base/max level and bias. With --texsample
 * the textureGrad queries of every Nth configuration also go through
 * `texsample lookup --volume` by files.
 *
 *   GALLIUM_DRIVER=softpipe mesa_volume [--texsample PATH [--texsample-stride N]] [-v]
 *
 * Exit 0: agreement; 1: a difference over the bound; 77: no usable OSMesa
 * context (ctest SKIP).
 */
#include "mesa_gl.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define QW 32
#define NQ 256
/* Texture under test: powers of two, so that ρ is exact on both sides
 * (softpipe takes log2 from a table; mesa_check.c). */
#define VW 8
#define VH 4
#define VD 16
/* Agreement bound (mesa_check.c's, doc/mip-and-lod.md): softpipe's
 * trilinear is three nested lerps a + w(b − a) and one more for the level
 * blend; ours recon_bilerp per slice and two blends: a few units in the
 * last place of 1.0. */
#define TOL 1e-6f
#define SKIP 77

static int verbose;
static uint32_t rng = 424242u;
static float rnd01(void) { return mesa_rnd01(&rng); }
static int rnd_int(int n) { return (int)(mesa_rnd_u32(&rng) % (uint32_t)n); }

/* Query i's three texels: (s, t, r, lod), dP/dx, dP/dy. */
static const char *fs_src = MESA_FS_QUERY3("sampler3D");

/* glTexImage3D of every level of tex, texel by texel as libsample reads
 * them (sample_texture_texel_layer: slice k is layer k). */
static void upload_volume(const sample_texture *tex)
{
    sample_texture_info info;
    int k, i, j, z, w, h, d;
    sample_texture_info_get(tex, &info);
    for (k = 0; k < info.levels; ++k) {
        float *buf;
        sample_texture_level_size3(tex, k, &w, &h, &d);
        buf = (float *)malloc((size_t)w * h * d * 4 * sizeof(float));
        if (!buf) return;
        for (z = 0; z < d; ++z)
            for (j = 0; j < h; ++j)
                for (i = 0; i < w; ++i)
                    sample_texture_texel_layer(tex, k, z, i, j, buf + 4 * ((size_t)i + (size_t)w * (j + (size_t)h * z)));
        glTexImage3D(GL_TEXTURE_3D, k, GL_RGBA32F, w, h, d, 0, GL_RGBA, GL_FLOAT, buf);
        free(buf);
    }
}

/* A coordinate in [−1.25, 2.25]; |c| ≥ ½ for the mirror-clamps, where
 * softpipe omits the extension's lower bound 1/(2N) (mesa_check.c). */
static float coord(sample_wrap w)
{
    if (w == SAMPLE_WRAP_MIRROR_CLAMP || w == SAMPLE_WRAP_MIRROR_CLAMP_TO_BORDER) {
        float a = 0.5f + 1.75f * rnd01();
        return rnd01() < 0.5f ? -a : a;
    }
    return -1.25f + 3.5f * rnd01();
}


/* NQ queries: q[i] with, for textureLod, lod[i]. textureGrad's columns
 * each lie along one texel axis (any of s, t, r, chosen at random):
 * there softpipe's ρ — the largest |component| times the axis's size —
 * is the specification's (the longer column). textureLod's λ is handed to
 * libsample as a per-call bias on a Jacobian of ρ = 1 (dr/dy = 1/d). */
static void make_queries(const sample_sampler *s, int use_lod, sample_query3 *q, float *lod)
{
    static const float pts[] = {-0.5f, 0.0f, 0.25f, 0.5f - 1.0f / 1024, 0.5f + 1.0f / 1024, 0.75f, 1.0f, 1.25f,
                                1.5f, 2.0f, 2.5f, 3.0f, 3.5f, 4.0f, 4.5f, 6.0f};
    const int n[3] = {VW >> s->base_level, VH >> s->base_level, VD >> s->base_level};
    const sample_wrap w[3] = {s->wrap_s, s->wrap_t, s->wrap_r};
    int i, a;
    for (i = 0; i < NQ; ++i) {
        memset(&q[i], 0, sizeof q[i]);
        for (a = 0; a < 3; ++a) q[i].p[a] = coord(w[a]);
        lod[i] = 0.0f;
        if (use_lod) {
            lod[i] = (i % 2) ? pts[(i / 2) % (int)(sizeof pts / sizeof pts[0])] : -1.0f + 6.0f * rnd01();
        } else {
            int ax = rnd_int(3), ay = rnd_int(3);
            q[i].dpdx[ax] = mesa_grad_scale(&rng, -2, 5) / (float)(n[ax] > 0 ? n[ax] : 1) * (rnd01() < 0.5f ? -1.0f : 1.0f);
            q[i].dpdy[ay] = mesa_grad_scale(&rng, -2, 5) / (float)(n[ay] > 0 ? n[ay] : 1);
        }
    }
}

static int mesa_run(mesa_gl *g, const sample_sampler *s, const sample_query3 *q, const float *lod, int use_lod,
                    float *out)
{
    static float qt[NQ * 12];
    int i;
    for (i = 0; i < NQ; ++i) {
        float *t = qt + 12 * i;
        memcpy(t, q[i].p, 3 * sizeof(float));
        t[3] = lod[i];
        memcpy(t + 4, q[i].dpdx, 3 * sizeof(float));
        memcpy(t + 8, q[i].dpdy, 3 * sizeof(float));
        t[7] = t[11] = 0.0f;
    }
    glActiveTexture(GL_TEXTURE0);
    mesa_gl_sampler(GL_TEXTURE_3D, s);
    glUniform1i(glGetUniformLocation(g->prog, "use_lod"), use_lod);
    return mesa_gl_render(g, qt, 3, out);
}

static void lib_run(const sample_texture *tex, const sample_sampler *s, const sample_query3 *q, const float *lod,
                    int use_lod, float *out)
{
    static sample_query3 lq[NQ];
    int i, w, h, d;
    sample_batch3_args a = {NQ, lq, lod, out, NULL};
    sample_texture_level_size3(tex, s->base_level, &w, &h, &d);
    for (i = 0; i < NQ; ++i) {
        lq[i] = q[i];
        if (use_lod) {
            memset(lq[i].dpdx, 0, sizeof lq[i].dpdx);
            memset(lq[i].dpdy, 0, sizeof lq[i].dpdy);
            lq[i].dpdy[2] = 1.0f / (float)d;
        }
    }
    if (sample_batch_3d(tex, s, &a) != SAMPLE_OK) fprintf(stderr, "mesa_volume: sample_batch_3d failed\n");
}

/* The volume and its levels as raw files (tex.raw, tex.k.raw) for
 * `texsample lookup --volume --levels`. */
static int dump_levels(const char *dir, const sample_texture *tex)
{
    sample_texture_info info;
    int k, i, j, z, w, h, d, ok = 1;
    sample_texture_info_get(tex, &info);
    for (k = 0; k < info.levels && ok; ++k) {
        char path[4096];
        FILE *f;
        float t[4];
        sample_texture_level_size3(tex, k, &w, &h, &d);
        if (k == 0) snprintf(path, sizeof path, "%s/tex.raw", dir);
        else snprintf(path, sizeof path, "%s/tex.%d.raw", dir, k);
        if (!(f = fopen(path, "wb"))) return 0;
        for (z = 0; z < d; ++z)
            for (j = 0; j < h; ++j)
                for (i = 0; i < w; ++i) {
                    sample_texture_texel_layer(tex, k, z, i, j, t);
                    ok &= fwrite(t, sizeof t, 1, f) == 1;
                }
        ok &= fclose(f) == 0;
    }
    return ok;
}

/* textureGrad queries through `texsample lookup --volume`; 1 when it ran
 * and out holds its results. */
static int texsample_run(const char *exe, const char *dir, const sample_sampler *s, const sample_query3 *q,
                         float *out)
{
    char cmd[8192], path[4096];
    FILE *f;
    size_t n = 0;
    snprintf(path, sizeof path, "%s/queries.bin", dir);
    if (!(f = fopen(path, "wb"))) return 0;
    n = fwrite(q, sizeof *q, NQ, f);
    if (fclose(f) != 0 || n != NQ) return 0;
    snprintf(cmd, sizeof cmd,
             "'%s' lookup --volume '%s/tex.raw' --w %d --h %d --d %d --levels '%s/tex' --queries '%s' "
             "--out '%s/ours.bin' --wrap-s %s --wrap-t %s --wrap-r %s --min %s --mag %s --border %g,%g,%g,%g "
             "--lod-bias %g --min-lod %g --max-lod %g --base-level %d --max-level %d --nearest-level-floor",
             exe, dir, VW, VH, VD, dir, path, dir, sample_wrap_name(s->wrap_s), sample_wrap_name(s->wrap_t),
             sample_wrap_name(s->wrap_r), sample_filter_name(s->min_filter), sample_filter_name(s->mag_filter),
             s->border_color[0], s->border_color[1], s->border_color[2], s->border_color[3], s->lod_bias, s->min_lod,
             s->max_lod, s->base_level, s->max_level);
    if (verbose) fprintf(stderr, "%s\n", cmd);
    if (system(cmd) != 0) {
        fprintf(stderr, "mesa_volume: texsample lookup failed: %s\n", cmd);
        return 0;
    }
    snprintf(path, sizeof path, "%s/ours.bin", dir);
    if (!(f = fopen(path, "rb"))) return 0;
    n = fread(out, 4 * sizeof(float), NQ, f);
    fclose(f);
    return n == NQ;
}

/* The largest |a − b| over the results, and the query it is in. */
static float worst_diff(const float *a, const float *b, int *at)
{
    float m = 0.0f;
    int i;
    *at = 0;
    for (i = 0; i < NQ * 4; ++i)
        if (!(fabsf(a[i] - b[i]) <= m)) {
            m = fabsf(a[i] - b[i]);
            *at = i / 4;
        }
    return m;
}

int main(int argc, char **argv)
{
    static float base[VW * VH * VD * 4], mesa[NQ * 4], ours[NQ * 4], tool[NQ * 4], lod[NQ];
    static sample_query3 q[NQ];
    const char *texsample = NULL;
    char dir[] = "/tmp/mesa_volume.XXXXXX";
    sample_volume v = {VW, VH, VD, 4, SAMPLE_FORMAT_F32, base, 0, 0};
    sample_mip_params mp;
    sample_texture *tex = NULL;
    mesa_gl g;
    GLuint gltex;
    int i, w, mag, min, use_lod, configs = 0, failures = 0, tool_runs = 0, stride = 1;
    float worst_all = 0.0f, worst_tool = 0.0f;

    for (i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--texsample") && i + 1 < argc) texsample = argv[++i];
        else if (!strcmp(argv[i], "--texsample-stride") && i + 1 < argc) stride = atoi(argv[++i]) > 0 ? atoi(argv[i]) : 1;
        else if (!strcmp(argv[i], "-v")) verbose = 1;
        else {
            fprintf(stderr, "usage: mesa_volume [--texsample PATH [--texsample-stride N]] [-v]\n");
            return 2;
        }
    }
    if (!mesa_gl_init(&g, "mesa_volume", fs_src, QW, NQ / QW)) return SKIP;
    for (i = 0; i < VW * VH * VD * 4; ++i) base[i] = rnd01();
    sample_mip_params_init(&mp);
    if (sample_texture_create_3d(&v, &mp, &tex, NULL) != SAMPLE_OK) return 1;
    glGenTextures(1, &gltex);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_3D, gltex);
    upload_volume(tex);
    if (texsample && (!mkdtemp(dir) || !dump_levels(dir, tex))) return 1;

    /* Every wrap mode, mixed over s, t, r, × mag × the six min filters,
     * then trilinear with lod clamps, base/max level and bias; each with
     * textureGrad and textureLod queries. */
    for (w = 0; w < SAMPLE_WRAP_COUNT; ++w)
        for (mag = 0; mag < 2; ++mag)
            for (min = 0; min < 6 + 4; ++min)
                for (use_lod = 0; use_lod < 2; ++use_lod) {
                    sample_sampler s;
                    int extra = min - 6, at;
                    float d;
                    sample_sampler_init(&s);
                    s.wrap_r = (sample_wrap)w;
                    s.wrap_s = (sample_wrap)((w + 1 + min % 3) % SAMPLE_WRAP_COUNT);
                    s.wrap_t = (sample_wrap)((w + 3 * mag + use_lod) % SAMPLE_WRAP_COUNT);
                    s.mag_filter = mag ? SAMPLE_LINEAR : SAMPLE_NEAREST;
                    s.min_filter = extra < 0 ? (sample_filter)min : SAMPLE_LINEAR_MIPMAP_LINEAR;
                    /* Mesa rounds NEAREST_MIPMAP_* levels as ⌊λ + ½⌋. */
                    s.options = SAMPLE_OPT_NEAREST_LEVEL_FLOOR;
                    s.border_color[0] = 0.25f;
                    s.border_color[1] = 0.5f;
                    s.border_color[2] = 0.75f;
                    s.border_color[3] = 1.0f;
                    if (extra == 0) { s.min_lod = 0.75f; s.max_lod = 2.25f; }
                    if (extra == 1) { s.base_level = 1; s.max_level = 3; }
                    if (extra == 2) { s.min_filter = SAMPLE_NEAREST_MIPMAP_NEAREST; s.base_level = 1; }
                    if (extra == 3) {
                        /* softpipe drops GL_TEXTURE_LOD_BIAS for textureGrad
                         * (mesa_check.c, doc/mip-and-lod.md). */
                        if (!use_lod) continue;
                        s.lod_bias = 0.75f;
                    }
                    make_queries(&s, use_lod, q, lod);
                    if (!mesa_run(&g, &s, q, lod, use_lod, mesa)) return 1;
                    lib_run(tex, &s, q, lod, use_lod, ours);
                    d = worst_diff(mesa, ours, &at);
                    ++configs;
                    if (d > worst_all) worst_all = d;
                    if (!(d <= TOL) || verbose)
                        fprintf(stderr,
                                "%s %.3g wrap %s/%s/%s mag %s min %s %s [bias %g lod %g..%g levels %d..%d]: query %d "
                                "(p %.9g %.9g %.9g dx %g %g %g dy %g %g %g lod %g): mesa %.9g %.9g %.9g %.9g, "
                                "libsample %.9g %.9g %.9g %.9g\n",
                                d <= TOL ? "ok" : "DIFF", d, sample_wrap_name(s.wrap_s), sample_wrap_name(s.wrap_t),
                                sample_wrap_name(s.wrap_r), sample_filter_name(s.mag_filter),
                                sample_filter_name(s.min_filter), use_lod ? "textureLod" : "textureGrad", s.lod_bias,
                                s.min_lod, s.max_lod, s.base_level, s.max_level, at, q[at].p[0], q[at].p[1],
                                q[at].p[2], q[at].dpdx[0], q[at].dpdx[1], q[at].dpdx[2], q[at].dpdy[0],
                                q[at].dpdy[1], q[at].dpdy[2], lod[at], mesa[4 * at], mesa[4 * at + 1],
                                mesa[4 * at + 2], mesa[4 * at + 3], ours[4 * at], ours[4 * at + 1], ours[4 * at + 2],
                                ours[4 * at + 3]);
                    if (!(d <= TOL)) ++failures;
                    if (texsample && !use_lod && configs % stride == 0) {
                        if (!texsample_run(texsample, dir, &s, q, tool)) return 1;
                        d = worst_diff(mesa, tool, &at);
                        ++tool_runs;
                        if (d > worst_tool) worst_tool = d;
                        if (!(d <= TOL)) {
                            ++failures;
                            fprintf(stderr, "DIFF %.3g texsample lookup --volume vs mesa, query %d\n", d, at);
                        }
                    }
                }
    printf("mesa_volume: %d configurations x %d queries, max |mesa - libsample| = %.3g (bound %.3g)", configs, NQ,
           (double)worst_all, (double)TOL);
    if (tool_runs) printf("; %d texsample lookup runs, max |mesa - texsample| = %.3g", tool_runs, (double)worst_tool);
    printf("; %d over the bound\n", failures);
    if (texsample) {
        char cmd[256];
        snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
        if (system(cmd) != 0) fprintf(stderr, "mesa_volume: could not remove %s\n", dir);
    }
    sample_texture_destroy(tex);
    mesa_gl_destroy(&g);
    return failures ? 1 : 0;
}
