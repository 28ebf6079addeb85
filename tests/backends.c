/*
 * The backends of tools/backend.h (doc/backends.md), in one process so that
 * llvmpipe starts once:
 *
 *   - OpenGL through EGL (Mesa llvmpipe) reproduces libsample's GL-exact
 *     bilinear and trilinear filters on the same levels and queries within
 *     GL_TOL (below);
 *   - an outside program round-trips: `texsample lookup` as the program
 *     gives libsample's values bit for bit, tools/examples/bilinear.py
 *     gives GL_LINEAR within float rounding, and says "n/a" (exit 3) for a
 *     wrap mode it lacks;
 *   - a missing device, a failing program, a program that writes the wrong
 *     amount are errors with a clear message, and `texsample freq` exits 1
 *     with it;
 *   - the interface's whole batch (tool_backend_run): libsample's backend
 *     gives sample_batch's values bit for bit, stochastic draws and
 *     texel counts included; a backend without `run` (a program) answers
 *     a plain 2D batch and is n/a with the reason for direction queries,
 *     stochastic draws and environment maps; libsample's backend over a
 *     caller's batch function passes its context.
 *
 *   backends TEXSAMPLE EXAMPLE_DIR OUT_DIR
 *
 * Exit 77 when no OpenGL context can be made here (the other parts still
 * run and are checked).
 */
#define _POSIX_C_SOURCE 200809L
#include "backend.h"
#include "check.h"
#include "filters.h"
#include "query_gen.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NQ 512
#define TW 32
#define TH 16

/* llvmpipe against libsample, results in [0, 1]. Both evaluate GL 4.6
 * §8.14 in float from the same texels: the coordinate u = s·w − ½, its
 * floor and fraction, the lerps, and for trilinear λ = log2 ρ and the level
 * blend. llvmpipe takes λ as ½·log2(ρ²) with a fast log2 (exponent plus
 * the mantissa's fraction, linear in between: λ low by up to ½ · 0.086,
 * doc/backends.md), exact where ρ² is a power of two; the queries
 * keep ρ = 2^(k/2) so that λ ∈ {k, k + ½} on both sides, up to the rounding
 * of √2. What is left is the order of the float operations in the lerps
 * (a + w(b − a) against (1 − w)a + wb) and λ's last bit: each rounds by
 * 2^−24 relative, a handful of them give a few units in the last place of
 * 1.0. 2e-6 is 32 such units; the measured maximum is printed. */
#define GL_TOL 2e-6f

static const char *texsample, *examples, *outdir;

static sample_texture *random_texture(void)
{
    static float px[TW * TH * 4];
    sample_image img = {0};
    sample_mip_params mip;
    sample_texture *tex = NULL;
    sample_error err;
    int k;
    for (k = 0; k < TW * TH * 4; ++k) px[k] = frand(0.0f, 1.0f);
    img.width = TW;
    img.height = TH;
    img.channels = 4;
    img.format = SAMPLE_FORMAT_F32;
    img.data = px;
    sample_mip_params_init(&mip);
    if (sample_texture_create(&img, &mip, &tex, &err) != SAMPLE_OK) return NULL;
    return tex;
}

/* A texel-space scale 2^(k/2), k in [−4, 8]: ρ² a power of two (GL_TOL). */
static float half_octave(void)
{
    int k = (int)(rnd() % 13) - 4;
    return ldexpf(k % 2 ? 1.41421356f : 1.0f, (k - (k % 2 + 2) % 2) / 2);
}

/* Axis-aligned Jacobians, ρ = 2^(k/2) on each axis (GL_TOL). */
static void make_queries(sample_query *q, int n)
{
    int i;
    for (i = 0; i < n; ++i) {
        float a = half_octave(), b = half_octave();
        q[i].s = -1.25f + 3.5f * frand(0.0f, 1.0f);
        q[i].t = -1.25f + 3.5f * frand(0.0f, 1.0f);
        q[i].dsdx = a / TW;
        q[i].dtdx = 0.0f;
        q[i].dsdy = 0.0f;
        q[i].dtdy = b / TH;
    }
}

/* Largest |difference| of n RGBA results. */
static float max_diff(const float *a, const float *b, int n)
{
    float m = 0.0f;
    int k;
    for (k = 0; k < 4 * n; ++k) {
        float d = fabsf(a[k] - b[k]);
        if (!(d <= m)) m = d;
    }
    return m;
}

/* libsample's results of a registry entry with these wraps. */
static void lib_results(const sample_texture *tex, const sample_sampler *s, const sample_query *q,
                        int n, float *out)
{
    sample_batch_args a = {0};
    a.count = (size_t)n;
    a.queries = q;
    a.rgba = out;
    CHECK(sample_batch(tex, s, &a) == SAMPLE_OK, "sample_batch");
}

static void sampler_of(const char *name, sample_wrap ws, sample_wrap wt, sample_sampler *s)
{
    const tool_filter *f = tool_filter_by_name(name);
    sample_sampler_init(s);
    s->wrap_s = ws;
    s->wrap_t = wt;
    if (f) tool_filter_apply(f, s);
    CHECK(f != NULL, "registry entry %s", name);
}

/* Run one backend on one configuration; its status, results in out. */
static int backend_results(tool_backend *b, const sample_texture *tex, const sample_sampler *s,
                           const sample_query *q, int n, float *out, char *err, size_t errlen)
{
    tool_backend_tex *x = NULL;
    int rc = tool_backend_prepare(b, tex, s, &x, NULL, err, errlen);
    if (rc != 0) return rc;
    rc = tool_backend_sample(b, x, q, (size_t)n, out, NULL, NULL, err, errlen);
    tool_backend_release(b, x);
    return rc;
}

static sample_texture *tex;
static sample_query queries[NQ];
static int gl_ok; /* an OpenGL context could be made here */

static void test_gl(void)
{
    static const struct {
        const char *filter;
        sample_wrap ws, wt;
    } cfg[] = {
        {"bilinear", SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_REPEAT},
        {"bilinear", SAMPLE_WRAP_CLAMP_TO_EDGE, SAMPLE_WRAP_MIRRORED_REPEAT},
        {"trilinear", SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_REPEAT},
        {"trilinear", SAMPLE_WRAP_MIRRORED_REPEAT, SAMPLE_WRAP_CLAMP_TO_BORDER},
        {"nearest_mipmap_nearest", SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_CLAMP_TO_EDGE},
    };
    static float want[4 * NQ], got[4 * NQ];
    tool_backend gl;
    sample_sampler s;
    char err[512];
    size_t k;
    int rc;
    if (!tool_backend_gl_available()) {
        check_skip("this build has no OpenGL backend (EGL not found at configure time)");
        return;
    }
    /* A device that is not there: an error that says so. */
    rc = tool_backend_gl_open(&gl, "no-such-device-xyz", err, sizeof err);
    CHECK(rc == TOOL_BACKEND_ERROR && strstr(err, "no device matches 'no-such-device-xyz'"),
          "missing device: %d, %s", rc, err);
    if (tool_backend_gl_open(&gl, NULL, err, sizeof err) != 0) {
        char why[600];
        snprintf(why, sizeof why, "no OpenGL context here: %s", err);
        check_skip(why);
        return;
    }
    printf("OpenGL: %s\n", gl.driver);
    gl_ok = 1;
    for (k = 0; k < sizeof cfg / sizeof cfg[0]; ++k) {
        float d;
        sampler_of(cfg[k].filter, cfg[k].ws, cfg[k].wt, &s);
        s.border_color[0] = 0.25f;
        s.border_color[3] = 1.0f;
        lib_results(tex, &s, queries, NQ, want);
        rc = backend_results(&gl, tex, &s, queries, NQ, got, err, sizeof err);
        CHECK(rc == 0, "gl %s: %s", cfg[k].filter, err);
        d = max_diff(want, got, NQ);
        printf("gl %-24s %-16s %-16s max |gl - libsample| %.3g\n", cfg[k].filter,
               sample_wrap_name(cfg[k].ws), sample_wrap_name(cfg[k].wt), (double)d);
        CHECK(rc == 0 && d <= GL_TOL, "gl %s (%s/%s): %.3g over %.3g", cfg[k].filter,
              sample_wrap_name(cfg[k].ws), sample_wrap_name(cfg[k].wt), (double)d, (double)GL_TOL);
    }
    /* What GL's core profile lacks is "n/a" with the reason. */
    sampler_of("trilinear", SAMPLE_WRAP_CLAMP, SAMPLE_WRAP_REPEAT, &s);
    rc = backend_results(&gl, tex, &s, queries, 4, got, err, sizeof err);
    CHECK(rc == TOOL_BACKEND_NA && strstr(err, "clamp"), "GL_CLAMP n/a: %d %s", rc, err);
    sampler_of("ewa", SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_REPEAT, &s);
    rc = backend_results(&gl, tex, &s, queries, 4, got, err, sizeof err);
    CHECK(rc == TOOL_BACKEND_NA && strstr(err, "ewa"), "EWA n/a: %d %s", rc, err);
    tool_backend_close(&gl);
}

static void test_program(void)
{
    static float want[4 * NQ], got[4 * NQ];
    tool_backend p;
    sample_sampler s;
    char cmd[1400], err[1024];
    int rc;
    /* texsample lookup speaks the protocol: libsample's trilinear, exactly. */
    snprintf(cmd, sizeof cmd, "'%s' lookup --min linear_mipmap_linear --mag linear", texsample);
    CHECK(tool_backend_program_open(&p, cmd, err, sizeof err) == 0, "open: %s", err);
    sampler_of("trilinear", SAMPLE_WRAP_MIRRORED_REPEAT, SAMPLE_WRAP_CLAMP_TO_BORDER, &s);
    s.border_color[1] = 0.5f;
    lib_results(tex, &s, queries, NQ, want);
    rc = backend_results(&p, tex, &s, queries, NQ, got, err, sizeof err);
    CHECK(rc == 0 && memcmp(want, got, sizeof want) == 0, "lookup round trip: %d %s, max %.3g", rc,
          err, (double)max_diff(want, got, NQ));
    tool_backend_close(&p);

    /* The example program: GL_LINEAR in Python, in double. */
    snprintf(cmd, sizeof cmd, "python3 '%s/bilinear.py'", examples);
    CHECK(tool_backend_program_open(&p, cmd, err, sizeof err) == 0, "open: %s", err);
    sampler_of("bilinear", SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_CLAMP_TO_EDGE, &s);
    lib_results(tex, &s, queries, NQ, want);
    rc = backend_results(&p, tex, &s, queries, NQ, got, err, sizeof err);
    if (rc == TOOL_BACKEND_ERROR && strstr(err, "status 127")) {
        check_skip("no python3 for the example program");
    } else {
        /* libsample's float lerps against Python's double ones. */
        CHECK(rc == 0 && max_diff(want, got, NQ) <= 1e-6f, "bilinear.py: %d %s, max %.3g", rc, err,
              (double)max_diff(want, got, NQ));
        sampler_of("bilinear", SAMPLE_WRAP_MIRRORED_REPEAT, SAMPLE_WRAP_REPEAT, &s);
        rc = backend_results(&p, tex, &s, queries, 4, got, err, sizeof err);
        CHECK(rc == TOOL_BACKEND_NA && strstr(err, "not mirrored_repeat"), "example n/a: %d %s", rc, err);
    }
    tool_backend_close(&p);

    /* Row names: their own, once. */
    {
        tool_program_row rows[2];
        CHECK(tool_program_row_parse("mine=true", rows, 0, err, sizeof err) == 0 &&
                  strcmp(rows[0].name, "mine") == 0 && strcmp(rows[0].command, "true") == 0,
              "NAME=COMMAND: %s", err);
        CHECK(tool_program_row_parse("mine=false", rows, 1, err, sizeof err) < 0 &&
                  strstr(err, "two rows are called 'mine'"), "twice: %s", err);
        CHECK(tool_program_row_parse("trilinear=true", rows, 1, err, sizeof err) < 0 &&
                  strstr(err, "registry"), "registry name: %s", err);
        CHECK(tool_program_row_parse("a/b=true", rows, 1, err, sizeof err) < 0 &&
                  strstr(err, "only letters"), "file-name-safe: %s", err);
        CHECK(tool_program_row_parse("noequals", rows, 1, err, sizeof err) < 0 &&
                  strstr(err, "NAME=COMMAND"), "no '=': %s", err);
    }

    /* Failures: a clear message, never a crash. */
    CHECK(tool_backend_program_open(&p, "echo 'broken sampler' >&2; exit 5", err, sizeof err) == 0,
          "open: %s", err);
    rc = backend_results(&p, tex, &s, queries, 4, got, err, sizeof err);
    CHECK(rc == TOOL_BACKEND_ERROR && strstr(err, "exited with status 5: broken sampler"),
          "failing program: %d %s", rc, err);
    tool_backend_close(&p);
    CHECK(tool_backend_program_open(&p, "true", err, sizeof err) == 0, "open: %s", err);
    rc = backend_results(&p, tex, &s, queries, 4, got, err, sizeof err);
    CHECK(rc == TOOL_BACKEND_ERROR && strstr(err, "wrote no") != NULL, "no output: %d %s", rc, err);
    tool_backend_close(&p);
    CHECK(tool_backend_program_open(&p, "f() { printf 1234 > \"${12}\"; }; f", err, sizeof err) == 0,
          "open: %s", err);
    rc = backend_results(&p, tex, &s, queries, 4, got, err, sizeof err);
    CHECK(rc == TOOL_BACKEND_ERROR && strstr(err, "wrote 4 bytes, not 64"), "short output: %d %s", rc,
          err);
    tool_backend_close(&p);
    /* A program that never ends is killed at the time limit, with what it
     * started (the sleep, a child of the shell): 0.3 s here. */
    setenv("TEXSAMPLE_PROGRAM_TIMEOUT", "0.3", 1);
    CHECK(tool_backend_program_open(&p, "sleep 30; :", err, sizeof err) == 0, "open: %s", err);
    rc = backend_results(&p, tex, &s, queries, 4, got, err, sizeof err);
    CHECK(rc == TOOL_BACKEND_ERROR && strstr(err, "ran past 0.3 s and was killed"), "hung program: %d %s", rc, err);
    tool_backend_close(&p);
    unsetenv("TEXSAMPLE_PROGRAM_TIMEOUT");
}

/* A batch function with a context (tool_backend_libsample_ctx): counts
 * its calls in *ctx. */
static sample_status counted_batch(void *ctx, const sample_texture *t, const sample_sampler *s,
                                   const sample_batch_args *a)
{
    ++*(int *)ctx;
    return sample_batch(t, s, a);
}

static void test_interface(void)
{
    enum { N = 64 };
    tool_backend lib, p;
    tool_backend_tex *x = NULL;
    tool_backend_batch a;
    sample_batch_args want = {0};
    sample_sampler s;
    sample_stats st[N], st_want[N];
    sample_query3 q3[1] = {{{0}, {0}, {0}}};
    float u[N], got[4 * N], ref[4 * N];
    double texels = 0.0, sum = 0.0;
    char err[512], cmd[1200];
    int k, calls = 0;
    sampler_of("ewa", SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_REPEAT, &s);
    for (k = 0; k < N; ++k) u[k] = (float)k / N;
    CHECK(tool_backend_libsample(&lib, NULL) == 0 && lib.thread_safe && lib.counts_texels, "libsample");
    CHECK(tool_backend_prepare(&lib, tex, &s, &x, NULL, err, sizeof err) == 0, "%s", err);
    tool_backend_batch_init(&a, N, queries, NULL, got, st);
    a.u = u;
    a.draws = 3;
    CHECK(tool_backend_run(&lib, x, &a, NULL, err, sizeof err) == 0, "%s", err);
    want.count = N;
    want.queries = queries;
    want.rgba = ref;
    want.stats = st_want;
    want.u = u;
    want.draws = 3;
    CHECK(sample_batch(tex, &s, &want) == SAMPLE_OK, "sample_batch");
    CHECK(memcmp(got, ref, sizeof got) == 0, "stochastic batch through the backend as sample_batch");
    for (k = 0; k < N; ++k) CHECK(st[k].texels == st_want[k].texels, "stats of query %d", k);
    /* tool_backend_sample: deterministic, the texels summed. */
    CHECK(tool_backend_sample(&lib, x, queries, N, got, &texels, NULL, err, sizeof err) == 0, "%s", err);
    want.u = NULL;
    CHECK(sample_batch(tex, &s, &want) == SAMPLE_OK, "sample_batch");
    for (k = 0; k < N; ++k) sum += st_want[k].texels;
    CHECK(memcmp(got, ref, sizeof got) == 0 && texels == sum, "texels %g, want %g", texels, sum);
    tool_backend_release(&lib, x);
    tool_backend_close(&lib);

    /* libsample through a caller's batch function and its context (bench
     * --cache-mb: a texture system's): the function's values and context,
     * direction queries n/a. */
    CHECK(tool_backend_libsample_ctx(&lib, counted_batch, &calls, "counted") == 0 &&
              strstr(lib.driver, "counted") && lib.thread_safe,
          "libsample with a context: %s", lib.driver);
    CHECK(tool_backend_prepare(&lib, tex, &s, &x, NULL, err, sizeof err) == 0, "%s", err);
    tool_backend_batch_init(&a, N, queries, NULL, got, NULL);
    CHECK(tool_backend_run(&lib, x, &a, NULL, err, sizeof err) == 0 && calls == 1, "%s", err);
    CHECK(memcmp(got, ref, sizeof got) == 0, "the context's batch as sample_batch");
    tool_backend_batch_init(&a, 1, NULL, q3, got, NULL);
    CHECK(tool_backend_run(&lib, x, &a, NULL, err, sizeof err) == TOOL_BACKEND_NA &&
              strstr(err, "no direction or volume queries") && calls == 1,
          "direction queries: %s", err);
    tool_backend_release(&lib, x);
    tool_backend_close(&lib);

    /* A program has `sample` alone. */
    sampler_of("bilinear", SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_REPEAT, &s);
    snprintf(cmd, sizeof cmd, "'%s' lookup --min linear --mag linear", texsample);
    CHECK(tool_backend_program_open(&p, cmd, err, sizeof err) == 0, "open: %s", err);
    CHECK(!p.thread_safe, "a program is called from one thread");
    CHECK(tool_backend_prepare_env(&p, tex, &s, &x, NULL, err, sizeof err) == TOOL_BACKEND_NA &&
              strcmp(err, "no environment maps") == 0,
          "environment map: %s", err);
    CHECK(tool_backend_prepare(&p, tex, &s, &x, NULL, err, sizeof err) == 0, "%s", err);
    tool_backend_batch_init(&a, 1, NULL, q3, got, NULL);
    CHECK(tool_backend_run(&p, x, &a, NULL, err, sizeof err) == TOOL_BACKEND_NA &&
              strcmp(err, "no direction or volume queries") == 0,
          "direction queries: %s", err);
    tool_backend_batch_init(&a, 4, queries, NULL, got, NULL);
    a.u = u;
    CHECK(tool_backend_run(&p, x, &a, NULL, err, sizeof err) == TOOL_BACKEND_NA &&
              strcmp(err, "no stochastic draws") == 0,
          "stochastic draws: %s", err);
    a.u = NULL;
    CHECK(tool_backend_run(&p, x, &a, NULL, err, sizeof err) == 0, "plain 2D batch: %s", err);
    lib_results(tex, &s, queries, 4, ref);
    CHECK(memcmp(got, ref, 16 * sizeof *got) == 0, "the program's 2D batch as libsample's");
    tool_backend_release(&p, x);
    tool_backend_close(&p);
}

/* The RMSE field of results.csv's row `config` of scene plane, or "". */
static void csv_rmse(const char *csv, const char *config, char *out, size_t len)
{
    char key[64];
    const char *p, *q;
    snprintf(key, sizeof key, "\nplane,%s,\"", config);
    out[0] = '\0';
    /* scene,config,"label",rmse,...: the field after the quoted label. */
    if (!csv || !(p = strstr(csv, key)) || !(p = strchr(p + strlen(key), '"'))) return;
    if (!(p = strchr(p, ','))) return;
    q = strchr(++p, ',');
    snprintf(out, len, "%.*s", q ? (int)(q - p) : 0, p);
}

/* The tools: rows in compare's table, errors as exit 1 with the message
 * (a process of texsample-image each, so only two: the messages of the
 * other failures are checked above, where they are made). The program row
 * is `texsample lookup` (python3 may be missing; the example ran above). */
static void test_cli(void)
{
    char cmd[3000], *csv, a[64], b[64];
    int rc;
    snprintf(cmd, sizeof cmd,
             "'%s' compare --scene plane --size 8 --truth-samples 2 --runs 1 --threads 1 "
             "--configs bilinear%s --backend-program \"lookup='%s' lookup --min linear --mag linear\" "
             "--backend-program 'na=echo cannot here; exit 3' --out '%s/cmp' "
             ">/dev/null 2>&1",
             texsample, gl_ok ? ",gl-bilinear" : "", texsample, outdir);
    rc = check_shell(cmd);
    CHECK(rc == 0, "compare with backend rows: %d", rc);
    snprintf(cmd, sizeof cmd, "%s/cmp", outdir);
    csv = check_slurp_in(cmd, "results.csv");
    csv_rmse(csv, "bilinear", a, sizeof a);
    csv_rmse(csv, "lookup", b, sizeof b);
    CHECK(a[0] && strcmp(a, b) == 0, "the program's row scores as libsample's: '%s' '%s'", a, b);
    CHECK(csv && strstr(csv, "\"n/a: cannot here\"") && strstr(csv, ",na,"),
          "a program that cannot is a row n/a with its reason");
    if (gl_ok) {
        csv_rmse(csv, "gl-bilinear", b, sizeof b);
        CHECK(b[0] && strcmp(a, b) == 0, "the OpenGL row scores as libsample's: '%s' '%s'", a, b);
    }
    free(csv);
    snprintf(cmd, sizeof cmd,
             "'%s' freq --quick --filters bilinear --backend-program 'bad=exit 9' --out '%s/fq' "
             "2>'%s/fq.err' >/dev/null",
             texsample, outdir, outdir);
    CHECK(check_shell(cmd) == 1, "freq with a failing program exits 1");
    snprintf(cmd, sizeof cmd, "%s/fq.err", outdir);
    csv = check_slurp(cmd, NULL);
    CHECK(csv && strstr(csv, "bad: program 'exit 9' exited with status 9"), "freq says why: %s",
          csv ? csv : "");
    free(csv);
}

int main(int argc, char **argv)
{
    if (argc != 4) {
        fprintf(stderr, "usage: backends TEXSAMPLE EXAMPLE_DIR OUT_DIR\n");
        return 2;
    }
    texsample = argv[1];
    examples = argv[2];
    outdir = argv[3];
    tex = random_texture();
    CHECK(tex != NULL, "texture");
    if (!tex) return check_finish();
    make_queries(queries, NQ);
    RUN(test_gl);
    RUN(test_program);
    RUN(test_interface);
    RUN(test_cli);
    sample_texture_destroy(tex);
    return check_finish();
}
