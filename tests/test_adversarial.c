/*
 * Adversarial queries (DESIGN §10): every filter configuration and
 * wrap mode, on textures of 1×1, 1×N, N×1 and ordinary sizes, against NaN,
 * ±inf, ±1e30, −0.0 and denormals in every coordinate and Jacobian entry,
 * zero, rank-one and 1e20-sized Jacobians, and self-intersecting or
 * inside-out corner quads. Every result must be finite or exactly the
 * border colour, and no query may read more than the documented cap.
 */
#include "check.h"
#include "sample/sample.h"

#include <float.h>
#include <stdlib.h>

static const float specials[] = {
    0.0f, -0.0f, 0.5f, -0.5f, 1.0f, 1e-45f, -1e-45f, 1e-38f, 1e30f, -1e30f,
    FLT_MAX, -FLT_MAX, 1e20f, 3.0f, NAN, INFINITY, -INFINITY,
};
#define NSPEC ((int)(sizeof specials / sizeof specials[0]))

typedef struct { sample_filter min, mag; sample_footprint fp; } config;
static const config configs[] = {
    {SAMPLE_NEAREST, SAMPLE_NEAREST, SAMPLE_FOOTPRINT_NONE},
    {SAMPLE_LINEAR, SAMPLE_LINEAR, SAMPLE_FOOTPRINT_NONE},
    {SAMPLE_NEAREST_MIPMAP_NEAREST, SAMPLE_LINEAR, SAMPLE_FOOTPRINT_NONE},
    {SAMPLE_LINEAR_MIPMAP_NEAREST, SAMPLE_LINEAR, SAMPLE_FOOTPRINT_NONE},
    {SAMPLE_NEAREST_MIPMAP_LINEAR, SAMPLE_NEAREST, SAMPLE_FOOTPRINT_NONE},
    {SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_LINEAR, SAMPLE_FOOTPRINT_NONE},
    {SAMPLE_CUBIC_MIPMAP_LINEAR, SAMPLE_CUBIC, SAMPLE_FOOTPRINT_NONE},
    {SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_LINEAR, SAMPLE_FOOTPRINT_ANISOTROPIC},
    {SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_LINEAR, SAMPLE_FOOTPRINT_BLINN_NEWELL},
    {SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_LINEAR, SAMPLE_FOOTPRINT_EWA},
};
#define NCONF ((int)(sizeof configs / sizeof configs[0]))

static int finite4(const float *v)
{
    return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]) && isfinite(v[3]);
}

static int is_border(const float *v, const float *b) { return memcmp(v, b, 4 * sizeof(float)) == 0; }

static sample_texture *make(int w, int h)
{
    float *px = (float *)malloc(sizeof(float) * 4 * (size_t)w * (size_t)h);
    sample_image im = {w, h, 4, SAMPLE_FORMAT_F32, px, 0};
    sample_mip_params mp;
    sample_texture *t = NULL;
    int k;
    for (k = 0; k < 4 * w * h; ++k) px[k] = (float)((k * 37) % 101) / 100.0f;
    sample_mip_params_init(&mp);
    CHECK(sample_texture_create(&im, &mp, &t, NULL) == SAMPLE_OK, "create %dx%d", w, h);
    free(px);
    return t;
}

/* Pseudo-random but reproducible picks from the specials table. */
static unsigned rng = 12345u;
static float pick(void)
{
    rng = rng * 1103515245u + 12345u;
    return specials[(rng >> 16) % NSPEC];
}

static void run_queries(const sample_texture *t, const char *what)
{
    enum { NQ = 600 };
    static sample_query q[NQ];
    static sample_quad quad[NQ];
    static float out[NQ * 4], ds[NQ * 4], dt[NQ * 4];
    static sample_stats st[NQ];
    int c, w, k, j;
    for (k = 0; k < NQ; ++k) {
        float *f = &q[k].s;
        for (j = 0; j < 6; ++j) f[j] = pick();
        /* Some structured cases among the random ones. */
        if (k % 7 == 0) { q[k].dsdx = q[k].dsdy = 1e20f; q[k].dtdx = -1e20f; q[k].dtdy = 1e20f; }
        if (k % 11 == 0) { q[k].dsdy = q[k].dsdx; q[k].dtdy = q[k].dtdx; } /* rank one */
        if (k % 13 == 0) { q[k].dsdx = q[k].dtdx = q[k].dsdy = q[k].dtdy = 0.0f; }
        for (j = 0; j < 4; ++j) {
            quad[k].st[j][0] = (k % 3) ? q[k].s + pick() * 1e-3f : pick();
            quad[k].st[j][1] = (k % 3) ? q[k].t + pick() * 1e-3f : pick();
        }
        if (k % 5 == 0) { /* self-intersecting bow tie */
            quad[k].st[0][0] = 0.1f; quad[k].st[0][1] = 0.1f;
            quad[k].st[1][0] = 0.9f; quad[k].st[1][1] = 0.9f;
            quad[k].st[2][0] = 0.9f; quad[k].st[2][1] = 0.1f;
            quad[k].st[3][0] = 0.1f; quad[k].st[3][1] = 0.9f;
        }
        if (k % 5 == 1) { /* inside-out (clockwise) large quad */
            quad[k].st[0][0] = -50.0f; quad[k].st[0][1] = -50.0f;
            quad[k].st[1][0] = -50.0f; quad[k].st[1][1] = 50.0f;
            quad[k].st[2][0] = 50.0f; quad[k].st[2][1] = 50.0f;
            quad[k].st[3][0] = 50.0f; quad[k].st[3][1] = -50.0f;
        }
    }
    for (c = 0; c < NCONF; ++c) {
        for (w = 0; w < SAMPLE_WRAP_COUNT; ++w) {
            sample_sampler s;
            sample_batch_args a;
            int use_corners;
            sample_sampler_init(&s);
            s.min_filter = configs[c].min;
            s.mag_filter = configs[c].mag;
            s.footprint = configs[c].fp;
            s.max_anisotropy = 16.0f;
            s.wrap_s = (sample_wrap)w;
            s.wrap_t = (sample_wrap)((w + 3) % SAMPLE_WRAP_COUNT);
            s.border_color[0] = 0.25f; s.border_color[3] = 0.5f;
            for (use_corners = 0; use_corners < 2; ++use_corners) {
                memset(&a, 0, sizeof a);
                a.count = NQ; a.queries = q; a.rgba = out; a.stats = st;
                a.drgba_ds = ds; a.drgba_dt = dt;
                a.corners = use_corners ? quad : NULL;
                CHECK(sample_batch(t, &s, &a) == SAMPLE_OK, "batch");
                for (k = 0; k < NQ; ++k) {
                    CHECK(finite4(&out[4 * k]) || is_border(&out[4 * k], s.border_color),
                          "%s conf %d wrap %d query %d: non-finite (%g %g / %g %g %g %g)", what, c, w, k,
                          (double)q[k].s, (double)q[k].t, (double)q[k].dsdx, (double)q[k].dtdx,
                          (double)q[k].dsdy, (double)q[k].dtdy);
                    /* Texels and border lie in [0, 1]; every filter but the
                     * (overshooting) cubic is a convex combination of them. */
                    if (configs[c].mag != SAMPLE_CUBIC)
                        CHECK(out[4 * k] >= 0.0f && out[4 * k] <= 1.0f, "%s conf %d: value %g outside [0, 1]",
                              what, c, (double)out[4 * k]);
                    CHECK(st[k].texels <= SAMPLE_MAX_FOOTPRINT_TEXELS, "%s conf %d: %u texels > cap", what, c,
                          (unsigned)st[k].texels);
                }
            }
        }
    }
}

static void adversarial_all(void)
{
    static const int sizes[][2] = {{1, 1}, {1, 17}, {17, 1}, {2, 2}, {33, 20}, {64, 64}};
    int k;
    for (k = 0; k < (int)(sizeof sizes / sizeof sizes[0]); ++k) {
        char what[32];
        sample_texture *t = make(sizes[k][0], sizes[k][1]);
        snprintf(what, sizeof what, "%dx%d", sizes[k][0], sizes[k][1]);
        if (t) run_queries(t, what);
        sample_texture_destroy(t);
    }
}

/* The largest texture side is accepted when its bytes fit: 65536 × 1. */
static void maximal_sizes(void)
{
    const int w = SAMPLE_MAX_SIZE;
    unsigned char *px = (unsigned char *)calloc((size_t)w, 1);
    sample_image im = {w, 1, 1, SAMPLE_FORMAT_UNORM8, px, 0};
    sample_mip_params mp;
    sample_texture *t = NULL;
    sample_texture_info inf;
    sample_mip_params_init(&mp);
    CHECK(sample_texture_create(&im, &mp, &t, NULL) == SAMPLE_OK, "65536 x 1");
    sample_texture_info_get(t, &inf);
    CHECK(inf.levels == 17, "65536 wide has 17 levels, got %d", inf.levels);
    if (t) run_queries(t, "65536x1");
    sample_texture_destroy(t);
    im.width = w + 1;
    CHECK(sample_texture_create(&im, &mp, &t, NULL) == SAMPLE_E_TOO_LARGE, "65537 refused");
    free(px);
}

int main(void)
{
    RUN(adversarial_all);
    RUN(maximal_sizes);
    return check_finish();
}
