/*
 * Footprint filters (DESIGN §7): invariants every filter must keep —
 * constants exactly, normalized non-negative weights, symmetry of the
 * footprint description, the bilinear limit, wrapping, the level choice and
 * the texel cap on degenerate input — and the anisotropic probe rule checked
 * by hand. Blinn–Newell against brute-force integration is in
 * test_footprint_bn.c.
 */
#include "footprint_util.h"

/* Random values are drawn into named variables, one initializer or
 * statement each, before the call that uses them: the order in which a
 * call's arguments are evaluated is unspecified in C (GCC goes right to
 * left, Clang left to right), so several urand() calls in one argument
 * list gave the two compilers different queries. The variables are drawn
 * last argument first, the order GCC used, so the queries are the ones the
 * suite has always tested. */

static float f_const(int i, int j, int ch) { (void)i; (void)j; return ch == 3 ? 1.0f : 0.3f + 0.1f * ch; }
static float f_mild(int i, int j, int ch)
{
    (void)ch;
    return (float)(0.5 + 0.2 * sin(0.27 * i + 0.1) * cos(0.19 * j + 0.4) + 0.1 * sin(0.05 * (i + 2 * j)));
}

/* A constant texture gives exactly that constant, whatever the footprint and
 * the (non-border) wrap mode. Blinn–Newell and EWA accumulate in double and
 * divide once, so Σw·T/Σw rounds back to T exactly; the anisotropic probes
 * are GL bilinear lookups computed in float, whose four weights may sum to
 * 1 ± 1 ulp, hence 2 ulps there. */
static void constant_exact(void)
{
    static const sample_wrap wraps[] = {SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_MIRRORED_REPEAT,
                                        SAMPLE_WRAP_CLAMP_TO_EDGE, SAMPLE_WRAP_MIRROR_CLAMP_TO_EDGE};
    sample_texture *t = tex_from(37, 20, f_const, 1);
    int f, w, n, k;
    for (w = 0; w < 4; ++w) {
        sample_sampler s;
        sample_ctx c;
        sample_sampler_init(&s);
        s.wrap_s = wraps[w];
        s.wrap_t = wraps[(w + 1) & 3];
        s.max_anisotropy = 16.0f;
        c = ctx_for(t, &s);
        for (n = 0; n < 60; ++n) {
            double a = exp2(urand(-3, 9)), b = a * exp2(urand(-8, 0));
            double skew = urand(0, 6.3), th = urand(0, 6.3), ct = urand(-2, 3), cs = urand(-2, 3);
            sample_query q = footprint((float)cs, (float)ct, a, b, th, skew, 37, 20);
            for (f = 0; f < FILTER_N; ++f) {
                float out[4];
                run_filter(f, &c, &q, NULL, out, NULL, NULL, NULL);
                for (k = 0; k < 4; ++k) {
                    float want = k == 3 ? 1.0f : 0.3f + 0.1f * k;
                    if (f == FILTER_ANISO)
                        CHECK_NEAR(out[k], want, 2.0 * 6e-8 * want);
                    else
                        CHECK(out[k] == want, "%s wrap %d: %.9g != %.9g", filter_names[f], w, out[k], want);
                }
            }
        }
    }
    sample_texture_destroy(t);
}

/* Weights are non-negative and sum to one: the results for the 64
 * single-texel indicator textures of an 8 × 8 texture (mip levels built by
 * the linear box filter, so the filter stays linear in the texels) are each
 * ≥ 0 and sum to 1. */
static int ind_i, ind_j;
static float f_indicator(int i, int j, int ch) { (void)ch; return (i == ind_i && j == ind_j) ? 1.0f : 0.0f; }

static void weights_normalized(void)
{
    sample_sampler s;
    int f, n;
    sample_sampler_init(&s);
    s.max_anisotropy = 8.0f;
    for (n = 0; n < 3; ++n) {
        double skew = urand(0, 3), th = urand(0, 3), ct = urand(0, 1), cs = urand(0, 1);
        sample_query q = footprint((float)cs, (float)ct, 2.5 + n, 0.7 + 0.5 * n, th, skew, 8, 8);
        double sum[FILTER_N] = {0, 0, 0};
        for (ind_j = 0; ind_j < 8; ++ind_j)
            for (ind_i = 0; ind_i < 8; ++ind_i) {
                sample_texture *t = tex_from(8, 8, f_indicator, 1);
                sample_ctx c = ctx_for(t, &s);
                for (f = 0; f < FILTER_N; ++f) {
                    float out[4];
                    run_filter(f, &c, &q, NULL, out, NULL, NULL, NULL);
                    CHECK(out[0] >= 0.0f, "%s: negative weight %g", filter_names[f], out[0]);
                    sum[f] += out[0];
                }
                sample_texture_destroy(t);
            }
        for (f = 0; f < FILTER_N; ++f) CHECK_NEAR(sum[f], 1.0, 1e-5);
    }
}

/* Swapping the Jacobian's columns or negating one describes the same
 * footprint (same parallelogram, same ellipse, probes mirrored about the
 * centre), so the result must not change beyond float rounding of the
 * geometry (1e-5 on values in [0.2, 0.8]). */
static void column_symmetry(void)
{
    sample_texture *t = tex_from(64, 48, f_mild, 1);
    sample_sampler s;
    sample_ctx c;
    int n, f;
    c = footprint_ctx(t, &s);
    for (n = 0; n < 40; ++n) {
        double a = exp2(urand(0, 6)), b = a * exp2(urand(-5, 0));
        double skew = urand(0, 6.3), th = urand(0, 6.3), ct = urand(0, 1), cs = urand(0, 1);
        sample_query q = footprint((float)cs, (float)ct, a, b, th, skew, 64, 48);
        sample_query sw = q, ng = q;
        sw.dsdx = q.dsdy; sw.dtdx = q.dtdy; sw.dsdy = q.dsdx; sw.dtdy = q.dtdx;
        ng.dsdy = -q.dsdy; ng.dtdy = -q.dtdy;
        for (f = 0; f < FILTER_N; ++f) {
            float o[4], o2[4], o3[4];
            run_filter(f, &c, &q, NULL, o, NULL, NULL, NULL);
            run_filter(f, &c, &sw, NULL, o2, NULL, NULL, NULL);
            run_filter(f, &c, &ng, NULL, o3, NULL, NULL, NULL);
            CHECK_NEAR(o2[0], o[0], 1e-5);
            CHECK_NEAR(o3[0], o[0], 1e-5);
        }
    }
    sample_texture_destroy(t);
}

/* Transposing the texture and the footprint (s ↔ t, the Jacobian's rows
 * exchanged) gives the same filter, and for Blinn–Newell and EWA the same
 * bits, values and derivatives (∂/∂s ↔ ∂/∂t), wherever one of the two is
 * walked by columns: the level's geometry is symmetric to the bit
 * (ls_fp_shape_of's Q and R trade places, ls_fp_shape_reshape the rows of J′),
 * and a footprint tall enough to be walked by columns (fp_walk_columns) is
 * walked in exactly the order its transpose's rows are — so a mistake in
 * the column walk (an axis, a pitch, a derivative not swapped) shows up as
 * a difference. Footprints 4 to 40 texels long, 6 to 32 times as long as
 * wide (the eccentricity clamp acts), within 15° of an axis, so that the
 * walk is by columns one way and by rows the other even after the
 * widening and for any skew; a near-round footprint is walked by rows
 * both ways, which sums in another order: close, not equal. On a square
 * level with the same wrap on both axes, every wrap mode but the border
 * ones, near edges too. Texels are multiples of 1/128, so that the box
 * pyramid's sums are exact and the transpose's levels are the transposes
 * of the levels. */
static float f_rough(int i, int j, int ch) { return (float)((i * 37 + j * 91 + ch * 13) % 101) / 128.0f; }
static float f_rough_t(int i, int j, int ch) { return f_rough(j, i, ch); }

static void transpose_symmetry(void)
{
    static const sample_wrap wraps[] = {SAMPLE_WRAP_REPEAT, SAMPLE_WRAP_MIRRORED_REPEAT, SAMPLE_WRAP_CLAMP_TO_EDGE,
                                        SAMPLE_WRAP_MIRROR_CLAMP_TO_EDGE};
    sample_texture *t = tex_from(64, 64, f_rough, 1), *tt = tex_from(64, 64, f_rough_t, 1);
    sample_sampler s;
    int n, f, k, bad = 0, far = 0;
    for (n = 0; n < 600; ++n) {
        const int steep = n < 400; /* else any shape and angle */
        sample_ctx c, ct;
        double skew = urand(0, 6.3), th = steep ? (n & 1) * 1.5707963 + urand(-0.26, 0.26) : urand(0, 6.3);
        double a = steep ? exp2(urand(2, 5.3)) : exp2(urand(-2, 5.3));
        double b = a * (steep ? exp2(urand(-5, -2.6)) : exp2(urand(-5, 0)));
        float ts = (float)urand(-0.2, 1.2), ss = (float)urand(-0.2, 1.2);
        sample_query q = footprint(ss, ts, a, b, th, skew, 64, 64), qt = q;
        c = footprint_ctx(t, &s);
        s.wrap_s = s.wrap_t = wraps[n % 4];
        ct = ctx_for(tt, &s);
        qt.s = q.t;
        qt.t = q.s;
        qt.dsdx = q.dtdx;
        qt.dtdx = q.dsdx;
        qt.dsdy = q.dtdy;
        qt.dtdy = q.dsdy;
        for (f = FILTER_BN; f <= FILTER_EWA; ++f) {
            float o[4], ds[4], dt[4], p[4], pds[4], pdt[4], v[4], vt[4];
            run_filter(f, &c, &q, NULL, o, ds, dt, NULL);
            run_filter(f, &ct, &qt, NULL, p, pds, pdt, NULL);
            run_filter(f, &c, &q, NULL, v, NULL, NULL, NULL); /* the row kernels */
            run_filter(f, &ct, &qt, NULL, vt, NULL, NULL, NULL);
            for (k = 0; k < 4; ++k) {
                if (steep && (memcmp(&o[k], &p[k], 4) || memcmp(&ds[k], &pdt[k], 4) || memcmp(&dt[k], &pds[k], 4) ||
                              memcmp(&v[k], &vt[k], 4) || memcmp(&v[k], &o[k], 4)) && ++bad <= 3)
                    fprintf(stderr, "%s n=%d ch %d: %.9g / %.9g (row kernels %.9g / %.9g), d/ds %.9g, d/dt %.9g\n",
                            filter_names[f], n, k, o[k], p[k], v[k], vt[k], ds[k], pdt[k]);
                if (!(fabsf(o[k] - p[k]) <= 1e-6f && fabsf(v[k] - vt[k]) <= 1e-6f)) ++far;
            }
        }
    }
    CHECK(bad == 0, "%d channels of 800 tall/wide transposed queries differ", bad);
    CHECK(far == 0, "%d channels of 1200 transposed queries differ by more than 1e-6", far);
    sample_texture_destroy(t);
    sample_texture_destroy(tt);
}

/* A tiny axis-aligned square footprint: anisotropic is one bilinear probe
 * on the base level (exact); Blinn–Newell's widened pyramid has half-width
 * √(1 + ε²) texels, so its weights differ from the bilinear ones by O(ε²)
 * (1e-6 for ε = 1e-3); EWA's unit-variance Gaussian is a different 3 × 3
 * kernel, so it is only close on smooth content: f_mild has curvature
 * < 0.03 per texel² and the kernel's extra variance is under one texel²,
 * bounding the gap by about 0.03 (measured worst 1.8e-2). */
static void tiny_is_bilinear(void)
{
    sample_texture *t = tex_from(64, 48, f_mild, 1);
    sample_sampler s;
    sample_ctx c;
    int n;
    sample_sampler_init(&s);
    c = ctx_for(t, &s);
    for (n = 0; n < 50; ++n) {
        double ct = urand(0, 1), cs = urand(0, 1);
        sample_query q = footprint((float)cs, (float)ct, 1e-3, 1e-3, 0.0, 0.0, 64, 48);
        float bil[4], o[4];
        ls_recon_level(&c, 0, SAMPLE_LINEAR, q.s, q.t, bil, NULL, NULL);
        run_filter(FILTER_ANISO, &c, &q, NULL, o, NULL, NULL, NULL);
        CHECK(o[0] == bil[0], "aniso %.9g vs bilinear %.9g", o[0], bil[0]);
        run_filter(FILTER_BN, &c, &q, NULL, o, NULL, NULL, NULL);
        CHECK_NEAR(o[0], bil[0], 1e-6);
        run_filter(FILTER_EWA, &c, &q, NULL, o, NULL, NULL, NULL);
        CHECK_NEAR(o[0], bil[0], 0.03);
    }
    sample_texture_destroy(t);
}

/* Level choice, exactly: levels of constant, distinct colours (OIIO's
 * texture-filtersize idea). Blinn–Newell and EWA use the level where the
 * minor semi-axis is FP_MINOR_TEXELS = 2 texels: a round footprint of
 * radius 2^(k+1) base texels reads level k alone. Sweeping the size by 1 %
 * steps the blend moves by at most log2(1.01)·max colour step (0.015), so
 * any jump above 0.02 would be a pop between levels. */
static sample_texture *level_colour_tex(void)
{
    static float lv[9][256 * 256 * 4];
    sample_image im[9];
    sample_texture *t = NULL;
    sample_error err;
    int k, n, sz;
    for (k = 0; k < 9; ++k) {
        sz = 256 >> k;
        for (n = 0; n < sz * sz * 4; ++n) lv[k][n] = (n & 3) == 3 ? 1.0f : (float)k;
        im[k].width = im[k].height = sz;
        im[k].channels = 4;
        im[k].format = SAMPLE_FORMAT_F32;
        im[k].data = lv[k];
        im[k].row_stride = 0;
    }
    CHECK(sample_texture_create_levels(im, 9, &t, &err) == SAMPLE_OK, "levels: %s", err.message);
    return t;
}

static void level_choice_and_continuity(void)
{
    sample_texture *t = level_colour_tex();
    sample_sampler s;
    sample_ctx c;
    int f, k, n;
    c = footprint_ctx(t, &s);
    for (f = FILTER_BN; f <= FILTER_EWA; ++f) {
        for (k = 0; k <= 6; ++k) {
            float o[4];
            sample_stats st;
            double r = exp2(k + 1);
            sample_query q = footprint(0.3f, 0.6f, r, r, 0.4, 0.0, 256, 256);
            run_filter(f, &c, &q, NULL, o, NULL, NULL, &st);
            CHECK_NEAR(o[0], k, 1e-5);
            CHECK(st.level0 == k && st.level1 == -1, "%s k=%d: levels %d %d", filter_names[f], k, st.level0, st.level1);
            CHECK_NEAR(st.lod, k, 1e-6);
        }
        {
            double prev = -1.0, jump = 0.0;
            for (n = 0; n <= 700; ++n) {
                float o[4];
                double r = 1.5 * pow(1.01, n);
                sample_query q = footprint(0.37f, 0.61f, 3.0 * r, r, 0.7, 0.3, 256, 256);
                run_filter(f, &c, &q, NULL, o, NULL, NULL, NULL);
                if (prev >= 0.0 && fabs(o[0] - prev) > jump) jump = fabs(o[0] - prev);
                prev = o[0];
            }
            CHECK(jump <= 0.02, "%s: jump %.4g between 1%% steps", filter_names[f], jump);
        }
    }
    sample_texture_destroy(t);
}

/* Anisotropic probe rule by hand. A one-level 256 × 8 texture that is 0
 * except a column of 1 at i = 129 (centre u = 129.5); an 8:1 footprint of
 * Pmax = 16, Pmin = 2 texels along u centred at u = 128.5: N = min(8, 16) = 8,
 * λ = log2(16/8) = 1, probes at u = 128.5 + 16·(i/9 − ½). Only the probe at
 * 128.5 + 8/9 is within one texel of the column: bilinear weight
 * 1 − (129.5 − 129.389) = 8/9, averaged over 8 probes: 1/9. */
static float f_column(int i, int j, int ch) { (void)j; (void)ch; return i == 129 ? 1.0f : 0.0f; }

static void aniso_probes(void)
{
    sample_texture *t = tex_from(256, 8, f_column, 0);
    sample_sampler s;
    sample_ctx c;
    sample_query q = {128.5f / 256.0f, 4.5f / 8.0f, 16.0f / 256.0f, 0.0f, 0.0f, 2.0f / 8.0f};
    sample_stats st;
    float o[4];
    uint32_t n;
    sample_sampler_init(&s);
    s.wrap_s = s.wrap_t = SAMPLE_WRAP_CLAMP_TO_EDGE;
    s.max_anisotropy = 16.0f;
    CHECK(ls_fp_aniso_count(&s, 16.0, 2.0) == 8, "N = %d", ls_fp_aniso_count(&s, 16.0, 2.0));
    c = ctx_for(t, &s);
    n = ls_fp_anisotropic(&c, &q, 0.0f, o, NULL, NULL, &st);
    CHECK_NEAR(o[0], 1.0 / 9.0, 1e-6);
    CHECK_EQF(st.lod, 1.0f);
    CHECK(n == 8 * 4, "texels %u", n); /* 8 bilinear probes on the only level */
    /* Column order does not matter: the longer one is the major axis. */
    {
        sample_query r = {q.s, q.t, 0.0f, 2.0f / 8.0f, 16.0f / 256.0f, 0.0f};
        ls_fp_anisotropic(&c, &r, 0.0f, o, NULL, NULL, &st);
        CHECK_NEAR(o[0], 1.0 / 9.0, 1e-6);
    }
    /* max_anisotropy 4 caps N: λ = log2(16/4) = 2. */
    s.max_anisotropy = 4.0f;
    CHECK(ls_fp_aniso_count(&s, 16.0, 2.0) == 4, "N = %d", ls_fp_aniso_count(&s, 16.0, 2.0));
    ls_fp_anisotropic(&c, &q, 0.0f, o, NULL, NULL, &st);
    CHECK_EQF(st.lod, 2.0f);
    /* ⌈5.2⌉ = 6 probes; the power-of-two option rounds up to 8; 1.9:1 → 2;
     * a rank-one footprint takes the maximum; maxAniso 1 is trilinear. */
    s.max_anisotropy = 16.0f;
    CHECK(ls_fp_aniso_count(&s, 5.2, 1.0) == 6, "N");
    s.options = SAMPLE_OPT_ANISO_POW2;
    CHECK(ls_fp_aniso_count(&s, 5.2, 1.0) == 8, "N pow2");
    s.options = 0;
    CHECK(ls_fp_aniso_count(&s, 1.9, 1.0) == 2, "N");
    CHECK(ls_fp_aniso_count(&s, 3.0, 0.0) == 16, "N rank one");
    s.max_anisotropy = 1.0f;
    CHECK(ls_fp_aniso_count(&s, 8.0, 1.0) == 1, "N trilinear");
    s.max_anisotropy = 1e9f;
    CHECK(ls_fp_aniso_count(&s, 1e9, 1.0) == SAMPLE_MAX_FOOTPRINT_TEXELS / 8, "N capped");
    sample_texture_destroy(t);
}

/* Footprints across the s = 0 edge, centred on it with a footprint
 * symmetric about it, on a texture 1 in its left half and 0 in its right:
 * REPEAT reads the right half's 0s to the left and the left half's 1s to the
 * right of the seam with mirrored weights, so exactly ½; CLAMP_TO_BORDER on
 * a zero texture with border 2 gives 2·½ = 1. */
static float f_halves(int i, int j, int ch) { (void)j; (void)ch; return i < 16 ? 1.0f : 0.0f; }
static float f_zero(int i, int j, int ch) { (void)i; (void)j; (void)ch; return 0.0f; }

static void wrap_across_edge(void)
{
    sample_texture *t = tex_from(32, 32, f_halves, 1), *z = tex_from(32, 32, f_zero, 1);
    sample_sampler s;
    sample_ctx c;
    int f;
    sample_query q = footprint(0.0f, 0.5f, 6.0, 2.0, 0.0, 0.0, 32, 32);
    c = footprint_ctx(t, &s);
    for (f = 0; f < FILTER_N; ++f) {
        float o[4];
        run_filter(f, &c, &q, NULL, o, NULL, NULL, NULL);
        CHECK_NEAR(o[0], 0.5, 1e-6);
    }
    s.wrap_s = s.wrap_t = SAMPLE_WRAP_CLAMP_TO_BORDER;
    s.border_color[0] = s.border_color[1] = s.border_color[2] = s.border_color[3] = 2.0f;
    c = ctx_for(z, &s);
    for (f = 0; f < FILTER_N; ++f) {
        float o[4];
        run_filter(f, &c, &q, NULL, o, NULL, NULL, NULL);
        CHECK_NEAR(o[0], 1.0, 1e-6);
    }
    sample_texture_destroy(t);
    sample_texture_destroy(z);
}

/* Degenerate and extreme input through the public API, for every filter:
 * the result is finite (NaN/inf input: the border colour, DESIGN §10), the
 * texel cap holds, and it returns (bounded time is what lets this loop of
 * 3 × 3000 queries finish). */
static void degenerate_and_cap(void)
{
    enum { NQ = 3000 };
    static sample_query qs[NQ];
    static sample_quad quads[NQ];
    static float out[NQ * 4];
    static sample_stats st[NQ];
    sample_texture *t = tex_from(256, 128, f_mild, 1);
    sample_sampler s;
    sample_batch_args a;
    int f, n, k, bad = 0, over = 0;
    for (n = 0; n < NQ; ++n) {
        double mag = exp2(urand(-40, 70)), ecc = exp2(urand(-60, 0));
        double skew = urand(0, 6.3), th = urand(0, 6.3), ct = urand(-3, 3), cs = urand(-1e3, 1e3);
        qs[n] = footprint((float)cs, (float)ct, mag, mag * ecc, th, skew, 256, 128);
        for (k = 0; k < 4; ++k) {
            quads[n].st[k][0] = (float)(qs[n].s + urand(-1, 1) * mag / 256);
            quads[n].st[k][1] = (float)(qs[n].t + urand(-1, 1) * mag / 128);
        }
    }
    /* Hand-made degenerate cases first. */
    memset(&qs[0], 0, sizeof qs[0]);                               /* zero */
    qs[1].dsdx = qs[1].dtdx = 1e20f; qs[1].dsdy = qs[1].dtdy = 1e20f; /* rank one, huge */
    qs[2].dsdx = 1e20f; qs[2].dtdy = -1e20f;                       /* huge */
    qs[3].dsdx = 0.5f; qs[3].dsdy = 0.0f; qs[3].dtdx = 0.0f; qs[3].dtdy = 0.0f; /* rank one */
    qs[4].dsdx = NAN; qs[5].dtdy = INFINITY; qs[6].s = -INFINITY;
    qs[7].dsdx = 3.4e38f; qs[7].dtdy = 1e-38f;
    for (k = 0; k < 4; ++k) quads[8].st[k][0] = quads[8].st[k][1] = 0.25f; /* zero area */
    memcpy(quads[9].st, (float[4][2]){{0, 0}, {1, 1}, {1, 0}, {0, 1}}, sizeof quads[9].st); /* bow-tie */
    memcpy(quads[10].st, (float[4][2]){{0, 0}, {1e30f, 0}, {0, 1e-30f}, {0, 1}}, sizeof quads[10].st);
    for (f = 0; f < FILTER_N; ++f) {
        sample_sampler_init(&s);
        s.footprint = f == FILTER_ANISO ? SAMPLE_FOOTPRINT_ANISOTROPIC
                                        : (f == FILTER_BN ? SAMPLE_FOOTPRINT_BLINN_NEWELL : SAMPLE_FOOTPRINT_EWA);
        s.max_anisotropy = 64.0f;
        s.wrap_s = (sample_wrap)(f % SAMPLE_WRAP_COUNT);
        memset(&a, 0, sizeof a);
        a.count = NQ;
        a.queries = qs;
        a.corners = f == FILTER_BN ? quads : NULL;
        a.rgba = out;
        a.stats = st;
        CHECK(sample_batch(t, &s, &a) == SAMPLE_OK, "batch");
        for (n = 0; n < NQ; ++n) {
            for (k = 0; k < 4; ++k) bad += !isfinite(out[4 * n + k]);
            over += st[n].texels > SAMPLE_MAX_FOOTPRINT_TEXELS;
        }
        CHECK(bad == 0 && over == 0, "%s: %d non-finite, %d over the cap", filter_names[f], bad, over);
        /* NaN and inf give the border colour (0, 0, 0, 0). */
        for (n = 4; n <= 6; ++n) CHECK(out[4 * n] == 0.0f && out[4 * n + 3] == 0.0f, "non-finite -> border");
    }
    sample_texture_destroy(t);
}

int main(void)
{
    RUN(constant_exact);
    RUN(weights_normalized);
    RUN(column_symmetry);
    RUN(transpose_symmetry);
    RUN(tiny_is_bilinear);
    RUN(level_choice_and_continuity);
    RUN(aniso_probes);
    RUN(wrap_across_edge);
    RUN(degenerate_and_cap);
    return check_finish();
}
