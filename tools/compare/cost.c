/*
 * Error against cost (doc/comparison.md, "The quality frontier"): each
 * filter of a scene as one marker at (ns/sample, RMSE), the time on a
 * logarithmic axis, both axes named with their units and ticked with
 * their values, and a legend naming each marker's filter by colour —
 * all drawn into the PNG itself with the pictures' 5 × 7 font, so the
 * picture reads on its own (written as <scene>/cost.png).
 */
#include "cmp_internal.h"

#include <math.h>
#include <stdio.h>

enum { AX_X = 64, AX_Y = 30, AX_W = 320, AX_H = 240, LEGEND_X = AX_X + AX_W + 24, PLOT_W = LEGEND_X + 280,
       MARK = 7 };

/* Distinct colours for the markers (a row's colour is its index's). */
static const unsigned char palette[10][3] = {
    {31, 119, 180}, {255, 127, 14}, {44, 160, 44}, {214, 39, 40},  {148, 103, 189},
    {140, 86, 75},  {227, 119, 194}, {127, 127, 127}, {188, 189, 34}, {23, 190, 207},
};

int cmp_cost_plot(const char *dir, const cmp_scene_result *s)
{
    static const unsigned char white[3] = {255, 255, 255}, black[3] = {0, 0, 0}, grid[3] = {224, 224, 224};
    double lo = HUGE_VAL, hi = 0.0, emax = 0.0, d0, d1, v;
    char rel[512], path[1024], err[512], text[128], line[1][CMP_LINE_MAX];
    int r, k, n = 0, h;
    cmp_pic p = {0, 0, NULL};
    for (r = 0; r < s->nrows; ++r) {
        const cmp_row *w = &s->rows[r];
        if (!w->ok || !(w->ns_per_sample > 0.0) || !isfinite(w->m.rmse)) continue;
        lo = fmin(lo, w->ns_per_sample);
        hi = fmax(hi, w->ns_per_sample);
        emax = fmax(emax, w->m.rmse);
        ++n;
    }
    if (!n) return 0; /* nothing timed: no plot */
    d0 = floor(log10(lo));
    d1 = ceil(log10(hi));
    if (d1 <= d0) d1 = d0 + 1.0;
    if (!(emax > 0.0)) emax = 1.0;
    h = AX_Y + AX_H + 40;
    if (h < AX_Y + 12 * (s->nrows + 1)) h = AX_Y + 12 * (s->nrows + 1);
    if (cmp_pic_alloc(&p, PLOT_W, h)) return 1;
    cmp_pic_fill(&p, 0, 0, p.w, p.h, white);
    snprintf(text, sizeof text, "%s: RMSE against time per sample", s->label);
    cmp_pic_text(&p, 4, 4, text, 1, black);
    cmp_pic_text(&p, 4, AX_Y - 12, "RMSE", 1, black);
    /* Decades of ns/sample, and quarters of the error range. */
    for (v = d0; v <= d1 + 1e-9; v += 1.0) {
        int x = AX_X + (int)lround(AX_W * (v - d0) / (d1 - d0));
        cmp_pic_fill(&p, x, AX_Y, 1, AX_H, grid);
        snprintf(text, sizeof text, "%.0f", pow(10.0, v));
        cmp_pic_text(&p, x - cmp_text_width(text, 1) / 2, AX_Y + AX_H + 4, text, 1, black);
    }
    for (k = 0; k <= 4; ++k) {
        int y = AX_Y + AX_H - (int)lround(AX_H * k / 4.0);
        cmp_pic_fill(&p, AX_X, y, AX_W, 1, grid);
        snprintf(text, sizeof text, "%.3g", emax * 1.1 * k / 4.0);
        cmp_pic_text(&p, AX_X - 4 - cmp_text_width(text, 1), y - 3, text, 1, black);
    }
    cmp_pic_rect(&p, AX_X, AX_Y, AX_W + 1, AX_H + 1, black);
    snprintf(text, sizeof text, "ns/sample (log scale), median of %d runs", s->runs);
    cmp_pic_text(&p, AX_X + (AX_W - cmp_text_width(text, 1)) / 2, AX_Y + AX_H + 18, text, 1, black);
    for (r = 0, k = 0; r < s->nrows; ++r) {
        const cmp_row *w = &s->rows[r];
        const unsigned char *c = palette[r % 10];
        int x, y;
        if (!w->ok || !(w->ns_per_sample > 0.0) || !isfinite(w->m.rmse)) continue;
        x = AX_X + (int)lround(AX_W * (log10(w->ns_per_sample) - d0) / (d1 - d0));
        y = AX_Y + AX_H - (int)lround(AX_H * w->m.rmse / (emax * 1.1));
        cmp_pic_fill(&p, x - MARK / 2, y - MARK / 2, MARK, MARK, c);
        /* Legend: the marker's colour, then the filter's label. */
        cmp_pic_fill(&p, LEGEND_X, AX_Y + 12 * k, MARK, MARK, c);
        if (cmp_text_wrap(w->cfg->label, PLOT_W - LEGEND_X - 14, 1, line, 1) == 1)
            cmp_pic_text(&p, LEGEND_X + 12, AX_Y + 12 * k, line[0], 1, black);
        ++k;
    }
    cmp_pic_path(rel, sizeof rel, s, "cost", "");
    snprintf(path, sizeof path, "%s/%s", dir, rel);
    k = cmp_pic_write(path, &p, err, sizeof err);
    if (k) fprintf(stderr, "texsample compare: cannot write %s: %s\n", path, err);
    cmp_pic_free(&p);
    return k ? 1 : 0;
}
