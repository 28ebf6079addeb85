/*
 * Cross-check of libsample's OpenGL filters against Mesa's softpipe
 * (doc/mip-and-lod.md, "How to check lookup against Mesa").
 *
 * An OSMesa context renders one fragment per query into an RGBA32F
 * framebuffer; the fragment shader fetches its query from an RGBA32F
 * texture (exact floats, no interpolation) and calls textureGrad or
 * textureLod on a random RGBA32F texture whose levels are uploaded
 * explicitly (libsample's box pyramid, so both sides read the same texels).
 * Every wrap mode × mag filter × min filter is compared with sample_batch on
 * the same texels, state and queries; with --texsample the same queries also
 * go through `texsample lookup` by files.
 *
 *   GALLIUM_DRIVER=softpipe mesa_check [--texsample PATH] [--dump DIR] [-v]
 *
 * Exit 0: agreement; 1: a difference over the bound; 77: no usable OSMesa
 * context (ctest SKIP).
 */
#include "mesa_gl.h"

#include "sample/sample.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define SKIP 77
#define QW 32        /* framebuffer width: queries per row */
#define NQ 512       /* queries per configuration */
/* Agreement bound on results in [0, 1] (doc/mip-and-lod.md): softpipe
 * evaluates the same formulas in float with a different operation order
 * (lerps as a + w(b − a), two nested lerps for bilinear, a third for the
 * level blend): each rounds by ≤ 2^-24 relative, a handful of them give a
 * few units in the last place of 1.0. 1e-6 is 16 such units; the measured
 * maximum is 1.8e-7. */
#define TOL 1e-6f

/* Texture under test: power-of-two so that textureGrad's ρ is exact in
 * both implementations (doc: softpipe takes log2 with a 16-bit mantissa
 * table, exact for the ρ values generated here). */
#define TW 16
#define TH 8

static int verbose;

static uint32_t rng = 12345u;
static uint32_t rnd_u32(void) { return mesa_rnd_u32(&rng); }
static float rnd01(void) { return mesa_rnd01(&rng); }

/* ---- GL plumbing (mesa_gl.h) ---------------------------------------------- */

/* Query i sits at fragment (i mod QW, i / QW); its two RGBA32F texels are
 * (s, t, ds/dx, dt/dx) and (ds/dy, dt/dy, lod, 0). */
static const char *fs_src =
    "#version 330 core\n"
    "uniform sampler2D tex;\n"
    "uniform sampler2D qtex;\n"
    "uniform int use_lod;\n"
    "out vec4 color;\n"
    "void main() {\n"
    "  ivec2 p = ivec2(gl_FragCoord.xy);\n"
    "  vec4 a = texelFetch(qtex, ivec2(2 * p.x, p.y), 0);\n"
    "  vec4 b = texelFetch(qtex, ivec2(2 * p.x + 1, p.y), 0);\n"
    "  if (use_lod != 0) color = textureLod(tex, a.xy, b.z);\n"
    "  else color = textureGrad(tex, a.xy, a.zw, b.xy);\n"
    "}\n";

typedef struct gl_state {
    mesa_gl m;
    GLuint tex;
} gl_state;

static int gl_init(gl_state *g)
{
    if (!mesa_gl_init(&g->m, "mesa_check", fs_src, QW, NQ / QW)) return 0;
    glGenTextures(1, &g->tex);
    return glGetError() == GL_NO_ERROR;
}

static void gl_upload_levels(gl_state *g, const sample_texture *tex)
{
    sample_texture_info info;
    int k;
    sample_texture_info_get(tex, &info);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, g->tex);
    for (k = 0; k < info.levels; ++k) mesa_gl_upload(GL_TEXTURE_2D, tex, k, 0);
}

/* Render the NQ queries (7 floats each: s t dsdx dtdx dsdy dtdy lod). */
static int gl_render(gl_state *g, const sample_sampler *s, const float *q7, int use_lod, float *out)
{
    static float qt[NQ * 8];
    int i;
    for (i = 0; i < NQ; ++i) {
        memcpy(qt + 8 * i, q7 + 7 * i, 6 * sizeof(float));
        qt[8 * i + 6] = q7[7 * i + 6];
        qt[8 * i + 7] = 0.0f;
    }
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, g->tex);
    mesa_gl_sampler(GL_TEXTURE_2D, s);
    glUniform1i(glGetUniformLocation(g->m.prog, "use_lod"), use_lod);
    return mesa_gl_render(&g->m, qt, 2, out);
}

/* ---- Queries --------------------------------------------------------------- */

/* A coordinate in [−1.25, 2.25]. For the mirror-clamp-to-border pair of
 * EXT_texture_mirror_clamp, |coordinate| ≥ ½ instead: DESIGN §3 takes the
 * extension's s' = max(1/(2N), |s|) as written, softpipe omits the lower
 * bound and blends the border colour within half a texel of s = 0 (a known
 * deviation, doc/mip-and-lod.md); from |s| ≥ ½ the bound is inactive on
 * every level, down to 1 × 1. */
static float coord(sample_wrap w)
{
    if (w == SAMPLE_WRAP_MIRROR_CLAMP || w == SAMPLE_WRAP_MIRROR_CLAMP_TO_BORDER) {
        float a = 0.5f + 1.75f * rnd01();
        return (rnd_u32() & 1) ? -a : a;
    }
    return -1.25f + 3.5f * rnd01();
}

/* A texel-space scale 2^e·(1 + m/256): a mantissa of 8 bits, so that ρ and
 * its logarithm are exact in softpipe's 16-bit log2 table as well. */
static float grad_scale(void) { return mesa_grad_scale(&rng, -2, 5); }

/* textureGrad queries: axis-aligned Jacobians, on the diagonal or the
 * anti-diagonal, where softpipe's ρ (max of |components| per axis) equals
 * the specification's (max of column lengths). */
static void make_grad_queries(float *q7, const sample_sampler *s, int base_w, int base_h)
{
    int i;
    for (i = 0; i < NQ; ++i) {
        float *q = q7 + 7 * i, a = grad_scale(), b = grad_scale();
        q[0] = coord(s->wrap_s);
        q[1] = coord(s->wrap_t);
        q[2] = q[3] = q[4] = q[5] = 0.0f;
        if (rnd_u32() & 1) {
            q[2] = a / (float)base_w; /* ds/dx */
            q[5] = b / (float)base_h; /* dt/dy */
        } else {
            q[3] = a / (float)base_h; /* dt/dx */
            q[4] = b / (float)base_w; /* ds/dy */
        }
        if (rnd_u32() & 1) q[2] = -q[2], q[3] = -q[3];
        q[6] = 0.0f;
    }
}

/* textureLod queries: λ on every switch-over point and at random. */
static void make_lod_queries(float *q7, const sample_sampler *s)
{
    static const float pts[] = {-0.5f, 0.0f, 0.25f, 0.5f - 1.0f / 1024, 0.5f + 1.0f / 1024, 0.75f, 1.0f, 1.25f,
                                1.5f, 2.0f, 2.5f, 3.0f, 3.5f, 4.0f, 4.5f, 6.0f};
    int i;
    for (i = 0; i < NQ; ++i) {
        float *q = q7 + 7 * i;
        q[0] = coord(s->wrap_s);
        q[1] = coord(s->wrap_t);
        q[2] = q[3] = q[4] = q[5] = 0.0f;
        q[6] = (i % 2) ? pts[(i / 2) % (int)(sizeof pts / sizeof pts[0])] : -1.0f + 6.0f * rnd01();
    }
}

/* libsample's view of the same queries. textureLod's λ becomes a per-call
 * bias on a Jacobian with ρ = 1 exactly (dt/dy = 1/h of the base level, a
 * power of two): λ_base = 0, λ = lod, then the lod clamps as in GL. */
static void lib_run(const sample_texture *tex, const sample_sampler *s, const float *q7, int use_lod,
                    float *out)
{
    static sample_query q[NQ];
    static float bias[NQ];
    sample_batch_args a;
    int i, bw, bh;
    sample_texture_level_size(tex, s->base_level, &bw, &bh);
    for (i = 0; i < NQ; ++i) {
        const float *r = q7 + 7 * i;
        q[i] = (sample_query){r[0], r[1], r[2], r[3], r[4], r[5]};
        bias[i] = 0.0f;
        if (use_lod) {
            q[i].dsdx = q[i].dtdx = q[i].dsdy = 0.0f;
            q[i].dtdy = 1.0f / (float)bh;
            bias[i] = r[6];
        }
    }
    memset(&a, 0, sizeof a);
    a.count = NQ;
    a.queries = q;
    a.lod_bias = bias;
    a.rgba = out;
    if (sample_batch(tex, s, &a) != SAMPLE_OK) fprintf(stderr, "mesa_check: sample_batch failed\n");
}

/* ---- texsample lookup by files ------------------------------------------------ */

/* Runs `texsample lookup` on the dumped files; 1 when it ran and `out` holds
 * its results. The command line is printed with -v, to be copied. Only
 * textureGrad queries go through the tool: a query file has no per-query λ
 * (textureLod), and --lod-bias is one value per run. */
static int texsample_run(const char *exe, const char *dir, const sample_sampler *s, const float *q7, float *out)
{
    static float q6[NQ * 6];
    char cmd[8192], path[4096];
    int i;
    for (i = 0; i < NQ; ++i) memcpy(q6 + 6 * i, q7 + 7 * i, 6 * sizeof(float));
    snprintf(path, sizeof path, "%s/queries.bin", dir);
    if (!mesa_write_file(path, q6, sizeof q6)) return 0;
    snprintf(cmd, sizeof cmd,
             "'%s' lookup --raw '%s/tex.raw' --w %d --h %d --levels '%s/tex' --queries '%s/queries.bin' "
             "--out '%s/ours.bin' ",
             exe, dir, TW, TH, dir, dir, dir);
    mesa_sampler_args(cmd + strlen(cmd), sizeof cmd - strlen(cmd), s);
    return mesa_lookup_run(cmd, dir, verbose, out, NQ);
}

/* ---- Comparison ------------------------------------------------------------ */

static float max_diff(const float *a, const float *b, int *worst)
{
    float m = 0.0f;
    int i;
    *worst = 0;
    for (i = 0; i < NQ * 4; ++i) {
        float d = fabsf(a[i] - b[i]);
        if (!(d <= m)) {
            m = d;
            *worst = i / 4;
        }
    }
    return m;
}

int main(int argc, char **argv)
{
    static float q7[NQ * 7], mesa[NQ * 4], ours[NQ * 4], tool[NQ * 4];
    static float base[TW * TH * 4];
    const char *texsample = NULL, *dump = NULL;
    char tmpdir[] = "/tmp/mesa_check.XXXXXX";
    gl_state g;
    sample_image im = {TW, TH, 4, SAMPLE_FORMAT_F32, base, 0};
    sample_mip_params mp;
    sample_texture *tex = NULL;
    int i, w, mag, min, extra, use_lod, configs = 0, failures = 0, tool_runs = 0, stride = 1;
    float worst_all = 0.0f, worst_tool = 0.0f;

    for (i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--texsample") && i + 1 < argc) texsample = argv[++i];
        else if (!strcmp(argv[i], "--dump") && i + 1 < argc) dump = argv[++i];
        else if (!strcmp(argv[i], "--texsample-stride") && i + 1 < argc) stride = atoi(argv[++i]) > 0 ? atoi(argv[i]) : 1;
        else if (!strcmp(argv[i], "-v")) verbose = 1;
        else if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            printf("usage: mesa_check [--texsample PATH [--texsample-stride N]] [--dump DIR] [-v]\n"
                   "Compares sample_batch (and texsample lookup) with Mesa softpipe through OSMesa.\n"
                   "--texsample-stride N runs the program on every Nth configuration only\n"
                   "(each run starts a process that loads the image libraries).\n"
                   "Run with GALLIUM_DRIVER=softpipe. Exit 0 agree, 1 differ, 77 no OSMesa context.\n");
            return 0;
        } else {
            fprintf(stderr, "mesa_check: unknown option '%s'\n", argv[i]);
            return 2;
        }
    }
    if (!gl_init(&g)) return SKIP;

    for (i = 0; i < TW * TH * 4; ++i) base[i] = rnd01();
    sample_mip_params_init(&mp);
    if (sample_texture_create(&im, &mp, &tex, NULL) != SAMPLE_OK) return 1;
    gl_upload_levels(&g, tex);
    if (texsample || dump) {
        if (!dump) {
            if (!mkdtemp(tmpdir)) return 1;
            dump = tmpdir;
        } else {
            mkdir(dump, 0777);
        }
        mesa_dump_levels(dump, tex, 1);
    }

    /* Every wrap mode (both axes) × mag × the six min filters, then extra
     * states for bias, lod clamps and base/max level with trilinear; each
     * with textureGrad and textureLod queries. */
    for (w = 0; w < SAMPLE_WRAP_COUNT; ++w)
        for (mag = 0; mag < 2; ++mag)
            for (min = 0; min < 6 + 5; ++min)
                for (use_lod = 0; use_lod < 2; ++use_lod) {
                    sample_sampler s;
                    int worst;
                    float d;
                    extra = min - 6;
                    sample_sampler_init(&s);
                    s.wrap_s = (sample_wrap)w;
                    s.wrap_t = (sample_wrap)((w + (min % 3 == 2)) % SAMPLE_WRAP_COUNT); /* some mixed pairs */
                    s.mag_filter = mag ? SAMPLE_LINEAR : SAMPLE_NEAREST;
                    s.min_filter = extra < 0 ? (sample_filter)min : SAMPLE_LINEAR_MIPMAP_LINEAR;
                    /* Mesa rounds NEAREST_MIPMAP_* levels as ⌊λ + ½⌋. */
                    s.options = SAMPLE_OPT_NEAREST_LEVEL_FLOOR;
                    s.border_color[0] = 0.25f; s.border_color[1] = 0.5f;
                    s.border_color[2] = 0.75f; s.border_color[3] = 1.0f;
                    if (extra == 0) { s.min_lod = 0.75f; s.max_lod = 2.25f; }
                    if (extra == 1) { s.base_level = 1; s.max_level = 2; }
                    if (extra == 2) { s.min_filter = SAMPLE_NEAREST_MIPMAP_NEAREST; s.base_level = 1; }
                    if (extra == 3) { s.min_lod = -0.5f; s.max_lod = 1.5f; s.base_level = 1; }
                    if (extra == 4) {
                        /* softpipe drops GL_TEXTURE_LOD_BIAS for textureGrad
                         * (doc/mip-and-lod.md); test_lod checks that path
                         * against the specification instead. */
                        if (!use_lod) continue;
                        s.lod_bias = 0.75f;
                    }
                    if (use_lod) make_lod_queries(q7, &s);
                    else make_grad_queries(q7, &s, TW >> s.base_level, TH >> s.base_level);
                    if (!gl_render(&g, &s, q7, use_lod, mesa)) return 1;
                    lib_run(tex, &s, q7, use_lod, ours);
                    d = max_diff(mesa, ours, &worst);
                    ++configs;
                    if (d > worst_all) worst_all = d;
                    if (!(d <= TOL)) {
                        const float *q = q7 + 7 * worst;
                        ++failures;
                        fprintf(stderr,
                                "DIFF %.3g wrap %s/%s mag %s min %s %s [bias %g lod %g..%g levels %d..%d]: query %d (s %.9g t %.9g J %g %g %g %g "
                                "lod %g): mesa %.9g %.9g %.9g %.9g, libsample %.9g %.9g %.9g %.9g\n",
                                d, sample_wrap_name(s.wrap_s), sample_wrap_name(s.wrap_t),
                                sample_filter_name(s.mag_filter), sample_filter_name(s.min_filter),
                                use_lod ? "textureLod" : "textureGrad", s.lod_bias, s.min_lod, s.max_lod,
                                s.base_level, s.max_level, worst, q[0], q[1], q[2], q[3], q[4], q[5],
                                q[6], mesa[4 * worst], mesa[4 * worst + 1], mesa[4 * worst + 2],
                                mesa[4 * worst + 3], ours[4 * worst], ours[4 * worst + 1], ours[4 * worst + 2],
                                ours[4 * worst + 3]);
                    } else if (verbose) {
                        fprintf(stderr, "ok %.3g wrap %s/%s mag %s min %s %s\n", d, sample_wrap_name(s.wrap_s),
                                sample_wrap_name(s.wrap_t), sample_filter_name(s.mag_filter),
                                sample_filter_name(s.min_filter), use_lod ? "textureLod" : "textureGrad");
                    }
                    if (texsample && !use_lod && configs % stride == 0) {
                        if (!texsample_run(texsample, dump, &s, q7, tool)) return 1;
                        d = max_diff(mesa, tool, &worst);
                        ++tool_runs;
                        if (d > worst_tool) worst_tool = d;
                        if (!(d <= TOL)) {
                            ++failures;
                            fprintf(stderr, "DIFF %.3g texsample lookup vs mesa, wrap %s min %s\n", d,
                                    sample_wrap_name(s.wrap_s), sample_filter_name(s.min_filter));
                        }
                    }
                }
    printf("mesa_check: %d configurations x %d queries, max |mesa - libsample| = %.3g (bound %.3g)", configs, NQ,
           (double)worst_all, (double)TOL);
    if (tool_runs) printf("; %d texsample lookup runs, max |mesa - texsample| = %.3g", tool_runs, (double)worst_tool);
    printf("; %d over the bound\n", failures);
    sample_texture_destroy(tex);
    mesa_gl_destroy(&g.m);
    return failures ? 1 : 0;
}
