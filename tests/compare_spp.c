/*
 * compare's stochastic sweep (doc/comparison.md, "Stochastic filters") on
 * a tiny plane (16 × 16 pixels, 4 × 4 truth samples per footprint):
 *
 *   - the per-pixel uniforms are in [0, 1), the same for the same
 *     (pixel, lookup), and spread evenly (their mean near ½);
 *   - for trilinear, anisotropic x16 and EWA the RMSE of the mean of spp
 *     lookups falls as spp grows (1, 4, 32) and at 32 is close to the
 *     deterministic filter's: an unbiased estimate (doc/footprint-filters.md,
 *     "Stochastic filtering") has RMSE² = deterministic RMSE² + variance/spp
 *     in expectation, so RMSE(32)² − RMSE_det² is checked against
 *     (RMSE(1)² − RMSE_det²)/32 with room for the sampling noise (a factor
 *     of 4);
 *   - the sweep gives the same numbers on 1 and 2 threads (trilinear);
 *   - spp.png exists, 688 × 310 pixels (the plot's fixed layout).
 */
#include "check.h"
#include "cmp_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static const char err_hint[] = "(see the condition)";

/* Width and height from a PNG's IHDR chunk (bytes 16 … 23, big-endian). */
static int png_size(const char *path, int *w, int *h)
{
    unsigned char b[24];
    FILE *f = fopen(path, "rb");
    size_t n = f ? fread(b, 1, sizeof b, f) : 0;
    if (f) fclose(f);
    if (n != sizeof b || memcmp(b + 12, "IHDR", 4) != 0) return -1;
    *w = (b[16] << 24) | (b[17] << 16) | (b[18] << 8) | b[19];
    *h = (b[20] << 24) | (b[21] << 16) | (b[22] << 8) | b[23];
    return 0;
}

static void uniforms(void)
{
    double sum = 0.0;
    int k;
    for (k = 0; k < 4096; ++k) {
        float u = cmp_spp_u((size_t)k * 7u, k % 5);
        CHECK(u >= 0.0f && u < 1.0f, "u %g", (double)u);
        CHECK(u == cmp_spp_u((size_t)k * 7u, k % 5), "%s", err_hint);
        sum += u;
    }
    CHECK(fabs(sum / 4096 - 0.5) < 0.02, "mean of u %g", sum / 4096);
    CHECK(cmp_spp_u(1, 0) != cmp_spp_u(1, 1) && cmp_spp_u(1, 0) != cmp_spp_u(2, 0), "%s", err_hint);
}

static void sweep(const char *dir)
{
    static const char *const names[] = {"trilinear", "aniso16", "ewa"};
    static const int spp[] = {1, 4, 32};
    render_scene *sc = NULL;
    cmp_view v;
    cmp_truth t;
    cmp_scene_result *s = calloc(1, sizeof *s);
    cmp_config cfg[3];
    tool_backend lib;
    char err[512], label[64], path[1024];
    int k, w = 0, h = 0;
    memset(&v, 0, sizeof v);
    CHECK(s != NULL, "%s", err_hint);
    if (!s) return;
    CHECK(cmp_scene_open("plane", 16, RENDER_CACHE_MB, &sc, label, sizeof label, err, sizeof err) == 0, "%s", err);
    CHECK(cmp_view_build(sc, 2, &v, err, sizeof err) == 0, "%s", err);
    CHECK(cmp_truth_build(&v, 4, 2, &t, err, sizeof err) == 0, "%s", err);
    CHECK(tool_backend_libsample(&lib, NULL) == 0, "%s", err_hint);
    snprintf(s->label, sizeof s->label, "%s", label);
    memcpy(s->spp, spp, sizeof spp);
    s->nspp = 3;
    s->draws = 1;
    for (k = 0; k < 3; ++k) {
        cmp_spp_row *x = &s->spp_rows[k], again;
        cmp_result r;
        cmp_metrics m;
        double var1, var32;
        CHECK(cmp_configs_parse(names[k], 0, &cfg[k], 1, err, sizeof err) == 1, "%s", err);
        cfg[k].tb = &lib;
        CHECK(cmp_config_stochastic(&cfg[k], &v.sampler), "%s is stochastic", names[k]);
        CHECK(cmp_run_backend(&v, &cfg[k], 2, 1, &r, err, sizeof err) == 0, "%s", err);
        cmp_metrics_compute(r.rgba, t.rgba, t.mask, (size_t)v.w * (size_t)v.h, &m);
        cmp_result_free(&r);
        CHECK(cmp_spp_sweep(&v, &cfg[k], &t, spp, 3, 1, 2, x, err, sizeof err) == 0, "%s", err);
        if (k == 0) {
            CHECK(cmp_spp_sweep(&v, &cfg[k], &t, spp, 3, 1, 1, &again, err, sizeof err) == 0, "%s", err);
            CHECK(memcmp(x->rmse, again.rmse, sizeof x->rmse) == 0, "%s: same on 1 and 2 threads",
                  names[k]);
        }
        x->det_rmse = m.rmse;
        printf("%-10s rmse at 1, 4, 32 spp: %.5f %.5f %.5f; deterministic %.5f\n", names[k], x->rmse[0],
               x->rmse[1], x->rmse[2], m.rmse);
        CHECK(x->ok && x->rmse[0] > x->rmse[1] && x->rmse[1] > x->rmse[2], "%s: falls with spp",
              names[k]);
        var1 = x->rmse[0] * x->rmse[0] - m.rmse * m.rmse;
        var32 = x->rmse[2] * x->rmse[2] - m.rmse * m.rmse;
        CHECK(var1 > 0.0, "%s: one lookup adds noise", names[k]);
        /* 1/spp, within the noise of a few hundred pixels (the cross term
         * of the deterministic error and the noise is not 0 on so few):
         * at most 4 times the expected excess, an eighth of one lookup's,
         * and the RMSE within 25 % of the deterministic one. */
        CHECK(var32 < 4.0 * var1 / 32 + 1e-5, "%s: excess %g against %g / 32", names[k], var32, var1);
        CHECK(x->rmse[2] < 1.25 * m.rmse, "%s: %g against %g", names[k], x->rmse[2], m.rmse);
    }
    s->nspp_rows = 3;
#ifndef TEXSAMPLE_HAVE_IO
    /* No PNG writer in this build: the numbers are checked, the picture
     * cannot be. */
    check_skip("this build has no libsample_io to write spp.png");
#endif
    snprintf(path, sizeof path, "%s/%s", dir, s->label);
    mkdir(dir, 0777);
    mkdir(path, 0777);
    CHECK(cmp_spp_plot(dir, s) == 0, "%s", err_hint);
    snprintf(path, sizeof path, "%s/%s/spp.png", dir, s->label);
    CHECK(png_size(path, &w, &h) == 0, "%s is a PNG", path);
    CHECK(w == 688 && h == 310, "spp.png is %d x %d", w, h);
    tool_backend_close(&lib);
    cmp_truth_free(&t);
    cmp_view_free(&v);
    render_scene_destroy(sc);
    free(s);
}

int main(int argc, char **argv)
{
    uniforms();
    sweep(argc > 1 ? argv[1] : "compare_spp_out");
    return check_finish();
}
