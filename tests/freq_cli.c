/*
 * `texsample freq` end to end (doc/frequency-tests.md §6): exit codes, the
 * quick sweep's files, the ideal low-pass where DESIGN §9 puts it in the
 * SVG and the CSV, the figures' titles, axis names and legend (in the SVG
 * files and inlined in the page), nearest's leakage against trilinear's, and
 * an HTML page whose links all resolve in its folder.
 *
 * usage: freq_cli TEXSAMPLE OUTDIR
 */
#define _POSIX_C_SOURCE 200809L
#include "check.h"
#include "freq.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

static const char *exe, *dir;

static int run(const char *args)
{
    char cmd[4096];
    snprintf(cmd, sizeof cmd, "'%s' freq %s >/dev/null 2>&1", exe, args);
    return check_shell(cmd);
}

static void test_usage(void)
{
    char args[2100];
    CHECK(run("--help") == 0, "--help");
    CHECK(run("--bogus") == 2, "unknown option");
    CHECK(run("--size 100") == 2, "size not a power of two");
    CHECK(run("--m 0") == 2, "m = 0");
    CHECK(run("--r 0.5") == 2, "r < 1");
    CHECK(run("--filters nearest,nope") == 2, "unknown filter");
    CHECK(run("--phases 1") == 2, "one offset");
    /* A folder that cannot be created: a runtime error, not a crash. */
    snprintf(args, sizeof args, "--quick --no-oiio --no-png --filters nearest --m 2 --theta 0 --r 1 "
                                "--out '%s/freq.csv/sub'", dir);
    CHECK(run(args) == 1, "unwritable output");
}

/* The value of attribute `name` in the tag that starts at `tag`. */
static double attr(const char *tag, const char *name)
{
    char key[64];
    const char *p;
    snprintf(key, sizeof key, " %s=\"", name);
    p = strstr(tag, key);
    return p ? atof(p + strlen(key)) : NAN;
}

/* The grid coordinate of the first tick label `cls` reading `label`. */
static double tick(const char *svg, const char *cls, const char *label, const char *axis)
{
    char key[64], text[32];
    const char *p = svg;
    snprintf(key, sizeof key, "<text class=\"%s\"", cls);
    snprintf(text, sizeof text, ">%s</text>", label);
    while ((p = strstr(p, key)) != NULL) {
        const char *end = strstr(p, "</text>");
        if (end && strncmp(strchr(p, '>'), text, strlen(text)) == 0) return attr(p, axis);
        p += strlen(key);
    }
    return NAN;
}

/* DESIGN §9: the ideal passes below ½ cycle/pixel unchanged and removes
 * everything above; in the first panel its step must sit on the tick
 * labelled 0.5 and run at the heights labelled 1 and 0, from F = 0 to 2. */
static void test_svg_ideal(void)
{
    char *svg = check_slurp_in(dir, "plot_r1_t0.svg");
    const char *p;
    double x[4], y[4];
    int k;
    CHECK(svg != NULL, "plot_r1_t0.svg missing");
    if (!svg) return;
    p = strstr(svg, "<polyline class=\"ideal\" points=\"");
    CHECK(p != NULL, "no ideal line");
    if (p) {
        p += strlen("<polyline class=\"ideal\" points=\"");
        for (k = 0; k < 4; ++k) {
            char *end;
            x[k] = strtod(p, &end);
            y[k] = strtod(end + 1, &end);
            p = end;
        }
        CHECK_NEAR(x[0], tick(svg, "xtick", "0", "x"), 0.01);
        CHECK_NEAR(x[1], tick(svg, "xtick", "0.5", "x"), 0.01);
        CHECK_NEAR(x[2], tick(svg, "xtick", "0.5", "x"), 0.01);
        CHECK_NEAR(x[3], tick(svg, "xtick", "2", "x"), 0.01);
        CHECK_NEAR(y[0], tick(svg, "ytick", "1", "y"), 0.01);
        CHECK_NEAR(y[1], tick(svg, "ytick", "1", "y"), 0.01);
        CHECK_NEAR(y[2], tick(svg, "ytick", "0", "y"), 0.01);
        CHECK_NEAR(y[3], tick(svg, "ytick", "0", "y"), 0.01);
        CHECK(x[1] > x[0] && y[2] > y[1], "step orientation");
    }
    /* One curve per filter in each of the three panels. */
    for (k = 0, p = svg; (p = strstr(p, "<polyline class=\"curve\" data-filter=\"nearest\"")); ++p) ++k;
    CHECK(k == 3, "nearest curves: %d", k);
    free(svg);
}

/* Count of `needle` in `hay`. */
static int count(const char *hay, const char *needle)
{
    int n = 0;
    for (; (hay = strstr(hay, needle)) != NULL; hay += strlen(needle)) ++n;
    return n;
}

/* A figure says what it shows: its title, each panel's m, the axis names
 * with units under and beside every panel, and a legend entry naming
 * every filter that has a curve in it (the registry's label of the curve's
 * data-filter name). */
static void check_figure_labels(const char *svg, const char *what)
{
    const char *p;
    char key[160];
    int filters = 0;
    CHECK(strstr(svg, "<text class=\"figtitle\"") && strstr(svg, "&#952; = 0&#176;, r = 1</text>"),
          "%s: figure title", what);
    CHECK(count(svg, "texels/pixel</text>") == 3, "%s: panel titles", what);
    snprintf(key, sizeof key, ">%s</text>", FQ_PLOT_XLABEL);
    CHECK(count(svg, key) == 3, "%s: x axis name on every panel", what);
    snprintf(key, sizeof key, ">%s</text>", FQ_PLOT_YLABEL);
    CHECK(count(svg, key) == 3, "%s: y axis name on every panel", what);
    CHECK(strstr(FQ_PLOT_XLABEL, "(cycles/pixel)") != NULL, "x axis unit");
    for (p = svg; (p = strstr(p, "data-filter=\"")) != NULL; ++p) {
        char name[64], label[TOOL_FILTER_LABEL_MAX];
        tool_pick pick;
        size_t len = strcspn(p + 13, "\"");
        if (len >= sizeof name) continue;
        memcpy(name, p + 13, len);
        name[len] = '\0';
        if (tool_pick_find(name, &pick, NULL) != 0) {
            CHECK(0, "%s: unknown filter %s", what, name);
            continue;
        }
        tool_pick_label(&pick, label, sizeof label);
        {
            char entry[160];
            snprintf(entry, sizeof entry, ">%s</text>", label);
            CHECK(count(svg, entry) == 1, "%s: legend entry for %s (%s)", what, name, label);
        }
        ++filters;
    }
    /* Three panels per curve name: each filter counted three times. */
    CHECK(filters >= 3 * 8, "%s: curves %d", what, filters);
    CHECK(strstr(svg, ">ideal low-pass (Nyquist 0.5)</text>") != NULL, "%s: ideal in legend", what);
}

static void test_labels(void)
{
    char *svg = check_slurp_in(dir, "plot_r1_t0.svg"), *html = check_slurp_in(dir, "index.html");
    CHECK(svg && html, "plot_r1_t0.svg, index.html");
    if (svg) check_figure_labels(svg, "plot_r1_t0.svg");
    if (html) {
        /* The page shows the labelled figures themselves, one per (θ, r). */
        static const char figure[] = "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"figure\"";
        const char *fig = strstr(html, figure), *fr = strstr(html, "class=\"frontier\"");
        CHECK(count(html, figure) == 4, "inline figures: %d", count(html, figure));
        /* And the pass-against-aliasing plot: named axes, a marker and a
         * legend entry per filter. */
        CHECK(count(html, "<svg ") == 5 && fr, "the frontier plot");
        CHECK(fr && strstr(fr, ">aliasing: mean |H| above") && strstr(fr, ">pass band: mean |H| below"),
              "frontier: axis names");
        CHECK(fr && count(fr, "<circle class=\"point\"") >= 3, "frontier: a marker per filter");
        CHECK(strstr(html, "<?xml") == NULL, "no XML declaration inside the page");
        CHECK(strstr(html, "plot_r1_t0.png") == NULL, "no unlabelled PNG plot");
        if (fig && strstr(fig, "</svg>")) {
            char *one = strndup(fig, (size_t)(strstr(fig, "</svg>") - fig));
            if (one) check_figure_labels(one, "page");
            free(one);
        }
        /* Lists of values read as lists: no "16; )" left over. */
        CHECK(strstr(html, "; )") == NULL && strstr(html, ", )") == NULL, "stray list separator");
        CHECK(strstr(html, "m = 1.5, 5.7, 16)") != NULL, "panel order sentence");
    }
    free(svg);
    free(html);
}

/* CSV: the ideal column follows the design, and at m = 16 nearest without
 * mips leaks nearly everything above Nyquist while trilinear leaks little. */
static void test_csv(void)
{
    char *csv = check_slurp_in(dir, "freq.csv"), *line, *save = NULL;
    double sum_n = 0, sum_t = 0;
    int n_n = 0, n_t = 0, rows = 0;
    CHECK(csv != NULL, "freq.csv missing");
    if (!csv) return;
    line = strtok_r(csv, "\n", &save);
    CHECK(line && strncmp(line, "filter,m,theta_deg,", 19) == 0, "header");
    while ((line = strtok_r(NULL, "\n", &save)) != NULL) {
        char filter[64], band[8];
        double m, th, thr, r, f, F, aF, re, im, amp, se, res, ideal;
        int n, p, q;
        if (sscanf(line, "%63[^,],%lf,%lf,%lf,%lf,%d,%d,%d,%lf,%lf,%7[^,],%lf,%lf,%lf,%lf,%lf,%lf,%lf",
                   filter, &m, &th, &thr, &r, &n, &p, &q, &f, &F, band, &aF, &re, &im, &amp, &se,
                   &res, &ideal) != 18) {
            CHECK(0, "bad row %s", line);
            break;
        }
        rows++;
        /* At Nyquist itself the step's midpoint, as a Fourier series has it. */
        CHECK(ideal == (F < 0.5 ? 1.0 : F > 0.5 ? 0.0 : 0.5), "ideal %g at F = %g", ideal, F);
        CHECK(strcmp(band, F < 0.5 ? "pass" : "stop") == 0, "band %s at F = %g", band, F);
        CHECK(f < 0.5, "grating above the base level's Nyquist: f = %g", f);
        CHECK_NEAR(F, f * m, 1e-6);
        if (m == 16 && r == 1 && F > 0.6) {
            if (strcmp(filter, "nearest") == 0) {
                sum_n += amp;
                n_n++;
            } else if (strcmp(filter, "trilinear") == 0) {
                sum_t += amp;
                n_t++;
            }
        }
    }
    CHECK(rows > 500, "rows %d", rows);
    CHECK(n_n > 0 && n_t > 0, "m = 16 points: %d, %d", n_n, n_t);
    if (n_n && n_t) {
        CHECK(sum_n / n_n > 0.95, "nearest leakage %.3f", sum_n / n_n);
        CHECK(sum_t / n_t < 0.1, "trilinear leakage %.3f", sum_t / n_t);
    }
    free(csv);
}

/* Every src/href of the page names a file in the folder (self-contained). */
static void test_html(void)
{
    char *html = check_slurp_in(dir, "index.html");
    const char *p;
    int links = 0;
    CHECK(html != NULL, "index.html missing");
    if (!html) return;
    for (p = html; (p = strpbrk(p, "sh")) != NULL; ++p) {
        const char *v;
        char name[256];
        size_t len;
        FILE *f;
        char path[2300];
        if (strncmp(p, "src=\"", 5) == 0)
            v = p + 5;
        else if (strncmp(p, "href=\"", 6) == 0)
            v = p + 6;
        else
            continue;
        len = strcspn(v, "\"");
        CHECK(len > 0 && len < sizeof name, "link length");
        if (!len || len >= sizeof name) continue;
        memcpy(name, v, len);
        name[len] = '\0';
        CHECK(strchr(name, '/') == NULL && strchr(name, ':') == NULL, "not relative: %s", name);
        snprintf(path, sizeof path, "%s/%s", dir, name);
        f = fopen(path, "rb");
        CHECK(f != NULL, "link to a missing file: %s", name);
        if (f) fclose(f);
        links++;
    }
    CHECK(links >= 6, "links %d", links);
    CHECK(strstr(html, "<table>") != NULL, "summary table");
    free(html);
}

int main(int argc, char **argv)
{
    char args[2100];
    if (argc != 3) {
        fprintf(stderr, "usage: freq_cli TEXSAMPLE OUTDIR\n");
        return 2;
    }
    exe = argv[1];
    dir = argv[2];
    snprintf(args, sizeof args, "--quick --out '%s'", dir);
    if (run(args) != 0) {
        fprintf(stderr, "texsample freq %s failed\n", args);
        return 1;
    }
    RUN(test_usage);
    RUN(test_svg_ideal);
    RUN(test_labels);
    RUN(test_csv);
    RUN(test_html);
    return check_finish();
}
