/*
 * compare's plots (doc/comparison.md, "The quality frontier"): RMSE
 * against a logarithmic x axis, both axes named with their units and
 * ticked with their values, and a legend naming each series by colour —
 * all drawn into the PNG itself with the pictures' 5 × 7 font, so the
 * picture reads on its own. One writer serves error against cost (each
 * filter one marker at (ns/sample, RMSE), <scene>/cost.png) and the
 * stochastic filters' error against samples per pixel (stochastic.c,
 * <scene>/spp.png).
 */
#include "cmp_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

enum { AX_X = 64, AX_Y = 30, AX_W = 320, AX_H = 240, LEGEND_X = AX_X + AX_W + 24, PLOT_W = LEGEND_X + 280,
       MARK = 7 };

/* Distinct colours for the series (a series' colour is its `colour`'s). */
static const unsigned char palette[10][3] = {
    {31, 119, 180}, {255, 127, 14}, {44, 160, 44}, {214, 39, 40},  {148, 103, 189},
    {140, 86, 75},  {227, 119, 194}, {127, 127, 127}, {188, 189, 34}, {23, 190, 207},
};

/* A line from (x0, y0) to (x1, y1), `dash` pixels on and off (0: solid). */
static void draw_line(cmp_pic *p, int x0, int y0, int x1, int y1, int dash, const unsigned char c[3])
{
    int dx = abs(x1 - x0), dy = abs(y1 - y0), n = dx > dy ? dx : dy, k;
    for (k = 0; k <= n; ++k) {
        int x = n ? x0 + (int)lround((double)(x1 - x0) * k / n) : x0;
        int y = n ? y0 + (int)lround((double)(y1 - y0) * k / n) : y0;
        if (dash && (k / dash) % 2) continue;
        cmp_pic_fill(p, x, y - 1, 1, 2, c);
    }
}

int cmp_plot_write(const char *path, const cmp_plot *pl)
{
    static const unsigned char white[3] = {255, 255, 255}, black[3] = {0, 0, 0}, grid[3] = {224, 224, 224};
    double lo = HUGE_VAL, hi = 0.0, emax = 0.0, d0, d1, v;
    char err[512], text[128], line[1][CMP_LINE_MAX];
    int r, k, i, n = 0, h, rc;
    cmp_pic p = {0, 0, NULL};
    for (r = 0; r < pl->nseries; ++r) {
        const cmp_series *s = &pl->series[r];
        for (i = 0; i < s->n; ++i) {
            if (!(s->x[i] > 0.0) || !isfinite(s->y[i])) continue;
            lo = fmin(lo, s->x[i]);
            hi = fmax(hi, s->x[i]);
            emax = fmax(emax, s->y[i]);
            ++n;
        }
        if (isfinite(s->hline) && s->hline >= 0.0) emax = fmax(emax, s->hline);
    }
    if (!n) return 0; /* nothing to draw: no plot */
    d0 = pl->xticks ? log10(pl->xticks[0]) : floor(log10(lo));
    d1 = pl->xticks ? log10(pl->xticks[pl->nxticks - 1]) : ceil(log10(hi));
    if (d1 <= d0) d1 = d0 + 1.0;
    if (!(emax > 0.0)) emax = 1.0;
    h = AX_Y + AX_H + 40;
    if (h < AX_Y + 12 * (pl->nseries + 1)) h = AX_Y + 12 * (pl->nseries + 1);
    if (cmp_pic_alloc(&p, PLOT_W, h)) return 1;
    cmp_pic_fill(&p, 0, 0, p.w, p.h, white);
    cmp_pic_text(&p, 4, 4, pl->title, 1, black);
    cmp_pic_text(&p, 4, AX_Y - 12, "RMSE", 1, black);
    /* The x ticks (decades unless given), and quarters of the error range. */
    for (k = 0, v = d0; pl->xticks ? k < pl->nxticks : v <= d1 + 1e-9; ++k, v += 1.0) {
        double t = pl->xticks ? log10(pl->xticks[k]) : v;
        int x = AX_X + (int)lround(AX_W * (t - d0) / (d1 - d0));
        cmp_pic_fill(&p, x, AX_Y, 1, AX_H, grid);
        snprintf(text, sizeof text, "%.0f", pow(10.0, t));
        cmp_pic_text(&p, x - cmp_text_width(text, 1) / 2, AX_Y + AX_H + 4, text, 1, black);
    }
    for (k = 0; k <= 4; ++k) {
        int y = AX_Y + AX_H - (int)lround(AX_H * k / 4.0);
        cmp_pic_fill(&p, AX_X, y, AX_W, 1, grid);
        snprintf(text, sizeof text, "%.3g", emax * 1.1 * k / 4.0);
        cmp_pic_text(&p, AX_X - 4 - cmp_text_width(text, 1), y - 3, text, 1, black);
    }
    cmp_pic_rect(&p, AX_X, AX_Y, AX_W + 1, AX_H + 1, black);
    cmp_pic_text(&p, AX_X + (AX_W - cmp_text_width(pl->xlabel, 1)) / 2, AX_Y + AX_H + 18, pl->xlabel, 1,
                 black);
    for (r = 0; r < pl->nseries; ++r) {
        const cmp_series *s = &pl->series[r];
        const unsigned char *c = palette[s->colour % 10];
        int px = 0, py = 0, have = 0;
        for (i = 0; i < s->n; ++i) {
            int x, y;
            if (!(s->x[i] > 0.0) || !isfinite(s->y[i])) continue;
            x = AX_X + (int)lround(AX_W * (log10(s->x[i]) - d0) / (d1 - d0));
            y = AX_Y + AX_H - (int)lround(AX_H * s->y[i] / (emax * 1.1));
            cmp_pic_fill(&p, x - MARK / 2, y - MARK / 2, MARK, MARK, c);
            if (have && s->n > 1) draw_line(&p, px, py, x, y, 0, c);
            px = x, py = y, have = 1;
        }
        if (isfinite(s->hline) && s->hline >= 0.0) {
            int y = AX_Y + AX_H - (int)lround(AX_H * s->hline / (emax * 1.1));
            draw_line(&p, AX_X + 1, y, AX_X + AX_W - 1, y, 4, c);
        }
        /* Legend: the series' colour (a dash for a line), then its label. */
        if (s->n > 0)
            cmp_pic_fill(&p, LEGEND_X, AX_Y + 12 * r, MARK, MARK, c);
        else
            cmp_pic_fill(&p, LEGEND_X, AX_Y + 12 * r + MARK / 2 - 1, MARK, 2, c);
        if (cmp_text_wrap(s->label, PLOT_W - LEGEND_X - 14, 1, line, 1) == 1)
            cmp_pic_text(&p, LEGEND_X + 12, AX_Y + 12 * r, line[0], 1, black);
    }
    rc = cmp_pic_write(path, &p, err, sizeof err);
    if (rc) fprintf(stderr, "texsample compare: cannot write %s: %s\n", path, err);
    cmp_pic_free(&p);
    return rc ? 1 : 0;
}

int cmp_cost_plot(const char *dir, const cmp_scene_result *s)
{
    cmp_series series[CMP_MAX_CONFIGS];
    double x[CMP_MAX_CONFIGS], y[CMP_MAX_CONFIGS];
    char rel[512], path[1024], title[128], xlabel[96];
    cmp_plot pl = {0};
    int r, n = 0;
    for (r = 0; r < s->nrows; ++r) {
        const cmp_row *w = &s->rows[r];
        if (!w->ok || !(w->ns_per_sample > 0.0) || !isfinite(w->m.rmse)) continue;
        x[n] = w->ns_per_sample;
        y[n] = w->m.rmse;
        series[n].label = w->cfg->label;
        series[n].colour = r;
        series[n].n = 1;
        series[n].x = &x[n];
        series[n].y = &y[n];
        series[n].hline = -1.0;
        ++n;
    }
    snprintf(title, sizeof title, "%s: RMSE against time per sample", s->label);
    snprintf(xlabel, sizeof xlabel, "ns/sample (log scale), median of %d runs", s->runs);
    pl.title = title;
    pl.xlabel = xlabel;
    pl.series = series;
    pl.nseries = n;
    cmp_pic_path(rel, sizeof rel, s, "cost", "");
    snprintf(path, sizeof path, "%s/%s", dir, rel);
    return cmp_plot_write(path, &pl);
}
