/*
 * The tables and the page: results.csv (one row per scene × configuration),
 * results.json (the same with the picture paths), and index.html, one
 * self-contained page (inline style, no script, relative links to the PNGs)
 * that puts pictures, numbers and the explanation together.
 */
#include "cmp_internal.h"
#include "cli.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- A growable text buffer ------------------------------------------- */

typedef struct buf {
    char *p;
    size_t len, cap;
    int oom;
} buf;

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static void bprintf(buf *b, const char *fmt, ...)
{
    va_list ap;
    int n;
    if (b->oom) return;
    for (;;) {
        size_t room = b->cap - b->len;
        va_start(ap, fmt);
        n = vsnprintf(b->p ? b->p + b->len : NULL, b->p ? room : 0, fmt, ap);
        va_end(ap);
        if (n < 0) {
            b->oom = 1;
            return;
        }
        if (b->p && (size_t)n < room) {
            b->len += (size_t)n;
            return;
        }
        {
            size_t cap = b->cap ? b->cap : 4096;
            char *q;
            while (cap < b->len + (size_t)n + 1) cap *= 2;
            q = realloc(b->p, cap);
            if (!q) {
                b->oom = 1;
                return;
            }
            b->p = q;
            b->cap = cap;
        }
    }
}

/* Characters that must not reach HTML (or a JSON string) as they are. */
static void bescape(buf *b, const char *s, int json)
{
    for (; *s; ++s) {
        unsigned char c = (unsigned char)*s;
        if (json && (c == '"' || c == '\\')) bprintf(b, "\\%c", c);
        else if (json && c < 0x20) bprintf(b, "\\u%04x", c);
        else if (!json && c == '<') bprintf(b, "&lt;");
        else if (!json && c == '>') bprintf(b, "&gt;");
        else if (!json && c == '&') bprintf(b, "&amp;");
        else if (!json && c == '"') bprintf(b, "&quot;");
        else bprintf(b, "%c", c);
    }
}

static int bwrite(buf *b, const char *path)
{
    int rc = b->oom || !cli_write_file(path, b->p ? b->p : "", b->len);
    free(b->p);
    return rc;
}

void cmp_pic_path(char *out, size_t len, const cmp_scene_result *s, const char *what,
                  const char *suffix)
{
    snprintf(out, len, "%s/%s%s.png", s->label, what, suffix);
}

/* A number for CSV/JSON: %.6g, or `none` when it has no finite value. */
static void bnum(buf *b, double v, const char *none)
{
    if (isfinite(v)) bprintf(b, "%.6g", v);
    else bprintf(b, "%s", none);
}

/* ---- CSV ----------------------------------------------------------------- */

/* A note as a quoted CSV field ("n/a: " first for an n/a row). */
static void bnote(buf *b, int na, const char *note)
{
    const char *c;
    bprintf(b, "\"%s", na ? "n/a: " : "");
    for (c = note; *c; ++c) bprintf(b, *c == '"' ? "\"\"" : "%c", *c);
    bprintf(b, "\"\n");
}

int cmp_write_csv(const char *path, const cmp_scene_result *s, int n)
{
    buf b = {0};
    int k, r;
    bprintf(&b, "scene,config,label,rmse,psnr_db,max_error,seconds,ns_per_sample,"
                "texels_per_sample,measured_pixels,truth_samples,runs,note\n");
    for (k = 0; k < n; ++k)
        for (r = 0; r < s[k].nrows; ++r) {
            const cmp_row *w = &s[k].rows[r];
            bprintf(&b, "%s,%s,\"%s\",", s[k].label, w->cfg->name, w->cfg->label);
            if (w->ok) {
                bnum(&b, w->m.rmse, "");
                bprintf(&b, ",");
                bnum(&b, w->m.psnr, "inf");
                bprintf(&b, ",");
                bnum(&b, w->m.max_err, "");
                bprintf(&b, ",%.6g,%.6g,", w->seconds, w->ns_per_sample);
                bnum(&b, w->texels >= 0 ? w->texels : NAN, "");
            } else {
                bprintf(&b, ",,,,,");
            }
            bprintf(&b, ",%zu,%d,%d,", s[k].measured, s[k].truth_samples, s[k].runs);
            bnote(&b, w->na, w->note);
        }
    return bwrite(&b, path);
}

/* The stochastic sweep: one line per (scene, filter, spp). */
int cmp_write_spp_csv(const char *path, const cmp_scene_result *s, int n)
{
    buf b = {0};
    int k, r, j;
    bprintf(&b, "scene,config,label,spp,draws,rmse,deterministic_rmse,ns_per_sample,note\n");
    for (k = 0; k < n; ++k)
        for (r = 0; r < s[k].nspp_rows; ++r) {
            const cmp_spp_row *w = &s[k].spp_rows[r];
            for (j = 0; j < s[k].nspp; ++j) {
                bprintf(&b, "%s,%s,\"%s\",%d,%u,", s[k].label, w->cfg->name, w->cfg->label,
                        s[k].spp[j], s[k].draws);
                if (w->ok) {
                    bnum(&b, w->rmse[j], "");
                    bprintf(&b, ",");
                    bnum(&b, w->det_rmse, "");
                    bprintf(&b, ",%.6g,", w->ns_per_sample);
                } else {
                    bprintf(&b, ",,,");
                }
                bnote(&b, !w->ok, w->note);
            }
        }
    return bwrite(&b, path);
}

/* ---- JSON ---------------------------------------------------------------- */

static void jstr(buf *b, const char *key, const char *v)
{
    bprintf(b, "\"%s\": \"", key);
    bescape(b, v, 1);
    bprintf(b, "\"");
}

int cmp_write_json(const char *path, const cmp_scene_result *s, int n, const char *command)
{
    buf b = {0};
    char p[512];
    int k, r;
    bprintf(&b, "{\n  ");
    jstr(&b, "command", command);
    bprintf(&b, ",\n  \"heat_scale\": %g,\n  \"scenes\": [", (double)CMP_HEAT_SCALE);
    for (k = 0; k < n; ++k) {
        const cmp_scene_result *c = &s[k];
        bprintf(&b, "%s\n    {", k ? "," : "");
        jstr(&b, "name", c->label);
        bprintf(&b, ", ");
        jstr(&b, "source", c->source);
        bprintf(&b, ", \"width\": %d, \"height\": %d, \"truth_samples\": %d, \"truth_seconds\": %.3f,"
                    " \"pixels\": %zu, \"measured_pixels\": %zu, \"runs\": %d,\n     \"crop\": {\"x\": %d,"
                    " \"y\": %d, \"size\": %d, \"zoom\": %d},\n     ",
                c->w, c->h, c->truth_samples, c->truth_seconds, c->pixels, c->measured, c->runs,
                c->crop_x, c->crop_y, c->crop_size, c->crop_zoom);
        cmp_pic_path(p, sizeof p, c, "truth", "");
        jstr(&b, "truth", p);
        bprintf(&b, ", ");
        cmp_pic_path(p, sizeof p, c, "contact", "");
        jstr(&b, "contact_sheet", p);
        bprintf(&b, ",\n     \"results\": [");
        for (r = 0; r < c->nrows; ++r) {
            const cmp_row *w = &c->rows[r];
            bprintf(&b, "%s\n      {", r ? "," : "");
            jstr(&b, "config", w->cfg->name);
            bprintf(&b, ", ");
            jstr(&b, "label", w->cfg->label);
            if (w->cfg->tb) {
                bprintf(&b, ", ");
                jstr(&b, "driver", w->cfg->tb->driver);
            }
            if (w->ok) {
                bprintf(&b, ", \"rmse\": ");
                bnum(&b, w->m.rmse, "null");
                bprintf(&b, ", \"psnr_db\": ");
                bnum(&b, w->m.psnr, "null");
                bprintf(&b, ", \"max_error\": ");
                bnum(&b, w->m.max_err, "null");
                bprintf(&b, ", \"seconds\": %.6g, \"ns_per_sample\": %.6g, \"texels_per_sample\": ",
                        w->seconds, w->ns_per_sample);
                bnum(&b, w->texels >= 0 ? w->texels : NAN, "null");
                bprintf(&b, ",\n       ");
                cmp_pic_path(p, sizeof p, c, w->cfg->name, "");
                jstr(&b, "image", p);
                bprintf(&b, ", ");
                cmp_pic_path(p, sizeof p, c, w->cfg->name, "_err");
                jstr(&b, "error_map", p);
                bprintf(&b, ", ");
                cmp_pic_path(p, sizeof p, c, w->cfg->name, "_crop");
                jstr(&b, "crop", p);
            } else {
                bprintf(&b, ", ");
                jstr(&b, w->na ? "n/a" : "error", w->note);
            }
            bprintf(&b, "}");
        }
        bprintf(&b, "\n     ]}");
    }
    bprintf(&b, "\n  ]\n}\n");
    return bwrite(&b, path);
}

/* ---- HTML ---------------------------------------------------------------- */

static const char html_head[] =
    "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
    "<title>libsample: filter comparison</title>\n<style>\n"
    "body{font-family:'DejaVu Sans',sans-serif;margin:1.5em;background:#fafafa;color:#222;"
    "max-width:1600px}\n"
    "table{border-collapse:collapse;margin:0.6em 0}td,th{border:1px solid #bbb;padding:2px 8px;"
    "text-align:right}th{background:#eee}td.l,th.l{text-align:left}\n"
    "tr.best td{background:#e3f4e3}\n"
    ".grid{display:flex;flex-wrap:wrap;gap:10px}figure{margin:0;background:#fff;"
    "border:1px solid #ccc;padding:6px}\n"
    ".strip{display:flex;gap:6px;overflow-x:auto;padding-bottom:6px;margin-bottom:10px}"
    ".strip figure{flex:none}.strip figcaption{max-width:none;width:min-content;min-width:100%}\n"
    "figure img{display:block;image-rendering:pixelated;margin-bottom:3px;height:auto}"
    "figcaption{font-size:12px;max-width:260px}\n"
    ".legend{display:inline-block;width:300px;height:14px;vertical-align:middle;"
    "background:linear-gradient(to right,#000004,#50127b,#b73779,#fc8961,#fcfdbf)}\n"
    "code{background:#eee;padding:0 3px}\n</style>\n</head>\n<body>\n";

static void html_intro(buf *b, const char *command)
{
    bprintf(b, "<h1>libsample: every filter against the ground truth</h1>\n<p>Command: <code>");
    bescape(b, command, 0);
    bprintf(b,
            "</code></p>\n<p>Each scene is rendered once per filter configuration; every "
            "configuration answers the same per-pixel queries: the exact (s,&nbsp;t) at the "
            "pixel centre and the exact screen-space Jacobian (and, for the Blinn&ndash;Newell "
            "corner mode, the exact texture-space corners of the 2&times;2-pixel footprint). "
            "The pictures show the filtered texture value only (no shading), so the error "
            "measures filtering.</p>\n"
            "<p><b>Ground truth</b> (DESIGN &sect;8): the texture integrated against the "
            "2&times;2-pixel pyramid (1&minus;|x|)(1&minus;|y|) through the exact "
            "screen&rarr;(s,&nbsp;t) mapping, by n&times;n stratified, jittered samples per "
            "footprint, each evaluated at its exact (s,&nbsp;t): analytically for procedural "
            "textures, by bilinear reconstruction of the base level for image textures.</p>\n"
            "<p><b>Metrics</b>: RMSE over R,&nbsp;G,&nbsp;B of linear values and PSNR "
            "(peak&nbsp;1), over the pixels whose whole footprint lies on the textured surface "
            "seen at the centre; pixels at silhouettes, at occlusion edges within an object "
            "and the background are left out (grey in the heat maps), since no texture "
            "filter can know about an edge. Time is the "
            "wall time of the whole image; ns/sample is the time inside the filter calls per "
            "query (all threads summed); both are the median of several runs (the table "
            "says how many), as one run's time moves with whatever else the machine is "
            "doing. texels/sample is libsample's count of texels read. "
            "The crop (magnified) is the window with the highest error summed over all "
            "configurations. Click a picture to see it at full size.</p>\n"
            "<p>Heat maps: per-pixel error (RMS over R,&nbsp;G,&nbsp;B) from 0 "
            "<span class=\"legend\"></span> %g and above.</p>\n"
            "<p>Tables: <a href=\"results.csv\">results.csv</a>, "
            "<a href=\"results.json\">results.json</a>.</p>\n",
            (double)CMP_HEAT_SCALE);
}

static void html_table(buf *b, const cmp_scene_result *c)
{
    double best = HUGE_VAL;
    int r;
    for (r = 0; r < c->nrows; ++r)
        if (c->rows[r].ok && c->rows[r].m.rmse < best) best = c->rows[r].m.rmse;
    bprintf(b, "<table>\n<tr><th class=\"l\">filter</th><th>RMSE</th><th>PSNR (dB)</th>"
               "<th>max error</th><th>time (ms),<br>median of %d run%s</th><th>ns/sample,<br>median "
               "of %d run%s</th><th>texels/sample</th></tr>\n",
            c->runs, c->runs == 1 ? "" : "s", c->runs, c->runs == 1 ? "" : "s");
    for (r = 0; r < c->nrows; ++r) {
        const cmp_row *w = &c->rows[r];
        bprintf(b, "<tr%s><td class=\"l\">", w->ok && w->m.rmse == best ? " class=\"best\"" : "");
        bescape(b, w->cfg->label, 0);
        if (w->cfg->tb) {
            /* Which driver and device, or which program, produced the row. */
            bprintf(b, "<br><small>");
            bescape(b, w->cfg->tb->driver, 0);
            bprintf(b, "</small>");
        }
        if (!w->ok) {
            bprintf(b, "</td><td class=\"l\" colspan=\"6\">%s: ", w->na ? "n/a" : "not run");
            bescape(b, w->note, 0);
            bprintf(b, "</td></tr>\n");
            continue;
        }
        bprintf(b, "</td><td>%.5f</td><td>%.2f</td><td>%.4f</td><td>%.1f</td><td>%.1f</td><td>",
                w->m.rmse, isfinite(w->m.psnr) ? w->m.psnr : 999.0, w->m.max_err,
                1e3 * w->seconds, w->ns_per_sample);
        if (w->texels >= 0) bprintf(b, "%.1f", w->texels);
        else bprintf(b, "&ndash;");
        bprintf(b, "</td></tr>\n");
    }
    bprintf(b, "</table>\n");
}

/* The largest width the page shows a scene's pictures at; a click opens
 * the picture itself at full size. */
enum { HTML_THUMB = 256 };

/* One picture: shown `width` wide (the height follows), linked to itself. */
static void html_img(buf *b, const cmp_scene_result *c, const char *name, const char *suffix,
                     int width, const char *alt)
{
    char p[512];
    cmp_pic_path(p, sizeof p, c, name, suffix);
    bprintf(b, "<a href=\"%s\"><img src=\"%s\" width=\"%d\" alt=\"", p, p, width);
    bescape(b, alt, 0);
    bprintf(b, "\"></a>");
}

/* Whether cmp_cost_plot drew the scene's cost.png: a row was timed. */
static int html_has_cost(const cmp_scene_result *c)
{
    int r;
    for (r = 0; r < c->nrows; ++r)
        if (c->rows[r].ok && c->rows[r].ns_per_sample > 0.0 && isfinite(c->rows[r].m.rmse)) return 1;
    return 0;
}

/* The stochastic sweep: its table (RMSE per samples per pixel, the
 * deterministic RMSE, the time per lookup) and spp.png. */
static void html_spp(buf *b, const cmp_scene_result *c)
{
    int r, k;
    if (!c->nspp_rows) return;
    bprintf(b, "<p>Stochastic filters (one random estimate per lookup, %u texel%s per EWA / "
               "Blinn&ndash;Newell lookup): RMSE of the mean of <i>spp</i> lookups per pixel, "
               "against the same ground truth; the deterministic filter's RMSE beside it.</p>\n"
               "<table>\n<tr><th class=\"l\">filter</th>",
            c->draws, c->draws == 1 ? "" : "s");
    for (k = 0; k < c->nspp; ++k) bprintf(b, "<th>%d spp</th>", c->spp[k]);
    bprintf(b, "<th>deterministic</th><th>ns/lookup,<br>median</th></tr>\n");
    for (r = 0; r < c->nspp_rows; ++r) {
        const cmp_spp_row *w = &c->spp_rows[r];
        bprintf(b, "<tr><td class=\"l\">");
        bescape(b, w->cfg->label, 0);
        bprintf(b, "</td>");
        if (!w->ok) {
            bprintf(b, "<td class=\"l\" colspan=\"%d\">n/a: ", c->nspp + 2);
            bescape(b, w->note, 0);
            bprintf(b, "</td></tr>\n");
            continue;
        }
        for (k = 0; k < c->nspp; ++k) bprintf(b, "<td>%.5f</td>", w->rmse[k]);
        bprintf(b, "<td>%.5f</td><td>%.1f</td></tr>\n", w->det_rmse, w->ns_per_sample);
    }
    bprintf(b, "</table>\n");
    for (r = 0; r < c->nspp_rows; ++r)
        if (c->spp_rows[r].ok) {
            /* cmp_spp_plot drew spp.png: a row was swept. */
            bprintf(b, "<p>");
            html_img(b, c, "spp", "", 560, "RMSE against samples per pixel");
            bprintf(b, "</p>\n");
            break;
        }
}

/* A filter's (or the truth's) image and its heat map (the truth: its mask). */
static void html_figure(buf *b, const cmp_scene_result *c, const char *name, const char *label,
                        const char *metrics, int heat)
{
    int dw = c->w < HTML_THUMB ? c->w : HTML_THUMB;
    char alt[160];
    bprintf(b, "<figure>");
    html_img(b, c, name, "", dw, name);
    snprintf(alt, sizeof alt, "%s %s", name, heat ? "error" : "mask");
    html_img(b, c, name, heat ? "_err" : "_mask", dw, alt);
    bprintf(b, "<figcaption><b>");
    bescape(b, label, 0);
    bprintf(b, "</b>%s</figcaption></figure>\n", metrics);
}

/* The crop of the truth and of every filter side by side, in one row, so
 * that the same window can be compared across filters at a glance. */
static void html_crop_strip(buf *b, const cmp_scene_result *c)
{
    /* Half the magnified crop (still at least 1 image pixel per page
     * pixel); a click gives the crop at full magnification. */
    int zoom = c->crop_zoom > 1 ? (c->crop_zoom + 1) / 2 : 1, dw = c->crop_size * zoom, r;
    char alt[160];
    bprintf(b, "<p>The crop (red frame in the ground truth), every filter side by side; click "
               "for %d&times; magnification.</p>\n<div class=\"strip\">\n",
            c->crop_zoom);
    bprintf(b, "<figure>");
    html_img(b, c, "truth", "_crop", dw, "truth crop");
    bprintf(b, "<figcaption><b>ground truth</b></figcaption></figure>\n");
    for (r = 0; r < c->nrows; ++r) {
        const cmp_row *w = &c->rows[r];
        if (!w->ok) continue;
        bprintf(b, "<figure>");
        snprintf(alt, sizeof alt, "%s crop", w->cfg->name);
        html_img(b, c, w->cfg->name, "_crop", dw, alt);
        bprintf(b, "<figcaption><b>");
        bescape(b, w->cfg->label, 0);
        bprintf(b, "</b></figcaption></figure>\n");
    }
    bprintf(b, "</div>\n");
}

int cmp_write_html(const char *path, const cmp_scene_result *s, int n, const char *command)
{
    buf b = {0};
    char p[512], metrics[160];
    int k, r;
    bprintf(&b, "%s", html_head);
    html_intro(&b, command);
    for (k = 0; k < n; ++k) {
        const cmp_scene_result *c = &s[k];
        bprintf(&b, "<h2 id=\"%s\">", c->label);
        bescape(&b, c->label, 0);
        bprintf(&b, "</h2>\n<p>Scene <code>");
        bescape(&b, c->source, 0);
        cmp_pic_path(p, sizeof p, c, "contact", "");
        bprintf(&b,
                "</code>, %d&times;%d pixels, ground truth with %d&times;%d samples per "
                "footprint (%.1f s); %zu of %zu pixels measured. Crop: %d&times;%d pixels at "
                "(%d,&nbsp;%d), magnified %d&times;. <a href=\"%s\">Contact sheet</a>.</p>\n",
                c->w, c->h, c->truth_samples, c->truth_samples, c->truth_seconds, c->measured,
                c->pixels, c->crop_size, c->crop_size, c->crop_x, c->crop_y, c->crop_zoom, p);
        html_table(&b, c);
        if (html_has_cost(c)) {
            bprintf(&b, "<p>RMSE against time per sample (axes and legend in the picture):</p>\n<p>");
            html_img(&b, c, "cost", "", 560, "RMSE against ns/sample");
            bprintf(&b, "</p>\n");
        }
        html_spp(&b, c);
        html_crop_strip(&b, c);
        bprintf(&b, "<div class=\"grid\">\n");
        html_figure(&b, c, "truth", "ground truth",
                    "<br>white: pixels measured; red frame: the crop", 0);
        for (r = 0; r < c->nrows; ++r) {
            const cmp_row *w = &c->rows[r];
            if (!w->ok) continue;
            snprintf(metrics, sizeof metrics, "<br>RMSE %.5f, PSNR %.2f dB", w->m.rmse,
                     isfinite(w->m.psnr) ? w->m.psnr : 999.0);
            html_figure(&b, c, w->cfg->name, w->cfg->label, metrics, 1);
        }
        bprintf(&b, "</div>\n");
    }
    bprintf(&b, "</body>\n</html>\n");
    return bwrite(&b, path);
}
