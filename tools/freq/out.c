/* Writing the outputs of `texsample freq`: every file is built in memory and
 * written atomically (cli_write_file); the zone-plate pictures go through
 * libsample_io when texsample has it (the page leaves them out otherwise). */
#define _POSIX_C_SOURCE 200809L
#include "cli.h"
#include "freq_cli.h"

#ifdef TEXSAMPLE_HAVE_IO
#include "sample/sample_io.h"
#endif

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static int write_buf(const char *dir, const char *name, const fq_buf *b, char *err, size_t errlen)
{
    char path[2048];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    if (b->failed) {
        snprintf(err, errlen, "%s: out of memory", path);
        return -1;
    }
    if (!cli_write_file(path, b->data ? b->data : "", b->len)) {
        snprintf(err, errlen, "cannot write %s: %s", path, strerror(errno));
        return -1;
    }
    return 0;
}

/* A picture as PNG; returns 1 written, 0 not available in this build, −1
 * failed. */
static int write_png(const char *dir, const char *name, const float *rgba, int w, int h,
                     char *err, size_t errlen)
{
#ifdef TEXSAMPLE_HAVE_IO
    char path[2048];
    sample_error serr;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    if (sample_io_write_image(path, rgba, w, h, 3, NULL, &serr) != SAMPLE_OK) {
        snprintf(err, errlen, "cannot write %s: %s", path, serr.message);
        return -1;
    }
    return 1;
#else
    (void)dir;
    (void)name;
    (void)rgba;
    (void)w;
    (void)h;
    (void)err;
    (void)errlen;
    return 0;
#endif
}

/* The figures as SVG files; names[k] gets figure k's file name. */
static int write_figures(const char *dir, const fq_plan *plan, const fq_sweep *s,
                         char (*names)[64], char *err, size_t errlen)
{
    int ir, it, k = 0;
    for (ir = 0; ir < plan->nr; ++ir)
        for (it = 0; it < plan->ntheta; ++it, ++k) {
            fq_buf b = {0};
            int rc;
            snprintf(names[k], 64, "plot_r%g_t%g.svg", plan->r[ir], plan->theta_deg[it]);
            fq_svg_figure(plan, s, it, ir, 1, &b);
            rc = write_buf(dir, names[k], &b, err, errlen);
            fq_buf_free(&b);
            if (rc != 0) return -1;
        }
    return 0;
}

int fq_write_outputs(const char *dir, const fq_plan *plan, const fq_sweep *s, float *const *zone,
                     int png, const char *command, char *err, size_t errlen)
{
    int nfig = plan->nr * plan->ntheta, k, rc = 0;
    char(*names)[64] = (char(*)[64])calloc((size_t)nfig, 64);
    const char **plots = (const char **)calloc((size_t)nfig, sizeof *plots);
    char(*znames)[64] = (char(*)[64])calloc((size_t)plan->nbackends, 64);
    const char **zlist = (const char **)calloc((size_t)plan->nbackends, sizeof *zlist);
    fq_buf b = {0};
    if (!names || !plots || !znames || !zlist) {
        snprintf(err, errlen, "out of memory");
        rc = -1;
        goto done;
    }
    if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
        snprintf(err, errlen, "cannot create %s: %s", dir, strerror(errno));
        rc = -1;
        goto done;
    }
    fq_report_csv(plan, s, &b);
    rc = write_buf(dir, "freq.csv", &b, err, errlen);
    fq_buf_free(&b);
    if (rc == 0) {
        fq_report_summary_csv(plan, s, &b);
        rc = write_buf(dir, "summary.csv", &b, err, errlen);
        fq_buf_free(&b);
    }
    if (rc == 0) {
        fq_report_summary_md(plan, s, &b);
        rc = write_buf(dir, "summary.md", &b, err, errlen);
        fq_buf_free(&b);
    }
    if (rc == 0) rc = write_figures(dir, plan, s, names, err, errlen);
    for (k = 0; rc == 0 && k < plan->nbackends; ++k) {
        int done;
        if (!zone || !zone[k] || !png) continue;
        snprintf(znames[k], 64, "zone_%s.png", plan->backends[k]->name);
        done = write_png(dir, znames[k], zone[k], FQ_ZONE_PIXELS, FQ_ZONE_PIXELS, err, errlen);
        if (done < 0) rc = -1;
        if (done > 0) zlist[k] = znames[k];
    }
    if (rc == 0) {
        for (k = 0; k < nfig; ++k) plots[k] = names[k];
        fq_report_html(plan, s, plots, zlist, command, &b);
        rc = write_buf(dir, "index.html", &b, err, errlen);
        fq_buf_free(&b);
    }
done:
    free(names);
    free(plots);
    free(znames);
    free(zlist);
    return rc;
}
