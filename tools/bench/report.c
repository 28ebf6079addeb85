/*
 * bench's output: a text table per (query set, format) for people, JSON for
 * scripts. Speeds are millions of samples per second, the median of the
 * timed runs with their range; the ratio is ours / OIIO at the matching
 * setting and thread count (> 1: libsample is faster).
 */
#define _POSIX_C_SOURCE 200809L
#include "bench.h"
#include "cli.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const bench_result *find(const bench_report *r, int set, int fmt, int engine,
                                int threads)
{
    size_t k;
    for (k = 0; k < r->count; ++k) {
        const bench_result *x = &r->results[k];
        if ((int)x->set == set && (int)x->format == fmt && x->engine == engine &&
            x->threads == threads)
            return x;
    }
    return NULL;
}

/* ours / OIIO's median at the same setting, or a negative value if there
 * is no OIIO twin measured. */
static double ratio(const bench_report *r, const bench_result *x)
{
    const bench_engine *e = &r->engines[x->engine];
    const bench_result *o;
    if (e->oiio || e->match < 0) return -1.0;
    o = find(r, x->set, x->format, e->match, x->threads);
    return o && o->timing.median > 0.0 ? x->timing.median / o->timing.median : -1.0;
}

static void cell(const bench_result *x)
{
    char buf[64];
    if (!x) {
        printf("  %-20s", "-");
        return;
    }
    snprintf(buf, sizeof buf, "%.2f [%.2f-%.2f]", x->timing.median * 1e-6, x->timing.min * 1e-6,
             x->timing.max * 1e-6);
    printf("  %-20s", buf);
}

/* The OpenGL rows (--gl): per set, format and filter, the sampling speed
 * and the transfers beside it. */
static void print_gl(const bench_report *r)
{
    size_t k;
    printf("\nOpenGL: %s\ntexture = upload of all levels (once); queries, read-back = per pass; "
           "sampling = the draw alone,\nmillions of samples per second, median [min-max] of %d "
           "runs after a warm-up.\n",
           r->gl_driver, r->runs);
    printf("  %-15s %-6s %-16s %10s %10s  %-22s %10s\n", "set", "format", "filter", "texture ms",
           "queries ms", "sampling", "read ms");
    for (k = 0; k < r->ngl; ++k) {
        const bench_gl_result *g = &r->gl[k];
        char buf[64];
        printf("  %-15s %-6s %-16s ", bench_set_names[g->set], bench_format_names[g->format],
               r->engines[g->engine].name);
        if (g->na) {
            printf("n/a: %s\n", g->note);
            continue;
        }
        snprintf(buf, sizeof buf, "%.2f [%.2f-%.2f]", g->sampling.median * 1e-6,
                 g->sampling.min * 1e-6, g->sampling.max * 1e-6);
        printf("%10.2f %10.2f  %-22s %10.2f\n", 1e3 * g->texture_upload_s, 1e3 * g->query_upload_s,
               buf, 1e3 * g->readback_s);
    }
}

void bench_print_table(const bench_report *r)
{
    int set, fmt, e, k, nthr = r->threads_max > 1 ? 2 : 1, nw = 13;
    const int thr[2] = {1, r->threads_max};
    /* The filter column fits the longest registry name measured. */
    for (e = 0; e < r->engine_count; ++e)
        if ((int)strlen(r->engines[e].name) > nw) nw = (int)strlen(r->engines[e].name);
    printf("texsample bench: %dx%d RGBA textures, %zu queries per set, batches of %zu,\n"
           "median [min-max] of %d runs after a warm-up, in millions of samples per second.\n"
           "texels = texels read per sample (libsample's sample_stats); ratio = ours / OIIO.\n"
           "1-minute load average: %.2f before, %.2f after (other processes skew timings).\n"
           "libsample path: %s.\n"
           "libsample ISA: %s.\n",
           r->size, r->size, r->queries, r->batch, r->runs, r->load[0], r->load[1],
           r->scalar ? "reference (sample_batch_reference)" : "default (fast path where it applies)",
           r->isa);
    for (set = 0; set < BENCH_SET_COUNT; ++set)
        for (fmt = 0; fmt < BENCH_FMT_COUNT; ++fmt) {
            int any = 0;
            for (k = 0; k < (int)r->count; ++k)
                any |= (int)r->results[k].set == set && (int)r->results[k].format == fmt;
            if (!any) continue;
            printf("\n== %s, %s ==\n%-*s %7s", bench_set_names[set], bench_format_names[fmt], nw,
                   "filter", "texels");
            for (k = 0; k < nthr; ++k) printf("  %-20s", k ? "ours (all threads)" : "ours (1 thread)");
            for (k = 0; k < nthr; ++k) printf("  %-20s", k ? "OIIO (all threads)" : "OIIO (1 thread)");
            for (k = 0; k < nthr; ++k) printf("  %-6s", k ? "ratio*" : "ratio1");
            printf("\n");
            for (e = 0; e < r->engine_count && !r->engines[e].oiio; ++e) {
                const bench_engine *en = &r->engines[e];
                const bench_result *x1 = find(r, set, fmt, e, 1);
                if (!x1 && !find(r, set, fmt, e, r->threads_max)) continue;
                printf("%-*s ", nw, en->name);
                if (x1 && x1->texels_per_sample >= 0.0)
                    printf("%7.2f", x1->texels_per_sample);
                else
                    printf("%7s", "-");
                for (k = 0; k < nthr; ++k) cell(find(r, set, fmt, e, thr[k]));
                for (k = 0; k < nthr; ++k)
                    cell(en->match >= 0 ? find(r, set, fmt, en->match, thr[k]) : NULL);
                for (k = 0; k < nthr; ++k) {
                    const bench_result *x = find(r, set, fmt, e, thr[k]);
                    double q = x ? ratio(r, x) : -1.0;
                    if (q >= 0.0)
                        printf("  %6.2f", q);
                    else
                        printf("  %6s", "-");
                }
                printf("\n");
            }
        }
    if (r->threads_max > 1)
        printf("\n(ratio1: 1 thread, ratio*: %d threads)\n", r->threads_max);
    else
        printf("\n(ratio1: 1 thread)\n");
    if (r->ngl) print_gl(r);
}

void bench_json_string(FILE *f, const char *s)
{
    fputc('"', f);
    for (; s && *s; ++s) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\')
            fprintf(f, "\\%c", c);
        else if (c < 0x20)
            fprintf(f, "\\u%04x", c);
        else
            fputc(c, f);
    }
    fputc('"', f);
}

static void json_results(FILE *f, const bench_report *r)
{
    size_t k;
    for (k = 0; k < r->count; ++k) {
        const bench_result *x = &r->results[k];
        const bench_engine *e = &r->engines[x->engine];
        double q = ratio(r, x);
        fprintf(f, "%s\n    {\"set\": \"%s\", \"format\": \"%s\", \"filter\": \"%s\", "
                   "\"engine\": \"%s\", \"threads\": %d,\n     \"samples_per_s\": "
                   "{\"median\": %.6g, \"min\": %.6g, \"max\": %.6g, \"runs\": %d}",
                k ? "," : "", bench_set_names[x->set], bench_format_names[x->format], e->name,
                e->oiio ? "oiio" : "libsample", x->threads, x->timing.median, x->timing.min,
                x->timing.max, x->timing.runs);
        if (x->texels_per_sample >= 0.0)
            fprintf(f, ", \"texels_per_sample\": %.6g", x->texels_per_sample);
        else
            fprintf(f, ", \"texels_per_sample\": null");
        if (q >= 0.0)
            fprintf(f, ", \"ratio_vs_oiio\": %.6g}", q);
        else
            fprintf(f, ", \"ratio_vs_oiio\": null}");
    }
}

static void json_gl(FILE *f, const bench_report *r)
{
    size_t k;
    fprintf(f, ",\n  \"gl\": {\"driver\": ");
    bench_json_string(f, r->gl_driver);
    fprintf(f, ", \"results\": [");
    for (k = 0; k < r->ngl; ++k) {
        const bench_gl_result *g = &r->gl[k];
        fprintf(f, "%s\n    {\"set\": \"%s\", \"format\": \"%s\", \"filter\": \"%s\", ",
                k ? "," : "", bench_set_names[g->set], bench_format_names[g->format],
                r->engines[g->engine].name);
        if (g->na) {
            fprintf(f, "\"n/a\": ");
            bench_json_string(f, g->note);
            fprintf(f, "}");
            continue;
        }
        fprintf(f, "\"texture_upload_s\": %.6g, \"query_upload_s\": %.6g, \"readback_s\": %.6g,\n"
                   "     \"sampling_samples_per_s\": {\"median\": %.6g, \"min\": %.6g, \"max\": %.6g, "
                   "\"runs\": %d}}",
                g->texture_upload_s, g->query_upload_s, g->readback_s, g->sampling.median,
                g->sampling.min, g->sampling.max, g->sampling.runs);
    }
    fprintf(f, "\n  ]}");
}

int bench_write_json(const bench_report *r, const char *path)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    int rc = 0;
    if (!f) return cli_runtime_error("bench", "out of memory");
    fprintf(f, "{\n  \"tool\": \"texsample bench\", \"version\": \"%s\",\n  \"command\": ",
            SAMPLE_VERSION_STRING);
    bench_json_string(f, r->command);
    fprintf(f, ",\n  \"size\": %d, \"queries\": %zu, \"batch\": %zu, \"runs\": %d, "
               "\"threads_max\": %d, \"scalar_path\": %s, \"isa\": ",
            r->size, r->queries, r->batch, r->runs, r->threads_max, r->scalar ? "true" : "false");
    bench_json_string(f, r->isa);
    fprintf(f, ",\n  \"load_before\": %.3g, \"load_after\": %.3g,\n  \"results\": [", r->load[0],
            r->load[1]);
    json_results(f, r);
    fprintf(f, "\n  ]");
    if (r->ngl) json_gl(f, r);
    fprintf(f, "\n}\n");
    if (fclose(f) != 0) {
        free(buf);
        return cli_runtime_error("bench", "out of memory");
    }
    if (strcmp(path, "-") == 0) {
        if (fwrite(buf, 1, len, stdout) != len) rc = -1;
    } else if (!cli_write_file(path, buf, len)) {
        rc = -1;
    }
    if (rc) cli_runtime_error("bench", "cannot write %s", path);
    free(buf);
    return rc;
}
