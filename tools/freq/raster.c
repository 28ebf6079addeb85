/* The SVG figure's raster twin (the PNG the HTML page shows): same geometry
 * (plot.c), lines drawn with coverage from the distance to each segment.
 * It carries no text; the page's captions and legend say what is drawn. */
#include "freq.h"

#include <math.h>
#include <stdlib.h>

typedef struct canvas {
    float *px;
    int w, h;
} canvas;

/* sRGB hex colour to linear RGB: the picture is linear and the PNG writer
 * encodes it as sRGB. */
static void hex_linear(unsigned hex, float rgb[3])
{
    rgb[0] = sample_srgb_to_linear((float)((hex >> 16) & 255) / 255.0f);
    rgb[1] = sample_srgb_to_linear((float)((hex >> 8) & 255) / 255.0f);
    rgb[2] = sample_srgb_to_linear((float)(hex & 255) / 255.0f);
}

/* Blend a segment of width `width` pixels into the canvas. Coverage is
 * 1 within width/2 of the segment and falls off over one pixel; a dash
 * pattern (on, off in pixels; on = 0 for solid) is measured along it. */
static void segment(canvas *c, double xa, double ya, double xb, double yb, double width,
                    const float rgb[3], double dash_on, double dash_off)
{
    double dx = xb - xa, dy = yb - ya, len2 = dx * dx + dy * dy, len = sqrt(len2);
    double r = width / 2 + 1.0;
    int x0 = (int)floor(fmin(xa, xb) - r), x1 = (int)ceil(fmax(xa, xb) + r);
    int y0 = (int)floor(fmin(ya, yb) - r), y1 = (int)ceil(fmax(ya, yb) + r), x, y;
    if (x0 < 0) x0 = 0;
    if (y0 < 0) y0 = 0;
    if (x1 > c->w - 1) x1 = c->w - 1;
    if (y1 > c->h - 1) y1 = c->h - 1;
    for (y = y0; y <= y1; ++y)
        for (x = x0; x <= x1; ++x) {
            double px = x + 0.5 - xa, py = y + 0.5 - ya, t = 0.0, d, cov;
            float *p = c->px + 4 * ((size_t)y * c->w + x);
            int k;
            if (len2 > 0) t = fmin(1.0, fmax(0.0, (px * dx + py * dy) / len2));
            d = hypot(px - t * dx, py - t * dy);
            cov = fmin(1.0, fmax(0.0, width / 2 + 0.5 - d));
            if (dash_on > 0 && fmod(t * len, dash_on + dash_off) > dash_on) cov = 0.0;
            for (k = 0; k < 3; ++k) p[k] = (float)(p[k] * (1.0 - cov) + rgb[k] * cov);
        }
}

static void panel(canvas *c, const fq_plan *plan, const fq_sweep *s, int im, int it, int ir)
{
    static const float grid[3] = {0.75f, 0.75f, 0.75f}, axes[3] = {0.2f, 0.2f, 0.2f},
                       black[3] = {0, 0, 0};
    double x0, y0, F[4], h[4], v;
    int aw = fq_plot_axes_w(), ah = fq_plot_axes_h(), b, k;
    fq_panel_origin(plan, im, &x0, &y0);
    for (v = 0.0; v <= plan->f_max + 1e-9; v += 0.25) {
        double x = x0 + fq_plot_x(plan, v);
        segment(c, x, y0, x, y0 + ah, 1.0, grid, 0, 0);
    }
    for (v = 0.0; v <= FQ_PLOT_YMAX + 1e-9; v += 0.25) {
        double y = y0 + fq_plot_y(v);
        segment(c, x0, y, x0 + aw, y, 1.0, grid, 0, 0);
    }
    segment(c, x0, y0, x0 + aw, y0, 1.0, axes, 0, 0);
    segment(c, x0, y0 + ah, x0 + aw, y0 + ah, 1.0, axes, 0, 0);
    segment(c, x0, y0, x0, y0 + ah, 1.0, axes, 0, 0);
    segment(c, x0 + aw, y0, x0 + aw, y0 + ah, 1.0, axes, 0, 0);
    for (b = 0; b < plan->nbackends; ++b) {
        const fq_point *p;
        size_t n = fq_curve(s, b, im, it, ir, &p), j;
        float rgb[3];
        hex_linear(fq_plot_color(b), rgb);
        for (j = 1; j < n; ++j)
            segment(c, x0 + fq_plot_x(plan, p[j - 1].res.F), y0 + fq_plot_y(p[j - 1].res.amp),
                    x0 + fq_plot_x(plan, p[j].res.F), y0 + fq_plot_y(p[j].res.amp), 1.5, rgb, 0,
                    0);
    }
    /* The ideal last, so that it stays visible over the curves. */
    fq_ideal_points(plan, F, h);
    for (k = 1; k < 4; ++k)
        segment(c, x0 + fq_plot_x(plan, F[k - 1]), y0 + fq_plot_y(h[k - 1]),
                x0 + fq_plot_x(plan, F[k]), y0 + fq_plot_y(h[k]), 1.5, black, 5, 3);
}

float *fq_raster_figure(const fq_plan *plan, const fq_sweep *s, int itheta, int ir, int *w,
                        int *h)
{
    fq_figure fig = fq_figure_size(plan);
    canvas c;
    size_t k, n = (size_t)fig.width * (size_t)fig.height;
    int im, b;
    c.w = fig.width;
    c.h = fig.height;
    c.px = (float *)malloc(n * 4 * sizeof *c.px);
    if (!c.px) return NULL;
    for (k = 0; k < 4 * n; ++k) c.px[k] = 1.0f;
    for (im = 0; im < plan->nm; ++im) panel(&c, plan, s, im, itheta, ir);
    /* Legend swatches in the SVG's places; the HTML names them. */
    for (b = 0; b < plan->nbackends; ++b) {
        double x, y;
        float rgb[3];
        fq_legend_pos(plan, b, &x, &y);
        hex_linear(fq_plot_color(b), rgb);
        segment(&c, x, y - 4, x + 20, y - 4, 3.0, rgb, 0, 0);
    }
    *w = c.w;
    *h = c.h;
    return c.px;
}
