/*
 * `texsample bench --save DIR`: the exact queries a run times and a
 * manifest that says everything another program needs to time them again
 * through OpenImageIO on its own (tools/bench/oiio_replay.cpp) — the file
 * layout, the texture files, each filter's settings on both sides as the
 * libraries spell them, and bench's own 1-thread numbers to compare ratios
 * with. The manifest describes itself so that a third party needs neither
 * our code nor our headers to read the query files.
 */
#define _POSIX_C_SOURCE 200809L
#include "bench.h"
#include "cli.h"

#include <stdlib.h>
#include <string.h>

enum { RECORD_FLOATS = 6, RECORD_BYTES = RECORD_FLOATS * 4 };

/* The record must be sample_query itself, six packed floats, or the file
 * would not be "the exact queries in the struct's order". */
_Static_assert(sizeof(sample_query) == RECORD_BYTES, "sample_query is six packed floats");

static void query_file_name(bench_set set, char *buf, size_t len)
{
    snprintf(buf, len, "queries_%s.bin", bench_set_names[set]);
}

int bench_save_queries(const char *dir, bench_set set, const sample_query *q, size_t n)
{
    char name[64], path[1100];
    unsigned char *buf = malloc(n * RECORD_BYTES), *p = buf;
    size_t i;
    int k, rc = 0;
    if (!buf) return cli_runtime_error("bench", "out of memory");
    for (i = 0; i < n; ++i) {
        const float f[RECORD_FLOATS] = {q[i].s,    q[i].t,    q[i].dsdx,
                                        q[i].dtdx, q[i].dsdy, q[i].dtdy};
        /* Little-endian whatever the host: the manifest promises it. */
        for (k = 0; k < RECORD_FLOATS; ++k, p += 4) {
            uint32_t u;
            memcpy(&u, &f[k], 4);
            p[0] = (unsigned char)u;
            p[1] = (unsigned char)(u >> 8);
            p[2] = (unsigned char)(u >> 16);
            p[3] = (unsigned char)(u >> 24);
        }
    }
    query_file_name(set, name, sizeof name);
    snprintf(path, sizeof path, "%s/%s", dir, name);
    if (!cli_write_file(path, buf, n * RECORD_BYTES))
        rc = cli_runtime_error("bench", "cannot write %s", path);
    free(buf);
    return rc;
}

int bench_save_texture(const char *dir, bench_format fmt, const char *path)
{
    void *data = NULL;
    size_t size = 0;
    const char *why = "";
    char out[1100];
    int rc = 0;
    snprintf(out, sizeof out, "%s/%s", dir, bench_oiio_file_names[fmt]);
    if (!cli_read_file(path, &data, &size, &why))
        rc = cli_runtime_error("bench", "cannot read %s: %s", path, why);
    else if (!cli_write_file(out, data, size))
        rc = cli_runtime_error("bench", "cannot write %s", out);
    free(data);
    return rc;
}

static void timing(FILE *f, const bench_result *x)
{
    if (!x) {
        fputs("null", f);
        return;
    }
    fprintf(f, "{\"median\": %.6g, \"min\": %.6g, \"max\": %.6g, \"runs\": %d}",
            x->timing.median, x->timing.min, x->timing.max, x->timing.runs);
}

static const bench_result *find1(const bench_report *r, int set, int fmt, int engine)
{
    size_t k;
    for (k = 0; k < r->count; ++k) {
        const bench_result *x = &r->results[k];
        if ((int)x->set == set && (int)x->format == fmt && x->engine == engine && x->threads == 1)
            return x;
    }
    return NULL;
}

static void sampler(FILE *f, const sample_sampler *s)
{
    static const struct {
        unsigned bit;
        const char *name;
    } opts[] = {
        {SAMPLE_OPT_LEGACY_SWITCHOVER, "legacy_switchover"},
        {SAMPLE_OPT_NEAREST_LEVEL_FLOOR, "nearest_level_floor"},
        {SAMPLE_OPT_CUBIC_CLAMP, "cubic_clamp"},
        {SAMPLE_OPT_ANISO_POW2, "aniso_pow2"},
        {SAMPLE_OPT_BN_AREA_WEIGHT, "bn_area_weight"},
    };
    size_t k;
    int n = 0;
    fprintf(f,
            "{\"wrap_s\": \"%s\", \"wrap_t\": \"%s\", \"min_filter\": \"%s\", "
            "\"mag_filter\": \"%s\",\n       \"footprint\": \"%s\", \"max_anisotropy\": %.9g, "
            "\"cubic\": \"%s\", \"lod_bias\": %.9g, \"min_lod\": %.9g, \"max_lod\": %.9g,\n"
            "       \"base_level\": %d, \"max_level\": %d, \"options\": [",
            sample_wrap_name(s->wrap_s), sample_wrap_name(s->wrap_t),
            sample_filter_name(s->min_filter), sample_filter_name(s->mag_filter),
            sample_footprint_name(s->footprint), (double)s->max_anisotropy,
            sample_cubic_name(s->cubic), (double)s->lod_bias, (double)s->min_lod,
            (double)s->max_lod, s->base_level, s->max_level);
    for (k = 0; k < sizeof opts / sizeof opts[0]; ++k)
        if (s->options & opts[k].bit) fprintf(f, "%s\"%s\"", n++ ? ", " : "", opts[k].name);
    fputs("]}", f);
}

/* The TextureOpt the shim sets, as it reports it; "null" without a twin. */
static int textureopt(FILE *f, const bench_engine *twin)
{
    oiio_ts_textureopt t;
    if (!twin) {
        fputs("null", f);
        return 0;
    }
    if (oiio_ts_describe(&twin->opts, &t) != 0)
        return cli_runtime_error("bench", "%s: the shim cannot describe its options", twin->name);
    fprintf(f,
            "{\"interpmode\": \"%s\", \"mipmode\": \"%s\", \"swrap\": \"%s\", "
            "\"twrap\": \"%s\",\n       \"anisotropic\": %d, \"conservative_filter\": %s, "
            "\"nchannels\": 4}",
            t.interpmode, t.mipmode, t.swrap, t.twrap, t.anisotropic,
            t.conservative_filter ? "true" : "false");
    return 0;
}

static void list_sets(FILE *f, const bench_save *s, size_t n)
{
    int set, first = 1;
    char name[64];
    fputs("  \"sets\": [", f);
    for (set = 0; set < BENCH_SET_COUNT; ++set) {
        if (!((s->sets >> set) & 1u)) continue;
        query_file_name((bench_set)set, name, sizeof name);
        fprintf(f, "%s\n    {\"name\": \"%s\", \"seed\": ", first ? "" : ",", bench_set_names[set]);
        if (bench_set_seeds[set])
            fprintf(f, "%u", bench_set_seeds[set]);
        else
            fputs("null", f);
        fprintf(f, ", \"file\": \"%s\", \"count\": %zu, \"bytes\": %zu}", name, n,
                n * (size_t)RECORD_BYTES);
        first = 0;
    }
    fputs("\n  ],\n", f);
}

static void list_formats(FILE *f, const bench_save *s)
{
    static const char *const oiio_type[BENCH_FMT_COUNT] = {"float", "half", "uint8"};
    static const sample_format ours[BENCH_FMT_COUNT] = {SAMPLE_FORMAT_F32, SAMPLE_FORMAT_F16,
                                                        SAMPLE_FORMAT_SRGB8};
    int fmt, first = 1;
    fputs("  \"formats\": [", f);
    for (fmt = 0; fmt < BENCH_FMT_COUNT; ++fmt) {
        if (!((s->formats >> fmt) & 1u)) continue;
        fprintf(f,
                "%s\n    {\"name\": \"%s\", \"oiio_file\": \"%s\", \"oiio_type\": \"%s\", "
                "\"libsample_format\": \"%s\"}",
                first ? "" : ",", bench_format_names[fmt], bench_oiio_file_names[fmt],
                oiio_type[fmt], sample_format_name(ours[fmt]));
        first = 0;
    }
    fputs("\n  ],\n", f);
}

static int list_filters(FILE *f, const bench_save *s, const bench_report *r)
{
    int e, first = 1;
    fputs("  \"filters\": [", f);
    for (e = 0; e < r->engine_count && !r->engines[e].oiio; ++e) {
        const bench_engine *en = &r->engines[e];
        if (!((s->filters >> e) & 1u)) continue;
        fprintf(f, "%s\n    {\"name\": \"%s\",\n     \"libsample\": ", first ? "" : ",", en->name);
        sampler(f, &en->smp);
        fputs(",\n     \"oiio\": ", f);
        if (textureopt(f, en->match >= 0 ? &r->engines[en->match] : NULL) != 0) return -1;
        fputs("}", f);
        first = 0;
    }
    fputs("\n  ],\n", f);
    return 0;
}

static void list_results(FILE *f, const bench_report *r)
{
    size_t k;
    int first = 1;
    fputs("  \"results\": [", f);
    for (k = 0; k < r->count; ++k) {
        const bench_result *x = &r->results[k], *o;
        const bench_engine *en = &r->engines[x->engine];
        if (en->oiio || x->threads != 1) continue;
        o = en->match >= 0 ? find1(r, x->set, x->format, en->match) : NULL;
        fprintf(f, "%s\n    {\"set\": \"%s\", \"format\": \"%s\", \"filter\": \"%s\",\n     \"ours\": ",
                first ? "" : ",", bench_set_names[x->set], bench_format_names[x->format],
                en->name);
        timing(f, x);
        fputs(",\n     \"oiio\": ", f);
        timing(f, o);
        if (o && o->timing.median > 0.0)
            fprintf(f, ", \"ratio\": %.6g}", x->timing.median / o->timing.median);
        else
            fputs(", \"ratio\": null}", f);
        first = 0;
    }
    fputs("\n  ]\n", f);
}

int bench_save_manifest(const bench_save *s, const bench_report *r)
{
    char *buf = NULL, path[1100];
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    int rc = 0;
    if (!f) return cli_runtime_error("bench", "out of memory");
    fprintf(f, "{\n  \"manifest\": \"texsample bench --save\", \"manifest_version\": 1,\n"
               "  \"version\": \"%s\", \"command\": ",
            SAMPLE_VERSION_STRING);
    bench_json_string(f, r->command);
    fprintf(f,
            ",\n  \"paths\": \"relative to the directory of this manifest\",\n"
            "  \"query_file\": {\"byte_order\": \"little-endian\", \"scalar\": \"float32\", "
            "\"record_bytes\": %d,\n"
            "    \"fields\": [\"s\", \"t\", \"dsdx\", \"dtdx\", \"dsdy\", \"dtdy\"],\n"
            "    \"about\": \"libsample's sample_query in its field order; (s, t) normalized, "
            "texel centres at (i + 0.5) / texture_size; derivatives full-pixel, normalized, "
            "dPdx = (dsdx, dtdx), dPdy = (dsdy, dtdy), passed to TextureSystem::texture as "
            "they are\"},\n"
            "  \"texture_size\": %d, \"channels\": 4, \"queries\": %zu,\n"
            "  \"timing\": {\"threads\": 1, \"warmup_passes\": 1, \"runs\": %d, "
            "\"statistic\": \"median\", \"batch\": %zu, \"unit\": \"samples per second\", "
            "\"load_before\": %.3g, \"load_after\": %.3g},\n",
            RECORD_BYTES, r->size, r->queries, r->runs, r->batch, r->load[0], r->load[1]);
    list_sets(f, s, r->queries);
    list_formats(f, s);
    rc = list_filters(f, s, r);
    list_results(f, r);
    fputs("}\n", f);
    if (fclose(f) != 0) {
        free(buf);
        return cli_runtime_error("bench", "out of memory");
    }
    snprintf(path, sizeof path, "%s/manifest.json", s->dir);
    if (rc == 0 && !cli_write_file(path, buf, len))
        rc = cli_runtime_error("bench", "cannot write %s", path);
    free(buf);
    return rc;
}
