/* texsample freq: frequency tests of every filter (DESIGN §9,
 * doc/frequency-tests.md). Options, the filter list and the run; the
 * measurement is in the texsample_freq library. */
#define _POSIX_C_SOURCE 200809L
#include "backend.h"
#include "cli.h"
#include "commands.h"
#include "freq_cli.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define MAX_LIST 16
#define MAX_BACKENDS 32
#define MAX_PROGRAMS 4

static const char help[] =
    "usage: texsample freq [options]\n"
    "\n"
    "Measure each filter as a linear system: sinusoidal gratings of f cycles/texel,\n"
    "sampled with m texels per pixel along the wave and m*r across it, at many\n"
    "offsets; the least-squares amplitude at the screen frequency F = f*m (below\n"
    "0.5 cycles/pixel: pass-band response) or at its alias (above: leakage).\n"
    "Writes freq.csv (every curve), summary.csv, summary.md, plot_r*_t*.svg\n"
    "(labelled figures, also shown in the page), zone_*.png and index.html into\n"
    "the output folder.\n"
    "\n"
    "Options:\n"
    "  --out DIR          output folder (default freq-out; created if missing)\n"
    "  --quick            reduced sweep for the test suite: m 1.5,5.7,16; theta 0,45;\n"
    "                     r 1,4; 256-texel textures; F step 1/16; 8 pixels x 32\n"
    "                     offsets (the full sweep is the default)\n"
    "  --m LIST           minifications, texels/pixel (default 1,1.5,2,3,5.7,16)\n"
    "  --theta LIST       orientations in degrees (default 0,22.5,45)\n"
    "  --r LIST           anisotropy ratios >= 1 (default 1,2,4,8,16)\n"
    "  --filters LIST     comma-separated filters, from the list below (default:\n"
    "                     those marked *, as far as available; 'all' is the same)\n"
    "  --no-oiio          leave out OpenImageIO's TextureSystem\n"

    "  --size N           texture side, a power of two 16..8192 (default 512)\n"
    "  --step F           screen-frequency grid step, cycles/pixel (default 1/64)\n"
    "  --fmax F           top of the grid, cycles/pixel (default 2)\n"
    "  --width N, --rows N, --phases N\n"
    "                     pixels per row, rows, offsets (default 16, 1, 64)\n"
    "  --no-png           no PNG pictures (no zone plates)\n";
static const char help_filters[] = "\nFilters (the tools' shared registry, doc/comparison.md):\n";
static const char help_tail[] = "\nExit codes: 0 success, 1 runtime error, 2 usage error.\n";

/* The picks freq can run in this build: libsample's entries without the
 * exact corners (the sweep has only Jacobians), OIIO twins with the shim,
 * OpenGL twins with EGL. */
static unsigned accepted(int no_oiio)
{
    return (tool_oiio_available() && !no_oiio ? TOOL_PICK_OIIO : 0u) |
           (tool_backend_gl_available() ? TOOL_PICK_GL : 0u);
}

static int parse_list(const char *s, double *out, int *n, double lo, double hi)
{
    char buf[512], *tok, *save = NULL;
    if (!s || strlen(s) >= sizeof buf) return 0;
    strcpy(buf, s);
    *n = 0;
    for (tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        float v;
        if (*n >= MAX_LIST || !cli_parse_float(tok, &v) || v < lo || v > hi) return 0;
        out[(*n)++] = v;
    }
    return *n > 0;
}

static void progress(size_t done, size_t total) { cli_progress("freq", done, total); }

/* Zone-plate pictures, one per backend (NULL where a backend failed: the
 * page leaves it out and the run goes on). */
static void render_zones(const fq_plan *plan, float **zone)
{
    sample_texture *tex;
    float *texels;
    sample_error serr;
    int b;
    if (fq_zone_texture(&tex, &texels, &serr) != SAMPLE_OK) {
        fprintf(stderr, "texsample freq: zone plate skipped: %s\n", serr.message);
        return;
    }
    for (b = 0; b < plan->nbackends; ++b) {
        char err[256] = "";
        void *ctx = plan->backends[b]->prepare(plan->backends[b], tex, texels, FQ_ZONE_N, 1,
                                               err, sizeof err);
        if (ctx) {
            zone[b] = fq_zone_render(plan->backends[b], ctx, err, sizeof err);
            plan->backends[b]->release(ctx);
        }
        if (!zone[b])
            fprintf(stderr, "texsample freq: zone plate of %s skipped: %s\n",
                    plan->backends[b]->name, err);
    }
    sample_texture_destroy(tex);
    free(texels);
}

int cmd_freq(int argc, char **argv)
{
    static const double def_m[] = {1, 1.5, 2, 3, 5.7, 16}, def_t[] = {0, 22.5, 45},
                        def_r[] = {1, 2, 4, 8, 16};
    static const double quick_m[] = {1.5, 5.7, 16}, quick_t[] = {0, 45}, quick_r[] = {1, 4};
    double m[MAX_LIST], th[MAX_LIST], r[MAX_LIST];
    int nm = 0, nt = 0, nr = 0, quick = 0, no_oiio = 0, png = 1, i, k, rc = EXIT_OK;
    int size = 0, width = 0, rows = 0, phases = 0, npicks, any_oiio = 0;
    float step = 0.0f, fmax = 2.0f;
    const char *out_dir = "freq-out", *filters = NULL, *gl_device = NULL;
    tool_program_row prog[MAX_PROGRAMS];
    tool_backend gl, progb[MAX_PROGRAMS], oiio[MAX_BACKENDS];
    tool_oiio_store *store = NULL;
    fq_tool_cfg tool_cfg[MAX_BACKENDS];
    fq_na_row na[MAX_BACKENDS];
    int nprog = 0, nna = 0;
    const fq_backend *list[MAX_BACKENDS];
    fq_backend backends[MAX_BACKENDS];
    tool_pick picks[MAX_BACKENDS];
    char err[512] = "", command[2048];
    fq_plan plan;
    fq_sweep sweep = {0};
    float *zone[MAX_BACKENDS] = {0};

    for (i = 1; i < argc; ++i) {
        const char *v = NULL;
        if (cli_is_help(argv[i])) {
            fputs(help, stdout);
            tool_backend_help(stdout, 21);
            fputs(help_filters, stdout);
            tool_picks_help(stdout, "  ", fq_default_filters, accepted(0));
            fputs(help_tail, stdout);
            return EXIT_OK;
        } else if (cli_opt(argc, argv, &i, "--quick", NULL)) {
            quick = 1;
        } else if (cli_opt(argc, argv, &i, "--no-oiio", NULL)) {
            no_oiio = 1;
        } else if (cli_opt(argc, argv, &i, "--no-png", NULL)) {
            png = 0;
        } else if (cli_opt(argc, argv, &i, "--out", &v)) {
            if (!v || !*v) return cli_usage_error("freq", "--out needs a folder");
            out_dir = v;
        } else if (cli_opt(argc, argv, &i, "--filters", &v)) {
            if (!v || !*v) return cli_usage_error("freq", "--filters needs a list");
            filters = v;
        } else if (cli_opt(argc, argv, &i, "--gl-device", &v)) {
            if (!v || !*v) return cli_usage_error("freq", "--gl-device needs a name (or 'list')");
            if (strcmp(v, "list") == 0) return tool_backend_gl_list(stdout, err, sizeof err) < 0
                                                   ? cli_runtime_error("freq", "%s", err)
                                                   : EXIT_OK;
            gl_device = v;
        } else if (cli_opt(argc, argv, &i, "--backend-program", &v)) {
            if (nprog == MAX_PROGRAMS)
                return cli_usage_error("freq", "at most %d --backend-program", MAX_PROGRAMS);
            if (tool_program_row_parse(v, prog, nprog, err, sizeof err) != 0)
                return cli_usage_error("freq", "--backend-program: %s", err);
            ++nprog;
        } else if (cli_opt(argc, argv, &i, "--m", &v)) {
            if (!parse_list(v, m, &nm, 1.0 / 64, 1024))
                return cli_usage_error("freq", "--m: up to %d numbers in [1/64, 1024]", MAX_LIST);
        } else if (cli_opt(argc, argv, &i, "--theta", &v)) {
            if (!parse_list(v, th, &nt, -360, 360))
                return cli_usage_error("freq", "--theta: up to %d angles in degrees", MAX_LIST);
        } else if (cli_opt(argc, argv, &i, "--r", &v)) {
            if (!parse_list(v, r, &nr, 1, 1024))
                return cli_usage_error("freq", "--r: up to %d numbers in [1, 1024]", MAX_LIST);
        } else if (cli_opt(argc, argv, &i, "--size", &v)) {
            if (!cli_parse_int(v, &size) || size < 16 || size > 8192 || (size & (size - 1)))
                return cli_usage_error("freq", "--size: a power of two from 16 to 8192");
        } else if (cli_opt(argc, argv, &i, "--step", &v)) {
            if (!cli_parse_float(v, &step) || !(step > 0.0f) || step > 1.0f)
                return cli_usage_error("freq", "--step: a number in (0, 1]");
        } else if (cli_opt(argc, argv, &i, "--fmax", &v)) {
            if (!cli_parse_float(v, &fmax) || !(fmax > 0.0f) || fmax > 8.0f)
                return cli_usage_error("freq", "--fmax: a number in (0, 8]");
        } else if (cli_opt(argc, argv, &i, "--width", &v)) {
            if (!cli_parse_int(v, &width) || width < 1 || width > 4096)
                return cli_usage_error("freq", "--width: 1 to 4096");
        } else if (cli_opt(argc, argv, &i, "--rows", &v)) {
            if (!cli_parse_int(v, &rows) || rows < 1 || rows > 256)
                return cli_usage_error("freq", "--rows: 1 to 256");
        } else if (cli_opt(argc, argv, &i, "--phases", &v)) {
            if (!cli_parse_int(v, &phases) || phases < 2 || phases > 4096)
                return cli_usage_error("freq", "--phases: 2 to 4096");
        } else {
            return cli_usage_error("freq", "unknown option '%s'", argv[i]);
        }
    }

    /* The quick mode only changes defaults; explicit options still win. */
#define DEFAULT_LIST(dst, n, q, d)                                                             \
    if (!n) {                                                                                  \
        const double *src = quick ? q : d;                                                     \
        n = quick ? (int)(sizeof q / sizeof q[0]) : (int)(sizeof d / sizeof d[0]);             \
        memcpy(dst, src, (size_t)n * sizeof *src);                                             \
    }
    DEFAULT_LIST(m, nm, quick_m, def_m)
    DEFAULT_LIST(th, nt, quick_t, def_t)
    DEFAULT_LIST(r, nr, quick_r, def_r)
#undef DEFAULT_LIST
    if (!size) size = quick ? 256 : 512;
    if (step == 0.0f) step = quick ? 1.0f / 16 : 1.0f / 64;
    if (!width) width = quick ? 8 : 16;
    if (!rows) rows = 1;
    if (!phases) phases = quick ? 32 : 64;

    npicks = tool_picks_parse("freq", filters ? filters : "all", fq_default_filters,
                              accepted(no_oiio), picks, MAX_BACKENDS, err, sizeof err);
    if (npicks < 0) return cli_usage_error("freq", "--filters: %s", err);
    if (npicks == 0 && nprog == 0) return cli_usage_error("freq", "--filters names no filter");
    if (npicks + nprog > MAX_BACKENDS)
        return cli_usage_error("freq", "at most %d rows in all", MAX_BACKENDS);
    for (k = 0; k < npicks; ++k) any_oiio |= picks[k].oiio;

    /* OpenImageIO writes a texture file per grating into the store's
     * private folder; one TextureSystem (64 MB of cache) for every row:
     * creating one per grating grows the process by about a megabyte each
     * time (OpenImageIO keeps per-system state). */
    if (any_oiio && !(store = tool_oiio_store_open(64.0, err, sizeof err)))
        return cli_runtime_error("freq", "OpenImageIO: %s", err);
    memset(&plan, 0, sizeof plan);
    memset(&gl, 0, sizeof gl);
    memset(progb, 0, sizeof progb);
    memset(oiio, 0, sizeof oiio);
    memset(tool_cfg, 0, sizeof tool_cfg);
    for (k = 0; k < npicks + nprog; ++k) {
        const tool_pick *p = k < npicks ? &picks[k] : NULL;
        if (p && p->oiio) {
            char name[TOOL_FILTER_NAME_MAX], label[TOOL_FILTER_LABEL_MAX];
            oiio_ts_opts opts;
            oiio_ts_opts_init(&opts);
            tool_filter_oiio_opts(p->f, &opts);
            if (tool_backend_oiio_open(&oiio[k], store, &opts, err, sizeof err) != 0) {
                rc = cli_runtime_error("freq", "OpenImageIO: %s", err);
                goto done;
            }
            tool_pick_name(p, name, sizeof name);
            tool_pick_label(p, label, sizeof label);
            fq_tool_backend(&oiio[k], p->f, name, label, NULL, &tool_cfg[k], &backends[k]);
        } else if (p && !p->gl) {
            if (fq_libsample_backend(p->f, &tool_cfg[k], &backends[k]) != 0) {
                rc = cli_runtime_error("freq", "out of memory");
                goto done;
            }
        } else {
            /* OpenGL and outside programs: opened here, and tried once so
             * that a configuration they cannot do is a row "n/a: why". */
            char name[TOOL_FILTER_NAME_MAX], label[TOOL_FILTER_LABEL_MAX];
            tool_backend *tb = p ? &gl : &progb[k - npicks];
            int st;
            if (!tb->ops &&
                (p ? tool_backend_gl_open(tb, gl_device, err, sizeof err)
                   : tool_backend_program_open(tb, prog[k - npicks].command, err, sizeof err)) != 0) {
                rc = cli_runtime_error("freq", "%s: %s", p ? "OpenGL" : prog[k - npicks].name, err);
                goto done;
            }
            if (p) {
                tool_pick_name(p, name, sizeof name);
                tool_pick_label(p, label, sizeof label);
            } else {
                snprintf(name, sizeof name, "%s", prog[k - npicks].name);
                snprintf(label, sizeof label, "%s (program)", prog[k - npicks].name);
            }
            fq_tool_backend(tb, p ? p->f : NULL, name, label, tb->driver, &tool_cfg[k], &backends[k]);
            if ((st = fq_tool_probe(&backends[k], err, sizeof err)) == TOOL_BACKEND_NA) {
                na[nna].label = tool_cfg[k].label;
                na[nna].driver = tb->driver;
                snprintf(na[nna++].reason, sizeof na[0].reason, "%.*s",
                         (int)sizeof na[0].reason - 1, err);
                fprintf(stderr, "texsample freq: %s: n/a: %s\n", name, err);
                continue;
            }
            if (st != 0) {
                rc = cli_runtime_error("freq", "%s: %s", name, err);
                goto done;
            }
        }
        list[plan.nbackends++] = &backends[k];
    }
    plan.na = na;
    plan.nna = nna;
    if (plan.nbackends == 0) {
        rc = cli_runtime_error("freq", "no row can run here (each is n/a)");
        goto done;
    }
    plan.m = m;
    plan.nm = nm;
    plan.theta_deg = th;
    plan.ntheta = nt;
    plan.r = r;
    plan.nr = nr;
    plan.n = size;
    plan.f_step = step;
    plan.f_max = fmax;
    plan.width = width;
    plan.rows = rows;
    plan.phases = phases;
    plan.backends = list;
    plan.progress = progress;

    if (fq_sweep_run(&plan, &sweep, err, sizeof err) != 0) {
        rc = cli_runtime_error("freq", "%s", err);
        goto done;
    }
    if (png) render_zones(&plan, zone);
    {
        size_t len = 0;
        command[0] = '\0';
        for (i = 0; i < argc; ++i) {
            int w = snprintf(command + len, sizeof command - len, "%s%s", i ? " " : "texsample ",
                             argv[i]);
            if (w < 0 || (size_t)w >= sizeof command - len) break;
            len += (size_t)w;
        }
    }
    if (fq_write_outputs(out_dir, &plan, &sweep, zone, png, command, err, sizeof err) != 0) {
        rc = cli_runtime_error("freq", "%s", err);
        goto done;
    }
    {
        fq_buf b = {0};
        fq_report_summary_md(&plan, &sweep, &b);
        if (!b.failed && b.data) fputs(b.data, stdout);
        fq_buf_free(&b);
    }
    printf("wrote %s/index.html (%zu points)\n", out_dir, sweep.count);
done:
    for (k = 0; k < MAX_BACKENDS; ++k) free(zone[k]);
    tool_backend_close(&gl);
    for (k = 0; k < MAX_PROGRAMS; ++k) tool_backend_close(&progb[k]);
    fq_sweep_free(&sweep);
    for (k = 0; k < MAX_BACKENDS; ++k) {
        tool_backend_close(&oiio[k]);
        tool_backend_close(&tool_cfg[k].own);
    }
    tool_oiio_store_close(store);
    return rc;
}
