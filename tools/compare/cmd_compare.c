/*
 * texsample compare: every filter configuration against the
 * ground truth of DESIGN §8, in pictures and numbers (doc/comparison.md).
 * For each scene: one ray cast per pixel (view.c), the ground truth
 * (truth.c), each configuration through its backend (backends.c, run.c),
 * the stochastic filters' sweep when asked (stochastic.c), metrics
 * (metrics.c), the pictures (sheet.c, cost.c); then the tables and the page
 * (report.c).
 */
#define _POSIX_C_SOURCE 200809L
#include "cli.h"
#include "cmp_internal.h"
#include "commands.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

enum { MAX_SCENES = 32, MAX_PROGRAMS = 4 };

typedef struct opts {
    const char *scenes[MAX_SCENES];
    int nscenes;
    int size, truth, threads, raw, runs;
    double cache_mb; /* image textures' texture system (render --cache-mb) */
    const char *out;
    cmp_config cfg[CMP_MAX_CONFIGS];
    int ncfg;
    const char *gl_device;
    tool_program_row prog[MAX_PROGRAMS];
    int nprog;
    /* opened by open_backends: libsample, OpenImageIO (one per row, one
     * store), OpenGL, the programs */
    tool_backend lib, oiio[CMP_MAX_CONFIGS], gl, progb[MAX_PROGRAMS];
    tool_oiio_store *store;
    int spp[CMP_MAX_SPP], nspp; /* the stochastic sweep; nspp 0: none */
    int draws;
} opts;

/* The rows compare runs: any registry pick, corners included; OpenImageIO's
 * twins unless --no-oiio; OpenGL's where the build has EGL. */
static unsigned accepted(int no_oiio)
{
    return TOOL_PICK_CORNERS | (no_oiio || !tool_oiio_available() ? 0u : TOOL_PICK_OIIO) |
           (tool_backend_gl_available() ? TOOL_PICK_GL : 0u);
}

static void usage(void)
{
    int k;
    printf("usage: texsample compare [--scene NAME|FILE]... [options]\n\n"
           "Renders each scene with every filter configuration and scores each against\n"
           "the ground truth (the texture integrated against the 2x2-pixel pyramid through\n"
           "the exact screen-to-texture mapping, DESIGN section 8). Writes PNG pictures,\n"
           "results.csv, results.json and index.html, and prints where they are.\n\n"
           "Options:\n"
           "  --scene NAME|FILE   scene to compare (repeatable); built-in:\n"
           "                     ");
    {
        /* The names, wrapped at 78 columns. */
        int col = 21;
        for (k = 0; cmp_scene_names[k]; ++k) {
            int len = (int)strlen(cmp_scene_names[k]) + 2;
            if (col + len > 78) {
                printf("\n                     ");
                col = 21;
            }
            printf(" %s,", cmp_scene_names[k]);
            col += len;
        }
    }
    printf("\n                      the renderer's others, 'all' for the comparison set,\n"
           "                      or a scene file (JSON). Default: ");
    for (k = 0; cmp_default_scenes[k]; ++k) printf("%s%s", k ? " and " : "", cmp_default_scenes[k]);
    printf(".\n  --size N            image size N x N (default 256)\n"
           "  --truth-samples N   N x N samples per 2x2-pixel footprint, even (default 32)\n"
           "  --threads N         worker threads (default: all processors)\n"
           "  --runs N            filter each image N times and report the median times\n"
           "                      (default 3; 1 to 100)\n"
           "  --out DIR           output folder (default out/compare)\n"
           "  --cache-mb N        image textures open through one texture system per scene\n"
           "                      whose tile cache holds N MiB (default 1024); 0 reads\n"
           "                      each image file whole (doc/renderer.md)\n"
           "  --configs LIST      comma-separated configurations from the tools' filter\n"
           "                      registry (doc/comparison.md); default, or 'all': those\n"
           "                      marked *\n");
    tool_picks_help(stdout, "                     ", cmp_default_configs, accepted(0));
    tool_backend_help(stdout, 22);
    printf("  --no-oiio           leave out OpenImageIO's TextureSystem\n"
           "  --spp LIST          also score the stochastic filters among the rows as RMSE\n"
           "                      against samples per pixel, at these counts (increasing,\n"
           "                      1 to 1024, e.g. 1,2,4,8,16,32); default: no sweep\n"
           "  --draws K           texels per EWA / Blinn-Newell stochastic lookup (default\n"
           "                      1; 1 to 64)\n"
           "  --raw               also write float32 RGBA images (truth.f32, CONFIG.f32) and\n"
           "                      the metric mask (mask.u8) into each scene's folder\n\n"
           "Exit codes: 0 success, 1 runtime error, 2 usage error.\n");
}

/* "1,2,4" into o->spp: increasing counts 1 to 1024. Returns 0, or −1. */
static int parse_spp(const char *v, opts *o)
{
    char buf[256], *tok, *save = NULL;
    if (strlen(v) >= sizeof buf) return -1;
    memcpy(buf, v, strlen(v) + 1);
    o->nspp = 0;
    for (tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        int n;
        if (o->nspp == CMP_MAX_SPP || !cli_parse_int(tok, &n) || n < 1 || n > 1024 ||
            (o->nspp && n <= o->spp[o->nspp - 1]))
            return -1;
        o->spp[o->nspp++] = n;
    }
    return o->nspp ? 0 : -1;
}

static int parse_args(int argc, char **argv, opts *o)
{
    char err[160];
    int i, k, no_oiio = 0;
    const char *v, *configs = "all";
    memset(o, 0, sizeof *o);
    o->size = 256;
    o->truth = 32;
    o->runs = 3;
    o->draws = 1;
    o->cache_mb = RENDER_CACHE_MB;
    o->out = "out/compare";
    {
        long n = sysconf(_SC_NPROCESSORS_ONLN);
        o->threads = n < 1 ? 1 : n > 256 ? 256 : (int)n;
    }
    for (i = 1; i < argc; ++i) {
        if (cli_opt(argc, argv, &i, "--scene", &v)) {
            if (!v) return cli_usage_error("compare", "--scene needs a value");
            if (strcmp(v, "all") == 0) {
                for (k = 0; cmp_scene_names[k] && o->nscenes < MAX_SCENES; ++k)
                    o->scenes[o->nscenes++] = cmp_scene_names[k];
            } else if (o->nscenes < MAX_SCENES) {
                o->scenes[o->nscenes++] = v;
            } else {
                return cli_usage_error("compare", "at most %d scenes", MAX_SCENES);
            }
        } else if (cli_opt(argc, argv, &i, "--cache-mb", &v)) {
            float mb;
            if (!v || !cli_parse_float(v, &mb) || !(mb >= 0.0f) || mb > 1048576.0f)
                return cli_usage_error("compare", "--cache-mb needs a size in MiB in [0, 1048576]");
            o->cache_mb = mb;
        } else if (cli_opt(argc, argv, &i, "--size", &v)) {
            if (!v || !cli_parse_int(v, &o->size) || o->size < 8 || o->size > 4096)
                return cli_usage_error("compare", "--size needs an integer 8 to 4096");
        } else if (cli_opt(argc, argv, &i, "--truth-samples", &v)) {
            if (!v || !cli_parse_int(v, &o->truth) || o->truth < 2 || o->truth > 1024 || o->truth % 2)
                return cli_usage_error("compare", "--truth-samples needs an even integer 2 to 1024");
        } else if (cli_opt(argc, argv, &i, "--threads", &v)) {
            if (!v || !cli_parse_int(v, &o->threads) || o->threads < 1 || o->threads > 256)
                return cli_usage_error("compare", "--threads needs an integer 1 to 256");
        } else if (cli_opt(argc, argv, &i, "--runs", &v)) {
            if (!v || !cli_parse_int(v, &o->runs) || o->runs < 1 || o->runs > 100)
                return cli_usage_error("compare", "--runs needs an integer 1 to 100");
        } else if (cli_opt(argc, argv, &i, "--out", &v)) {
            if (!v || !*v) return cli_usage_error("compare", "--out needs a folder");
            o->out = v;
        } else if (cli_opt(argc, argv, &i, "--configs", &v)) {
            if (!v) return cli_usage_error("compare", "--configs needs a list");
            configs = v;
        } else if (cli_opt(argc, argv, &i, "--spp", &v)) {
            if (!v || parse_spp(v, o) != 0)
                return cli_usage_error("compare", "--spp needs up to %d increasing counts 1 to 1024",
                                       CMP_MAX_SPP);
        } else if (cli_opt(argc, argv, &i, "--draws", &v)) {
            if (!v || !cli_parse_int(v, &o->draws) || o->draws < 1 || o->draws > 64)
                return cli_usage_error("compare", "--draws needs an integer 1 to 64");
        } else if (cli_opt(argc, argv, &i, "--no-oiio", NULL)) {
            no_oiio = 1;
        } else if (cli_opt(argc, argv, &i, "--gl-device", &v)) {
            if (!v || !*v) return cli_usage_error("compare", "--gl-device needs a name (or 'list')");
            if (strcmp(v, "list") == 0) {
                char why[512];
                return tool_backend_gl_list(stdout, why, sizeof why) < 0
                           ? cli_runtime_error("compare", "%s", why)
                           : EXIT_OK;
            }
            o->gl_device = v;
        } else if (cli_opt(argc, argv, &i, "--backend-program", &v)) {
            if (o->nprog == MAX_PROGRAMS)
                return cli_usage_error("compare", "at most %d --backend-program", MAX_PROGRAMS);
            if (tool_program_row_parse(v, o->prog, o->nprog, err, sizeof err) != 0)
                return cli_usage_error("compare", "--backend-program: %s", err);
            ++o->nprog;
        } else if (cli_opt(argc, argv, &i, "--raw", NULL)) {
            o->raw = 1;
        } else {
            return cli_usage_error("compare", "unknown option '%s'", argv[i]);
        }
    }
    /* After the loop: --no-oiio may follow --configs. */
    o->ncfg = cmp_configs_parse(configs, accepted(no_oiio), o->cfg, CMP_MAX_CONFIGS, err, sizeof err);
    if (o->ncfg < 0) return cli_usage_error("compare", "--configs: %s", err);
    for (k = 0; k < o->ncfg; ++k)
        o->cfg[k].tb = o->cfg[k].pick.gl ? &o->gl : o->cfg[k].pick.oiio ? &o->oiio[k] : &o->lib;
    if (o->ncfg + o->nprog > CMP_MAX_CONFIGS)
        return cli_usage_error("compare", "at most %d rows in all", CMP_MAX_CONFIGS);
    /* The programs' rows after the registry's. */
    for (k = 0; k < o->nprog; ++k) {
        cmp_config *c = &o->cfg[o->ncfg++];
        const char *name = o->prog[k].name;
        _Static_assert(sizeof c->name >= sizeof o->prog[k].name &&
                           sizeof c->label >= sizeof o->prog[k].name + sizeof " (program)",
                       "a program's name fits a row's name and label");
        memset(c, 0, sizeof *c);
        memcpy(c->name, name, strlen(name) + 1);
        memcpy(c->label, name, strlen(name));
        memcpy(c->label + strlen(name), " (program)", sizeof " (program)");
        c->tb = &o->progb[k];
    }
    if (o->ncfg == 0) return cli_usage_error("compare", "--configs names no configuration");
    if (o->nscenes == 0)
        for (k = 0; cmp_default_scenes[k]; ++k) o->scenes[o->nscenes++] = cmp_default_scenes[k];
    return -1;
}

/* libsample, OpenImageIO's TextureSystem (one store for every oiio-* row),
 * the OpenGL context (once, for every gl-* row) and the programs. */
static int open_backends(opts *o)
{
    char err[512];
    int k, gl = 0;
    if (tool_backend_libsample(&o->lib, NULL) != 0) return cli_runtime_error("compare", "out of memory");
    for (k = 0; k < o->ncfg; ++k) {
        oiio_ts_opts twin;
        gl |= o->cfg[k].pick.gl;
        if (!o->cfg[k].pick.oiio) continue;
        if (!o->store && !(o->store = tool_oiio_store_open(0.0, err, sizeof err)))
            return cli_runtime_error("compare", "OpenImageIO: %s", err);
        oiio_ts_opts_init(&twin);
        tool_filter_oiio_opts(o->cfg[k].pick.f, &twin);
        if (tool_backend_oiio_open(&o->oiio[k], o->store, &twin, err, sizeof err) != 0)
            return cli_runtime_error("compare", "OpenImageIO: %s", err);
    }
    if (gl && tool_backend_gl_open(&o->gl, o->gl_device, err, sizeof err) != 0)
        return cli_runtime_error("compare", "OpenGL: %s", err);
    for (k = 0; k < o->nprog; ++k)
        if (tool_backend_program_open(&o->progb[k], o->prog[k].command, err, sizeof err) != 0)
            return cli_runtime_error("compare", "%s: %s", o->prog[k].name, err);
    return EXIT_OK;
}

static void close_backends(opts *o)
{
    int k;
    tool_backend_close(&o->lib);
    for (k = 0; k < CMP_MAX_CONFIGS; ++k) tool_backend_close(&o->oiio[k]);
    tool_oiio_store_close(o->store);
    o->store = NULL;
    tool_backend_close(&o->gl);
    for (k = 0; k < o->nprog; ++k) tool_backend_close(&o->progb[k]);
}

/* The stochastic rows' sweep (stochastic.c), after the rows: each row's
 * deterministic RMSE is its row's. */
static int sweep_scene(const opts *o, const cmp_view *v, const cmp_truth *t, cmp_scene_result *s)
{
    char err[256];
    int r;
    memcpy(s->spp, o->spp, sizeof s->spp);
    s->nspp = o->nspp;
    s->draws = (unsigned)o->draws;
    for (r = 0; r < s->nrows; ++r) {
        const cmp_row *w = &s->rows[r];
        cmp_spp_row *x;
        int st;
        if (!w->ok || !cmp_config_stochastic(w->cfg, &v->sampler)) continue;
        x = &s->spp_rows[s->nspp_rows];
        fprintf(stderr, "compare %s: %s, 1 to %d samples per pixel\n", s->label, w->cfg->label,
                o->spp[o->nspp - 1]);
        st = cmp_spp_sweep(v, w->cfg, t, o->spp, o->nspp, (unsigned)o->draws, o->threads, x, err,
                           sizeof err);
        if (st == TOOL_BACKEND_NA) {
            fprintf(stderr, "texsample compare: %s: %s: stochastic sweep n/a: %s\n", s->label,
                    w->cfg->name, err);
            snprintf(x->note, sizeof x->note, "%.*s", (int)sizeof x->note - 1, err);
        } else if (st != 0) {
            return cli_runtime_error("compare", "%s: %s: stochastic sweep: %s", s->label,
                                     w->cfg->name, err);
        }
        x->cfg = w->cfg;
        x->det_rmse = w->m.rmse;
        ++s->nspp_rows;
    }
    return cmp_spp_plot(o->out, s) ? EXIT_RUNTIME : EXIT_OK;
}

/* mkdir -p */
static int make_dirs(const char *path)
{
    char p[1024];
    size_t k, n = strlen(path);
    if (n == 0 || n >= sizeof p) return 1;
    memcpy(p, path, n + 1);
    for (k = 1; k <= n; ++k)
        if (p[k] == '/' || p[k] == '\0') {
            char c = p[k];
            p[k] = '\0';
            if (mkdir(p, 0777) != 0 && errno != EEXIST) return 1;
            p[k] = c;
        }
    return 0;
}

static int write_raw(const char *dir, const char *label, const char *name, const void *data,
                     size_t bytes)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s/%s", dir, label, name);
    if (cli_write_file(path, data, bytes)) return 0;
    fprintf(stderr, "texsample compare: cannot write %s\n", path);
    return 1;
}

/* Crop: a quarter of the image side, magnified to about 256 pixels; placed
 * where the summed squared error of all configurations is largest. */
static void choose_crop(cmp_scene_result *s, float *const *images, const cmp_truth *t)
{
    size_t n = (size_t)s->w * (size_t)s->h, px;
    double *score = calloc(n, sizeof *score);
    float *err = malloc(sizeof *err * n);
    int r, side = s->w < s->h ? s->w : s->h;
    s->crop_size = side / 4 < 8 ? (side < 8 ? side : 8) : side / 4;
    s->crop_zoom = 256 / s->crop_size < 1 ? 1 : 256 / s->crop_size;
    s->crop_x = (s->w - s->crop_size) / 2;
    s->crop_y = (s->h - s->crop_size) / 2;
    if (score && err) {
        for (r = 0; r < s->nrows; ++r) {
            if (!images[r]) continue;
            cmp_error_map(images[r], t->rgba, n, err);
            for (px = 0; px < n; ++px) score[px] += (double)err[px] * err[px];
        }
        cmp_worst_window(score, t->mask, s->w, s->h, s->crop_size, &s->crop_x, &s->crop_y);
    }
    free(score);
    free(err);
}

static int compare_scene(const opts *o, const char *name, cmp_scene_result *s)
{
    render_scene *sc = NULL;
    cmp_view v;
    cmp_truth t;
    float *images[CMP_MAX_CONFIGS] = {0};
    char err[512], dir[1024];
    int k, rc = EXIT_RUNTIME;
    double t0 = cmp_now();
    memset(&v, 0, sizeof v);
    memset(&t, 0, sizeof t);
    memset(s, 0, sizeof *s);
    snprintf(s->source, sizeof s->source, "%s", name);
    s->runs = o->runs;
    if (cmp_scene_open(name, o->size, o->cache_mb, &sc, s->label, sizeof s->label, err, sizeof err))
        return cli_runtime_error("compare", "scene '%s': %s", name, err);
    snprintf(dir, sizeof dir, "%s/%s", o->out, s->label);
    if (make_dirs(dir)) {
        cli_runtime_error("compare", "cannot create folder %s", dir);
        goto out;
    }
    fprintf(stderr, "compare %s: casting rays\n", s->label);
    if (cmp_view_build(sc, o->threads, &v, err, sizeof err)) {
        cli_runtime_error("compare", "%s: %s", s->label, err);
        goto out;
    }
    s->w = v.w;
    s->h = v.h;
    s->pixels = (size_t)v.w * (size_t)v.h;
    fprintf(stderr, "compare %s: ground truth, %d x %d samples per footprint\n", s->label,
            o->truth, o->truth);
    if (cmp_truth_build(&v, o->truth, o->threads, &t, err, sizeof err)) {
        cli_runtime_error("compare", "%s: %s", s->label, err);
        goto out;
    }
    s->truth_samples = t.samples;
    s->truth_seconds = t.seconds;
    for (k = 0; k < o->ncfg; ++k) {
        const cmp_config *c = &o->cfg[k];
        cmp_row *w = &s->rows[s->nrows++];
        cmp_result r;
        w->cfg = c;
        fprintf(stderr, "compare %s: %s\n", s->label, c->label);
        {
            int st = cmp_run_backend(&v, c, o->threads, o->runs, &r, w->note, sizeof w->note);
            if (st == TOOL_BACKEND_NA) {
                w->na = 1;
                fprintf(stderr, "texsample compare: %s: %s: n/a: %s\n", s->label, c->name, w->note);
                continue;
            }
            if (st != 0) {
                cli_runtime_error("compare", "%s: %s: %s", s->label, c->name, w->note);
                goto out;
            }
        }
        w->ok = 1;
        cmp_metrics_compute(r.rgba, t.rgba, t.mask, s->pixels, &w->m);
        w->seconds = r.seconds;
        w->ns_per_sample = r.ns_per_sample;
        w->texels = r.texels;
        images[s->nrows - 1] = r.rgba;
        s->measured = w->m.count;
    }
    if (s->measured == 0) {
        size_t px;
        for (px = 0; px < s->pixels; ++px) s->measured += t.mask[px];
    }
    if (o->nspp && sweep_scene(o, &v, &t, s) != EXIT_OK) goto out;
    choose_crop(s, images, &t);
    if (cmp_scene_pictures(o->out, s, &t, images) || cmp_cost_plot(o->out, s)) goto out;
    if (o->raw) {
        size_t bytes = s->pixels * 4 * sizeof(float);
        char file[96];
        if (write_raw(o->out, s->label, "truth.f32", t.rgba, bytes) ||
            write_raw(o->out, s->label, "mask.u8", t.mask, s->pixels))
            goto out;
        for (k = 0; k < s->nrows; ++k) {
            if (!images[k]) continue;
            snprintf(file, sizeof file, "%s.f32", s->rows[k].cfg->name);
            if (write_raw(o->out, s->label, file, images[k], bytes)) goto out;
        }
    }
    fprintf(stderr, "compare %s: done in %.1f s\n", s->label, cmp_now() - t0);
    rc = EXIT_OK;
out:
    for (k = 0; k < CMP_MAX_CONFIGS; ++k) free(images[k]);
    cmp_truth_free(&t);
    cmp_view_free(&v);
    render_scene_destroy(sc);
    return rc;
}

static void print_table(const cmp_scene_result *s)
{
    /* The label column fits the longest label (labels are ASCII, so bytes
     * are columns), capped so that a long one cannot push the numbers off
     * any terminal. */
    int r, lw = (int)strlen("filter");
    for (r = 0; r < s->nrows; ++r) {
        size_t n = strlen(s->rows[r].cfg->label);
        if (n > (size_t)lw) lw = n > 60 ? 60 : (int)n;
    }
    printf("%s (%d x %d, truth %d x %d, %zu pixels measured; ns/sample: median of %d run%s)\n",
           s->label, s->w, s->h, s->truth_samples, s->truth_samples, s->measured, s->runs,
           s->runs == 1 ? "" : "s");
    printf("  %-*s %9s %9s %10s %9s\n", lw, "filter", "RMSE", "PSNR dB", "ns/sample", "texels");
    for (r = 0; r < s->nrows; ++r) {
        const cmp_row *w = &s->rows[r];
        if (!w->ok) {
            printf("  %-*s %s: %s\n", lw, w->cfg->label, w->na ? "n/a" : "not run", w->note);
            continue;
        }
        printf("  %-*s %9.5f %9.2f %10.1f ", lw, w->cfg->label, w->m.rmse, w->m.psnr,
               w->ns_per_sample);
        /* OpenImageIO does not count the texels it reads. */
        if (w->texels < 0)
            printf("%9s\n", "-");
        else
            printf("%9.1f\n", w->texels);
    }
}

static void print_spp_table(const cmp_scene_result *s)
{
    int r, k;
    if (!s->nspp_rows) return;
    printf("%s, stochastic filters: RMSE at samples per pixel (%u texel%s per EWA / Blinn-Newell "
           "lookup)\n  %-28s", s->label, s->draws, s->draws == 1 ? "" : "s", "filter");
    for (k = 0; k < s->nspp; ++k) printf(" %8d", s->spp[k]);
    printf(" %8s %10s\n", "determ.", "ns/sample");
    for (r = 0; r < s->nspp_rows; ++r) {
        const cmp_spp_row *w = &s->spp_rows[r];
        printf("  %-28.28s", w->cfg->label);
        if (!w->ok) {
            printf(" n/a: %s\n", w->note);
            continue;
        }
        for (k = 0; k < s->nspp; ++k) printf(" %8.5f", w->rmse[k]);
        printf(" %8.5f %10.1f\n", w->det_rmse, w->ns_per_sample);
    }
}

int cmd_compare(int argc, char **argv)
{
    opts o;
    cmp_scene_result *res;
    char path[1024], command[2048];
    size_t len;
    int k, rc = EXIT_OK;
    if (argc > 1 && cli_is_help(argv[1])) {
        usage();
        return EXIT_OK;
    }
    if ((k = parse_args(argc, argv, &o)) >= 0) return k;
    if ((k = open_backends(&o)) != EXIT_OK) {
        close_backends(&o);
        return k;
    }
    if (make_dirs(o.out)) {
        close_backends(&o);
        return cli_runtime_error("compare", "cannot create folder %s", o.out);
    }
    len = (size_t)snprintf(command, sizeof command, "texsample compare");
    for (k = 1; k < argc && len < sizeof command; ++k)
        len += (size_t)snprintf(command + len, sizeof command - len, " %s", argv[k]);
    res = calloc((size_t)o.nscenes, sizeof *res);
    if (!res) {
        close_backends(&o);
        return cli_runtime_error("compare", "out of memory");
    }
    for (k = 0; k < o.nscenes && rc == EXIT_OK; ++k) rc = compare_scene(&o, o.scenes[k], &res[k]);
    if (rc == EXIT_OK) {
        snprintf(path, sizeof path, "%s/results.csv", o.out);
        if (cmp_write_csv(path, res, o.nscenes)) rc = cli_runtime_error("compare", "cannot write %s", path);
        snprintf(path, sizeof path, "%s/results.json", o.out);
        if (cmp_write_json(path, res, o.nscenes, command))
            rc = cli_runtime_error("compare", "cannot write %s", path);
        snprintf(path, sizeof path, "%s/index.html", o.out);
        if (cmp_write_html(path, res, o.nscenes, command))
            rc = cli_runtime_error("compare", "cannot write %s", path);
        snprintf(path, sizeof path, "%s/stochastic.csv", o.out);
        if (o.nspp && cmp_write_spp_csv(path, res, o.nscenes))
            rc = cli_runtime_error("compare", "cannot write %s", path);
    }
    if (rc == EXIT_OK) {
        for (k = 0; k < o.nscenes; ++k) {
            print_table(&res[k]);
            print_spp_table(&res[k]);
        }
        printf("\nHTML page:      %s/index.html\n", o.out);
        printf("Table:          %s/results.csv, %s/results.json\n", o.out, o.out);
        for (k = 0; k < o.nscenes; ++k)
            printf("Pictures:       %s/%s/ (contact sheet %s/%s/contact.png)\n", o.out,
                   res[k].label, o.out, res[k].label);
    }
    free(res);
    close_backends(&o);
    return rc;
}
