/*
 * texsample bench, end to end but small: --help, usage errors (exit 2), and
 * a tiny --quick run whose JSON must parse and hold one result per (set,
 * format, filter, engine, thread count) asked for, positive speeds, the
 * exact texel counts of the filters whose cost is fixed (nearest 1,
 * bilinear 4, bicubic 16 on every query), and ratios exactly where an OIIO
 * twin exists; the instruction set it ran on (LIBSAMPLE_ISA) in the table
 * and the JSON (libsample's rows through --cache-mb's texture system on
 * OpenImageIO's file of each format); a tiny --env run's table; and a tiny --volume run (a row
 * per filter, texel counts of nearest 1 and trilinear 16, OpenImageIO's two
 * texture3d rows). No speed is asserted.
 */
#define _POSIX_C_SOURCE 200809L
#include "check.h"

#include <cjson/cJSON.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>

static const char *exe, *dir;

static int run(const char *args)
{
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "cd '%s' && '%s' bench %s >out.txt 2>err.txt", dir, exe, args);
    return check_shell(cmd);
}

static void help_and_usage(void)
{
    char *out;
    CHECK(run("--help") == 0, "--help exits 0");
    out = check_slurp_in(dir, "out.txt");
    CHECK(out && strstr(out, "usage: texsample bench") != NULL, "help text");
    free(out);
    CHECK(run("--frobnicate") == 2, "unknown option exits 2");
    CHECK(run("--runs 0") == 2, "--runs 0 exits 2");
    CHECK(run("--sets magnify,nope") == 2, "unknown set exits 2");
    out = check_slurp_in(dir, "err.txt");
    CHECK(out && strstr(out, "nope") != NULL, "the message names the bad set");
    free(out);
    CHECK(run("--json") == 2, "--json without a file exits 2");
    CHECK(run("--size 16 --queries 8 --runs 1 --threads 1 --no-oiio --sets magnify "
              "--formats float --filters nearest --json /nonexistent-dir/r.json") == 1,
          "an unwritable --json exits 1");
}

static double num(const cJSON *o, const char *k)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, k);
    return cJSON_IsNumber(v) ? v->valuedouble : -1.0;
}

static const char *str(const cJSON *o, const char *k)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, k);
    return cJSON_IsString(v) ? v->valuestring : "";
}

/* bench --env: a tiny run prints a row for each set × filter × map
 * (lat-long, cube, OIIO's lat-long where the build has OIIO); --env with
 * an option it does not take is a usage error. */
static void tiny_env(void)
{
    char *out;
    CHECK(run("--env --json x.json") == 2, "--env --json exits 2");
    CHECK(run("--env --size 64 --queries 512 --runs 1 --threads 2 --filters nearest,ewa") == 0, "--env run");
    out = check_slurp_in(dir, "out.txt");
    CHECK(out && strstr(out, "env-random       ewa                        cube") &&
              strstr(out, "env-reflection   nearest                    latlong") &&
              strstr(out, "env-reflection   oiio-nearest               latlong"),
          "the table: %s", out ? out : "(none)");
    free(out);
}

static void tiny_json(void)
{
    char *text;
    cJSON *root, *res, *x;
    int n = 0, rc;
    /* With --cache-mb: libsample's rows through a texture system that
     * opened OpenImageIO's file of each format, beside OIIO's rows on it. */
    rc = run("--quick --size 32 --queries 300 --runs 1 --threads 2 --batch 64 "
             "--sets magnify,plane --formats float,srgb8 --cache-mb 0.05 --json r.json");
    CHECK(rc == 0, "tiny run exits 0 (got %d)", rc);
    text = check_slurp_in(dir, "out.txt");
    CHECK(text && strstr(text, "\nlibsample ISA: ") != NULL, "the table names the instruction set");
    free(text);
    text = check_slurp_in(dir, "err.txt");
    CHECK(text && strstr(text, "libsample cache: tiles read ") && !strstr(text, "tiles read 0,") &&
              strstr(strstr(text, "libsample cache: ") + 1, "libsample cache: "),
          "each format's texture system read tiles: %s", text ? text : "");
    free(text);
    text = check_slurp_in(dir, "r.json");
    CHECK(text != NULL, "r.json written");
    if (!text) return;
    root = cJSON_Parse(text);
    free(text);
    CHECK(root != NULL, "r.json parses");
    if (!root) return;
    CHECK(num(root, "queries") == 300 && num(root, "size") == 32 && num(root, "runs") == 1,
          "parameters recorded");
    CHECK(strstr(str(root, "command"), "--quick") != NULL, "command recorded");
    CHECK(cJSON_IsNumber(cJSON_GetObjectItemCaseSensitive(root, "load_before")) &&
              cJSON_IsNumber(cJSON_GetObjectItemCaseSensitive(root, "load_after")),
          "load averages recorded");
    res = cJSON_GetObjectItemCaseSensitive(root, "results");
    CHECK(cJSON_IsArray(res), "results array");
    cJSON_ArrayForEach(x, res) {
        const char *filter = str(x, "filter"), *engine = str(x, "engine"), *set = str(x, "set");
        const cJSON *sps = cJSON_GetObjectItemCaseSensitive(x, "samples_per_s");
        const cJSON *ratio = cJSON_GetObjectItemCaseSensitive(x, "ratio_vs_oiio");
        double tps = num(x, "texels_per_sample");
        int ours = strcmp(engine, "libsample") == 0;
        n++;
        CHECK(ours || strcmp(engine, "oiio") == 0, "engine %s", engine);
        CHECK(strcmp(set, "magnify") == 0 || strcmp(set, "plane") == 0, "set %s", set);
        CHECK(num(x, "threads") == 1 || num(x, "threads") == 2, "threads");
        CHECK(num(sps, "median") > 0 && num(sps, "min") <= num(sps, "median") &&
                  num(sps, "median") <= num(sps, "max") && num(sps, "runs") == 1,
              "%s %s speeds ordered", filter, engine);
        if (!ours) {
            CHECK(cJSON_IsNull(cJSON_GetObjectItemCaseSensitive(x, "texels_per_sample")) &&
                      cJSON_IsNull(ratio), "oiio rows have no texel count or ratio");
            continue;
        }
        if (strcmp(filter, "nearest") == 0) CHECK(tps == 1.0, "nearest reads 1 texel: %g", tps);
        if (strcmp(filter, "bilinear") == 0) CHECK(tps == 4.0, "bilinear reads 4: %g", tps);
        if (strcmp(filter, "bicubic-bspline") == 0) CHECK(tps == 16.0, "bicubic-bspline reads 16: %g", tps);
        if (strcmp(filter, "blinn-newell") == 0 || strcmp(filter, "ewa") == 0)
            CHECK(cJSON_IsNull(ratio), "%s has no OIIO twin", filter);
        else
            CHECK(cJSON_IsNumber(ratio) && ratio->valuedouble > 0, "%s has a ratio", filter);
    }
    /* 2 sets × 2 formats × (7 libsample + 5 OIIO filters) × 2 thread counts. */
    CHECK(n == 2 * 2 * 12 * 2, "result count %d", n);
    cJSON_Delete(root);

    /* LIBSAMPLE_ISA reaches the library and the record ("scalar": every
     * build has it). */
    setenv("LIBSAMPLE_ISA", "scalar", 1);
    rc = run("--quick --size 32 --queries 50 --runs 1 --threads 1 --no-oiio --sets minify "
             "--formats half --filters trilinear,ewa --scalar --json -");
    unsetenv("LIBSAMPLE_ISA");
    CHECK(rc == 0, "--json - exits 0");
    text = check_slurp_in(dir, "out.txt");
    root = text ? cJSON_Parse(text) : NULL;
    CHECK(root != NULL, "--json - prints only JSON on stdout");
    res = root ? cJSON_GetObjectItemCaseSensitive(root, "results") : NULL;
    CHECK(cJSON_GetArraySize(res) == 2, "two filters, one thread count, no OIIO");
    CHECK(cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(root, "scalar_path")), "--scalar recorded");
    CHECK(strcmp(str(root, "isa"), "scalar") == 0, "LIBSAMPLE_ISA=scalar recorded: \"%s\"", str(root, "isa"));
    cJSON_Delete(root);
    free(text);
}

/* bench --volume on a 16³ volume: the five rows and the OIIO line; NEAREST
 * reads 1 texel, trilinear 16 (two levels of 8) on either set. */
static void tiny_volume(void)
{
    char *out;
    double a, b, c, d;
    int rc = run("--volume --size 16 --queries 64 --runs 1 --frame 24");
    CHECK(rc == 0, "--volume exits 0 (got %d)", rc);
    out = check_slurp_in(dir, "out.txt");
    CHECK(out != NULL, "table written");
    if (!out) return;
    CHECK(strstr(out, "3D texture 16 x 16 x 16") != NULL, "the volume's size");
    CHECK(strstr(out, "\nnearest ") && strstr(out, "\naniso16 ") && strstr(out, "\nblinn-newell ") &&
              strstr(out, "\newa "), "a row per filter");
    CHECK(sscanf(strstr(out, "\nnearest ") + 9, "%lf %lf %lf %lf", &a, &b, &c, &d) == 4 && b == 1.0 &&
              d == 1.0, "nearest reads 1 texel");
    CHECK(sscanf(strstr(out, "\ntrilinear ") + 11, "%lf %lf %lf %lf", &a, &b, &c, &d) == 4 &&
              b == 16.0 && d == 16.0, "trilinear reads 16 texels");
    CHECK(strstr(out, "\noiio closest ") && strstr(out, "\noiio linear "),
          "OpenImageIO's texture3d rows (timed, or why not)");
    free(out);
    CHECK(run("--volume --size 1024") == 2, "--volume --size over 512 exits 2");
    CHECK(run("--volume --frame 0") == 2, "--frame 0 exits 2");
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: bench_cli TEXSAMPLE OUTDIR\n");
        return 2;
    }
    exe = argv[1];
    dir = argv[2];
    mkdir(dir, 0777);
    RUN(help_and_usage);
    RUN(tiny_json);
    RUN(tiny_env);
    RUN(tiny_volume);
    return check_finish();
}
