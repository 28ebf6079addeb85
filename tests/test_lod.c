/*
 * Level of detail and level selection against OpenGL 4.6 §8.14
 * (doc/mip-and-lod.md). The texture's levels are told apart by value
 * (OpenImageIO's texture-filtersize idea): level k ≥ 1 is the constant k + 1;
 * level 0 alternates 1 and 1.5 along s, so at the query point NEAREST reads
 * 1, LINEAR 1.125 and Catmull–Rom 1.078125, and the value also shows whether
 * the magnification or the minification filter ran on level 0.
 *
 * Jacobians have ρ an exact power of two, so λ_base is an exact integer;
 * fractional λ comes from biases or the lod clamps, which are exact in float.
 */
#include "check.h"
#include "internal.h"

#include <stdlib.h>

#define N0 16   /* level 0 is N0 × N0 */
#define NLEV 5  /* 16, 8, 4, 2, 1 */
#define EPS (1.0f / 1024.0f)

/* u = 2.25 on level 0: NEAREST reads texel 2 (value 1); LINEAR blends
 * texels 1 and 2 by ¼, ¾: 0.25·1.5 + 0.75·1 = 1.125; Catmull–Rom at
 * f = ¾ has taps 0 … 3 weighted −3/128, 29/128, 111/128, −9/128:
 * −3/128 + 1.5·29/128 + 111/128 − 1.5·9/128 = 1.078125. */
#define QS (2.25f / N0)
#define QT (0.5f)

static sample_texture *level_texture(void)
{
    static float data[N0 * N0 + 64 + 16 + 4 + 1];
    sample_image lv[NLEV];
    sample_texture *tex = NULL;
    float *p = data;
    int k, i;
    for (k = 0; k < NLEV; ++k) {
        int n = N0 >> k;
        lv[k] = (sample_image){n, n, 1, SAMPLE_FORMAT_F32, p, 0};
        for (i = 0; i < n * n; ++i) p[i] = k == 0 ? ((i % n) % 2 ? 1.5f : 1.0f) : (float)(k + 1);
        p += n * n;
    }
    if (sample_texture_create_levels(lv, NLEV, &tex, NULL) != SAMPLE_OK) return NULL;
    return tex;
}

/* What reconstruction `kind` reads at the query point on level k. */
static float level_value(int k, sample_filter kind)
{
    if (k > 0) return (float)(k + 1);
    return kind == SAMPLE_NEAREST ? 1.0f : kind == SAMPLE_LINEAR ? 1.125f : 1.078125f;
}

typedef enum { FAM_NONE, FAM_NEAREST, FAM_LINEAR } family;

static const struct {
    sample_filter min;
    sample_filter kind; /* reconstruction within a level */
    family fam;
} filters[] = {
    {SAMPLE_NEAREST, SAMPLE_NEAREST, FAM_NONE},
    {SAMPLE_LINEAR, SAMPLE_LINEAR, FAM_NONE},
    {SAMPLE_NEAREST_MIPMAP_NEAREST, SAMPLE_NEAREST, FAM_NEAREST},
    {SAMPLE_LINEAR_MIPMAP_NEAREST, SAMPLE_LINEAR, FAM_NEAREST},
    {SAMPLE_NEAREST_MIPMAP_LINEAR, SAMPLE_NEAREST, FAM_LINEAR},
    {SAMPLE_LINEAR_MIPMAP_LINEAR, SAMPLE_LINEAR, FAM_LINEAR},
    {SAMPLE_CUBIC, SAMPLE_CUBIC, FAM_NONE},
    {SAMPLE_CUBIC_MIPMAP_NEAREST, SAMPLE_CUBIC, FAM_NEAREST},
    {SAMPLE_CUBIC_MIPMAP_LINEAR, SAMPLE_CUBIC, FAM_LINEAR},
};
#define NFILTERS ((int)(sizeof filters / sizeof filters[0]))

/* Hand-computed level choices for level_base = 0, q = 4 (GL 4.6 §8.14.3):
 *   d   = ⌈λ + ½⌉ − 1 (λ > ½; 0 for λ ≤ ½; q past q + ½),
 *   df  = ⌊λ + ½⌋ (the allowed alternative, SAMPLE_OPT_NEAREST_LEVEL_FLOOR),
 *   d1  = ⌊λ⌋ (q from λ ≥ q), frac = frac(λ) (0 from λ ≥ q). λ ≤ 0 magnifies;
 * for λ ≤ 0 the columns are unused. */
static const struct {
    float lam;
    int d, df, d1;
    float frac;
} table0[] = {
    {-1.0f, 0, 0, 0, 0.0f},
    {0.0f, 0, 0, 0, 0.0f},
    {EPS, 0, 0, 0, EPS},
    {0.25f, 0, 0, 0, 0.25f},
    {0.5f, 0, 0, 0, 0.5f},
    {0.5f + EPS, 1, 1, 0, 0.5f + EPS},
    {0.75f, 1, 1, 0, 0.75f},
    {1.0f - EPS, 1, 1, 0, 1.0f - EPS},
    {1.0f, 1, 1, 1, 0.0f},
    {1.0f + EPS, 1, 1, 1, EPS},
    {1.5f - EPS, 1, 1, 1, 0.5f - EPS},
    {1.5f, 1, 2, 1, 0.5f},
    {1.5f + EPS, 2, 2, 1, 0.5f + EPS},
    {2.0f, 2, 2, 2, 0.0f},
    {2.5f, 2, 3, 2, 0.5f},
    {2.5f + EPS, 3, 3, 2, 0.5f + EPS},
    {3.0f, 3, 3, 3, 0.0f},
    {3.5f, 3, 4, 3, 0.5f},
    {3.5f + EPS, 4, 4, 3, 0.5f + EPS},
    {4.0f - EPS, 4, 4, 3, 1.0f - EPS},
    {4.0f, 4, 4, 4, 0.0f},
    {4.25f, 4, 4, 4, 0.0f},
    {4.5f, 4, 4, 4, 0.0f},
    {4.5f + EPS, 4, 4, 4, 0.0f},
    {7.0f, 4, 4, 4, 0.0f},
};
#define NTABLE0 ((int)(sizeof table0 / sizeof table0[0]))

typedef struct expect {
    int level0, level1;
    float frac, value;
} expect;

/* The expected outcome from a table row. `c` is the switch-over point. */
static expect expected(int f, sample_filter mag, float lam, float c, int base, int d, int d1, float frac)
{
    expect e = {base, -1, 0.0f, 0.0f};
    if (lam <= c) {
        e.value = level_value(base, mag);
        return e;
    }
    switch (filters[f].fam) {
    case FAM_NONE: break;
    case FAM_NEAREST: e.level0 = d; break;
    case FAM_LINEAR:
        e.level0 = d1;
        e.frac = frac;
        if (frac != 0.0f) e.level1 = d1 + 1;
        break;
    }
    e.value = level_value(e.level0, filters[f].kind);
    if (e.level1 >= 0)
        e.value = (1.0f - e.frac) * e.value + e.frac * level_value(e.level1, filters[f].kind);
    return e;
}

/* The magnification filter that differs from the level-0 minification read:
 * LINEAR for NEAREST-within-level filters (as the legacy switch-over rule
 * needs), NEAREST otherwise. */
static sample_filter other_mag(int f)
{
    return filters[f].kind == SAMPLE_NEAREST ? SAMPLE_LINEAR : SAMPLE_NEAREST;
}

/* How λ is produced: Jacobian 2^n/size with the rest from the sampler bias,
 * from the per-call bias, or λ pinned by min_lod = max_lod on a zero
 * Jacobian; isotropic or anisotropic (minor axis a quarter of the major). */
enum { VIA_SAMPLER_BIAS, VIA_CALL_BIAS, VIA_LOD_CLAMP, VIA_COUNT };

static void run_query(const sample_texture *tex, const sample_sampler *smp, float lam, int via, int aniso,
                      int base_size, float out[4], sample_stats *st)
{
    sample_sampler s = *smp;
    sample_query q = {QS, QT, 0, 0, 0, 0};
    sample_batch_args a;
    float n = (lam < 0.0f) ? -1.0f : floorf(lam), bias = lam - n;
    float rho = ldexpf(1.0f, (int)n) / (float)base_size;
    memset(&a, 0, sizeof a);
    if (via == VIA_LOD_CLAMP) {
        s.min_lod = s.max_lod = lam;
    } else {
        /* ρ is the longer column; aniso puts it on dPdy with dPdx 4× shorter. */
        if (aniso) {
            q.dsdx = rho / 4.0f;
            q.dtdy = rho;
        } else {
            q.dsdx = rho;
            q.dtdy = rho;
        }
        if (via == VIA_SAMPLER_BIAS) s.lod_bias = bias;
        else a.lod_bias = &bias;
    }
    a.count = 1;
    a.queries = &q;
    a.rgba = out;
    a.stats = st;
    CHECK(sample_batch(tex, &s, &a) == SAMPLE_OK, "batch");
}

static int check_one(const sample_texture *tex, const sample_sampler *s, int f, float lam, int via, int aniso,
                     int base_size, expect e)
{
    float out[4];
    sample_stats st;
    int before = check_case_failed;
    run_query(tex, s, lam, via, aniso, base_size, out, &st);
    CHECK(st.lod == lam, "lod %.9g, expected %.9g", st.lod, lam);
    CHECK(st.level0 == e.level0 && st.level1 == e.level1 && st.level_frac == e.frac,
          "%s λ=%.9g via %d aniso %d: levels %d %d frac %.9g, expected %d %d %.9g",
          sample_filter_name(filters[f].min), lam, via, aniso, st.level0, st.level1, st.level_frac, e.level0,
          e.level1, e.frac);
    CHECK(fabsf(out[0] - e.value) <= 1e-6f, "%s λ=%.9g: value %.9g, expected %.9g",
          sample_filter_name(filters[f].min), lam, out[0], e.value);
    return check_case_failed == before;
}

static void test_level_choice(void)
{
    sample_texture *tex = level_texture();
    int f, r, via, aniso, opt;
    CHECK(tex != NULL, "levels");
    for (f = 0; f < NFILTERS; ++f)
        for (opt = 0; opt < 2; ++opt)
            for (r = 0; r < NTABLE0; ++r)
                for (via = 0; via < VIA_COUNT; ++via)
                    for (aniso = 0; aniso < 2; ++aniso) {
                        sample_sampler s;
                        expect e;
                        sample_sampler_init(&s);
                        s.min_filter = filters[f].min;
                        s.mag_filter = other_mag(f);
                        s.options = opt ? SAMPLE_OPT_NEAREST_LEVEL_FLOOR : 0;
                        e = expected(f, s.mag_filter, table0[r].lam, 0.0f, 0, opt ? table0[r].df : table0[r].d,
                                     table0[r].d1, table0[r].frac);
                        check_one(tex, &s, f, table0[r].lam, via, aniso, N0, e);
                    }
    sample_texture_destroy(tex);
}

/* Pre-4.5 switch-over point c = ½ (SAMPLE_OPT_LEGACY_SWITCHOVER): only for
 * mag LINEAR with min NEAREST_MIPMAP_NEAREST or NEAREST_MIPMAP_LINEAR. */
static void test_legacy_switchover(void)
{
    sample_texture *tex = level_texture();
    int f, r, magi;
    for (f = 0; f < NFILTERS; ++f)
        for (magi = 0; magi < 2; ++magi)
            for (r = 0; r < NTABLE0; ++r) {
                sample_sampler s;
                float c;
                expect e;
                sample_sampler_init(&s);
                s.min_filter = filters[f].min;
                s.mag_filter = magi ? SAMPLE_LINEAR : SAMPLE_NEAREST;
                s.options = SAMPLE_OPT_LEGACY_SWITCHOVER;
                c = (s.mag_filter == SAMPLE_LINEAR && (s.min_filter == SAMPLE_NEAREST_MIPMAP_NEAREST ||
                                                       s.min_filter == SAMPLE_NEAREST_MIPMAP_LINEAR))
                        ? 0.5f
                        : 0.0f;
                e = expected(f, s.mag_filter, table0[r].lam, c, 0, table0[r].d, table0[r].d1, table0[r].frac);
                check_one(tex, &s, f, table0[r].lam, VIA_SAMPLER_BIAS, 0, N0, e);
            }
    /* Spot checks of the table logic itself at the point it matters:
     * NEAREST_MIPMAP_LINEAR, mag LINEAR, λ = ¼ magnifies: level 0 LINEAR. */
    {
        sample_sampler s;
        float out[4];
        sample_stats st;
        sample_sampler_init(&s);
        s.min_filter = SAMPLE_NEAREST_MIPMAP_LINEAR;
        s.options = SAMPLE_OPT_LEGACY_SWITCHOVER;
        run_query(tex, &s, 0.25f, VIA_SAMPLER_BIAS, 0, N0, out, &st);
        CHECK_EQF(out[0], 1.125f);
        s.options = 0;
        run_query(tex, &s, 0.25f, VIA_SAMPLER_BIAS, 0, N0, out, &st);
        CHECK_EQF(out[0], 0.75f * 1.0f + 0.25f * 2.0f);
    }
    sample_texture_destroy(tex);
}

/* level_base = 1, level_max = 3 (q = 3). λ is measured on level 1 (8 × 8),
 * so a Jacobian of 2^n/8 gives λ_base = n. By hand:
 *   λ = −½: magnify, level 1 (constant 2);
 *   λ = ¼:  d = 1; d1 = 1, d2 = 2, frac ¼ → 2.25;
 *   λ = 1.5: base + λ = 2.5 ≤ q + ½: d = ⌈3⌉ − 1 = 2 (floor rule: 3); 2, 3, ½;
 *   λ = 2.5: 3.5 ≤ 3.5: d = 3 (floor: ⌊4⌋ = 4 → q = 3); base + λ ≥ q: 3 only;
 *   λ = 6:   d = q = 3; 3 only. */
static void test_base_max_level(void)
{
    static const struct {
        float lam;
        int d, df, d1;
        float frac;
    } t[] = {
        {-0.5f, 1, 1, 1, 0.0f}, {0.25f, 1, 1, 1, 0.25f}, {1.5f, 2, 3, 2, 0.5f},
        {2.5f, 3, 3, 3, 0.0f},  {6.0f, 3, 3, 3, 0.0f},
    };
    sample_texture *tex = level_texture();
    int f, r, opt, aniso;
    for (f = 0; f < NFILTERS; ++f)
        for (opt = 0; opt < 2; ++opt)
            for (aniso = 0; aniso < 2; ++aniso)
                for (r = 0; r < (int)(sizeof t / sizeof t[0]); ++r) {
                    sample_sampler s;
                    expect e;
                    sample_sampler_init(&s);
                    s.min_filter = filters[f].min;
                    s.mag_filter = other_mag(f);
                    s.base_level = 1;
                    s.max_level = 3;
                    s.options = opt ? SAMPLE_OPT_NEAREST_LEVEL_FLOOR : 0;
                    e = expected(f, s.mag_filter, t[r].lam, 0.0f, 1, opt ? t[r].df : t[r].d, t[r].d1, t[r].frac);
                    check_one(tex, &s, f, t[r].lam, VIA_SAMPLER_BIAS, aniso, N0 / 2, e);
                    check_one(tex, &s, f, t[r].lam, VIA_CALL_BIAS, aniso, N0 / 2, e);
                }
    sample_texture_destroy(tex);
}

/* λ' = λ_base + clamp(bias_sampler + bias_call, ±max_lod_bias) (eq. 8.6),
 * λ = clamp(λ', min_lod, max_lod) (eq. 8.7); trilinear reports λ and frac. */
static void test_bias_and_clamps(void)
{
    static const struct {
        float base_n, sbias, cbias, maxb, minl, maxl, lam;
    } t[] = {
        {1, 0.75f, 0.0f, 16, -1000, 1000, 1.75f},  /* sampler bias */
        {1, 0.0f, 0.75f, 16, -1000, 1000, 1.75f},  /* per-call bias */
        {1, 0.5f, 0.25f, 16, -1000, 1000, 1.75f},  /* both add */
        {0, 3.0f, 0.0f, 1, -1000, 1000, 1.0f},     /* clamped to +max */
        {0, 0.75f, 0.75f, 1, -1000, 1000, 1.0f},   /* the sum is clamped */
        {3, -3.0f, 0.0f, 2, -1000, 1000, 1.0f},    /* clamped to −max */
        {3, 0.0f, 0.0f, 16, -1000, 1.25f, 1.25f},  /* max_lod */
        {0, 0.0f, 0.0f, 16, 2.5f, 1000, 2.5f},     /* min_lod */
        {3, 1.0f, 0.0f, 16, 0.5f, 3.5f, 3.5f},     /* bias then max_lod */
        {-1, 0.0f, -2.0f, 16, -0.25f, 1000, -0.25f}, /* min_lod below 0: magnify */
    };
    sample_texture *tex = level_texture();
    size_t r;
    for (r = 0; r < sizeof t / sizeof t[0]; ++r) {
        sample_sampler s;
        sample_query q = {QS, QT, 0, 0, 0, 0};
        sample_batch_args a;
        sample_stats st;
        float out[4], lam = t[r].lam, expect_v;
        int d1 = (int)floorf(lam);
        float fr = lam - floorf(lam);
        sample_sampler_init(&s);
        s.min_filter = SAMPLE_LINEAR_MIPMAP_LINEAR;
        s.mag_filter = SAMPLE_NEAREST;
        s.lod_bias = t[r].sbias;
        s.max_lod_bias = t[r].maxb;
        s.min_lod = t[r].minl;
        s.max_lod = t[r].maxl;
        q.dsdx = q.dtdy = ldexpf(1.0f, (int)t[r].base_n) / N0;
        memset(&a, 0, sizeof a);
        a.count = 1;
        a.queries = &q;
        a.lod_bias = &t[r].cbias;
        a.rgba = out;
        a.stats = &st;
        CHECK(sample_batch(tex, &s, &a) == SAMPLE_OK, "batch");
        CHECK(st.lod == lam, "row %zu: λ %.9g, expected %.9g", r, st.lod, lam);
        if (lam <= 0.0f) {
            expect_v = 1.0f; /* mag NEAREST on level 0 */
        } else {
            expect_v = (1.0f - fr) * level_value(d1, SAMPLE_LINEAR) + fr * level_value(d1 + 1, SAMPLE_LINEAR);
            CHECK(st.level0 == d1 && st.level_frac == fr, "row %zu: level %d frac %.9g", r, st.level0, st.level_frac);
        }
        CHECK_NEAR(out[0], expect_v, 1e-6);
    }
    sample_texture_destroy(tex);
}

/* ---- Trilinear on smooth data -------------------------------------------- */

/* A linear ramp R = s, G = t: its box pyramid holds the ramp again at every
 * level's texel centres ((2i + ½ + 2i + 1½)/2 = 2i + 1 → centre of texel i
 * one level down), bilinear reproduces a linear function between centres,
 * and a blend of two exact values is exact. So trilinear returns (s, t) to
 * float rounding wherever no level's footprint reaches the clamped edge:
 * up to λ = 3 (8 × 8 texels) that is s, t ∈ [1/16, 15/16]. */
static void test_trilinear_ramp(void)
{
    enum { W = 64 };
    static float d[W * W * 2];
    sample_image im = {W, W, 2, SAMPLE_FORMAT_F32, d, 0};
    sample_mip_params mp;
    sample_texture *tex = NULL;
    sample_sampler s;
    sample_query q[200];
    float bias[200], out[800];
    sample_batch_args a;
    int i, j;
    unsigned seed = 5u;
    for (j = 0; j < W; ++j)
        for (i = 0; i < W; ++i) {
            d[2 * (j * W + i)] = (i + 0.5f) / W;
            d[2 * (j * W + i) + 1] = (j + 0.5f) / W;
        }
    sample_mip_params_init(&mp);
    CHECK(sample_texture_create(&im, &mp, &tex, NULL) == SAMPLE_OK, "create ramp");
    sample_sampler_init(&s);
    s.min_filter = SAMPLE_LINEAR_MIPMAP_LINEAR;
    s.wrap_s = s.wrap_t = SAMPLE_WRAP_CLAMP_TO_EDGE;
    for (i = 0; i < 200; ++i) {
        seed = seed * 1103515245u + 12345u;
        q[i].s = 0.0625f + 0.875f * (float)((seed >> 8) & 0xffff) / 65536.0f;
        seed = seed * 1103515245u + 12345u;
        q[i].t = 0.0625f + 0.875f * (float)((seed >> 8) & 0xffff) / 65536.0f;
        q[i].dsdx = q[i].dtdy = 1.0f / W; /* ρ = 1, λ_base = 0 */
        q[i].dtdx = q[i].dsdy = 0.0f;
        bias[i] = 3.0f * (float)i / 199.0f;
    }
    memset(&a, 0, sizeof a);
    a.count = 200;
    a.queries = q;
    a.lod_bias = bias;
    a.rgba = out;
    CHECK(sample_batch(tex, &s, &a) == SAMPLE_OK, "batch");
    for (i = 0; i < 200; ++i) {
        CHECK_NEAR(out[4 * i], q[i].s, 1e-6);
        CHECK_NEAR(out[4 * i + 1], q[i].t, 1e-6);
    }
    sample_texture_destroy(tex);
}

/* Trilinear is (1 − frac)·a_k + frac·a_(k+1) with a_k the bilinear value of
 * level k, so it is continuous in λ, including across integers (where the
 * pair of levels changes) and across λ = 0 with mag LINEAR. A step of δ in
 * λ moves the result by at most δ·max_k |a_(k+1) − a_k| plus rounding. */
static void test_trilinear_continuity(void)
{
    enum { W = 32, STEPS = 5 * 1024 + 1 };
    float *d = (float *)malloc(W * W * sizeof(float));
    sample_image im = {W, W, 1, SAMPLE_FORMAT_F32, d, 0};
    sample_mip_params mp;
    sample_texture *tex = NULL;
    sample_sampler s;
    sample_query *q = (sample_query *)malloc(STEPS * sizeof *q);
    float *bias = (float *)malloc(STEPS * sizeof *bias), *out = (float *)malloc(STEPS * 4 * sizeof *out);
    sample_batch_args a;
    float lipschitz = 0.0f, delta = 1.0f / 1024.0f, worst = 0.0f;
    unsigned seed = 77u;
    int i;
    for (i = 0; i < W * W; ++i) {
        seed = seed * 1103515245u + 12345u;
        d[i] = (float)((seed >> 8) & 0xffff) / 65536.0f;
    }
    sample_mip_params_init(&mp);
    CHECK(sample_texture_create(&im, &mp, &tex, NULL) == SAMPLE_OK, "create");
    sample_sampler_init(&s);
    s.min_filter = SAMPLE_LINEAR_MIPMAP_LINEAR;
    for (i = 0; i < STEPS; ++i) {
        q[i] = (sample_query){0.3717f, 0.6211f, 1.0f / W, 0, 0, 1.0f / W};
        bias[i] = -0.5f + (float)i * delta; /* λ from −½ to 4.5 */
    }
    memset(&a, 0, sizeof a);
    a.count = STEPS;
    a.queries = q;
    a.lod_bias = bias;
    a.rgba = out;
    CHECK(sample_batch(tex, &s, &a) == SAMPLE_OK, "batch");
    /* a_k: the values at integer λ = k (indices 512 + 1024 k). */
    for (i = 0; i + 1 < 5; ++i) {
        float da = fabsf(out[4 * (512 + 1024 * (i + 1))] - out[4 * (512 + 1024 * i)]);
        if (da > lipschitz) lipschitz = da;
    }
    for (i = 1; i < STEPS; ++i) {
        float jump = fabsf(out[4 * i] - out[4 * (i - 1)]);
        if (jump > worst) worst = jump;
    }
    CHECK(lipschitz > 0.0f, "levels differ, or the bound is vacuous");
    CHECK(worst <= delta * lipschitz + 1e-6f, "jump %.9g exceeds δ·L = %.9g", worst, delta * lipschitz);
    free(d);
    free(q);
    free(bias);
    free(out);
    sample_texture_destroy(tex);
}

int main(void)
{
    RUN(test_level_choice);
    RUN(test_legacy_switchover);
    RUN(test_base_max_level);
    RUN(test_bias_and_clamps);
    RUN(test_trilinear_ramp);
    RUN(test_trilinear_continuity);
    return check_finish();
}
