/*
 * freq.h — the frequency-test harness behind `texsample freq` (DESIGN §9,
 * doc/frequency-tests.md). Library code of the tools, not of libsample: the
 * texsample_freq static library (tools/freq.cmake) holds everything except
 * the command line (cmd_freq.c) and file output (out.c), so that tests can
 * call the measurement directly. Every row samples through a backend of
 * tools/backend.h (libsample, OpenImageIO, OpenGL, an outside program).
 *
 *   grating.c   wave vectors, grating and zone-plate textures
 *   measure.c   screen layout, offsets, least-squares amplitude fit
 *   filters.c   freq's default rows of the filter registry (tools/filters.h)
 *   backends.c  a row on a backend of tools/backend.h
 *   sweep.c     the (m, θ, r) × filter × frequency loops
 *   summary.c   per-curve and per-filter numbers
 *   report.c    CSV, Markdown and HTML text
 *   plot.c      plot geometry
 *   svg.c       SVG plots (files of their own and inlined in the page)
 *   frontier.c  pass band against aliasing, one marker per filter (in the page)
 *   strbuf.c    a growable text buffer
 *
 * GEOMETRY (doc/frequency-tests.md §2). Texel space of the base level,
 * u = s·N, v = t·N, texel centres at integers + ½. The grating is
 * g(u, v) = e^{2πi(p·u + q·v)/N} on an N × N REPEAT texture: p and q are
 * integers, so it has exactly (p, q) cycles across the texture and tiles
 * without a seam; its frequency is f = √(p² + q²)/N cycles/texel at the
 * angle θ = atan2(q, p). The screen maps pixel (x, y) to
 * (u, v) = o + x·m·e1 + y·m·r·e2 with e1 = (cos θ, sin θ) (along the wave
 * vector) and e2 = (−sin θ, cos θ) (along the crests), so the screen signal
 * is cos(2π F x + φ) with F = f·m cycles/pixel, constant along y, and the
 * Jacobian has columns m·e1/N and m·r·e2/N: λ = log2(m·r).
 */
#ifndef TEXSAMPLE_FREQ_H
#define TEXSAMPLE_FREQ_H

#include "backend.h"
#include "filters.h"
#include "sample/sample.h"

#include <stddef.h>
#include <stdint.h>

#define FQ_PI 3.14159265358979323846

/* ---- Text buffer (strbuf.c) ---------------------------------------------- */

typedef struct fq_buf {
    char *data;
    size_t len, cap;
    int failed; /* an allocation failed; the text is incomplete */
} fq_buf;

void fq_buf_printf(fq_buf *b, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
void fq_buf_free(fq_buf *b);

/* ---- Gratings (grating.c) ------------------------------------------------ */

typedef struct fq_wave {
    int n;       /* texture side N (a power of two) */
    int p, q;    /* cycles across the texture along u and v */
    double f;    /* √(p² + q²) / N, cycles per texel */
    double theta; /* atan2(q, p), radians */
} fq_wave;

/* The integer wave vector nearest to frequency f (cycles/texel) at angle
 * theta on an N-texel texture. f = 0 gives (0, 0). */
fq_wave fq_wave_nearest(int n, double f, double theta);

/* The float texture of the complex grating e^{2πi(p·u + q·v)/N}: channel 0
 * the cosine, channel 1 the sine (measure.c says why), with a box-filtered
 * REPEAT pyramid built by the library. p = q = 0 is the constant (1, 0). */
sample_status fq_grating_texture(const fq_wave *w, sample_texture **out, sample_error *err);

/* A texture from N × N float texels of 1 or 2 channels: box pyramid,
 * REPEAT (what every libsample configuration in the sweep reads). */
sample_status fq_texture_create(const float *texels, int n, int channels, sample_texture **out,
                                sample_error *err);

/* The grating's texel values (N × N × 2 floats, row v = 0 first); for the
 * texture above and for backends that build their own files. */
float *fq_grating_texels(const fq_wave *w);

/* A zone plate cos(π·((i − N/2)² + (j − N/2)²)/N): local frequency from 0 at
 * the centre to ½ cycle/texel at the edges, periodic for even N. */
float *fq_zone_plate_texels(int n);

/* ---- Backends ------------------------------------------------------------ */

/* Sample `count` queries on the texture the backend was prepared for; write
 * count × 4 floats into rgba and add the texels read to *texels (backends
 * that cannot count leave it). Returns 0, or −1 with a message in err. */
typedef int (*fq_sample_fn)(void *ctx, const sample_query *q, size_t count, float *rgba,
                            double *texels, char *err, size_t errlen);

/* A filter under test: how to prepare it for a grating, how to sample. */
typedef struct fq_backend {
    const char *name;  /* as in the CSV, e.g. "trilinear" */
    const char *label; /* for plots and tables */
    /* Prepare for one texture (levels built by the library in `tex`; its
     * N × N texels of `channels` floats in `texels`, for backends that need
     * a file). Returns a context for sample() or NULL with a message. */
    void *(*prepare)(const struct fq_backend *b, const sample_texture *tex, const float *texels,
                     int n, int channels, char *err, size_t errlen);
    fq_sample_fn sample;
    void (*release)(void *ctx);
    const void *config; /* backend data: the sampler state for libsample */
    int counts_texels;  /* 0: texels per sample is not known (OpenImageIO) */
    /* What produced the row (tools/backend.h: GL_RENDERER and GL_VERSION,
     * a program's command); NULL: libsample or OpenImageIO, named by the
     * label. */
    const char *driver;
} fq_backend;

/* A row asked for that its backend cannot run (tools/backend.h,
 * TOOL_BACKEND_NA): the tables show it as "n/a: reason". */
typedef struct fq_na_row {
    const char *label;
    const char *driver; /* may be NULL */
    char reason[200];
} fq_na_row;

/* freq's default rows, NULL-terminated registry names (tools/filters.h):
 * the OpenGL ladder, cubic, the footprint filters and OpenImageIO's
 * trilinear and anisotropic twins. */
extern const char *const fq_default_filters[];

/* A row on a backend of tools/backend.h (backends.c): a registry entry on
 * libsample, its OpenImageIO or OpenGL twin, or an outside program (f
 * NULL: the program's own filter). Caller-owned, must outlive the
 * fq_backend; `own` holds the backend where the row opened its own
 * (fq_libsample_backend). */
typedef struct fq_tool_cfg {
    tool_backend *tb;
    tool_backend own;
    const tool_filter *f;
    char name[TOOL_FILTER_NAME_MAX], label[TOOL_FILTER_LABEL_MAX];
} fq_tool_cfg;
/* The row as a backend of the sweep: REPEAT on both axes, f's settings.
 * driver: what the pages name as the row's sampler, or NULL (libsample
 * and OpenImageIO rows: their label says it). */
void fq_tool_backend(tool_backend *tb, const tool_filter *f, const char *name, const char *label,
                     const char *driver, fq_tool_cfg *cfg, fq_backend *out);
/* Registry entry f on libsample (its own backend in cfg->own). Returns 0,
 * or −1 (out of memory). */
int fq_libsample_backend(const tool_filter *f, fq_tool_cfg *cfg, fq_backend *out);
/* Try the row on a small texture and one query: 0 (it runs),
 * TOOL_BACKEND_NA or TOOL_BACKEND_ERROR with the reason in err. */
int fq_tool_probe(const fq_backend *b, char *err, size_t errlen);

/* ---- Measurement (measure.c) --------------------------------------------- */

typedef struct fq_layout {
    double m, r;       /* texels per pixel along the wave / across it */
    int width, rows;   /* pixels per row, rows */
    int phases;        /* offsets o_j */
    /* < 0: offsets uniform over the whole texture (jittered strata), the
     * normal mode. ≥ 0: every offset is an integer number of texels plus
     * this fixed sub-texel phase on both axes (closed-form tests). */
    double subtexel;
    int lattice; /* with subtexel ≥ 0: integer offsets are multiples of this */
    uint64_t seed;
} fq_layout;

/* Defaults: width 16, rows 1, phases 64, subtexel −1, lattice 1, seed 1. */
void fq_layout_init(fq_layout *l, double m, double r);

typedef struct fq_result {
    double F;        /* screen frequency f·m, cycles/pixel */
    double alias_F;  /* |F − round(F)|: where the output shows it */
    double re, im;   /* coherent complex response H */
    double amp;      /* |H|: response below Nyquist, leakage above */
    double stderr_;  /* standard error of amp, clustered by offset */
    double residual; /* RMS of |z − H·e^{iφ}|: what the fit leaves */
    double texels;   /* texels read per sample (NaN if not counted) */
    double ns;       /* wall time per sample, nanoseconds */
} fq_result;

/* Sample the texture of wave w through `b` (context ctx) on the layout and
 * fit z = H·e^{iφ} by least squares, z = channel 0 + i·channel 1 and φ the
 * grating's phase at each sample's exact position. Returns 0, or −1 with a
 * message. */
int fq_measure(const fq_backend *b, void *ctx, const fq_wave *w, const fq_layout *l,
               fq_result *out, char *err, size_t errlen);

/* The queries of one layout (width × rows × phases, phase-major), and the
 * grating phase 2π(p·u + q·v)/N at each query's exact (float) position.
 * Caller frees both. */
int fq_layout_queries(const fq_wave *w, const fq_layout *l, sample_query **queries,
                      double **phase, size_t *count);

/* ---- Sweep (sweep.c) ----------------------------------------------------- */

typedef struct fq_plan {
    const double *m; int nm;
    const double *theta_deg; int ntheta;
    const double *r; int nr;
    int n;            /* texture side */
    double f_step;    /* screen-frequency step of the grid, cycles/pixel */
    double f_max;     /* top of the grid (2) */
    int width, rows, phases;
    const fq_backend *const *backends; int nbackends;
    const fq_na_row *na; int nna; /* rows not run, for the tables */
    /* Called after each grating texture is done (may be NULL). */
    void (*progress)(size_t done, size_t total);
} fq_plan;

/* One measured point of one curve. */
typedef struct fq_point {
    int backend, im, itheta, ir; /* indices into the plan */
    fq_wave wave;
    fq_result res;
} fq_point;

typedef struct fq_sweep {
    fq_point *pts;
    size_t count, cap;
} fq_sweep;

/* The full sweep; points come out ordered by (backend, m, θ, r, F).
 * Returns 0, or −1 with a message (the points so far are kept). */
int fq_sweep_run(const fq_plan *plan, fq_sweep *out, char *err, size_t errlen);
void fq_sweep_free(fq_sweep *s);
/* The points of one curve, in increasing F: returns their count and sets
 * *first. */
size_t fq_curve(const fq_sweep *s, int backend, int im, int itheta, int ir, const fq_point **first);

/* ---- Summary (summary.c) ------------------------------------------------- */

#define FQ_PASS_BELOW 0.4 /* pass-band fidelity: mean response for 0 < F < 0.4 */
#define FQ_STOP_ABOVE 0.6 /* aliasing: mean leakage for 0.6 < F ≤ f_max */

typedef struct fq_stat {
    double pass, pass_worst;   /* mean over θ; worst (lowest) over θ */
    double alias, alias_worst; /* mean over θ; worst (highest) over θ */
    double texels, ns;         /* per sample, mean over the points */
    int npass, nstop;          /* points behind the numbers (0: n/a) */
} fq_stat;

/* Numbers of one backend at one (m, r), θ folded as above; im or ir < 0
 * folds that axis too (the worst is then over everything folded). */
fq_stat fq_summarize(const fq_plan *plan, const fq_sweep *s, int backend, int im, int ir);

/* ---- Text outputs (report.c) --------------------------------------------- */

void fq_report_csv(const fq_plan *plan, const fq_sweep *s, fq_buf *out);
/* summary.csv and the Markdown table (per filter, then per filter and r). */
void fq_report_summary_csv(const fq_plan *plan, const fq_sweep *s, fq_buf *out);
void fq_report_summary_md(const fq_plan *plan, const fq_sweep *s, fq_buf *out);
/* The HTML page, with every figure inlined (fq_svg_figure). `svgs` holds
 * the relative file name of each figure's SVG, per (r, θ), r-major, which
 * the page links; `zone` the zone-plate pictures (one per backend, NULL
 * entries skipped) or NULL; `command` the command line that produced it. */
void fq_report_html(const fq_plan *plan, const fq_sweep *s, const char *const *svgs,
                    const char *const *zone, const char *command, fq_buf *out);

/* ---- Zone plate (zone.c) -------------------------------------------------- */

#define FQ_ZONE_N 512    /* texture side */
#define FQ_ZONE_M 2.0    /* texels per pixel */
#define FQ_ZONE_PIXELS 256

/* The zone-plate texture (box pyramid, REPEAT) and its texels (caller
 * frees both). */
sample_status fq_zone_texture(sample_texture **out, float **texels, sample_error *err);
/* Render the zone plate through backend b (prepared on that texture) at
 * FQ_ZONE_M texels per pixel: FQ_ZONE_PIXELS² linear RGBA floats, grey
 * (½ + ½·value), caller frees; NULL with a message on failure. */
float *fq_zone_render(const fq_backend *b, void *ctx, char *err, size_t errlen);

/* ---- Plots (plot.c, svg.c) ----------------------------------------------- */

/* Plot geometry: one figure per (θ, r), a title line, one panel per m
 * (3 columns), response 0 … FQ_PLOT_YMAX against F = 0 … plan->f_max,
 * then the legend. */
#define FQ_PLOT_YMAX 1.25
#define FQ_FIG_TITLE_H 26
#define FQ_PANEL_W 300
#define FQ_PANEL_H 210
#define FQ_PANEL_MARGIN_L 48
#define FQ_PANEL_MARGIN_T 24
#define FQ_PANEL_MARGIN_B 40
#define FQ_PANEL_MARGIN_R 12
#define FQ_PLOT_COLS 3
/* The axis names, with their units (|H| is a ratio of amplitudes). */
#define FQ_PLOT_XLABEL "screen frequency F (cycles/pixel)"
#define FQ_PLOT_YLABEL "|H| (output/input)"

typedef struct fq_figure {
    int width, height, legend_h;
} fq_figure;

fq_figure fq_figure_size(const fq_plan *plan);
/* Panel k's plot area origin (top-left of the axes box) in the figure. */
void fq_panel_origin(const fq_plan *plan, int k, double *x0, double *y0);
/* Data → figure coordinates inside a panel's axes box. */
double fq_plot_x(const fq_plan *plan, double F);
double fq_plot_y(double h);
/* Size of a panel's axes box. */
int fq_plot_axes_w(void);
int fq_plot_axes_h(void);
/* Where backend k's legend entry starts (swatch left, text baseline). */
void fq_legend_pos(const fq_plan *plan, int k, double *x, double *y);
/* Colour of backend k as 0xRRGGBB. */
unsigned fq_plot_color(int k);
/* The ideal low-pass as the four corners of its step, and its value at F
 * (½ at exactly Nyquist). */
void fq_ideal_points(const fq_plan *plan, double F[4], double h[4]);
double fq_ideal(double F);

/* The figure of (θ index, r index) as SVG text: standalone 1 for a file of
 * its own (with the XML declaration), 0 for inlining in HTML. */
void fq_svg_figure(const fq_plan *plan, const fq_sweep *s, int itheta, int ir, int standalone,
                   fq_buf *out);

/* Every filter's pass-band fidelity against its aliasing (fq_summarize over
 * every curve) as inline SVG, with axis names and a legend (frontier.c). */
void fq_svg_frontier(const fq_plan *plan, const fq_sweep *s, fq_buf *out);

#endif
