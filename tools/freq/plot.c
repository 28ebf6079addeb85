/* Plot geometry of the SVG figures: where the title, the panels and the
 * legend go, and the data → figure mapping inside a panel. */
#include "freq.h"

#define AXES_W (FQ_PANEL_W - FQ_PANEL_MARGIN_L - FQ_PANEL_MARGIN_R)
#define AXES_H (FQ_PANEL_H - FQ_PANEL_MARGIN_T - FQ_PANEL_MARGIN_B)
#define LEGEND_ROW 16
#define LEGEND_COLS 3

fq_figure fq_figure_size(const fq_plan *plan)
{
    fq_figure f;
    int rows = (plan->nm + FQ_PLOT_COLS - 1) / FQ_PLOT_COLS;
    f.width = FQ_PLOT_COLS * FQ_PANEL_W;
    f.legend_h = ((plan->nbackends + LEGEND_COLS - 1) / LEGEND_COLS + 1) * LEGEND_ROW;
    f.height = FQ_FIG_TITLE_H + rows * FQ_PANEL_H + f.legend_h;
    return f;
}

void fq_panel_origin(const fq_plan *plan, int k, double *x0, double *y0)
{
    (void)plan;
    *x0 = (k % FQ_PLOT_COLS) * FQ_PANEL_W + FQ_PANEL_MARGIN_L;
    *y0 = FQ_FIG_TITLE_H + (k / FQ_PLOT_COLS) * FQ_PANEL_H + FQ_PANEL_MARGIN_T;
}

double fq_plot_x(const fq_plan *plan, double F) { return AXES_W * F / plan->f_max; }

double fq_plot_y(double h)
{
    /* Values past the axes are drawn at the edge, not outside the panel. */
    if (h > FQ_PLOT_YMAX) h = FQ_PLOT_YMAX;
    if (h < 0.0) h = 0.0;
    return AXES_H * (1.0 - h / FQ_PLOT_YMAX);
}

int fq_plot_axes_w(void) { return AXES_W; }
int fq_plot_axes_h(void) { return AXES_H; }

void fq_legend_pos(const fq_plan *plan, int k, double *x, double *y)
{
    int rows = (plan->nm + FQ_PLOT_COLS - 1) / FQ_PLOT_COLS;
    *x = 20 + (k % LEGEND_COLS) * (FQ_PLOT_COLS * FQ_PANEL_W / LEGEND_COLS);
    *y = FQ_FIG_TITLE_H + rows * FQ_PANEL_H + (k / LEGEND_COLS + 1) * LEGEND_ROW;
}

unsigned fq_plot_color(int k)
{
    /* Tableau 10: distinct at a glance and for the common colour-vision
     * deficiencies. */
    static const unsigned colors[] = {0x1f77b4, 0xff7f0e, 0x2ca02c, 0xd62728, 0x9467bd,
                                      0x8c564b, 0xe377c2, 0x7f7f7f, 0xbcbd22, 0x17becf};
    return colors[(unsigned)k % (sizeof colors / sizeof colors[0])];
}

/* The ideal low-pass of DESIGN §9: 1 below Nyquist (½ cycle/pixel), 0
 * above, drawn as the step through (0, 1), (½, 1), (½, 0), (f_max, 0). */
void fq_ideal_points(const fq_plan *plan, double F[4], double h[4])
{
    F[0] = 0.0;
    h[0] = 1.0;
    F[1] = 0.5;
    h[1] = 1.0;
    F[2] = 0.5;
    h[2] = 0.0;
    F[3] = plan->f_max;
    h[3] = 0.0;
}

double fq_ideal(double F) { return F < 0.5 ? 1.0 : (F > 0.5 ? 0.0 : 0.5); }
