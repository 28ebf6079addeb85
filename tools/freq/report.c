/* The sweep as text: every curve (CSV), the summary (CSV, Markdown) and the
 * HTML page that puts the plots and the tables together. */
#include "freq.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void fq_report_csv(const fq_plan *plan, const fq_sweep *s, fq_buf *out)
{
    size_t k;
    fq_buf_printf(out, "filter,m,theta_deg,theta_real_deg,r,n,p,q,f,F,band,alias_F,re,im,amp,"
                       "stderr,residual,ideal,texels,ns\n");
    for (k = 0; k < s->count; ++k) {
        const fq_point *p = &s->pts[k];
        const fq_result *r = &p->res;
        fq_buf_printf(out, "%s,%g,%g,%.4f,%g,%d,%d,%d,%.8f,%.8f,%s,%.8f,%.6f,%.6f,%.6f,%.6f,%.6f,%g,",
                      plan->backends[p->backend]->name, plan->m[p->im], plan->theta_deg[p->itheta],
                      p->wave.theta * 180.0 / FQ_PI, plan->r[p->ir], p->wave.n, p->wave.p,
                      p->wave.q, p->wave.f, r->F, r->F < 0.5 ? "pass" : "stop", r->alias_F, r->re,
                      r->im, r->amp, r->stderr_, r->residual, fq_ideal(r->F));
        if (isnan(r->texels))
            fq_buf_printf(out, ",%.1f\n", r->ns);
        else
            fq_buf_printf(out, "%.3f,%.1f\n", r->texels, r->ns);
    }
}

static void csv_num(fq_buf *out, double v, const char *sep)
{
    if (isnan(v))
        fq_buf_printf(out, "%s", sep);
    else
        fq_buf_printf(out, "%.4f%s", v, sep);
}

void fq_report_summary_csv(const fq_plan *plan, const fq_sweep *s, fq_buf *out)
{
    int b, im, ir;
    fq_buf_printf(out, "filter,m,r,pass,pass_worst,alias,alias_worst,texels,ns\n");
    for (b = 0; b < plan->nbackends; ++b)
        for (im = -1; im < plan->nm; ++im)
            for (ir = -1; ir < plan->nr; ++ir) {
                fq_stat st = fq_summarize(plan, s, b, im, ir);
                fq_buf_printf(out, "%s,", plan->backends[b]->name);
                if (im < 0) fq_buf_printf(out, "all,"); else fq_buf_printf(out, "%g,", plan->m[im]);
                if (ir < 0) fq_buf_printf(out, "all,"); else fq_buf_printf(out, "%g,", plan->r[ir]);
                csv_num(out, st.pass, ",");
                csv_num(out, st.pass_worst, ",");
                csv_num(out, st.alias, ",");
                csv_num(out, st.alias_worst, ",");
                csv_num(out, st.texels, ",");
                csv_num(out, st.ns, "\n");
            }
}

/* One table syntax for Markdown and HTML, so both show the same numbers
 * from the same code. */
typedef struct table_fmt {
    const char *begin, *row, *cell, *head_cell, *row_end, *end;
} table_fmt;

static const table_fmt MD = {"", "|", " ", " ", "\n", "\n"};
static const table_fmt HTML = {"<table>\n", "<tr>", "<td>", "<th>", "</tr>\n", "</table>\n"};

static void cell_end(fq_buf *out, const table_fmt *t, int head)
{
    if (t == &MD)
        fq_buf_printf(out, " |");
    else
        fq_buf_printf(out, head ? "</th>" : "</td>");
}

static void cell_text(fq_buf *out, const table_fmt *t, int head, const char *text)
{
    fq_buf_printf(out, "%s%s", head ? t->head_cell : t->cell, text);
    cell_end(out, t, head);
}

static void cell_num(fq_buf *out, const table_fmt *t, double v, const char *fmt)
{
    fq_buf_printf(out, "%s", t->cell);
    if (isnan(v))
        fq_buf_printf(out, "n/a");
    else
        fq_buf_printf(out, fmt, v);
    cell_end(out, t, 0);
}

static void header(fq_buf *out, const table_fmt *t, const char *const *cols, int n)
{
    int k;
    fq_buf_printf(out, "%s%s", t->begin, t->row);
    for (k = 0; k < n; ++k) cell_text(out, t, 1, cols[k]);
    fq_buf_printf(out, "%s", t->row_end);
    if (t == &MD) {
        fq_buf_printf(out, "|");
        for (k = 0; k < n; ++k) fq_buf_printf(out, "%s|", k ? "---:" : "---");
        fq_buf_printf(out, "\n");
    }
}

/* The rows that did not run, with the reason in the first number's
 * column and the other `ncols` − 2 cells empty. */
static void na_rows(const fq_plan *plan, const table_fmt *t, int ncols, fq_buf *out)
{
    int k, c;
    char text[256];
    for (k = 0; k < plan->nna; ++k) {
        fq_buf_printf(out, "%s", t->row);
        cell_text(out, t, 0, plan->na[k].label);
        snprintf(text, sizeof text, "n/a: %s", plan->na[k].reason);
        cell_text(out, t, 0, text);
        for (c = 2; c < ncols; ++c) cell_text(out, t, 0, "");
        fq_buf_printf(out, "%s", t->row_end);
    }
}

/* Per filter, everything folded: the two numbers with their worst case and
 * the cost. */
static void table_overall(const fq_plan *plan, const fq_sweep *s, const table_fmt *t, fq_buf *out)
{
    static const char *const cols[] = {"filter",           "pass-band (mean, F < 0.4)",
                                       "worst setting",    "aliasing (mean, F > 0.6)",
                                       "worst setting",    "texels/sample",
                                       "ns/sample"};
    int b;
    header(out, t, cols, 7);
    for (b = 0; b < plan->nbackends; ++b) {
        fq_stat st = fq_summarize(plan, s, b, -1, -1);
        fq_buf_printf(out, "%s", t->row);
        cell_text(out, t, 0, plan->backends[b]->label);
        cell_num(out, t, st.pass, "%.3f");
        cell_num(out, t, st.pass_worst, "%.3f");
        cell_num(out, t, st.alias, "%.3f");
        cell_num(out, t, st.alias_worst, "%.3f");
        cell_num(out, t, st.texels, "%.1f");
        cell_num(out, t, st.ns, "%.0f");
        fq_buf_printf(out, "%s", t->row_end);
    }
    na_rows(plan, t, 7, out);
    fq_buf_printf(out, "%s", t->end);
}

/* Per filter and anisotropy r (m and θ folded, worst over θ and m):
 * "pass / alias" in each cell. */
static void table_by_r(const fq_plan *plan, const fq_sweep *s, const table_fmt *t, fq_buf *out)
{
    const char *cols[16];
    char names[16][32];
    int b, ir, n = plan->nr < 15 ? plan->nr : 15;
    cols[0] = "filter: pass band / aliasing (worst of each)";
    for (ir = 0; ir < n; ++ir) {
        snprintf(names[ir], sizeof names[ir], "r = %g", plan->r[ir]);
        cols[ir + 1] = names[ir];
    }
    header(out, t, cols, n + 1);
    for (b = 0; b < plan->nbackends; ++b) {
        fq_buf_printf(out, "%s", t->row);
        cell_text(out, t, 0, plan->backends[b]->label);
        for (ir = 0; ir < n; ++ir) {
            fq_stat st = fq_summarize(plan, s, b, -1, ir);
            fq_buf_printf(out, "%s%.2f / %.2f (%.2f / %.2f)", t->cell, st.pass, st.alias,
                          st.pass_worst, st.alias_worst);
            cell_end(out, t, 0);
        }
        fq_buf_printf(out, "%s", t->row_end);
    }
    na_rows(plan, t, n + 1, out);
    fq_buf_printf(out, "%s", t->end);
}

void fq_report_summary_md(const fq_plan *plan, const fq_sweep *s, fq_buf *out)
{
    table_overall(plan, s, &MD, out);
    table_by_r(plan, s, &MD, out);
}

/* "1.5, 5.7, 16" (each value followed by `unit`). */
static void html_list(fq_buf *out, const double *v, int n, const char *unit)
{
    int k;
    for (k = 0; k < n; ++k) fq_buf_printf(out, "%s%g%s", k ? ", " : "", v[k], unit);
}

/* s with <, > and & escaped. */
static void html_text(fq_buf *out, const char *s)
{
    for (; *s; ++s) {
        if (*s == '<') fq_buf_printf(out, "&lt;");
        else if (*s == '>') fq_buf_printf(out, "&gt;");
        else if (*s == '&') fq_buf_printf(out, "&amp;");
        else fq_buf_printf(out, "%c", *s);
    }
}

/* Which sampler produced each row: the driver and device of an OpenGL row
 * (GL_RENDERER; GL_VERSION), an outside program's command. */
static void html_drivers(const fq_plan *plan, fq_buf *out)
{
    int b;
    fq_buf_printf(out, "<h2>Samplers</h2>\n<table>\n<tr><th>row</th><th>produced by</th></tr>\n");
    for (b = 0; b < plan->nbackends + plan->nna; ++b) {
        const char *label = b < plan->nbackends ? plan->backends[b]->label : plan->na[b - plan->nbackends].label;
        const char *driver = b < plan->nbackends ? plan->backends[b]->driver : plan->na[b - plan->nbackends].driver;
        fq_buf_printf(out, "<tr><td>");
        html_text(out, label);
        fq_buf_printf(out, "</td><td>");
        html_text(out, driver ? driver : strncmp(label, "OpenImageIO", 11) == 0 ? "OpenImageIO TextureSystem" : "libsample " SAMPLE_VERSION_STRING);
        fq_buf_printf(out, "</td></tr>\n");
    }
    fq_buf_printf(out, "</table>\n");
}

void fq_report_html(const fq_plan *plan, const fq_sweep *s, const char *const *svgs,
                    const char *const *zone, const char *command, fq_buf *out)
{
    int b, it, ir;
    fq_buf_printf(out,
                  "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
                  "<title>libsample frequency tests</title>\n<style>"
                  "body{font-family:sans-serif;max-width:1000px;margin:1em auto;padding:0 1em}"
                  "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #ccc;"
                  "padding:2px 6px;text-align:right}td:first-child,th:first-child{text-align:left}"
                  "img{max-width:100%%}svg.figure{display:block;max-width:100%%;height:auto}"
                  "code{background:#f4f4f4}figure{margin:1em 0}figcaption{margin-top:0.3em}"
                  ".zones{display:flex;flex-wrap:wrap;gap:1em}.zones figure{margin:0;width:%dpx}"
                  "</style></head><body>\n"
                  "<h1>Frequency tests</h1>\n<p>Produced by <code>",
                  FQ_ZONE_PIXELS);
    html_text(out, command);
    fq_buf_printf(out,
                  "</code>. A sinusoidal grating of f cycles/texel is sampled with m texels "
                  "per pixel along its wave vector and m&middot;r across it; the curves give "
                  "the amplitude |H| of the output at the input's screen frequency "
                  "F = f&middot;m (below 0.5 cycles/pixel: the pass-band response, ideally 1) "
                  "or at its alias frequency F &minus; round(F) (above: the leakage, ideally 0). "
                  "The dashed line is the ideal low-pass. Method and decisions: "
                  "doc/frequency-tests.md. Data: <a href=\"freq.csv\">freq.csv</a>, "
                  "<a href=\"summary.csv\">summary.csv</a>.</p>\n<p>m = ");
    html_list(out, plan->m, plan->nm, "");
    fq_buf_printf(out, "; &theta; = ");
    html_list(out, plan->theta_deg, plan->ntheta, "&deg;");
    fq_buf_printf(out, "; r = ");
    html_list(out, plan->r, plan->nr, "");
    fq_buf_printf(out, "; texture %d &times; %d, %d &times; %d pixels &times; %d offsets per point.</p>\n",
                  plan->n, plan->n, plan->width, plan->rows, plan->phases);
    fq_buf_printf(out, "<h2>Summary</h2>\n<p>Means weigh every (m, &theta;, r) curve "
                       "equally; worst is the lowest mean response below F = 0.4 and the highest "
                       "aliasing mean of any one curve.</p>\n");
    table_overall(plan, s, &HTML, out);
    table_by_r(plan, s, &HTML, out);
    html_drivers(plan, out);
    fq_buf_printf(out, "<figure>\n");
    fq_svg_frontier(plan, s, out);
    fq_buf_printf(out, "<figcaption>Pass band against aliasing: the upper left is best; the "
                       "shaded box is pass &#8805; 0.9 with aliasing &#8804; 0.05.</figcaption></figure>\n");
    fq_buf_printf(out, "<h2>Curves</h2>\n<p>One figure per (&theta;, r), one panel per m "
                       "(left to right, top to bottom: m = ");
    html_list(out, plan->m, plan->nm, "");
    fq_buf_printf(out, "); each figure names its axes and its filters and links its SVG "
                       "file.</p>\n");
    for (ir = 0; ir < plan->nr; ++ir) {
        fq_buf_printf(out, "<h3>r = %g</h3>\n", plan->r[ir]);
        for (it = 0; it < plan->ntheta; ++it) {
            fq_buf_printf(out, "<figure>\n");
            fq_svg_figure(plan, s, it, ir, 0, out);
            fq_buf_printf(out, "<figcaption>&theta; = %g&deg;, r = %g: <a href=\"%s\">SVG "
                               "file</a></figcaption></figure>\n",
                          plan->theta_deg[it], plan->r[ir], svgs[ir * plan->ntheta + it]);
        }
    }
    for (b = 0; zone && b < plan->nbackends && !zone[b]; ++b)
        ;
    if (zone && b < plan->nbackends) {
        fq_buf_printf(out, "<h2>Zone plate</h2>\n<p>cos(&pi;(x&sup2; + y&sup2;)/N), local "
                           "frequency 0 at the centre to 0.5 cycles/texel at the edges, seen "
                           "at 2 texels per pixel: every ring pattern away from the centre is "
                           "aliasing.</p>\n<div class=\"zones\">\n");
        for (b = 0; b < plan->nbackends; ++b)
            if (zone[b])
                fq_buf_printf(out, "<figure><a href=\"%s\"><img src=\"%s\" alt=\"%s\" "
                                   "width=\"%d\" height=\"%d\"></a><figcaption>%s</figcaption>"
                                   "</figure>\n",
                              zone[b], zone[b], plan->backends[b]->name, FQ_ZONE_PIXELS,
                              FQ_ZONE_PIXELS, plan->backends[b]->label);
        fq_buf_printf(out, "</div>\n");
    }
    fq_buf_printf(out, "</body></html>\n");
}
