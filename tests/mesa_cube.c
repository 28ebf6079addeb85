/*
 * Cross-check of libsample's cube maps against Mesa's softpipe through
 * OSMesa (doc/environment-maps.md, "How the tests check it").
 *
 * GL_TEXTURE_CUBE_MAP with GL_TEXTURE_CUBE_MAP_SEAMLESS enabled, six random
 * RGBA32F faces and libsample's box pyramid uploaded level by level, so
 * that both sides read the same texels; one fragment per query calls
 * textureGrad(samplerCube, R, dRdx, dRdy) or textureLod(samplerCube, R,
 * lod), and sample_batch_cube runs the same directions, derivatives and
 * sampler state. Every mag × min filter and some lod clamp and base/max
 * level states.
 *
 * Where softpipe departs from GL 4.6 the queries are chosen so that the
 * departure cannot show, and what remains is compared within float
 * rounding:
 *   - λ: softpipe takes ρ = max |dR component| · N / 2 instead of the
 *     derivatives of the face coordinates (§8.13); the two agree when R's
 *     major component is ±1 and dR/dx, dR/dy lie along the face's s and t
 *     axes (no ma term), with magnitudes of 8 mantissa bits (softpipe's
 *     log2 table is exact there), which is what textureGrad queries are;
 *   - corners: softpipe takes a LINEAR block's corner texel from one
 *     neighbouring face (sp_tex_sample.c, "Cheat with corners") instead of
 *     the mean of the three (§8.13.1); queries whose LINEAR blocks reach a
 *     corner on a level they read are counted and reported, not compared.
 *
 * With --texsample PATH the textureGrad states also run through
 * `texsample lookup --cube` on dumped files (the faces of each level one
 * after the other, as the tool reads them).
 *
 *   GALLIUM_DRIVER=softpipe mesa_cube [--texsample PATH] [--dump DIR] [-v]
 *
 * Exit 0: agreement; 1: a difference over the bound; 77: no usable OSMesa
 * context (ctest SKIP).
 */
#include "mesa_gl.h"

#include "cube.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define SKIP 77
#define QW 32  /* queries per framebuffer row */
#define NQ 512 /* queries per configuration */
#define N 32   /* face size: levels 32 … 1 */
/* As mesa_check's bound (its comment gives the rounding count); the face
 * coordinates add one rounding of s and t each, a few 2^-24 of a texel. */
#define TOL 2e-6f

static int verbose;

static uint32_t rng = 2026u;
static uint32_t rnd_u32(void) { return mesa_rnd_u32(&rng); }
static float rnd01(void) { return mesa_rnd01(&rng); }

/* Query i: texels (R, lod), (dR/dx, 0), (dR/dy, 0). */
static const char *fs_src = MESA_FS_QUERY3("samplerCube");

/* A texel-space scale 2^e·(1 + m/256) (mesa_check's grad_scale). */
static float grad_scale(void) { return mesa_grad_scale(&rng, -2, 6); }

/* A random direction with its major component exactly ±1, and its face. */
static int direction(float r[3])
{
    double d[3];
    float m;
    int k;
    do {
        for (k = 0; k < 3; ++k) r[k] = 2.0f * rnd01() - 1.0f;
        m = fmaxf(fabsf(r[0]), fmaxf(fabsf(r[1]), fabsf(r[2])));
    } while (!(m > 0.05f));
    for (k = 0; k < 3; ++k) {
        r[k] /= m;
        d[k] = r[k];
    }
    return cube_face_of(d);
}

/* 10 floats per query: R, lod, dR/dx, dR/dy. */
static void make_queries(float *q, int use_lod, int base)
{
    static const float pts[] = {-0.5f, 0.0f, 0.25f, 0.75f, 1.0f, 1.5f, 2.0f, 2.5f, 3.0f, 4.0f, 4.5f, 6.0f};
    const float n = (float)(N >> base);
    int i, k;
    for (i = 0; i < NQ; ++i) {
        float *x = q + 10 * i;
        int f = direction(x);
        memset(x + 3, 0, 7 * sizeof(float));
        if (use_lod) {
            x[3] = (i % 2) ? pts[(i / 2) % (int)(sizeof pts / sizeof pts[0])] : -1.0f + 7.0f * rnd01();
        } else {
            /* Along the face's U and V (or V and U): ∂s/∂x = a / n. */
            float a = grad_scale() * 2.0f / n, b = grad_scale() * 2.0f / n;
            int swap = (int)(rnd_u32() & 1), sa = (rnd_u32() & 1) ? -1 : 1;
            for (k = 0; k < 3; ++k) {
                x[4 + k] = sa * a * (float)ls_cube_frame[f][swap ? 2 : 1][k];
                x[7 + k] = b * (float)ls_cube_frame[f][swap ? 1 : 2][k];
            }
        }
    }
}

/* libsample's view of the queries: textureLod's λ as a per-call bias on
 * derivatives with ρ = 1 exactly (dR/dy = (2/n)·V: ∂t/∂y = 1/n). */
static void lib_run(const sample_texture *tex, const sample_sampler *s, const float *q, int use_lod, int base,
                    float *out, sample_stats *st)
{
    static sample_query3 q3[NQ];
    static float bias[NQ];
    sample_batch3_args a;
    int i, k;
    for (i = 0; i < NQ; ++i) {
        const float *x = q + 10 * i;
        memcpy(q3[i].p, x, 3 * sizeof(float));
        memcpy(q3[i].dpdx, x + 4, 3 * sizeof(float));
        memcpy(q3[i].dpdy, x + 7, 3 * sizeof(float));
        bias[i] = 0.0f;
        if (use_lod) {
            double d[3] = {x[0], x[1], x[2]};
            int f = cube_face_of(d);
            for (k = 0; k < 3; ++k) {
                q3[i].dpdx[k] = 0.0f;
                q3[i].dpdy[k] = 2.0f / (float)(N >> base) * (float)ls_cube_frame[f][2][k];
            }
            bias[i] = x[3];
        }
    }
    memset(&a, 0, sizeof a);
    a.count = NQ;
    a.queries = q3;
    a.lod_bias = bias;
    a.rgba = out;
    a.stats = st;
    if (sample_batch_cube(tex, s, &a) != SAMPLE_OK) fprintf(stderr, "mesa_cube: sample_batch_cube failed\n");
}

/* `texsample lookup --cube` on the dumped faces and the textureGrad
 * queries of q (10 floats each, as make_queries); 1 when `out` holds its
 * results. */
static int texsample_run(const char *exe, const char *dir, const sample_sampler *s, const float *q, float *out)
{
    static float q9[NQ * 9];
    char cmd[8192], path[4096];
    int i;
    for (i = 0; i < NQ; ++i) {
        memcpy(q9 + 9 * i, q + 10 * i, 3 * sizeof(float));
        memcpy(q9 + 9 * i + 3, q + 10 * i + 4, 6 * sizeof(float));
    }
    snprintf(path, sizeof path, "%s/queries.bin", dir);
    if (!mesa_write_file(path, q9, sizeof q9)) return 0;
    snprintf(cmd, sizeof cmd,
             "'%s' lookup --cube '%s/tex.raw' --size %d --levels '%s/tex' --queries '%s/queries.bin' --out "
             "'%s/ours.bin' ",
             exe, dir, N, dir, dir, dir);
    mesa_sampler_args(cmd + strlen(cmd), sizeof cmd - strlen(cmd), s);
    return mesa_lookup_run(cmd, dir, verbose, out, NQ);
}

/* Whether a LINEAR block on an n × n face at (s, t) holds a corner texel. */
static int corner_block(double s, double t, int n)
{
    double u = s * n, v = t * n;
    return (u < 0.5 || u > n - 0.5) && (v < 0.5 || v > n - 0.5);
}

/* Whether query i's result involves a corner block (the filter is LINEAR
 * per level, on a level it read). */
static int touches_corner(const float *x, const sample_sampler *s, const sample_stats *st)
{
    sample_query3 q;
    sample_query o;
    sample_filter kind = st->lod > 0.0f ? s->min_filter : s->mag_filter;
    int lin = kind == SAMPLE_LINEAR || kind == SAMPLE_LINEAR_MIPMAP_NEAREST || kind == SAMPLE_LINEAR_MIPMAP_LINEAR;
    memset(&q, 0, sizeof q);
    memcpy(q.p, x, sizeof q.p);
    if (!lin || ls_cube_query(&q, &o) < 0) return 0;
    return (st->level0 >= 0 && corner_block(o.s, o.t, N >> st->level0)) ||
           (st->level1 >= 0 && corner_block(o.s, o.t, N >> st->level1));
}

int main(int argc, char **argv)
{
    static float q[NQ * 10], qt[NQ * 12], mesa[NQ * 4], ours[NQ * 4], tool[NQ * 4];
    const char *texsample = NULL, *dump = NULL;
    char tmpdir[] = "/tmp/mesa_cube.XXXXXX";
    int tool_runs = 0;
    float worst_tool = 0.0f;
    static sample_stats st[NQ];
    static float base[6][N * N * 4];
    mesa_gl g;
    GLuint texname;
    sample_image faces[6];
    sample_mip_params mp;
    sample_texture *tex = NULL;
    sample_texture_info info;
    int i, f, k, mag, min, use_lod, configs = 0, failures = 0, compared = 0, corners = 0;
    float worst_all = 0.0f, worst_corner = 0.0f;

    for (i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "-v")) verbose = 1;
        else if (!strcmp(argv[i], "--texsample") && i + 1 < argc) texsample = argv[++i];
        else if (!strcmp(argv[i], "--dump") && i + 1 < argc) dump = argv[++i];
        else if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            printf("usage: mesa_cube [--texsample PATH] [--dump DIR] [-v]\n"
                   "Compares sample_batch_cube (and texsample lookup --cube) with Mesa softpipe's\n"
                   "seamless cube maps through OSMesa; --dump DIR keeps the files lookup read.\n"
                   "Run with GALLIUM_DRIVER=softpipe. Exit 0 agree, 1 differ, 77 no OSMesa context.\n");
            return 0;
        } else {
            fprintf(stderr, "mesa_cube: unknown option '%s'\n", argv[i]);
            return 2;
        }
    }
    if (!mesa_gl_init(&g, "mesa_cube", fs_src, QW, NQ / QW)) return SKIP;

    for (f = 0; f < 6; ++f) {
        for (i = 0; i < N * N * 4; ++i) base[f][i] = rnd01();
        faces[f] = (sample_image){N, N, 4, SAMPLE_FORMAT_F32, base[f], 0};
    }
    sample_mip_params_init(&mp);
    if (sample_texture_create_cube(faces, &mp, &tex, NULL) != SAMPLE_OK) return 1;
    sample_texture_info_get(tex, &info);
    glGenTextures(1, &texname);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_CUBE_MAP, texname);
    for (k = 0; k < info.levels; ++k)
        for (f = 0; f < 6; ++f) mesa_gl_upload(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, tex, k, f);
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    if (texsample || dump) {
        if (!dump) {
            if (!mkdtemp(tmpdir)) return 1;
            dump = tmpdir;
        } else {
            mkdir(dump, 0777);
        }
        mesa_dump_levels(dump, tex, 6);
    }

    for (mag = 0; mag < 2; ++mag)
        for (min = 0; min < 6 + 3; ++min)
            for (use_lod = 0; use_lod < 2; ++use_lod) {
                sample_sampler s;
                float d = 0.0f, dc = 0.0f;
                int extra = min - 6, worst = -1, bl;
                sample_sampler_init(&s);
                s.mag_filter = mag ? SAMPLE_LINEAR : SAMPLE_NEAREST;
                s.min_filter = extra < 0 ? (sample_filter)min : SAMPLE_LINEAR_MIPMAP_LINEAR;
                s.options = SAMPLE_OPT_NEAREST_LEVEL_FLOOR; /* Mesa's ⌊λ + ½⌋ */
                if (extra == 0) { s.min_lod = 0.75f; s.max_lod = 2.25f; }
                if (extra == 1) { s.base_level = 1; s.max_level = 3; }
                if (extra == 2) { s.min_filter = SAMPLE_NEAREST_MIPMAP_NEAREST; s.base_level = 2; }
                bl = s.base_level;
                make_queries(q, use_lod, bl);
                for (i = 0; i < NQ; ++i) {
                    memcpy(qt + 12 * i, q + 10 * i, 4 * sizeof(float));
                    memcpy(qt + 12 * i + 4, q + 10 * i + 4, 3 * sizeof(float));
                    qt[12 * i + 7] = 0.0f;
                    memcpy(qt + 12 * i + 8, q + 10 * i + 7, 3 * sizeof(float));
                    qt[12 * i + 11] = 0.0f;
                }
                glBindTexture(GL_TEXTURE_CUBE_MAP, texname);
                mesa_gl_sampler(GL_TEXTURE_CUBE_MAP, &s);
                glUniform1i(glGetUniformLocation(g.prog, "use_lod"), use_lod);
                if (!mesa_gl_render(&g, qt, 3, mesa)) return 1;
                lib_run(tex, &s, q, use_lod, bl, ours, st);
                ++configs;
                for (i = 0; i < NQ; ++i) {
                    int c, corner = touches_corner(q + 10 * i, &s, &st[i]);
                    for (c = 0; c < 4; ++c) {
                        float e = fabsf(mesa[4 * i + c] - ours[4 * i + c]);
                        if (corner) {
                            if (e > dc) dc = e;
                        } else if (!(e <= d)) {
                            d = e;
                            worst = i;
                        }
                    }
                    if (corner) ++corners;
                    else ++compared;
                }
                if (texsample && !use_lod) {
                    float dt = 0.0f;
                    if (!texsample_run(texsample, dump, &s, q, tool)) return 1;
                    ++tool_runs;
                    for (i = 0; i < NQ * 4; ++i)
                        if (!touches_corner(q + 10 * (i / 4), &s, &st[i / 4])) dt = fmaxf(dt, fabsf(mesa[i] - tool[i]));
                    if (dt > worst_tool) worst_tool = dt;
                    if (!(dt <= TOL)) {
                        ++failures;
                        fprintf(stderr, "DIFF %.3g texsample lookup --cube vs mesa, mag %s min %s\n", dt,
                                sample_filter_name(s.mag_filter), sample_filter_name(s.min_filter));
                    }
                }
                if (d > worst_all) worst_all = d;
                if (dc > worst_corner) worst_corner = dc;
                if (!(d <= TOL)) {
                    const float *x = q + 10 * worst;
                    ++failures;
                    fprintf(stderr,
                            "DIFF %.3g mag %s min %s %s [lod %g..%g levels %d..%d]: query %d (R %.9g %.9g %.9g "
                            "lod %g dRdx %g %g %g dRdy %g %g %g): mesa %.9g %.9g %.9g %.9g, libsample %.9g %.9g "
                            "%.9g %.9g (level %d/%d λ %g)\n",
                            d, sample_filter_name(s.mag_filter), sample_filter_name(s.min_filter),
                            use_lod ? "textureLod" : "textureGrad", s.min_lod, s.max_lod, s.base_level, s.max_level,
                            worst, x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], x[8], x[9], mesa[4 * worst],
                            mesa[4 * worst + 1], mesa[4 * worst + 2], mesa[4 * worst + 3], ours[4 * worst],
                            ours[4 * worst + 1], ours[4 * worst + 2], ours[4 * worst + 3], st[worst].level0,
                            st[worst].level1, st[worst].lod);
                } else if (verbose) {
                    fprintf(stderr, "ok %.3g (corners %.3g) mag %s min %s %s\n", d, dc,
                            sample_filter_name(s.mag_filter), sample_filter_name(s.min_filter),
                            use_lod ? "textureLod" : "textureGrad");
                }
            }
    printf("mesa_cube: %d configurations x %d queries: %d compared, max |mesa - libsample| = %.3g (bound %.3g); "
           "%d reach a corner (softpipe's corner rule differs: max difference %.3g)",
           configs, NQ, compared, (double)worst_all, (double)TOL, corners, (double)worst_corner);
    if (tool_runs) printf("; %d texsample lookup --cube runs, max |mesa - texsample| = %.3g", tool_runs, (double)worst_tool);
    printf("; %d over the bound\n", failures);
    sample_texture_destroy(tex);
    mesa_gl_destroy(&g);
    return failures ? 1 : 0;
}
