/*
 * The backend interface (backend.h): dispatch, and the command-line pieces
 * the tools share.
 */
#include "backend.h"
#include "filters.h"

#include <stdlib.h>
#include <string.h>

int tool_backend_prepare(tool_backend *b, const sample_texture *tex, const sample_sampler *smp,
                         tool_backend_tex **out, tool_backend_times *t, char *err, size_t errlen)
{
    tool_backend_times none = {0, 0, 0};
    *out = NULL;
    return b->ops->prepare(b, tex, smp, out, t ? t : &none, err, errlen);
}

int tool_backend_sample(tool_backend *b, tool_backend_tex *tx, const sample_query *q, size_t n,
                        float *rgba, double *texels, tool_backend_times *t, char *err,
                        size_t errlen)
{
    tool_backend_times none = {0, 0, 0};
    tool_backend_batch a;
    sample_stats *stats = NULL;
    size_t i;
    int rc;
    if (n == 0) return 0;
    if (b->ops->sample) return b->ops->sample(b, tx, q, n, rgba, texels, t ? t : &none, err, errlen);
    /* A backend with run alone: the texel counts from its stats. Stats in
     * the timed call: their cost is the same small per-query store for
     * every libsample filter (doc/frequency-tests.md §5). */
    if (texels && b->counts_texels && !(stats = malloc(n * sizeof *stats))) {
        snprintf(err, errlen, "out of memory");
        return TOOL_BACKEND_ERROR;
    }
    tool_backend_batch_init(&a, n, q, NULL, rgba, stats);
    rc = b->ops->run(b, tx, &a, t ? t : &none, err, errlen);
    if (rc == 0 && stats)
        for (i = 0; i < n; ++i) *texels += stats[i].texels;
    free(stats);
    return rc;
}

void tool_backend_batch_init(tool_backend_batch *a, size_t count, const sample_query *q,
                             const sample_query3 *q3, float *rgba, sample_stats *stats)
{
    memset(a, 0, sizeof *a);
    a->count = count;
    a->q = q;
    a->q3 = q3;
    a->rgba = rgba;
    a->stats = stats;
}

int tool_backend_prepare_env(tool_backend *b, const sample_texture *tex, const sample_sampler *smp,
                             tool_backend_tex **out, tool_backend_times *t, char *err,
                             size_t errlen)
{
    tool_backend_times none = {0, 0, 0};
    *out = NULL;
    if (!b->ops->prepare_env) {
        snprintf(err, errlen, "no environment maps");
        return TOOL_BACKEND_NA;
    }
    return b->ops->prepare_env(b, tex, smp, out, t ? t : &none, err, errlen);
}

int tool_backend_run(tool_backend *b, tool_backend_tex *tx, const tool_backend_batch *a,
                     tool_backend_times *t, char *err, size_t errlen)
{
    tool_backend_times none = {0, 0, 0};
    const char *lacks = NULL;
    if (a->count == 0) return 0;
    if (b->ops->run) return b->ops->run(b, tx, a, t ? t : &none, err, errlen);
    if (a->q3) lacks = "direction or volume queries";
    else if (a->corners) lacks = "exact footprint corners";
    else if (a->u) lacks = "stochastic draws";
    if (lacks) {
        snprintf(err, errlen, "no %s", lacks);
        return TOOL_BACKEND_NA;
    }
    return b->ops->sample(b, tx, a->q, a->count, a->rgba, NULL, t ? t : &none, err, errlen);
}

void tool_backend_release(tool_backend *b, tool_backend_tex *tx)
{
    if (tx) b->ops->release(b, tx);
}

void tool_backend_close(tool_backend *b)
{
    if (b->ops) b->ops->close(b);
    memset(b, 0, sizeof *b);
}

int tool_program_row_parse(const char *spec, tool_program_row *rows, int n, char *err,
                           size_t errlen)
{
    const char *eq = spec ? strchr(spec, '=') : NULL;
    tool_program_row *out = &rows[n];
    tool_pick pick;
    size_t len, k;
    int j;
    memset(out, 0, sizeof *out);
    if (!eq || eq == spec || !eq[1]) {
        snprintf(err, errlen, "'%s' is not NAME=COMMAND", spec ? spec : "");
        return -1;
    }
    len = (size_t)(eq - spec);
    if (len >= sizeof out->name) {
        snprintf(err, errlen, "the name '%.*s' is longer than %d characters", (int)len, spec,
                 (int)sizeof out->name - 1);
        return -1;
    }
    /* The name becomes file names (compare's CONFIG.f32) and CSV fields. */
    for (k = 0; k < len; ++k) {
        char c = spec[k];
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
              c == '-' || c == '_' || c == '.')) {
            snprintf(err, errlen, "the name '%.*s' may hold only letters, digits, '-', '_', '.'",
                     (int)len, spec);
            return -1;
        }
    }
    memcpy(out->name, spec, len);
    out->command = eq + 1;
    if (tool_pick_find(out->name, &pick, NULL) >= 0) {
        snprintf(err, errlen, "'%s' is a registry filter's name; give the program's row its own",
                 out->name);
        return -1;
    }
    for (j = 0; j < n; ++j)
        if (strcmp(rows[j].name, out->name) == 0) {
            snprintf(err, errlen, "two rows are called '%s'", out->name);
            return -1;
        }
    return 0;
}

void tool_backend_help(FILE *out, int col)
{
    /* Option, then its description's lines; NULL ends each. */
    static const char *const text[] = {
        "--gl-device NAME", "the OpenGL driver of the gl-* rows: an EGL device",
        "by index, DRM node or part of its GL_RENDERER",
        "(default: Mesa's surfaceless platform, llvmpipe);",
        "'list' lists the devices and exits", NULL,
        "--backend-program NAME=COMMAND", "add a row sampled by an outside program that",
        "speaks the lookup file protocol (doc/backends.md);", "repeatable, up to 4", NULL, NULL};
    int k = 0;
    while (text[k]) {
        const char *opt = text[k++];
        int first = 1, w = 2 + (int)strlen(opt);
        fprintf(out, "  %s", opt);
        for (; text[k]; ++k, first = 0) {
            if (first && w < col)
                fprintf(out, "%*s%s\n", col - w, "", text[k]);
            else
                fprintf(out, "%s%*s%s\n", first ? "\n" : "", col, "", text[k]);
        }
        ++k;
    }
}
