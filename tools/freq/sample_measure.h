/*
 * sample_measure.h — the tools' measurements as a C API for other
 * languages: the frequency test (`texsample freq`, DESIGN §9,
 * doc/frequency-tests.md) and the comparison against the ground truth
 * (`texsample compare`, DESIGN §8, doc/comparison.md), in the shared
 * library libsample_measure (tools/sample_measure.cmake) that the Python
 * package loads (doc/python.md). The measurements are the code the
 * command line runs (tools/freq/sweep.c, measure.c, summary.c;
 * tools/compare/view.c, truth.c, run.c, metrics.c); this API adds only
 * filters given as callbacks and results as plain arrays.
 */
#ifndef SAMPLE_MEASURE_H
#define SAMPLE_MEASURE_H

#include "sample/sample.h"

#include <stddef.h>

#ifndef SAMPLE_MEASURE_API
#if defined(SAMPLE_MEASURE_BUILDING_SHARED) && (defined(__GNUC__) || defined(__clang__))
#define SAMPLE_MEASURE_API __attribute__((visibility("default")))
#else
#define SAMPLE_MEASURE_API
#endif
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* A filter given as a function: sample `count` queries (sample_query, the
 * Jacobian of each pixel) on `tex` and write count × 4 floats to rgba.
 * Returns 0, or nonzero with a message in err (errlen bytes), which stops
 * the run. freq calls it with batches of width × rows × phases queries on
 * the grating under test (a 2-channel float REPEAT texture with its box
 * pyramid); compare with the pixels of one row that show one texture of
 * the scene, from one thread at a time. */
typedef int (*sample_measure_fn)(void *user, const sample_texture *tex, const sample_query *queries,
                                 size_t count, float *rgba, char *err, size_t errlen);

typedef struct sample_measure_filter {
    /* fn NULL: a name of the tools' filter registry (tools/filters.h:
     * "trilinear", "ewa", ...), sampled by libsample. Else a label. */
    const char *name;
    sample_measure_fn fn;
    void *user;
} sample_measure_filter;

/* What `texsample freq` sweeps (its --m, --theta, --r, --size, --step,
 * --fmax, --width, --rows, --phases). */
typedef struct sample_freq_params {
    const double *m;
    int nm;
    const double *theta_deg;
    int ntheta;
    const double *r;
    int nr;
    int n;           /* texture side, a power of two */
    double f_step;   /* screen-frequency grid step, cycles/pixel */
    double f_max;    /* top of the grid */
    int width, rows, phases;
} sample_freq_params;

/* One measured point (freq.h's fq_point and fq_result). */
typedef struct sample_freq_point {
    int filter, im, itheta, ir; /* indices into the filters and params lists */
    int p, q;                   /* the grating's wave vector (cycles across the texture) */
    double f;                   /* its frequency, cycles/texel */
    double F, alias_F;          /* screen frequency f·m, and where it aliases to */
    double re, im_, amp;        /* complex response and |H| */
    double stderr_, residual;   /* standard error of amp, RMS of what the fit leaves */
    double texels, ns;          /* texels read (NaN: not counted) and time, per sample */
} sample_freq_point;

/* freq's two numbers per filter (freq.h's fq_stat): pass-band fidelity
 * (mean |H| for 0 < F < 0.4) and aliasing (mean leakage for F > 0.6), each
 * with its worst case over orientations. */
typedef struct sample_freq_summary {
    double pass, pass_worst, alias, alias_worst, texels, ns;
    int npass, nstop;
} sample_freq_summary;

typedef struct sample_freq_result sample_freq_result;

/* Run the sweep with `nfilters` filters. Returns 0 and *out (free with
 * sample_freq_free), or −1 with a message in err. */
SAMPLE_MEASURE_API int sample_freq_run(const sample_freq_params *params, const sample_measure_filter *filters,
                                       int nfilters, sample_freq_result **out, char *err, size_t errlen);
/* The points, ordered by (filter, m, θ, r, F): count, and a copy into
 * out[0 … count). */
SAMPLE_MEASURE_API size_t sample_freq_count(const sample_freq_result *res);
SAMPLE_MEASURE_API void sample_freq_points(const sample_freq_result *res, sample_freq_point *out);
/* The summary of one filter at m index im and r index ir; −1 folds that
 * axis (as texsample freq's summary tables). */
SAMPLE_MEASURE_API sample_freq_summary sample_freq_summarize(const sample_freq_result *res, int filter, int im,
                                                             int ir);
SAMPLE_MEASURE_API void sample_freq_free(sample_freq_result *res);

/* ---- Comparison against the ground truth ---------------------------------- */

/* What `texsample compare` renders (its --scene, --size, --truth-samples,
 * --threads). */
typedef struct sample_compare_params {
    const char *scene; /* a scene of compare's set ("plane", "teapot", "zoneplate", ...) or a scene file */
    int size;          /* picture side, pixels */
    int truth;         /* n × n truth samples per 2 × 2-pixel footprint, even, >= 2 */
    int threads;       /* threads for the view, the truth and registry filters (>= 1) */
} sample_compare_params;

/* One filter's row of results.csv (cmp_metrics, cmp_result). */
typedef struct sample_compare_metrics {
    double rmse, psnr, max_err; /* over R, G, B of the measured pixels, linear */
    double count;               /* pixels measured */
    double seconds, ns_per_sample;
    double texels;              /* per query; < 0: not counted */
} sample_compare_metrics;

typedef struct sample_compare_result sample_compare_result;

/* Cast the view, build the truth, run every filter (registry names may be
 * corner-mode entries; callbacks get the Jacobians) and measure each.
 * Returns 0 and *out (free with sample_compare_free), or −1 with a message. */
SAMPLE_MEASURE_API int sample_compare_run(const sample_compare_params *params, const sample_measure_filter *filters,
                                          int nfilters, sample_compare_result **out, char *err, size_t errlen);
/* Picture size; the truth and each filter's picture (w × h × 4 linear
 * floats, row 0 at the top), the metric mask (w × h, 1: measured). */
SAMPLE_MEASURE_API void sample_compare_size(const sample_compare_result *res, int *w, int *h);
SAMPLE_MEASURE_API const float *sample_compare_truth(const sample_compare_result *res);
SAMPLE_MEASURE_API const unsigned char *sample_compare_mask(const sample_compare_result *res);
SAMPLE_MEASURE_API const float *sample_compare_image(const sample_compare_result *res, int filter);
SAMPLE_MEASURE_API sample_compare_metrics sample_compare_metrics_get(const sample_compare_result *res, int filter);
SAMPLE_MEASURE_API void sample_compare_free(sample_compare_result *res);

#ifdef __cplusplus
}
#endif
#endif
