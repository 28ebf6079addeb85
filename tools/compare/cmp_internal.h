/*
 * compare's private header: where its pieces meet (doc/comparison.md).
 *
 *   configs.c     the default rows and --configs parsing (tools/filters.h)
 *   scenes.c      the built-in comparison set (scene names → scenes)
 *   view.c        one ray cast per pixel: the queries every filter answers
 *   run.c         one configuration over a view, on many threads, timed
 *   backends.c    a row through its backend of tools/backend.h (libsample,
 *                 OpenImageIO, OpenGL, outside programs)
 *   stochastic.c  stochastic filters: RMSE against samples per pixel
 *   truth.c       the ground truth of DESIGN §8 and the metric mask
 *   metrics.c     RMSE, PSNR, per-pixel error, the worst crop
 *   picture.c     8-bit pictures: tone, heat map + legend, crops, contact sheet;
 *                 written through libsample_io
 *   font.c        a 5 × 7 bitmap font for labels in the pictures
 *   legend.c      where the heat map's colour scale and its labels go
 *   sheet.c       a scene's pictures and its contact sheet
 *   cost.c        the plots: RMSE against ns/sample, and the writer
 *                 stochastic.c's plot shares
 *   report.c      results.csv, results.json, index.html, stochastic.csv
 *   cmd_compare.c the subcommand
 */
#ifndef TEXSAMPLE_CMP_INTERNAL_H
#define TEXSAMPLE_CMP_INTERNAL_H

#include "backend.h"
#include "filters.h"
#include "render/render.h"
#include "sample/sample.h"

#include <stddef.h>

/* ---- Configurations (configs.c) -------------------------------------- */

#define CMP_MAX_CONFIGS 32

/* One row: a registry pick (libsample, its OpenImageIO or OpenGL twin), or
 * an outside program (pick.f NULL: the program's own filter), and the
 * backend that samples it. */
typedef struct cmp_config {
    tool_pick pick;
    char name[TOOL_FILTER_NAME_MAX];   /* command-line and file name: "trilinear" */
    char label[TOOL_FILTER_LABEL_MAX]; /* what the page calls it */
    tool_backend *tb; /* the backend that samples (cmd_compare.c opens them) */
} cmp_config;

/* compare's default rows, NULL-terminated registry names. */
extern const char *const cmp_default_configs[];
/* Parse "a,b,c" (registry names, or "all" for the defaults) into rows, in
 * registry order (tool_picks_parse). Returns the count, or −1 with what is
 * wrong in err. */
int cmp_configs_parse(const char *list, unsigned accept, cmp_config *out, int max, char *err,
                      size_t errlen);
/* The scene's sampler with the configuration's filters (wrap modes and
 * border colour stay the scene's). */
void cmp_config_sampler(const cmp_config *c, const sample_sampler *scene, sample_sampler *out);

/* ---- Scenes (scenes.c) ------------------------------------------------- */

/* The comparison set, NULL-terminated, and the default subset. */
extern const char *const cmp_scene_names[];
extern const char *const cmp_default_scenes[];
/* A built-in scene of render (render_builtin_names), one of compare's own,
 * or a scene file. label gets a file-name-safe name. Image textures open
 * through a texture system of cache_mb MiB (render_parse_options.cache_mb;
 * 0: read whole). Returns 0 on success. */
int cmp_scene_open(const char *name, int size, double cache_mb, render_scene **out, char *label,
                   size_t labellen, char *err, size_t errlen);

/* ---- View: what every configuration is asked (view.c) ---------------- */

typedef struct cmp_view {
    const render_scene *sc;
    render_cache *cache;
    int w, h;
    int *tex;              /* per pixel: texture index; −1 surface without texture; −2 background;
                              env_tex: a mirror of the environment */
    int env_tex;           /* the environment's index (the scene's texture count), −1 none */
    int *object;           /* per pixel: object hit at the centre, −1 background */
    sample_query *q;       /* per pixel: (s, t) and exact Jacobian at the centre */
    sample_query3 *q3;     /* per pixel where tex is env_tex: the reflected direction and its
                              exact derivatives; on a solid texture (cmp_view_3d): (s, t, r)
                              in its volume and the exact dP/dx, dP/dy; NULL if the scene has
                              neither */
    sample_quad *quad;     /* per pixel: exact corners, where quad_ok */
    unsigned char *quad_ok;
    float background[4];   /* linear RGBA for pixels (and truth samples) that miss */
    sample_sampler sampler; /* the scene's sampler */
} cmp_view;

/* 1 if the texture's queries are v->q3's (a solid texture's volume). */
int cmp_view_3d(const cmp_view *v, int texture);
/* Ray-cast every pixel centre and its corners. Returns 0 on success. */
int cmp_view_build(const render_scene *sc, int threads, cmp_view *v, char *err, size_t errlen);
void cmp_view_free(cmp_view *v);

/* ---- Running one configuration (run.c) ------------------------------- */

typedef struct cmp_result {
    float *rgba;          /* w × h × 4 linear */
    int runs;             /* the image was filtered this many times; times are medians */
    double seconds;       /* wall time of the whole image */
    double ns_per_sample; /* time inside the filter calls, per query, all threads summed */
    double texels;        /* texels read per query (libsample's count; OIIO: not known, −1) */
    size_t queries;
} cmp_result;

/* An engine: filter n queries of one texture (quad: exact corners or NULL)
 * into n × 4 floats; px: the queries' pixel indices; stats may be NULL. For the environment (texture ==
 * env_tex) and a solid texture (cmp_view_3d) q is NULL and q3 holds the
 * direction or volume queries; else q3 is NULL. Returns 0 on success. Called from
 * many threads at once. */
typedef int (*cmp_batch_fn)(void *ctx, int texture, const size_t *px, const sample_query *q,
                            const sample_query3 *q3, const sample_quad *quad, size_t n, float *rgba,
                            sample_stats *stats);
/* Run an engine over every textured pixel of the view, `runs` times (≥ 1)
 * (run.c): the times are the medians over the runs (one run's time moves
 * with whatever else the machine does); the image and texel counts are the
 * same every run. stats: ask for texel counts. Returns 0 on success. */
int cmp_run(const cmp_view *v, int corners, cmp_batch_fn fn, void *ctx, int stats, int threads,
            int runs, cmp_result *r);

/* ---- Rows through their backends (backends.c) ------------------------ */

/* A row's backend with every texture of the view that a pixel uses
 * prepared (tex[k] for texture k; tex[env_tex] the environment). */
typedef struct cmp_prepared {
    tool_backend *tb;
    tool_backend_tex **tex;
    int ntex;
} cmp_prepared;
/* Prepare c's backend for the view (the scene's sampler with c's filter; a
 * solid texture with its own wrap). Returns 0, TOOL_BACKEND_NA or
 * TOOL_BACKEND_ERROR with the reason in err. */
int cmp_prepare(const cmp_view *v, const cmp_config *c, cmp_prepared *p, char *err, size_t errlen);
void cmp_prepared_release(cmp_prepared *p);
/* One batch of texture `texture` (tool_backend_run): u and draws for
 * stochastic lookups (NULL, 0: deterministic); stats where the backend
 * counts texels; t may be NULL. */
int cmp_prepared_batch(const cmp_prepared *p, int texture, const sample_query *q,
                       const sample_query3 *q3, const sample_quad *quad, const float *u,
                       unsigned draws, size_t n, float *rgba, sample_stats *stats,
                       tool_backend_times *t, char *err, size_t errlen);
/* Row c over every textured pixel, `runs` times: a backend that serves
 * many threads (libsample, OpenImageIO) through cmp_run on `threads`
 * threads, with texel counts where it counts them; any other (OpenGL, a
 * program) one batch per texture on one thread, ns_per_sample the sampling
 * alone (the backend's upload and read-back left out). Returns 0,
 * TOOL_BACKEND_NA or TOOL_BACKEND_ERROR with the reason in err. */
int cmp_run_backend(const cmp_view *v, const cmp_config *c, int threads, int runs, cmp_result *r,
                    char *err, size_t errlen);
void cmp_result_free(cmp_result *r);

/* Background and untextured pixels, shared by every engine. */
void cmp_fill_untextured(const cmp_view *v, float *rgba);

/* ---- Ground truth (truth.c) ------------------------------------------ */

typedef struct cmp_truth {
    float *rgba;         /* w × h × 4 linear */
    unsigned char *mask; /* 1: pixel counted by the metrics (whole footprint on the centre's
                            textured object, on no occlusion edge: truth.c) */
    int samples;         /* n: n × n samples over each 2 × 2-pixel footprint */
    double seconds;
} cmp_truth;

/* n must be even and ≥ 2. Returns 0 on success. */
int cmp_truth_build(const cmp_view *v, int n, int threads, cmp_truth *t, char *err, size_t errlen);
void cmp_truth_free(cmp_truth *t);

/* ---- Metrics (metrics.c) --------------------------------------------- */

typedef struct cmp_metrics {
    double rmse;     /* over R, G, B of the masked pixels, linear */
    double psnr;     /* dB, peak 1; +inf when rmse is 0 */
    double max_err;  /* largest per-pixel error (RMS over R, G, B) */
    size_t count;    /* pixels measured */
} cmp_metrics;

/* img, ref: n pixels × 4 floats; mask may be NULL (all pixels). */
void cmp_metrics_compute(const float *img, const float *ref, const unsigned char *mask, size_t n,
                         cmp_metrics *m);
/* Per-pixel error e = sqrt(mean over R, G, B of the squared difference). */
void cmp_error_map(const float *img, const float *ref, size_t n, float *err);
/* The median of v[0..n) (n ≥ 1; the mean of the middle two for even n);
 * sorts v. */
double cmp_median(double *v, int n);
/* The size × size window with the largest sum of `score` over masked pixels
 * (score: w × h). Ties go to the first in row order. */
void cmp_worst_window(const double *score, const unsigned char *mask, int w, int h, int size,
                      int *x0, int *y0);

/* ---- Pictures (picture.c, font.c) ------------------------------------ */

typedef struct cmp_pic {
    int w, h;
    unsigned char *rgb; /* w × h × 3 sRGB-encoded */
} cmp_pic;

int cmp_pic_alloc(cmp_pic *p, int w, int h);
void cmp_pic_free(cmp_pic *p);
/* Linear RGBA → sRGB picture, clamped to [0, 1]. */
int cmp_pic_from_linear(cmp_pic *p, const float *rgba, int w, int h);
/* Heat map of per-pixel error over [0, scale], with a colour scale legend
 * below the image; unmasked pixels are drawn grey. */
int cmp_pic_heatmap(cmp_pic *p, const float *err, const unsigned char *mask, int w, int h,
                    float scale);
/* The colour of a value in [0, 1] on the heat map's scale (sRGB bytes). */
void cmp_heat_colour(float v, unsigned char rgb[3]);
/* The heat map's legend in a picture w pixels wide, below the image: the
 * bar (x, width; width 0: too narrow for one) and the labels that fit, each
 * inside the picture and at least 4 pixels clear of the others; label
 * coordinates are relative to the legend's top. */
typedef struct cmp_label {
    int x, y, w, h; /* the text's box */
    int tick_x;     /* the bar position it names */
    char text[16];
} cmp_label;
typedef struct cmp_legend {
    int bar_x, bar_w;
    int n;
    cmp_label label[3];
} cmp_legend;
void cmp_heat_legend(int w, float scale, cmp_legend *lg);
/* Window (x0, y0, size) of src magnified by an integer factor. */
int cmp_pic_crop(cmp_pic *p, const cmp_pic *src, int x0, int y0, int size, int zoom);
/* dst ← src at (x, y), src shrunk by the integer `down` (box). */
void cmp_pic_blit(cmp_pic *dst, const cmp_pic *src, int x, int y, int down);
void cmp_pic_fill(cmp_pic *p, int x, int y, int w, int h, const unsigned char rgb[3]);
void cmp_pic_rect(cmp_pic *p, int x, int y, int w, int h, const unsigned char rgb[3]);
/* Text in the 5 × 7 font, `scale` pixels per font pixel; returns the width. */
int cmp_pic_text(cmp_pic *p, int x, int y, const char *text, int scale, const unsigned char rgb[3]);
int cmp_text_width(const char *text, int scale);
/* Text cut into at most maxlines lines that each fit `width` pixels
 * (cmp_text_width, the last glyph's blank column not counted), breaking
 * after '-' or '_' where one falls in a line; what does not fit is left
 * out. Returns the number of lines. */
#define CMP_LINE_MAX 64
int cmp_text_wrap(const char *text, int width, int scale, char lines[][CMP_LINE_MAX], int maxlines);
/* One glyph: 7 rows of 5 bits (bit 4 = leftmost), NULL for unknown characters. */
const unsigned char *cmp_font_glyph(char c);

/* The picture as an 8-bit RGB PNG (or any format sample_io writes, by the
 * extension), codes unchanged; through a temporary file, so a failed write
 * leaves nothing. Returns 0 on success, else 1 with a message in err. */
int cmp_pic_write(const char *path, const cmp_pic *p, char *err, size_t errlen);

/* ---- Results and the report (report.c) ------------------------------- */

/* The heat maps' full scale: per-pixel error (linear, RMS over R, G, B) at
 * which the colour saturates; one value for every scene so that pictures
 * compare across scenes. */
#define CMP_HEAT_SCALE 0.25f

typedef struct cmp_row {
    const cmp_config *cfg;
    int ok;             /* 0: not run (note says why) */
    int na;             /* not run because the backend cannot do the scene's state */
    char note[200];
    cmp_metrics m;
    double seconds, ns_per_sample, texels; /* texels < 0: not known */
} cmp_row;

/* A stochastic filter's sweep (stochastic.c). */
#define CMP_MAX_SPP 12
typedef struct cmp_spp_row {
    const cmp_config *cfg;
    int ok;                   /* 0: n/a, note says why */
    char note[160];
    double rmse[CMP_MAX_SPP]; /* at the scene's spp[k] */
    double det_rmse;          /* the deterministic row's (NaN: not run) */
    double ns_per_sample;     /* one stochastic lookup, median over the lookups */
} cmp_spp_row;

typedef struct cmp_scene_result {
    char label[64];      /* file-name-safe; also the folder of its pictures */
    char source[256];    /* what --scene said */
    int w, h;
    int truth_samples;
    int runs;            /* times are medians of this many runs */
    double truth_seconds;
    size_t pixels, measured; /* all pixels, pixels in the metrics */
    int crop_x, crop_y, crop_size, crop_zoom;
    cmp_row rows[CMP_MAX_CONFIGS];
    int nrows;
    int spp[CMP_MAX_SPP], nspp;    /* the sweep's samples per pixel; nspp 0: no sweep */
    unsigned draws;                /* texels per EWA / Blinn–Newell lookup */
    cmp_spp_row spp_rows[CMP_MAX_CONFIGS];
    int nspp_rows;
} cmp_scene_result;

/* Paths of a scene's pictures relative to the output folder. */
void cmp_pic_path(char *out, size_t len, const cmp_scene_result *s, const char *what,
                  const char *suffix);

/* Write the scene's pictures under dir/<label>/ (the folder must exist):
 * images[r] is row r's image (NULL where the row did not run). */
int cmp_scene_pictures(const char *dir, const cmp_scene_result *s, const cmp_truth *t,
                       float *const *images);

/* A plot (cost.c): series of (x, RMSE) points on a logarithmic x axis,
 * named axes and a legend in the picture. */
typedef struct cmp_series {
    const char *label;
    int colour;           /* palette index */
    int n;                /* points; joined by lines when more than one */
    const double *x, *y;
    double hline;         /* >= 0: a dashed horizontal line at this RMSE */
} cmp_series;
typedef struct cmp_plot {
    const char *title, *xlabel;
    const double *xticks; /* NULL: decades */
    int nxticks;
    const cmp_series *series;
    int nseries;
} cmp_plot;
/* Write the plot as a PNG at path; nothing when no series has a point.
 * Returns 0, or 1 after a message on stderr. */
int cmp_plot_write(const char *path, const cmp_plot *pl);
/* dir/<label>/cost.png: every row's RMSE against its ns/sample; nothing
 * when no row was timed. Returns as cmp_plot_write. */
int cmp_cost_plot(const char *dir, const cmp_scene_result *s);

/* ---- Stochastic filters (stochastic.c) -------------------------------- */

/* 1 if row c is libsample's and u changes its result (a footprint filter
 * or a two-level mipmap blend). */
int cmp_config_stochastic(const cmp_config *c, const sample_sampler *scene);
/* The sweep's uniform for lookup `lookup` of pixel `pixel`: a fixed-seed
 * hash, in [0, 1), the same on every run and for any thread count. */
float cmp_spp_u(size_t pixel, int lookup);
/* Row c at spp[0] < … < spp[nspp − 1] samples per pixel: each pixel the
 * mean of spp stochastic lookups (draws texels per EWA / Blinn–Newell
 * lookup), scored against t. Returns 0 (out->ok), TOOL_BACKEND_NA or
 * TOOL_BACKEND_ERROR with the reason in err. */
int cmp_spp_sweep(const cmp_view *v, const cmp_config *c, const cmp_truth *t, const int *spp, int nspp,
                  unsigned draws, int threads, cmp_spp_row *out, char *err, size_t errlen);
/* dir/<label>/spp.png: each swept row's RMSE against samples per pixel,
 * its deterministic RMSE a dashed line; nothing without a sweep. */
int cmp_spp_plot(const char *dir, const cmp_scene_result *s);

/* results.csv, results.json, index.html in dir. command: the command line,
 * quoted on the page. Return 0 on success. */
int cmp_write_csv(const char *path, const cmp_scene_result *s, int n);
int cmp_write_json(const char *path, const cmp_scene_result *s, int n, const char *command);
int cmp_write_html(const char *path, const cmp_scene_result *s, int n, const char *command);
/* stochastic.csv: every scene's sweep (nothing written when none ran). */
int cmp_write_spp_csv(const char *path, const cmp_scene_result *s, int n);

/* Monotonic seconds, for the timings (run.c). Rows run in parallel through
 * the renderer's render_parallel_rows (render.h). */
double cmp_now(void);

#endif
