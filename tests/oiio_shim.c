/*
 * tools/oiio's TextureSystem shim against libsample on the same texels:
 * closest agrees exactly away from texel edges (which also pins the
 * orientation: t = 0 is the first stored row in both), bilinear
 * magnification of the base level agrees within a float rounding bound,
 * the wrap modes map to their OpenGL equivalents, and the formats round
 * the same way. OpenImageIO's backend (tools/backends/oiio.c) writes a
 * texture's own format where asked (bench) and float otherwise (compare,
 * freq), and opens an existing file as it is. The texture files go to the
 * working directory (ctest runs each test in the build tree) and are
 * removed afterwards.
 */
#define _POSIX_C_SOURCE 200809L
#include "backend.h"
#include "check.h"
#include "oiio_ts.h"
#include "sample/sample.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

enum { W = 16, H = 8, NQ = 2000 };

static float texels[W * H * 4];
static char path[128];
static oiio_ts *ts;
static int files; /* texture files written: each gets its own name, as
                   * OIIO caches a file by name for the system's lifetime */

static void file_name(int k, oiio_ts_format fmt)
{
    /* TIFF cannot hold half in OIIO 2.4; OpenEXR cannot hold uint8. */
    snprintf(path, sizeof path, "oiio_shim_%ld_%d.%s", (long)getpid(), k,
             fmt == OIIO_TS_HALF ? "exr" : "tx");
}

/* xorshift32: a fixed, platform-independent sequence. Callers draw each
 * value in its own initializer, in order: the expressions of one braced
 * initializer list are indeterminately sequenced (C11 6.7.9p23), so two
 * rnd() calls in one list need not run left to right on every compiler. */
static uint32_t rng_state = 12345u;
static float rnd(void)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 17;
    rng_state ^= rng_state << 5;
    return (float)(rng_state >> 8) / 16777216.0f;
}

static sample_texture *make_ours(sample_format fmt)
{
    static uint16_t half[W * H * 4];
    static unsigned char u8[W * H * 4];
    sample_image img = {W, H, 4, fmt, texels, 0};
    sample_texture *tex = NULL;
    int k;
    if (fmt == SAMPLE_FORMAT_F16) {
        for (k = 0; k < W * H * 4; ++k) half[k] = sample_float_to_half(texels[k]);
        img.data = half;
    } else if (fmt == SAMPLE_FORMAT_UNORM8 || fmt == SAMPLE_FORMAT_SRGB8) {
        for (k = 0; k < W * H * 4; ++k) u8[k] = (unsigned char)(texels[k] * 255.0f + 0.5f);
        img.data = u8;
    }
    CHECK(sample_texture_create(&img, NULL, &tex, NULL) == SAMPLE_OK, "create %d", (int)fmt);
    return tex;
}

static oiio_ts_tex *make_theirs(oiio_ts_format fmt, sample_wrap ws, sample_wrap wt)
{
    char err[512];
    oiio_ts_tex *t;
    file_name(files++, fmt);
    if (oiio_ts_make_texture(texels, W, H, fmt, ws, wt, path, err, sizeof err) != 0) {
        CHECK(0, "make_texture: %s", err);
        return NULL;
    }
    t = oiio_ts_open(ts, path, err, sizeof err);
    CHECK(t != NULL, "open: %s", err);
    return t;
}

/* A coordinate at a random texel's centre ± 0.4 texel: never within 0.1
 * texel of an edge, where float rounding could pick either neighbour. */
static float off_edge(int n, float lo_period, float periods)
{
    float i = (float)(int)(rnd() * (float)n * periods);
    return lo_period + (i + 0.5f + 0.8f * (rnd() - 0.5f)) / (float)n;
}

/* Closest on every format: exact, including outside [0, 1] for the wraps
 * OIIO shares with OpenGL — except that OIIO turns an 8-bit code into float
 * as code · (1/255), which is an ulp off the correctly rounded code/255
 * that OpenGL asks for (GL 4.6 eq. 2.1) for some codes: one ulp is allowed
 * there, and only there. */
static void closest_exact(void)
{
    static const sample_wrap wraps[] = {SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_MIRRORED_REPEAT,
                                        SAMPLE_WRAP_CLAMP_TO_EDGE, SAMPLE_WRAP_CLAMP_TO_BORDER};
    static const struct { sample_format ours; oiio_ts_format theirs; } fmts[] = {
        {SAMPLE_FORMAT_F32, OIIO_TS_FLOAT}, {SAMPLE_FORMAT_F16, OIIO_TS_HALF},
        {SAMPLE_FORMAT_UNORM8, OIIO_TS_UINT8}};
    size_t f, w, i;
    for (f = 0; f < sizeof fmts / sizeof fmts[0]; ++f) {
        sample_texture *tex = make_ours(fmts[f].ours);
        for (w = 0; w < sizeof wraps / sizeof wraps[0]; ++w) {
            oiio_ts_tex *ot = make_theirs(fmts[f].theirs, wraps[w], wraps[w]);
            static sample_query q[NQ];
            static float a[NQ * 4], b[NQ * 4];
            sample_sampler smp;
            oiio_ts_opts o;
            int bad = 0;
            sample_batch_args args = {0};
            if (!tex || !ot) continue;
            for (i = 0; i < NQ; ++i) {
                float s = off_edge(W, -1.0f, 3.0f), t = off_edge(H, -1.0f, 3.0f);
                sample_query z = {s, t, 0, 0, 0, 0};
                q[i] = z;
            }
            sample_sampler_init(&smp);
            smp.wrap_s = smp.wrap_t = wraps[w];
            smp.min_filter = smp.mag_filter = SAMPLE_NEAREST;
            args.count = NQ;
            args.queries = q;
            args.rgba = a;
            CHECK(sample_batch(tex, &smp, &args) == SAMPLE_OK, "batch");
            oiio_ts_opts_init(&o);
            o.mode = OIIO_TS_CLOSEST;
            o.wrap_s = o.wrap_t = wraps[w];
            CHECK(oiio_ts_sample(ts, ot, &o, q, NQ, b, NULL, 0) == 0, "oiio sample");
            for (i = 0; i < NQ * 4 && bad < 5; ++i)
                if (a[i] != b[i] && !(fmts[f].ours == SAMPLE_FORMAT_UNORM8 &&
                                      b[i] == nextafterf(a[i], b[i]))) {
                    CHECK(a[i] == b[i], "%s %s query (%.6f, %.6f) ch %d: ours %.9g oiio %.9g",
                          sample_format_name(fmts[f].ours), sample_wrap_name(wraps[w]),
                          (double)q[i / 4].s, (double)q[i / 4].t, (int)(i % 4), (double)a[i],
                          (double)b[i]);
                    bad++;
                }
        }
        sample_texture_destroy(tex);
    }
}

/* Bilinear magnification of the base level, float texels in [0, 1]: both
 * blend in float but not with the same sequence of operations, so results
 * may differ by a few roundings of values below 1. Bound: 4 ulps of 1
 * (4·FLT_EPSILON); measured worst over these queries: 1 ulp. */
static void bilinear_close(void)
{
    static sample_query q[NQ];
    static float a[NQ * 4], b[NQ * 4];
    sample_texture *tex = make_ours(SAMPLE_FORMAT_F32);
    oiio_ts_tex *ot = make_theirs(OIIO_TS_FLOAT, SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_REPEAT);
    sample_sampler smp;
    oiio_ts_opts o;
    sample_batch_args args = {0};
    double worst = 0.0;
    size_t i;
    if (!tex || !ot) return;
    for (i = 0; i < NQ; ++i) {
        float s = rnd() * 3.0f - 1.0f, t = rnd() * 3.0f - 1.0f;
        sample_query z = {s, t, 0, 0, 0, 0};
        q[i] = z;
    }
    sample_sampler_init(&smp);
    smp.min_filter = smp.mag_filter = SAMPLE_LINEAR;
    args.count = NQ;
    args.queries = q;
    args.rgba = a;
    CHECK(sample_batch(tex, &smp, &args) == SAMPLE_OK, "batch");
    oiio_ts_opts_init(&o);
    o.mode = OIIO_TS_BILINEAR;
    CHECK(oiio_ts_sample(ts, ot, &o, q, NQ, b, NULL, 0) == 0, "oiio sample");
    for (i = 0; i < NQ * 4; ++i) {
        double d = fabs((double)a[i] - (double)b[i]);
        if (d > worst) worst = d;
    }
    CHECK(worst <= 4.0 * FLT_EPSILON, "bilinear worst difference %.3g", worst);
    sample_texture_destroy(tex);
}

/* What has no OIIO equivalent is refused, with a message. */
static void unsupported(void)
{
    char err[256] = "";
    oiio_ts_opts o;
    oiio_ts_tex *ot = make_theirs(OIIO_TS_FLOAT, SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_REPEAT);
    sample_query q = {0.5f, 0.5f, 0, 0, 0, 0};
    float r[4];
    CHECK(oiio_ts_wrap_supported(SAMPLE_WRAP_CLAMP) == 0, "GL_CLAMP has no OIIO twin");
    CHECK(oiio_ts_wrap_supported(SAMPLE_WRAP_MIRRORED_REPEAT) == 1, "mirror");
    oiio_ts_opts_init(&o);
    o.wrap_t = SAMPLE_WRAP_MIRROR_CLAMP_TO_EDGE;
    CHECK(oiio_ts_sample(ts, ot, &o, &q, 1, r, err, sizeof err) == -1, "refused");
    CHECK(strstr(err, "mirror_clamp_to_edge") != NULL, "message names the mode: %s", err);
    file_name(files++, OIIO_TS_FLOAT);
    CHECK(oiio_ts_make_texture(texels, W, H, OIIO_TS_HALF, SAMPLE_WRAP_REPEAT,
                               SAMPLE_WRAP_REPEAT, path, err, sizeof err) == -1, "half in TIFF");
    CHECK(strstr(err, "half") != NULL, "message says why: %s", err);
    CHECK(oiio_ts_make_texture(texels, W, H, OIIO_TS_FLOAT, SAMPLE_WRAP_CLAMP,
                               SAMPLE_WRAP_REPEAT, path, err, sizeof err) == -1, "make refused");
    CHECK(oiio_ts_open(ts, "/nonexistent/x.tx", err, sizeof err) == NULL, "missing file");
    CHECK(strstr(err, "/nonexistent/x.tx") != NULL, "message names the file: %s", err);
    CHECK(oiio_ts_mode_parse("aniso") == OIIO_TS_ANISO, "parse");
    CHECK(oiio_ts_mode_parse("nope") == -1, "parse unknown");
}

/* Every texel centre of a W × H texture, OpenImageIO's closest through
 * backend b on x, into out (W·H·4). */
static void backend_texels(tool_backend *b, tool_backend_tex *x, float *out)
{
    static sample_query q[W * H];
    tool_backend_batch a;
    char err[256] = "";
    int i, j;
    for (j = 0; j < H; ++j)
        for (i = 0; i < W; ++i)
            q[j * W + i] = (sample_query){(i + 0.5f) / W, (j + 0.5f) / H, 1.0f / W, 0, 0, 1.0f / H};
    tool_backend_batch_init(&a, W * H, q, NULL, out, NULL);
    CHECK(tool_backend_run(b, x, &a, NULL, err, sizeof err) == 0, "backend run: %s", err);
}

static int ends_with(const char *s, const char *tail)
{
    size_t n = strlen(s), m = strlen(tail);
    return n >= m && strcmp(s + n - m, tail) == 0;
}

/* The backend's files: a native-format store gives OpenImageIO an sRGB
 * texture's stored codes (read as code/255, up to the ulp closest_exact
 * allows) and a half texture's halves; the default store the decoded
 * floats. A texture a row holds is found again; an existing file is
 * opened as it is; a wrap mode without an equivalent is n/a. */
static void backend_files(void)
{
    static const sample_format fmts[] = {SAMPLE_FORMAT_SRGB8, SAMPLE_FORMAT_F16};
    static float nat[W * H * 4], flt[W * H * 4], again[W * H * 4];
    tool_oiio_store *sn, *sf;
    tool_backend bn, bf;
    oiio_ts_opts o;
    sample_sampler smp;
    char err[256] = "";
    int f, k;
    sn = tool_oiio_store_open_in(0.0, ".", err, sizeof err);
    sf = tool_oiio_store_open_in(0.0, ".", err, sizeof err);
    CHECK(sn && sf, "stores: %s", err);
    if (!sn || !sf) return;
    tool_oiio_store_native_formats(sn);
    oiio_ts_opts_init(&o);
    o.mode = OIIO_TS_CLOSEST;
    CHECK(tool_backend_oiio_open(&bn, sn, &o, err, sizeof err) == 0 &&
          tool_backend_oiio_open(&bf, sf, &o, err, sizeof err) == 0, "open: %s", err);
    sample_sampler_init(&smp);
    for (f = 0; f < 2; ++f) {
        sample_texture *tex = make_ours(fmts[f]);
        tool_backend_tex *xn = NULL, *xf = NULL, *x2 = NULL;
        int srgb = fmts[f] == SAMPLE_FORMAT_SRGB8, far = 0;
        if (!tex) continue;
        CHECK(tool_backend_prepare(&bn, tex, &smp, &xn, NULL, err, sizeof err) == 0 &&
              tool_backend_prepare(&bf, tex, &smp, &xf, NULL, err, sizeof err) == 0, "prepare: %s", err);
        if (!xn || !xf) continue;
        CHECK(ends_with(tool_oiio_file(xn), srgb ? ".tx" : ".exr") && ends_with(tool_oiio_file(xf), ".exr"),
              "file names %s %s", tool_oiio_file(xn), tool_oiio_file(xf));
        backend_texels(&bn, xn, nat);
        backend_texels(&bf, xf, flt);
        for (k = 0; k < W * H * 4; ++k) {
            float dec[4], code = (float)(unsigned char)(texels[k] * 255.0f + 0.5f) / 255.0f;
            sample_texture_texel(tex, 0, (k / 4) % W, k / 4 / W, dec);
            if (srgb)
                CHECK(fabsf(nat[k] - code) <= FLT_EPSILON, "srgb8 texel %d: %.9g, code/255 %.9g", k, nat[k], code);
            else
                CHECK(nat[k] == dec[k % 4], "half texel %d: %.9g, stored %.9g", k, nat[k], dec[k % 4]);
            CHECK(flt[k] == dec[k % 4], "float file texel %d: %.9g, decoded %.9g", k, flt[k], dec[k % 4]);
            far += fabsf(nat[k] - flt[k]) > 1e-3f;
        }
        CHECK(srgb ? far > 0 : far == 0, "%d texels apart between the native and the float file", far);
        CHECK(tool_backend_prepare(&bn, tex, &smp, &x2, NULL, err, sizeof err) == 0 && x2 &&
              strcmp(tool_oiio_file(x2), tool_oiio_file(xn)) == 0, "the held texture's file again");
        if (x2) tool_backend_release(&bn, x2);
        x2 = NULL;
        CHECK(tool_backend_oiio_prepare_file(&bf, tool_oiio_file(xn), &smp, &x2, err, sizeof err) == 0,
              "existing file: %s", err);
        if (x2) {
            backend_texels(&bf, x2, again);
            CHECK(memcmp(again, nat, sizeof nat) == 0, "the existing file read as it is");
            tool_backend_release(&bf, x2);
        }
        smp.wrap_s = SAMPLE_WRAP_MIRROR_CLAMP_TO_EDGE;
        CHECK(tool_backend_oiio_prepare_file(&bf, tool_oiio_file(xn), &smp, &x2, err, sizeof err) ==
                      TOOL_BACKEND_NA && strstr(err, "mirror_clamp_to_edge"), "n/a: %s", err);
        smp.wrap_s = SAMPLE_WRAP_REPEAT;
        tool_backend_release(&bn, xn);
        tool_backend_release(&bf, xf);
        sample_texture_destroy(tex);
    }
    tool_backend_close(&bn);
    tool_backend_close(&bf);
    tool_oiio_store_close(sn);
    tool_oiio_store_close(sf);
}

int main(void)
{
    int k;
    for (k = 0; k < W * H * 4; ++k) texels[k] = rnd();
    ts = oiio_ts_create(0);
    if (!ts) {
        fprintf(stderr, "cannot create a TextureSystem\n");
        return 1;
    }
    RUN(closest_exact);
    RUN(bilinear_close);
    RUN(unsupported);
    RUN(backend_files);
    oiio_ts_destroy(ts);
    for (k = 0; k < files; ++k) {
        file_name(k, OIIO_TS_FLOAT);
        remove(path);
        file_name(k, OIIO_TS_HALF);
        remove(path);
    }
    return check_finish();
}
