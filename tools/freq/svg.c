/* One figure per (θ, r) as SVG: a title, a panel per minification m with
 * every filter's |H| against screen frequency and the ideal low-pass, axis
 * names with their units, and a legend naming each filter. The same text
 * is a file of its own (standalone) and is inlined in the HTML page, so the
 * page shows the labelled figure itself. */
#include "freq.h"

#include <math.h>

static void svg_polyline(fq_buf *out, const char *cls, double x0, double y0,
                         const double *F, const double *h, size_t n, const fq_plan *plan)
{
    size_t k;
    fq_buf_printf(out, "<polyline class=\"%s\" points=\"", cls);
    for (k = 0; k < n; ++k)
        fq_buf_printf(out, "%s%.2f,%.2f", k ? " " : "", x0 + fq_plot_x(plan, F[k]),
                      y0 + fq_plot_y(h[k]));
    fq_buf_printf(out, "\"/>\n");
}

static void svg_panel(const fq_plan *plan, const fq_sweep *s, int im, int it, int ir, fq_buf *out)
{
    double x0, y0, F[4], h[4], v;
    int aw = fq_plot_axes_w(), ah = fq_plot_axes_h(), b;
    fq_panel_origin(plan, im, &x0, &y0);
    fq_buf_printf(out, "<g class=\"panel\" data-m=\"%g\">\n", plan->m[im]);
    fq_buf_printf(out, "<text class=\"title\" x=\"%.2f\" y=\"%.2f\">m = %g texels/pixel</text>\n",
                  x0, y0 - 8, plan->m[im]);
    /* Grid every ¼ cycle/pixel and every ¼ of response, labelled every ½;
     * a tick label's x (xtick) or y (ytick) is its grid line's, so the
     * labels locate the data (tests/freq_cli.c reads them back). */
    for (v = 0.0; v <= plan->f_max + 1e-9; v += 0.25) {
        double x = x0 + fq_plot_x(plan, v);
        fq_buf_printf(out, "<line class=\"grid\" x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n",
                      x, y0, x, y0 + ah);
        if (fmod(v, 0.5) == 0.0)
            fq_buf_printf(out, "<text class=\"xtick\" x=\"%.2f\" y=\"%.2f\">%g</text>\n", x,
                          y0 + ah + 12, v);
    }
    for (v = 0.0; v <= FQ_PLOT_YMAX + 1e-9; v += 0.25) {
        double y = y0 + fq_plot_y(v);
        fq_buf_printf(out, "<line class=\"grid\" x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n",
                      x0, y, x0 + aw, y);
        if (fmod(v, 0.5) == 0.0)
            fq_buf_printf(out, "<text class=\"ytick\" x=\"%.2f\" y=\"%.2f\">%g</text>\n", x0 - 4,
                          y, v);
    }
    fq_buf_printf(out, "<rect class=\"axes\" x=\"%.2f\" y=\"%.2f\" width=\"%d\" height=\"%d\"/>\n",
                  x0, y0, aw, ah);
    fq_buf_printf(out, "<text class=\"xlabel\" x=\"%.2f\" y=\"%.2f\">%s</text>\n", x0 + aw / 2.0,
                  y0 + ah + 27, FQ_PLOT_XLABEL);
    /* Rotated: its baseline runs up the panel's left margin, clear of the
     * tick labels (right-aligned at x0 − 4). */
    fq_buf_printf(out,
                  "<text class=\"ylabel\" x=\"%.2f\" y=\"%.2f\" transform=\"rotate(-90 %.2f %.2f)\">"
                  "%s</text>\n",
                  x0 - FQ_PANEL_MARGIN_L + 12, y0 + ah / 2.0, x0 - FQ_PANEL_MARGIN_L + 12,
                  y0 + ah / 2.0, FQ_PLOT_YLABEL);
    fq_ideal_points(plan, F, h);
    svg_polyline(out, "ideal", x0, y0, F, h, 4, plan);
    for (b = 0; b < plan->nbackends; ++b) {
        const fq_point *p;
        size_t n = fq_curve(s, b, im, it, ir, &p), k;
        if (!n) continue;
        fq_buf_printf(out, "<polyline class=\"curve\" data-filter=\"%s\" stroke=\"#%06x\" points=\"",
                      plan->backends[b]->name, fq_plot_color(b));
        for (k = 0; k < n; ++k)
            fq_buf_printf(out, "%s%.2f,%.2f", k ? " " : "", x0 + fq_plot_x(plan, p[k].res.F),
                          y0 + fq_plot_y(p[k].res.amp));
        fq_buf_printf(out, "\"/>\n");
    }
    fq_buf_printf(out, "</g>\n");
}

void fq_svg_figure(const fq_plan *plan, const fq_sweep *s, int itheta, int ir, int standalone,
                   fq_buf *out)
{
    fq_figure fig = fq_figure_size(plan);
    int im, b;
    if (standalone) fq_buf_printf(out, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    fq_buf_printf(out,
                  "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"figure\" width=\"%d\" "
                  "height=\"%d\" viewBox=\"0 0 %d %d\" font-family=\"sans-serif\" "
                  "font-size=\"11\">\n"
                  "<style>.grid{stroke:#e0e0e0;stroke-width:1}"
                  ".axes{fill:none;stroke:#808080;stroke-width:1}"
                  ".ideal{fill:none;stroke:#000;stroke-width:1.5;stroke-dasharray:5,3}"
                  ".curve{fill:none;stroke-width:1.5}"
                  ".xtick,.xlabel,.ylabel{text-anchor:middle}"
                  ".ytick{text-anchor:end;dominant-baseline:middle}"
                  ".title{font-weight:bold}.figtitle{font-weight:bold;font-size:13px}</style>\n"
                  "<rect width=\"100%%\" height=\"100%%\" fill=\"#fff\"/>\n",
                  fig.width, fig.height, fig.width, fig.height);
    fq_buf_printf(out,
                  "<text class=\"figtitle\" x=\"10\" y=\"18\">Response |H| of each filter, "
                  "&#952; = %g&#176;, r = %g</text>\n",
                  plan->theta_deg[itheta], plan->r[ir]);
    for (im = 0; im < plan->nm; ++im) svg_panel(plan, s, im, itheta, ir, out);
    for (b = 0; b < plan->nbackends; ++b) {
        double x, y;
        fq_legend_pos(plan, b, &x, &y);
        fq_buf_printf(out,
                      "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#%06x\" "
                      "stroke-width=\"3\"/><text class=\"legend\" x=\"%.1f\" y=\"%.1f\">%s</text>\n",
                      x, y - 4, x + 20, y - 4, fq_plot_color(b), x + 26, y, plan->backends[b]->label);
    }
    {
        double x, y;
        fq_legend_pos(plan, plan->nbackends, &x, &y);
        fq_buf_printf(out,
                      "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" class=\"ideal\"/>"
                      "<text class=\"legend\" x=\"%.1f\" y=\"%.1f\">ideal low-pass (Nyquist 0.5)</text>\n",
                      x, y - 4, x + 20, y - 4, x + 26, y);
    }
    fq_buf_printf(out, "</svg>\n");
}
