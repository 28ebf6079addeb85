/*
 * `texsample bench --save` and `oiio_replay`, end to end but small: a tiny
 * saved run, replayed; the manifest parses (cJSON, not the replay's own
 * reader) and says what the files hold; each query file is count × record
 * bytes and holds bit for bit the queries bench generates; and the values
 * oiio_replay's TextureSystem returns equal, within 1e-6, what bench's shim
 * returns for the same queries and the settings the manifest names — so
 * the replay times the same lookups bench did. Garbled, truncated and
 * missing inputs exit 1 with a message; usage errors 2. No timing is
 * asserted.
 */
#define _POSIX_C_SOURCE 200809L
#include "bench.h"
#include "check.h"

#include <cjson/cJSON.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>

enum { N = 256, SIZE = 64 };

static const char *texsample, *replay, *dir;

/* A shell command in the output directory, stdout/stderr to out.txt/err.txt;
 * returns its exit status. */
static int sh(const char *fmt, ...)
{
    char cmd[4096], body[3072];
    va_list ap;
    int st;
    va_start(ap, fmt);
    vsnprintf(body, sizeof body, fmt, ap);
    va_end(ap);
    snprintf(cmd, sizeof cmd, "cd '%s' && %s >out.txt 2>err.txt", dir, body);
    st = system(cmd);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* A file of the output directory, NUL-terminated; *len gets its size. */
static char *slurp(const char *name, size_t *len)
{
    char p[1024];
    snprintf(p, sizeof p, "%s/%s", dir, name);
    return check_slurp(p, len);
}

static int contains(const char *file, const char *what)
{
    char *s = slurp(file, NULL);
    int yes = s && strstr(s, what) != NULL;
    free(s);
    return yes;
}

static float le_float(const unsigned char *p)
{
    uint32_t u = (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
    float f;
    memcpy(&f, &u, 4);
    return f;
}

static const cJSON *item(const cJSON *o, const char *k)
{
    return cJSON_GetObjectItemCaseSensitive(o, k);
}

static const char *str(const cJSON *o, const char *k)
{
    const cJSON *v = item(o, k);
    return cJSON_IsString(v) ? v->valuestring : "";
}

static double num(const cJSON *o, const char *k)
{
    const cJSON *v = item(o, k);
    return cJSON_IsNumber(v) ? v->valuedouble : -1.0;
}

static int set_index(const char *name)
{
    int k;
    for (k = 0; k < BENCH_SET_COUNT; ++k)
        if (strcmp(name, bench_set_names[k]) == 0) return k;
    return -1;
}

static void usage_errors(void)
{
    CHECK(sh("'%s' --help", replay) == 0, "--help exits 0");
    CHECK(contains("out.txt", "usage: oiio_replay"), "help text");
    CHECK(sh("'%s'", replay) == 2, "no directory exits 2");
    CHECK(sh("'%s' save --runs 0", replay) == 2, "--runs 0 exits 2");
    CHECK(sh("'%s' save --frobnicate", replay) == 2, "unknown option exits 2");
    CHECK(contains("err.txt", "--frobnicate"), "the message names the option");
    CHECK(sh("'%s' bench --save", texsample) == 2, "bench --save without a directory exits 2");
    CHECK(sh("touch afile && '%s' bench --size 16 --queries 8 --runs 1 --threads 1 --sets magnify "
             "--formats float --filters nearest --save afile/sub",
             texsample) == 1,
          "bench --save into a path it cannot create exits 1");
    CHECK(contains("err.txt", "afile/sub"), "the message names the directory");
}

static void save_and_replay(void)
{
    int rc;
    rc = sh("rm -rf save dump && '%s' bench --quick --size %d --queries %d --runs 1 --save save",
            texsample, SIZE, N);
    CHECK(rc == 0, "bench --save exits 0 (got %d)", rc);
    rc = sh("'%s' save --runs 1 --dump dump", replay);
    CHECK(rc == 0, "oiio_replay exits 0 (got %d)", rc);
    CHECK(contains("out.txt", "ratio replay"), "the replay prints its table");
    CHECK(contains("out.txt", "(none evicted)"), "no tile evicted");
    CHECK(contains("out.txt", "not replayed (no OIIO twin): blinn-newell ewa"),
          "filters without a twin are named as skipped");
}

/* The manifest's own words, checked against what bench is known to do. */
static void manifest_and_query_files(void)
{
    static const char *const fields[6] = {"s", "t", "dsdx", "dtdx", "dsdy", "dtdy"};
    sample_query *want = malloc(N * sizeof *want);
    char *text = slurp("save/manifest.json", NULL), path[256];
    cJSON *root = text ? cJSON_Parse(text) : NULL;
    const cJSON *qf, *x, *sets, *f;
    int k, nsets = 0, ntwins = 0, nres = 0;
    free(text);
    CHECK(root != NULL, "manifest.json parses");
    if (!root || !want) goto done;
    CHECK(num(root, "manifest_version") == 1, "manifest_version");
    CHECK(num(root, "texture_size") == SIZE && num(root, "queries") == N, "size and count");
    qf = item(root, "query_file");
    CHECK(strcmp(str(qf, "byte_order"), "little-endian") == 0 &&
              strcmp(str(qf, "scalar"), "float32") == 0,
          "little-endian float32");
    CHECK(num(qf, "record_bytes") == (double)sizeof(sample_query), "record = sizeof(sample_query)");
    CHECK(cJSON_GetArraySize(item(qf, "fields")) == 6, "six fields");
    for (k = 0; k < 6; ++k) {
        const cJSON *v = cJSON_GetArrayItem(item(qf, "fields"), k);
        CHECK(cJSON_IsString(v) && strcmp(v->valuestring, fields[k]) == 0,
              "field %d is %s, sample_query's order", k, fields[k]);
    }
    /* The member order of sample_query, which the file claims to follow. */
    CHECK(offsetof(sample_query, t) == 4 && offsetof(sample_query, dsdx) == 8 &&
              offsetof(sample_query, dtdx) == 12 && offsetof(sample_query, dsdy) == 16 &&
              offsetof(sample_query, dtdy) == 20,
          "sample_query layout");

    sets = item(root, "sets");
    cJSON_ArrayForEach(x, sets) {
        const char *name = str(x, "name");
        int s = set_index(name);
        size_t len = 0, i;
        unsigned char *raw;
        nsets++;
        CHECK(s >= 0, "set %s is one of bench's", name);
        if (s < 0) continue;
        CHECK(num(x, "count") == N && num(x, "bytes") == N * 24.0, "%s: count and bytes", name);
        if (bench_set_seeds[s])
            CHECK(num(x, "seed") == bench_set_seeds[s], "%s: seed", name);
        else
            CHECK(cJSON_IsNull(item(x, "seed")), "%s: no seed", name);
        snprintf(path, sizeof path, "save/%s", str(x, "file"));
        raw = (unsigned char *)slurp(path, &len);
        CHECK(raw && len == (size_t)N * 24, "%s: %zu bytes, count x 24 expected", path, len);
        if (raw && len == (size_t)N * 24) {
            int same = 1;
            bench_queries((bench_set)s, SIZE, want, N);
            for (i = 0; i < N; ++i) {
                const float *w = &want[i].s;
                for (k = 0; k < 6; ++k) {
                    float v = le_float(raw + 24 * i + 4 * (size_t)k);
                    same &= memcmp(&v, &w[k], 4) == 0;
                }
            }
            CHECK(same, "%s holds bench's queries bit for bit", path);
        }
        free(raw);
    }
    CHECK(nsets == BENCH_SET_COUNT, "every set saved (%d)", nsets);
    cJSON_ArrayForEach(x, item(root, "formats")) {
        struct stat st;
        snprintf(path, sizeof path, "%s/save/%s", dir, str(x, "oiio_file"));
        CHECK(stat(path, &st) == 0 && st.st_size > 0, "%s kept", path);
    }
    CHECK(cJSON_GetArraySize(item(root, "formats")) == BENCH_FMT_COUNT, "every format");
    cJSON_ArrayForEach(f, item(root, "filters")) ntwins += cJSON_IsObject(item(f, "oiio"));
    CHECK(cJSON_GetArraySize(item(root, "filters")) == 7 && ntwins == 5, "7 filters, 5 twins");
    cJSON_ArrayForEach(x, item(root, "results")) {
        const cJSON *o = item(x, "oiio");
        nres++;
        CHECK(num(item(x, "ours"), "median") > 0, "our timing");
        if (cJSON_IsObject(o))
            CHECK(num(o, "median") > 0 && num(x, "ratio") > 0, "OIIO timing and ratio");
    }
    CHECK(nres == BENCH_SET_COUNT * BENCH_FMT_COUNT * 7, "one result per set x format x filter");
done:
    cJSON_Delete(root);
    free(want);
}

/* The shim options whose TextureOpt (as the shim describes it) is the one
 * the manifest names. Returns 0 if there is one. */
static int shim_opts(const cJSON *oiio, oiio_ts_opts *o)
{
    int m, ws, wt;
    oiio_ts_opts_init(o);
    o->max_aniso = (int)num(oiio, "anisotropic");
    o->conservative = cJSON_IsTrue(item(oiio, "conservative_filter"));
    for (m = 0; m < OIIO_TS_MODE_COUNT; ++m)
        for (ws = 0; ws < SAMPLE_WRAP_COUNT; ++ws)
            for (wt = 0; wt < SAMPLE_WRAP_COUNT; ++wt) {
                oiio_ts_textureopt d;
                o->mode = (oiio_ts_mode)m;
                o->wrap_s = (sample_wrap)ws;
                o->wrap_t = (sample_wrap)wt;
                if (oiio_ts_describe(o, &d) == 0 && strcmp(d.interpmode, str(oiio, "interpmode")) == 0 &&
                    strcmp(d.mipmode, str(oiio, "mipmode")) == 0 &&
                    strcmp(d.swrap, str(oiio, "swrap")) == 0 &&
                    strcmp(d.twrap, str(oiio, "twrap")) == 0 &&
                    d.anisotropic == (int)num(oiio, "anisotropic"))
                    return 0;
            }
    return -1;
}

/* oiio_replay's lookups against the shim's, query by query. */
static void replay_values(void)
{
    char *text = slurp("save/manifest.json", NULL), path[512], err[512];
    cJSON *root = text ? cJSON_Parse(text) : NULL;
    oiio_ts *ts = oiio_ts_create(0);
    sample_query *q = malloc(N * sizeof *q);
    float *ours = malloc(N * 4 * sizeof *ours);
    const cJSON *set, *fmt, *flt;
    int compared = 0;
    free(text);
    CHECK(root && ts && q && ours, "setup");
    if (!root || !ts || !q || !ours) goto done;
    cJSON_ArrayForEach(fmt, item(root, "formats")) {
        oiio_ts_tex *tex;
        snprintf(path, sizeof path, "%s/save/%s", dir, str(fmt, "oiio_file"));
        tex = oiio_ts_open(ts, path, err, sizeof err);
        CHECK(tex != NULL, "%s", err);
        if (!tex) continue;
        cJSON_ArrayForEach(set, item(root, "sets")) {
            int s = set_index(str(set, "name"));
            if (s < 0) continue;
            /* The saved queries are bench's (checked above). */
            bench_queries((bench_set)s, SIZE, q, N);
            cJSON_ArrayForEach(flt, item(root, "filters")) {
                const cJSON *oiio = item(flt, "oiio");
                oiio_ts_opts o;
                size_t len = 0, i;
                unsigned char *theirs;
                double worst = 0.0;
                if (!cJSON_IsObject(oiio)) continue;
                CHECK(shim_opts(oiio, &o) == 0, "%s: the shim can set what the manifest says",
                      str(flt, "name"));
                CHECK(oiio_ts_sample(ts, tex, &o, q, N, ours, err, sizeof err) == 0, "%s", err);
                snprintf(path, sizeof path, "dump/%s_%s_%s.rgba", str(set, "name"),
                         str(fmt, "name"), str(flt, "name"));
                theirs = (unsigned char *)slurp(path, &len);
                CHECK(theirs && len == (size_t)N * 16, "%s: %zu bytes", path, len);
                if (theirs && len == (size_t)N * 16) {
                    for (i = 0; i < (size_t)N * 4; ++i) {
                        double d = fabs((double)le_float(theirs + 4 * i) - (double)ours[i]);
                        if (!(d <= worst)) worst = d; /* NaN sticks */
                    }
                    CHECK(worst <= 1e-6, "%s: replay and shim differ by %g", path, worst);
                    compared++;
                }
                free(theirs);
            }
        }
    }
    CHECK(compared == BENCH_SET_COUNT * BENCH_FMT_COUNT * 5, "%d lookups compared", compared);
done:
    cJSON_Delete(root);
    oiio_ts_destroy(ts);
    free(q);
    free(ours);
}

static void bad_inputs(void)
{
    int rc;
    CHECK(sh("'%s' no-such-dir", replay) == 1, "a missing directory exits 1");
    CHECK(contains("err.txt", "no-such-dir"), "the message names it");

    rc = sh("rm -rf bad && mkdir bad && head -c 700 save/manifest.json >bad/manifest.json && "
            "'%s' bad",
            replay);
    CHECK(rc == 1, "a cut manifest exits 1 (got %d)", rc);
    CHECK(contains("err.txt", "manifest.json: not valid JSON"), "and says where");

    rc = sh("rm -rf bad && mkdir bad && printf '%%0100000d' 0 | tr 0 '[' >bad/manifest.json && "
            "'%s' bad",
            replay);
    CHECK(rc == 1, "deeply nested garbage exits 1 (got %d)", rc);
    CHECK(contains("err.txt", "nested too deeply"), "without recursing without bound");

    rc = sh("rm -rf bad && mkdir bad && cp save/manifest.json save/*.bin bad/ && "
            "truncate -s -5 bad/queries_minify.bin && '%s' bad",
            replay);
    CHECK(rc == 1, "a truncated query file exits 1 (got %d)", rc);
    CHECK(contains("err.txt", "queries_minify.bin") && contains("err.txt", "truncated"),
          "and names the file");

    rc = sh("rm -rf bad && mkdir bad && cp save/*.bin bad/ && "
            "sed 's/MipModeTrilinear/MipModeTrilinaer/' save/manifest.json >bad/manifest.json && "
            "'%s' bad",
            replay);
    CHECK(rc == 1 && contains("err.txt", "MipModeTrilinaer"), "an unknown mip mode exits 1");

    rc = sh("rm -rf bad && mkdir bad && cp save/*.bin bad/ && "
            "sed 's/\"periodic\"/\"periodc\"/' save/manifest.json >bad/manifest.json && '%s' bad",
            replay);
    CHECK(rc == 1 && contains("err.txt", "periodc"),
          "an unknown wrap name exits 1 (not OIIO's silent default)");

    rc = sh("rm -rf bad && mkdir bad && cp save/* bad/ && "
            "sed 's/bench_half.exr/missing.exr/' save/manifest.json >bad/manifest.json && "
            "'%s' bad",
            replay);
    CHECK(rc == 1 && contains("err.txt", "missing.exr"), "a missing texture file exits 1");
}

int main(int argc, char **argv)
{
    if (argc != 4) {
        fprintf(stderr, "usage: bench_replay TEXSAMPLE OIIO_REPLAY OUTDIR\n");
        return 2;
    }
    texsample = argv[1];
    replay = argv[2];
    dir = argv[3];
    mkdir(dir, 0777);
    RUN(save_and_replay);
    RUN(usage_errors);
    RUN(manifest_and_query_files);
    RUN(replay_values);
    RUN(bad_inputs);
    return check_finish();
}
