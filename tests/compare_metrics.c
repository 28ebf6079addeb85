/*
 * compare's metrics on synthetic images whose error is known by hand:
 * RMSE and PSNR exact, the mask, alpha ignored, the worst-window search;
 * the median of the timed runs; and the placement of the text in the
 * pictures: the heat map's scale labels and the contact sheet's column
 * names never overlap and never leave the picture, at any width.
 */
#include "check.h"
#include "cmp_internal.h"

#include <math.h>
#include <string.h>

/* 4 pixels; one channel of one pixel off by 0.3: MSE = 0.09 / 12. */
static void rmse_one_channel(void)
{
    float ref[16], img[16];
    cmp_metrics m;
    int k;
    for (k = 0; k < 16; ++k) ref[k] = img[k] = 0.5f;
    img[1 * 4 + 2] = 0.8f;
    cmp_metrics_compute(img, ref, NULL, 4, &m);
    CHECK(m.count == 4, "count %zu", m.count);
    CHECK_NEAR(m.rmse, sqrt(0.09 / 12.0), 1e-7);
    CHECK_NEAR(m.psnr, 10.0 * log10(12.0 / 0.09), 1e-5);
    CHECK_NEAR(m.max_err, sqrt(0.09 / 3.0), 1e-7);
}

/* Every channel off by 0.1 (alpha off by 1, ignored): RMSE 0.1, PSNR 20 dB. */
static void rmse_uniform(void)
{
    float ref[32], img[32];
    cmp_metrics m;
    int k;
    for (k = 0; k < 32; ++k) {
        ref[k] = 0.25f;
        img[k] = k % 4 == 3 ? 1.25f : 0.35f;
    }
    cmp_metrics_compute(img, ref, NULL, 8, &m);
    CHECK_NEAR(m.rmse, 0.1, 1e-6);
    CHECK_NEAR(m.psnr, 20.0, 1e-4);
}

/* The mask leaves out the only wrong pixel: zero error, infinite PSNR; an
 * empty mask counts nothing. */
static void masked(void)
{
    float ref[8] = {0, 0, 0, 1, 0, 0, 0, 1}, img[8] = {0, 0, 0, 1, 1, 1, 1, 1};
    unsigned char mask[2] = {1, 0}, none[2] = {0, 0};
    cmp_metrics m;
    cmp_metrics_compute(img, ref, mask, 2, &m);
    CHECK(m.count == 1, "count %zu", m.count);
    CHECK_EQF(m.rmse, 0.0);
    CHECK(isinf(m.psnr) && m.psnr > 0, "psnr %g", m.psnr);
    cmp_metrics_compute(img, ref, NULL, 2, &m);
    CHECK_NEAR(m.rmse, sqrt(0.5), 1e-7);
    CHECK_NEAR(m.psnr, 10.0 * log10(2.0), 1e-6);
    cmp_metrics_compute(img, ref, none, 2, &m);
    CHECK(m.count == 0 && m.rmse == 0.0, "count %zu rmse %g", m.count, m.rmse);
}

static void error_map(void)
{
    float ref[8] = {0, 0, 0, 0, 1, 1, 1, 1}, img[8] = {0.3f, 0, 0, 9, 1, 1, 0.4f, 1}, e[2];
    cmp_error_map(img, ref, 2, e);
    CHECK_NEAR(e[0], sqrt(0.09 / 3.0), 1e-7);
    CHECK_NEAR(e[1], sqrt(0.36 / 3.0), 1e-7);
}

/* 8 × 6 scores with a hot 2 × 2 block at (5, 3); masked-out hotter pixel
 * at (0, 0) must not attract the window. */
static void worst_window(void)
{
    double score[48] = {0};
    unsigned char mask[48];
    int k, x = -1, y = -1;
    for (k = 0; k < 48; ++k) mask[k] = 1;
    score[3 * 8 + 5] = score[3 * 8 + 6] = score[4 * 8 + 5] = score[4 * 8 + 6] = 1.0;
    score[0] = 100.0;
    mask[0] = 0;
    cmp_worst_window(score, mask, 8, 6, 2, &x, &y);
    CHECK(x == 5 && y == 3, "window at (%d, %d)", x, y);
    cmp_worst_window(score, NULL, 8, 6, 3, &x, &y);
    CHECK(x == 0 && y == 0, "unmasked window at (%d, %d)", x, y);
    /* A window larger than the image is clipped to 6 × 6; x = 1 and 2 both
     * hold the whole block, the first wins. */
    cmp_worst_window(score, mask, 8, 6, 50, &x, &y);
    CHECK(x == 1 && y == 0, "clipped window at (%d, %d)", x, y);
}

/* Odd count: the middle value; even: the mean of the two middle ones; the
 * order of the runs does not matter and an outlier does not move it. */
static void median(void)
{
    double one[1] = {7.0}, odd[5] = {9.0, 1.0, 250.0, 3.0, 2.0}, even[4] = {4.0, 1.0, 3.0, 100.0},
           same[3] = {2.5, 2.5, 2.5};
    CHECK_EQF(cmp_median(one, 1), 7.0);
    CHECK_EQF(cmp_median(odd, 5), 3.0);
    CHECK_EQF(cmp_median(even, 4), 3.5);
    CHECK_EQF(cmp_median(same, 3), 2.5);
}

static int boxes_clear(const cmp_label *a, const cmp_label *b)
{
    return a->x + a->w < b->x || b->x + b->w < a->x || a->y + a->h < b->y || b->y + b->h < a->y;
}

/* At every picture width from 1 to 1024 and for scales with short and long
 * labels: each label lies inside the picture, no two touch, the ends come
 * first. --size 96 (the picture is 96 wide): the middle value "0.125"
 * would cover ">=0.25", so it is left out; 256 keeps all three. */
static void heat_legend(void)
{
    static const float scales[] = {0.25f, 1.0f, 0.0625f, 12.5f};
    cmp_legend lg;
    int w, s, k, l, bad = 0;
    for (s = 0; s < 4; ++s)
        for (w = 1; w <= 1024; ++w) {
            cmp_heat_legend(w, scales[s], &lg);
            for (k = 0; k < lg.n; ++k) {
                const cmp_label *a = &lg.label[k];
                if (a->x < 0 || a->x + a->w > w || a->w != cmp_text_width(a->text, 1)) ++bad;
                if (a->tick_x < lg.bar_x || a->tick_x >= lg.bar_x + lg.bar_w) ++bad;
                for (l = k + 1; l < lg.n; ++l)
                    if (!boxes_clear(a, &lg.label[l])) ++bad;
            }
            if (lg.bar_x < 0 || lg.bar_x + lg.bar_w > w) ++bad;
        }
    CHECK(bad == 0, "%d misplaced labels", bad);
    cmp_heat_legend(96, 0.25f, &lg);
    CHECK(lg.n == 2 && strcmp(lg.label[0].text, "0") == 0 && strcmp(lg.label[1].text, ">=0.25") == 0,
          "at 96: %d labels", lg.n);
    CHECK(lg.bar_x == 8 && lg.bar_w == 80, "bar %d + %d", lg.bar_x, lg.bar_w);
    cmp_heat_legend(256, 0.25f, &lg);
    CHECK(lg.n == 3 && strcmp(lg.label[2].text, "0.125") == 0, "at 256: %d labels", lg.n);
    CHECK(lg.label[2].x == 8 + 239 / 2 - 15, "middle label at %d", lg.label[2].x);
    cmp_heat_legend(3, 0.25f, &lg);
    CHECK(lg.n == 0, "at 3: %d labels", lg.n);
}

/* Column names of the contact sheet: each line fits the column, breaks
 * follow '-', and what fits is the name's beginning, in order. */
static void text_wrap(void)
{
    char lines[2][CMP_LINE_MAX];
    int n, w, l;
    n = cmp_text_wrap("blinn-newell-corners-area", 94, 1, lines, 2);
    CHECK(n == 2 && strcmp(lines[0], "blinn-newell-") == 0 && strcmp(lines[1], "corners-area") == 0,
          "%d lines: '%s' '%s'", n, lines[0], n > 1 ? lines[1] : "");
    n = cmp_text_wrap("trilinear", 94, 1, lines, 2);
    CHECK(n == 1 && strcmp(lines[0], "trilinear") == 0, "short name");
    n = cmp_text_wrap("nearest_mipmap_nearest", 30, 1, lines, 2);
    CHECK(n == 2 && strcmp(lines[0], "neare") == 0 && strcmp(lines[1], "st_mi") == 0,
          "narrow: '%s' '%s'", lines[0], n > 1 ? lines[1] : "");
    for (w = 1; w < 300; ++w) {
        n = cmp_text_wrap("blinn-newell-corners-area", w, 1, lines, 2);
        for (l = 0; l < n; ++l) CHECK(cmp_text_width(lines[l], 1) - 1 <= w, "w %d line %d", w, l);
    }
}

int main(void)
{
    RUN(median);
    RUN(heat_legend);
    RUN(text_wrap);
    RUN(rmse_one_channel);
    RUN(rmse_uniform);
    RUN(masked);
    RUN(error_map);
    RUN(worst_window);
    return check_finish();
}
