/* The quality frontier as SVG: every filter's pass-band fidelity against
 * its aliasing (fq_summarize over every curve), one marker each, the axes
 * named with what they measure, the region pass ≥ 0.9 with aliasing ≤ 0.05
 * shaded, and a legend naming the filters by colour. Inlined in the page
 * after the summary tables (doc/frequency-tests.md). */
#include "freq.h"

#define FR_W 420 /* axes box */
#define FR_H 280
#define FR_X0 60
#define FR_Y0 34
#define FR_LEAK_MAX 0.3
#define FR_PASS_MAX 1.4
#define FR_LEGEND_W 300

static double fr_x(double leak) { return FR_X0 + FR_W * (leak < FR_LEAK_MAX ? leak : FR_LEAK_MAX) / FR_LEAK_MAX; }
static double fr_y(double pass) { return FR_Y0 + FR_H * (1.0 - (pass < FR_PASS_MAX ? pass : FR_PASS_MAX) / FR_PASS_MAX); }

void fq_svg_frontier(const fq_plan *plan, const fq_sweep *s, fq_buf *out)
{
    const int width = FR_X0 + FR_W + 20 + FR_LEGEND_W, legend_h = FR_Y0 + 16 * (plan->nbackends + 1) + 8,
              height = legend_h > FR_Y0 + FR_H + 44 ? legend_h : FR_Y0 + FR_H + 44;
    double v;
    int b;
    fq_buf_printf(out,
                  "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"frontier\" width=\"%d\" height=\"%d\" "
                  "viewBox=\"0 0 %d %d\" font-family=\"sans-serif\" font-size=\"11\" "
                  "style=\"display:block;max-width:100%%;height:auto\">\n"
                  "<rect width=\"100%%\" height=\"100%%\" fill=\"#fff\"/>\n"
                  "<text x=\"10\" y=\"18\" font-weight=\"bold\" font-size=\"13\">Pass band against "
                  "aliasing (means over every curve)</text>\n",
                  width, height, width, height);
    /* The goal: pass ≥ 0.9 with aliasing ≤ 0.05. */
    fq_buf_printf(out, "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"#e8f5e8\"/>\n", fr_x(0.0),
                  fr_y(FR_PASS_MAX), fr_x(0.05) - fr_x(0.0), fr_y(0.9) - fr_y(FR_PASS_MAX));
    for (v = 0.0; v <= FR_LEAK_MAX + 1e-9; v += 0.05)
        fq_buf_printf(out,
                      "<line x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\" stroke=\"#e0e0e0\"/>"
                      "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">%g</text>\n",
                      fr_x(v), FR_Y0, fr_x(v), FR_Y0 + FR_H, fr_x(v), FR_Y0 + FR_H + 14, v);
    for (v = 0.0; v <= FR_PASS_MAX + 1e-9; v += 0.2)
        fq_buf_printf(out,
                      "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"#e0e0e0\"/>"
                      "<text x=\"%d\" y=\"%.1f\" text-anchor=\"end\" dominant-baseline=\"middle\">%.1f</text>\n",
                      FR_X0, fr_y(v), FR_X0 + FR_W, fr_y(v), FR_X0 - 4, fr_y(v), v);
    fq_buf_printf(out,
                  "<rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" fill=\"none\" stroke=\"#808080\"/>\n"
                  "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">aliasing: mean |H| above %.1f "
                  "cycles/pixel (lower is better)</text>\n"
                  "<text x=\"14\" y=\"%.1f\" text-anchor=\"middle\" transform=\"rotate(-90 14 %.1f)\">pass "
                  "band: mean |H| below %.1f cycles/pixel</text>\n",
                  FR_X0, FR_Y0, FR_W, FR_H, FR_X0 + FR_W / 2.0, FR_Y0 + FR_H + 32, FQ_STOP_ABOVE,
                  FR_Y0 + FR_H / 2.0, FR_Y0 + FR_H / 2.0, FQ_PASS_BELOW);
    for (b = 0; b < plan->nbackends; ++b) {
        fq_stat st = fq_summarize(plan, s, b, -1, -1);
        const double ly = FR_Y0 + 8 + 16.0 * b;
        if (st.npass && st.nstop)
            fq_buf_printf(out, "<circle class=\"point\" data-filter=\"%s\" cx=\"%.1f\" cy=\"%.1f\" r=\"5\" "
                               "fill=\"#%06x\"/>\n",
                          plan->backends[b]->name, fr_x(st.alias), fr_y(st.pass), fq_plot_color(b));
        fq_buf_printf(out,
                      "<circle cx=\"%d\" cy=\"%.1f\" r=\"5\" fill=\"#%06x\"/><text x=\"%d\" y=\"%.1f\" "
                      "dominant-baseline=\"middle\">%s</text>\n",
                      FR_X0 + FR_W + 26, ly, fq_plot_color(b), FR_X0 + FR_W + 36, ly, plan->backends[b]->label);
    }
    fq_buf_printf(out, "<rect x=\"%d\" y=\"%.1f\" width=\"10\" height=\"10\" fill=\"#e8f5e8\"/><text x=\"%d\" "
                       "y=\"%.1f\" dominant-baseline=\"middle\">pass &#8805; 0.9, aliasing &#8804; 0.05</text>\n",
                  FR_X0 + FR_W + 21, FR_Y0 + 3 + 16.0 * plan->nbackends, FR_X0 + FR_W + 36,
                  FR_Y0 + 8 + 16.0 * plan->nbackends);
    fq_buf_printf(out, "</svg>\n");
}
