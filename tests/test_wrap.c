/*
 * Wrap modes (DESIGN §3, GL 4.6 §8.14.2 table 8.20, EXT_texture_mirror_clamp)
 * for NEAREST and LINEAR through the public API. Every expected value below
 * was worked out by hand from the table's formulas; the working is in the
 * comments so a reviewer can redo it.
 *
 * Texture: n × 1 (or 1 × n for the t axis), texel i holds R = 10·(i + 1);
 * the border colour is R = −100, so a result names the texels it came from.
 */
#include "check.h"
#include "sample/sample.h"

enum { R_ = SAMPLE_WRAP_REPEAT, MR = SAMPLE_WRAP_MIRRORED_REPEAT, CE = SAMPLE_WRAP_CLAMP_TO_EDGE,
       CB = SAMPLE_WRAP_CLAMP_TO_BORDER, MCE = SAMPLE_WRAP_MIRROR_CLAMP_TO_EDGE, CL = SAMPLE_WRAP_CLAMP,
       MC = SAMPLE_WRAP_MIRROR_CLAMP, MCB = SAMPLE_WRAP_MIRROR_CLAMP_TO_BORDER };

#define B (-100.0f) /* border */

/* One row of a table: coordinate, then the expected R for the 8 modes in
 * enum order: REPEAT, MIRRORED_REPEAT, CLAMP_TO_EDGE, CLAMP_TO_BORDER,
 * MIRROR_CLAMP_TO_EDGE, CLAMP, MIRROR_CLAMP, MIRROR_CLAMP_TO_BORDER. */
typedef struct { float s; float r[8]; } row;

static sample_texture *make_line(int n, int along_t)
{
    float px[4 * 8];
    sample_image im = {0};
    sample_texture *tex = NULL;
    int i;
    for (i = 0; i < n; ++i) {
        px[4 * i] = 10.0f * (float)(i + 1);
        px[4 * i + 1] = px[4 * i + 2] = 0.0f;
        px[4 * i + 3] = 1.0f;
    }
    im.width = along_t ? 1 : n;
    im.height = along_t ? n : 1;
    im.channels = 4;
    im.format = SAMPLE_FORMAT_F32;
    im.data = px;
    CHECK(sample_texture_create(&im, NULL, &tex, NULL) == SAMPLE_OK, "create %d", n);
    return tex;
}

static void run_table(int n, sample_filter filt, const row *rows, int nrows)
{
    int axis, k, m;
    for (axis = 0; axis < 2; ++axis) {
        sample_texture *tex = make_line(n, axis);
        for (m = 0; m < 8; ++m) {
            sample_sampler s;
            sample_sampler_init(&s);
            s.mag_filter = filt;
            s.min_filter = filt;
            s.border_color[0] = B;
            /* The other axis has one texel and is sampled at its centre
             * with REPEAT, so it contributes weight 1 to that texel. */
            if (axis) s.wrap_t = (sample_wrap)m; else s.wrap_s = (sample_wrap)m;
            for (k = 0; k < nrows; ++k) {
                sample_query q = {0};
                float out[4];
                q.s = axis ? 0.5f : rows[k].s;
                q.t = axis ? rows[k].s : 0.5f;
                CHECK(sample_one(tex, &s, &q, out) == SAMPLE_OK, "sample");
                CHECK(out[0] == rows[k].r[m], "n=%d %s %s axis %c coord %.9g: got %.9g expected %.9g", n,
                      sample_filter_name(filt), sample_wrap_name((sample_wrap)m), axis ? 't' : 's',
                      (double)rows[k].s, (double)out[0], (double)rows[k].r[m]);
            }
        }
        sample_texture_destroy(tex);
    }
}

/* NEAREST: i = ⌊s'·n⌋ then the table. Texel values 10, 20, 30 for n = 3. */
static void nearest_n3(void)
{
    static const row rows[] = {
        /*  s      R   MR  CE  CB  MCE CL  MC  MCB */
        {0.0f, {10, 10, 10, 10, 10, 10, 10, 10}},      /* i=0; MC/MCB: s'=1/6 → u=0.5 → 0 */
        {0.5f, {20, 20, 20, 20, 20, 20, 20, 20}},      /* i=1 */
        {1.0f, {10, 30, 30, B, 30, 30, 30, B}},        /* i=3: 3 mod 3=0; MR: (3 mod 6)−3=0 → 2; MCB s'=1 → i=3 → border */
        {-1.0f, {10, 30, 10, B, 30, 10, 30, B}},       /* i=−3: MR (−3 mod 6)=3 → 2; MCE mirror(−3)=2; CL s'=0; MC |s|=1 */
        {2.0f, {10, 10, 30, B, 30, 30, 30, B}},        /* i=6: MR 6 mod 6=0 → a=−3 → mirror 2 → 0; MCB s'=7/6 */
        {-1.0f / 6.0f, {30, 10, 10, B, 10, 10, 10, 10}}, /* u=−0.5 → i=−1: R 2; MR (5−3)=2 → mirror 2 → 0; MC |s|=1/6 → 0 */
        {7.0f / 6.0f, {10, 30, 30, B, 30, 30, 30, B}}, /* u=3.5 → i=3 */
        {-0.4f, {20, 20, 10, B, 20, 10, 20, 20}},      /* u=−1.2 → i=−2: R 1; MR 4−3=1 → 2−1=1; MCE mirror(−2)=1; MC |s|=.4 → 1 */
        {1.4f, {20, 20, 30, B, 30, 30, 30, B}},        /* u=4.2 → i=4: R 1; MR 4 → a=1 → 1; MCB s'=7/6 → 3 → border */
        {1e7f, {10, 10, 30, B, 30, 30, 30, B}},        /* i=3e7: 3e7 mod 3 = 0, 3e7 mod 6 = 0 → 0 */
        {-1e7f, {10, 10, 10, B, 30, 10, 30, B}},       /* i=−3e7: MCE mirror = 3e7−1 → clamp 2 */
    };
    run_table(3, SAMPLE_NEAREST, rows, (int)(sizeof rows / sizeof rows[0]));
}

static void nearest_n2_n1(void)
{
    static const row rows2[] = {
        {-0.25f, {20, 10, 10, B, 10, 10, 10, 10}},  /* u=−0.5 → i=−1: R 1; MR (3−2)=1 → 1−1=0; MC s'=1/4 → u=.5 → 0 */
        {1.25f, {10, 20, 20, B, 20, 20, 20, B}},    /* u=2.5 → i=2: R 0; MR (2−2)=0 → 1; CL s'=1 → i=2 → 1; MCB s'=1.25 → border */
        {-0.75f, {10, 20, 10, B, 20, 10, 20, 20}},  /* u=−1.5 → i=−2: R 0; MR (2−2)=0 → 1; MCE mirror(−2)=1; MC |s| → 1 */
        {-1.25f, {20, 20, 10, B, 20, 10, 20, B}},   /* u=−2.5 → i=−3: R 1; MR (1−2)=−1 → mirror 0 → 1; MCE mirror(−3)=2 → 1 */
    };
    static const row rows1[] = {
        {0.5f, {10, 10, 10, 10, 10, 10, 10, 10}},
        {-0.5f, {10, 10, 10, B, 10, 10, 10, 10}},   /* i=−1 */
        {1.0f, {10, 10, 10, B, 10, 10, 10, B}},     /* i=1 */
        {1.5f, {10, 10, 10, B, 10, 10, 10, B}},     /* i=1; MCB s'=min(1.5, 1.5) → i=1 → border */
    };
    run_table(2, SAMPLE_NEAREST, rows2, (int)(sizeof rows2 / sizeof rows2[0]));
    run_table(1, SAMPLE_NEAREST, rows1, (int)(sizeof rows1 / sizeof rows1[0]));
}

/* LINEAR: i0 = ⌊u − ½⌋, i1 = i0 + 1, α = frac(u − ½); result
 * (1 − α)·T[i0] + α·T[i1], border texels reading −100. */
static void linear_n3(void)
{
    static const row rows[] = {
        /* u=0: i0=−1, i1=0, α=½. R: (30+10)/2; CB/CL: (−100+10)/2; MC/MCB: s'=1/6 → u=.5 → T0 */
        {0.0f, {20, 10, 10, -45, 10, -45, 10, 10}},
        {0.5f, {20, 20, 20, 20, 20, 20, 20, 20}},        /* u=1.5 → i0=1, α=0 */
        {1.0f / 3.0f, {15, 15, 15, 15, 15, 15, 15, 15}}, /* u=1 → i0=0, α=½ */
        /* u=3: i0=2, i1=3, α=½. R (30+10)/2; MR 3 → 2; CB (30−100)/2; every clamp → 30 or border */
        {1.0f, {20, 30, 30, -35, 30, -35, -35, -35}},
        /* u=−0.5: i0=−1, α=0 → T[i0] alone. R 30; MR/MCE 0 → 10; CL s'=0 → as u=0 */
        {-1.0f / 6.0f, {30, 10, 10, B, 10, -45, 10, 10}},
        /* u=3.5: i0=3, α=0. R T0; MR/CE/MCE T2; CL/MC s'=1 → as u=3; MCB s'=7/6 → u=3.5 → border */
        {7.0f / 6.0f, {10, 30, 30, B, 30, -35, -35, B}},
        /* u=−3: i0=−4, i1=−3, α=½. R: 2,0 → 20; MR: 2,2 → 30; MCE: 3→2, 2 → 30; CL s'=0; MC |s|=1 */
        {-1.0f, {20, 30, 10, B, 30, -45, -35, -35}},
        /* u=3e7: u−½ rounds to 3e7 in float → i0=3e7, α=0. CL/MC: s'=1 → as u=3;
         * MCB: s'=7/6 → u=3.5 → i0=3, α=0 → border */
        {1e7f, {10, 10, 30, B, 30, -35, -35, B}},
        {-1e7f, {10, 10, 10, B, 30, -45, -35, B}},
    };
    run_table(3, SAMPLE_LINEAR, rows, (int)(sizeof rows / sizeof rows[0]));
}

static void linear_n2_n1(void)
{
    static const row rows2[] = {
        {0.0f, {15, 10, 10, -45, 10, -45, 10, 10}},  /* i0=−1, α=½; MR −1 → 0 */
        /* u=2.5: i0=2, α=0. R T0; MR 2 → 1; CL/MC: s'=1 → u=2 → i0=1, α=½ → (20−100)/2 */
        {1.25f, {10, 20, 20, B, 20, -40, -40, B}},
    };
    static const row rows1[] = {
        {0.5f, {10, 10, 10, 10, 10, 10, 10, 10}},
        {0.0f, {10, 10, 10, -45, 10, -45, 10, 10}},   /* i0=−1, α=½; MC s'=½ */
        {1.0f, {10, 10, 10, -45, 10, -45, -45, -45}}, /* i0=0, i1=1, α=½ */
    };
    run_table(2, SAMPLE_LINEAR, rows2, (int)(sizeof rows2 / sizeof rows2[0]));
    run_table(1, SAMPLE_LINEAR, rows1, (int)(sizeof rows1 / sizeof rows1[0]));
}

/* Even size n = 4 with REPEAT/MIRRORED_REPEAT around integers of s. */
static void linear_n4_periodic(void)
{
    static const row rows[] = {
        /* values 10,20,30,40. s=1: u=4 → i0=3, i1=4, α=½: R (40+10)/2; MR 4 → 3 → 40 */
        {1.0f, {25, 40, 40, -30, 40, -30, -30, -30}},
        /* s=−0.125: u=−0.5 → i0=−1, α=0: R T3 = 40; MR −1 → 0 → 10 */
        {-0.125f, {40, 10, 10, B, 10, -45, 10, 10}},
        /* s=2.125: u=8.5 → i0=8, α=0: R 8 mod 4 = 0 → 10; MR 8 mod 8 = 0 → 10; CL s'=1 → u=4 → (40−100)/2;
         * MC: s'=1 → same; MCB: s'=min(1.125, 2.125)=1.125 → u=4.5 → i0=4 → border */
        {2.125f, {10, 10, 40, B, 40, -30, -30, B}},
    };
    run_table(4, SAMPLE_LINEAR, rows, (int)(sizeof rows / sizeof rows[0]));
}

/* DESIGN §10: non-finite coordinates give the border colour; 1e30 stays in
 * bounds and gives one of the texels. */
static void extreme_coordinates(void)
{
    sample_texture *tex = make_line(3, 0);
    const float bad[] = {NAN, INFINITY, -INFINITY};
    const float huge[] = {1e30f, -1e30f, 3.4e38f, -3.4e38f, 1e-45f, -0.0f};
    int m, k, f;
    for (f = 0; f < 2; ++f) {
        for (m = 0; m < SAMPLE_WRAP_COUNT; ++m) {
            sample_sampler s;
            sample_sampler_init(&s);
            s.mag_filter = s.min_filter = f ? SAMPLE_LINEAR : SAMPLE_NEAREST;
            s.wrap_s = s.wrap_t = (sample_wrap)m;
            s.border_color[0] = B;
            s.border_color[3] = 0.25f;
            for (k = 0; k < 3; ++k) {
                sample_query q = {0};
                float out[4];
                q.s = bad[k];
                q.t = 0.5f;
                sample_one(tex, &s, &q, out);
                CHECK(out[0] == B && out[3] == 0.25f, "non-finite s must give the border colour (%s)",
                      sample_wrap_name((sample_wrap)m));
                q.s = 0.5f;
                q.dsdx = bad[k];
                sample_one(tex, &s, &q, out);
                CHECK(out[0] == B, "non-finite Jacobian must give the border colour");
            }
            for (k = 0; k < 6; ++k) {
                sample_query q = {0};
                float out[4];
                q.s = huge[k];
                q.t = 0.5f;
                sample_one(tex, &s, &q, out);
                /* Any in-range texel, the border, or a blend of the two. */
                CHECK(isfinite(out[0]) && out[0] >= B && out[0] <= 30.0f, "s=%g gives %g", (double)huge[k],
                      (double)out[0]);
            }
        }
    }
    sample_texture_destroy(tex);
}

int main(void)
{
    RUN(nearest_n3);
    RUN(nearest_n2_n1);
    RUN(linear_n3);
    RUN(linear_n2_n1);
    RUN(linear_n4_periodic);
    RUN(extreme_coordinates);
    return check_finish();
}
