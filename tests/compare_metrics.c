/*
 * compare's metrics on synthetic images whose error is known by hand:
 * RMSE and PSNR exact, the mask, alpha ignored, the worst-window search.
 */
#include "check.h"
#include "cmp_internal.h"

#include <math.h>

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

int main(void)
{
    RUN(rmse_one_channel);
    RUN(rmse_uniform);
    RUN(masked);
    RUN(error_map);
    RUN(worst_window);
    return check_finish();
}
