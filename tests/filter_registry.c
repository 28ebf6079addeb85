/*
 * The tools' filter registry (tools/filters.h):
 *   - names are unique, every pick's name reads back to the same pick, and
 *     an entry named by the library carries the library's name for its
 *     enum (sample_filter_name / sample_footprint_name);
 *   - every old spelling reads as the entry it named, and a few names map
 *     to exact sampler and OpenImageIO settings;
 *   - each tool's --help lists exactly the registry names that tool can
 *     run, marks its defaults, and the tool runs every name it lists (a
 *     tiny run each: lookup, bench, freq, compare), aliases included.
 * Usage: filter_registry TEXSAMPLE WORKDIR
 */
#define _POSIX_C_SOURCE 200809L
#include "check.h"
#include "filters.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

static const char *exe, *dir;

static int run(const char *args)
{
    char cmd[8192];
    snprintf(cmd, sizeof cmd, "mkdir -p %s && cd %s && %s %s >out.txt 2>err.txt", dir, dir, exe, args);
    return check_shell(cmd);
}

/* Names are at most TOOL_FILTER_NAME_MAX − 1 = 47 characters: the commands
 * below print them with %.47s, which also tells GCC their length. */
_Static_assert(TOOL_FILTER_NAME_MAX == 48, "the %.47s below");

/* Every pick the registry has: each entry, then each OIIO twin, then each
 * OpenGL twin. */
static int all_picks(tool_pick *out)
{
    int k, n = 0;
    for (k = 0; k < tool_filter_count; ++k) out[n++] = (tool_pick){&tool_filters[k], 0, 0};
    for (k = 0; k < tool_filter_count; ++k)
        if (tool_filters[k].oiio.twin) out[n++] = (tool_pick){&tool_filters[k], 1, 0};
    for (k = 0; k < tool_filter_count; ++k)
        if (tool_filter_gl_twin(&tool_filters[k])) out[n++] = (tool_pick){&tool_filters[k], 0, 1};
    return n;
}

static void names(void)
{
    tool_pick p[64], q;
    char a[TOOL_FILTER_NAME_MAX], b[TOOL_FILTER_NAME_MAX];
    int n = all_picks(p), i, j;
    CHECK(n > 10, "%d picks", n);
    for (i = 0; i < n; ++i) {
        tool_pick_name(&p[i], a, sizeof a);
        CHECK(strlen(a) > 0 && strlen(a) + 1 < sizeof a && !strchr(a, ','), "name '%s'", a);
        CHECK(tool_pick_find(a, &q, NULL) == 0 && q.f == p[i].f && q.oiio == p[i].oiio &&
                  q.gl == p[i].gl,
              "'%s' reads back as itself", a);
        CHECK(strcmp(a, "all") != 0, "'all' is the tools' word for their defaults");
        for (j = 0; j < i; ++j)
            CHECK(strcmp(a, tool_pick_name(&p[j], b, sizeof b)) != 0, "'%s' twice", a);
        for (j = 0; j < tool_filter_alias_count; ++j)
            CHECK(strcmp(a, tool_filter_aliases[j].alias) != 0, "alias '%s' is a name", a);
    }
    /* Named by the library: the name parses back to the enum it names. */
    for (i = 0; i < tool_filter_count; ++i) {
        const tool_filter *f = &tool_filters[i];
        const char *nm = tool_filter_name(f);
        if (f->name) continue;
        if (f->footprint != SAMPLE_FOOTPRINT_NONE)
            CHECK(sample_footprint_parse(nm) == (int)f->footprint, "'%s' is the footprint's name", nm);
        else
            CHECK(sample_filter_parse(nm) == (int)f->min, "'%s' is the min filter's name", nm);
    }
    CHECK(tool_pick_find("oiio-blinn-newell", &q, NULL) < 0, "no twin, no oiio- name");
    /* OpenGL has the six GL filters and GL_TEXTURE_MAX_ANISOTROPY, nothing
     * else (GL 4.6 §8.14). */
    CHECK(tool_pick_find("gl-trilinear", &q, NULL) == 0 && q.gl && !q.oiio, "gl-trilinear");
    CHECK(tool_pick_find("gl-aniso2", &q, NULL) == 0 && q.gl && q.f->max_aniso == 2.0f, "gl-aniso2");
    CHECK(tool_pick_find("gl-aniso4", &q, NULL) == 0 && q.f->max_aniso == 4.0f, "gl-aniso4");
    CHECK(tool_pick_find("gl-nearest_mipmap_nearest", &q, NULL) == 0, "gl-nearest_mipmap_nearest");
    CHECK(tool_pick_find("gl-ewa", &q, NULL) < 0 && tool_pick_find("gl-blinn-newell", &q, NULL) < 0 &&
              tool_pick_find("gl-bicubic-bspline", &q, NULL) < 0 &&
              tool_pick_find("gl-cubic_mipmap_linear", &q, NULL) < 0,
          "no GL twin for footprint and cubic filters");
    CHECK(tool_pick_find("nope", &q, NULL) < 0 && tool_pick_find("", &q, NULL) < 0, "unknown names");
}

/* Alias and canonical name read as the same pick. */
static void same(const char *alias, const char *name)
{
    tool_pick a, b;
    const char *canon = NULL;
    CHECK(tool_pick_find(alias, &a, &canon) == 1, "'%s' is an alias", alias);
    CHECK(canon && strcmp(canon, name) == 0, "'%s' prints as '%s', not '%s'", alias, name, canon ? canon : "");
    CHECK(tool_pick_find(name, &b, NULL) == 0, "'%s' is a name", name);
    CHECK(a.f == b.f && a.oiio == b.oiio, "'%s' and '%s' are one entry", alias, name);
}

static void aliases(void)
{
    int k;
    same("blinn_newell", "blinn-newell");
    same("bn-jacobian", "blinn-newell");
    same("bn-corners", "blinn-newell-corners");
    same("bn-corners-area", "blinn-newell-corners-area");
    same("nmn", "nearest_mipmap_nearest");
    same("bicubic", "bicubic-bspline");
    same("oiio", "oiio-aniso16");
    same("oiio_aniso", "oiio-aniso16");
    same("oiio_trilinear", "oiio-trilinear");
    for (k = 0; k < tool_filter_alias_count; ++k)
        same(tool_filter_aliases[k].alias, tool_filter_aliases[k].name);
}

/* The sampler a name sets, from OpenGL's initial state. */
static sample_sampler settings(const char *name)
{
    const tool_filter *f = tool_filter_by_name(name);
    sample_sampler s;
    sample_sampler_init(&s);
    CHECK(f != NULL, "'%s' is an entry", name);
    if (f) tool_filter_apply(f, &s);
    CHECK(sample_sampler_validate(&s) == SAMPLE_OK, "'%s' is a valid sampler", name);
    return s;
}

static void mapping(void)
{
    sample_sampler s;
    const tool_filter *f;
    oiio_ts_opts o;
    s = settings("trilinear");
    CHECK(s.min_filter == SAMPLE_LINEAR_MIPMAP_LINEAR && s.mag_filter == SAMPLE_LINEAR &&
              s.footprint == SAMPLE_FOOTPRINT_NONE && s.max_anisotropy == 1.0f && s.options == 0,
          "trilinear");
    s = settings("nearest");
    CHECK(s.min_filter == SAMPLE_NEAREST && s.mag_filter == SAMPLE_NEAREST && s.footprint == SAMPLE_FOOTPRINT_NONE,
          "nearest");
    s = settings("aniso16");
    CHECK(s.min_filter == SAMPLE_LINEAR_MIPMAP_LINEAR && s.footprint == SAMPLE_FOOTPRINT_ANISOTROPIC &&
              s.max_anisotropy == 16.0f,
          "aniso16");
    s = settings("bicubic-bspline");
    CHECK(s.min_filter == SAMPLE_CUBIC && s.mag_filter == SAMPLE_CUBIC && s.cubic == SAMPLE_CUBIC_BSPLINE,
          "bicubic-bspline");
    s = settings("cubic_mipmap_linear");
    CHECK(s.min_filter == SAMPLE_CUBIC_MIPMAP_LINEAR && s.mag_filter == SAMPLE_CUBIC &&
              s.cubic == SAMPLE_CUBIC_CATMULL_ROM,
          "cubic_mipmap_linear");
    s = settings("blinn-newell-corners-area");
    CHECK(s.footprint == SAMPLE_FOOTPRINT_BLINN_NEWELL && s.options == SAMPLE_OPT_BN_AREA_WEIGHT,
          "blinn-newell-corners-area");
    f = tool_filter_by_name("blinn-newell-corners-area");
    CHECK(f && f->corners, "the corner mode passes corners");
    f = tool_filter_by_name("blinn-newell");
    CHECK(f && !f->corners && !f->oiio.twin, "blinn-newell: Jacobian, no twin");
    /* The twins: OIIO's bicubic is the B-spline; aniso16's is MipModeAniso
     * with 16 probes; trilinear's keeps the shim's anisotropic. */
    f = tool_filter_by_name("bicubic-bspline");
    CHECK(f && f->oiio.twin && f->oiio.mode == OIIO_TS_BICUBIC, "bicubic-bspline twin");
    memset(&o, 0, sizeof o);
    o.max_aniso = 7;
    f = tool_filter_by_name("aniso16");
    if (f) tool_filter_oiio_opts(f, &o);
    CHECK(f && f->oiio.twin && o.mode == OIIO_TS_ANISO && o.max_aniso == 16, "aniso16 twin");
    o.max_aniso = 7;
    f = tool_filter_by_name("trilinear");
    if (f) tool_filter_oiio_opts(f, &o);
    CHECK(f && o.mode == OIIO_TS_TRILINEAR && o.max_aniso == 7, "trilinear twin");
}

/* The registry names a --help lists ("  * name  label" lines, '*' marking
 * the defaults) after the first `after`: every line whose first word is a
 * registry name. Returns the count. */
static int help_names(const char *help, const char *after, char names[][TOOL_FILTER_NAME_MAX], int *dflt, int max)
{
    const char *p = help ? strstr(help, after) : NULL;
    int n = 0;
    tool_pick q;
    if (!p) return 0;
    while ((p = strchr(p, '\n')) && n < max) {
        char nm[TOOL_FILTER_NAME_MAX];
        int star;
        ++p;
        p += strspn(p, " ");
        star = *p == '*';
        if (sscanf(p + star, " %47s", nm) != 1 || tool_pick_find(nm, &q, NULL) != 0) continue;
        snprintf(names[n], TOOL_FILTER_NAME_MAX, "%s", nm);
        dflt[n++] = star;
    }
    return n;
}

/* The tool's --help lists exactly the picks allowed under `accept`. */
static int check_help(const char *tool, const char *after, unsigned accept,
                      char names[][TOOL_FILTER_NAME_MAX], int *dflt)
{
    tool_pick p[64], q;
    char cmd[256], *help, nm[TOOL_FILTER_NAME_MAX];
    int n, i, j, want = 0, ndflt = 0;
    snprintf(cmd, sizeof cmd, "%s --help", tool);
    CHECK(run(cmd) == 0, "%s --help exits 0", tool);
    help = check_slurp_in(dir, "out.txt");
    n = help_names(help, after, names, dflt, 64);
    free(help);
    for (i = 0, j = all_picks(p); i < j; ++i) {
        int k, found = 0;
        if (!tool_pick_allowed(&p[i], accept)) continue;
        ++want;
        tool_pick_name(&p[i], nm, sizeof nm);
        for (k = 0; k < n; ++k) found |= strcmp(names[k], nm) == 0;
        CHECK(found, "%s --help lists %s", tool, nm);
    }
    for (i = 0; i < n; ++i) {
        CHECK(tool_pick_find(names[i], &q, NULL) == 0 && tool_pick_allowed(&q, accept),
              "%s lists '%s', which it cannot run", tool, names[i]);
        ndflt += dflt[i];
    }
    CHECK(n == want, "%s --help lists %d names, the registry has %d for it", tool, n, want);
    CHECK(!strcmp(tool, "lookup") || ndflt > 3, "%s marks its defaults (%d)", tool, ndflt);
    return n;
}

static void lookup_runs(void)
{
    const float tex[4 * 16] = {0};
    const float q[6] = {0.3f, 0.6f, 0.5f, 0.1f, 0.0f, 0.25f};
    char names[64][TOOL_FILTER_NAME_MAX], args[512], *a, *b;
    int dflt[64], n, k;
    FILE *f;
    char p[1024];
    snprintf(p, sizeof p, "mkdir -p %s", dir);
    CHECK(system(p) == 0, "mkdir");
    snprintf(p, sizeof p, "%s/tex.raw", dir);
    if ((f = fopen(p, "wb"))) {
        fwrite(tex, sizeof tex, 1, f);
        fclose(f);
    }
    snprintf(p, sizeof p, "%s/q.raw", dir);
    if ((f = fopen(p, "wb"))) {
        fwrite(q, sizeof q, 1, f);
        fclose(f);
    }
    n = check_help("lookup", "Registry filters", 0, names, dflt);
    for (k = 0; k < n; ++k) {
        snprintf(args, sizeof args, "lookup --raw tex.raw --w 4 --h 4 --queries q.raw --filter %.47s", names[k]);
        CHECK(run(args) == 0, "lookup --filter %s", names[k]);
    }
    /* An alias samples as its entry and says which it is. */
    CHECK(run("lookup --raw tex.raw --w 4 --h 4 --queries q.raw --filter nmn --stats") == 0, "nmn");
    a = check_slurp_in(dir, "err.txt");
    CHECK(a && strstr(a, "'nmn' is read as 'nearest_mipmap_nearest'"), "alias note: %s", a ? a : "");
    CHECK(run("lookup --raw tex.raw --w 4 --h 4 --queries q.raw --filter nearest_mipmap_nearest --stats") == 0,
          "nearest_mipmap_nearest");
    b = check_slurp_in(dir, "err.txt");
    CHECK(a && b && strstr(a, strstr(b, "queries") ? strstr(b, "queries") : "?"), "same texels read");
    free(a);
    free(b);
    CHECK(run("lookup --raw tex.raw --w 4 --h 4 --queries q.raw --filter nope") == 2, "unknown: exit 2");
    CHECK(run("lookup --raw tex.raw --w 4 --h 4 --queries q.raw --filter blinn-newell-corners") == 2,
          "corner entry without a tool's corners: exit 2");
}

/* The n names joined by commas into buf (each tool takes a list): one run
 * per tool checks that it accepts every name its help lists, instead of a
 * start-up per name (each loads OpenImageIO). The OpenGL rows are left to
 * tests/backends.c: Mesa's allocations at exit are not ours to report, and
 * only that test runs without leak detection. */
static const char *join_names(char names[][TOOL_FILTER_NAME_MAX], int n, char *buf, size_t size)
{
    size_t used = 0;
    int k;
    buf[0] = '\0';
    for (k = 0; k < n && used < size; ++k)
        if (strncmp(names[k], "gl-", 3) != 0)
            used += (size_t)snprintf(buf + used, size - used, "%s%s", used ? "," : "", names[k]);
    CHECK(used < size, "the joined names fit");
    return buf;
}

static void bench_runs(void)
{
    char names[64][TOOL_FILTER_NAME_MAX], args[4096], list[3072], *out;
    int dflt[64], n;
    n = check_help("bench", "\nFilters:\n", 0, names, dflt);
    snprintf(args, sizeof args,
             "bench --filters %s --size 16 --queries 16 --runs 1 --threads 1 --sets magnify "
             "--formats float --no-oiio --json -", join_names(names, n, list, sizeof list));
    CHECK(run(args) == 0, "bench --filters %s", list);
    CHECK(run("bench --filters bicubic --size 16 --queries 16 --runs 1 --threads 1 --sets magnify "
              "--formats float --no-oiio --json -") == 0, "bench --filters bicubic");
    out = check_slurp_in(dir, "out.txt");
    CHECK(out && strstr(out, "\"bicubic-bspline\"") && !strstr(out, "\"bicubic\""),
          "the JSON names the canonical entry");
    free(out);
    CHECK(run("bench --filters oiio-trilinear") == 2, "bench takes twins with their filter only");
}

static void freq_runs(void)
{
    char names[64][TOOL_FILTER_NAME_MAX], args[4096], list[3072], *csv;
    int dflt[64], n, k;
    tool_pick q;
    unsigned accept = 0;
    CHECK(run("freq --help") == 0, "freq --help");
    csv = check_slurp_in(dir, "out.txt");
    /* The shim is in the build when freq lists a twin; EGL when it lists
     * an OpenGL one. */
    if (csv && strstr(csv, "oiio-trilinear")) accept = TOOL_PICK_OIIO;
    if (csv && strstr(csv, "gl-trilinear")) accept |= TOOL_PICK_GL;
    free(csv);
    n = check_help("freq", "Filters (", accept, names, dflt);
    snprintf(args, sizeof args,
             "freq --filters %s --quick --m 2 --theta 0 --r 1 --size 16 --step 0.5 --fmax 1 "
             "--width 2 --phases 2 --no-png --out f", join_names(names, n, list, sizeof list));
    CHECK(run(args) == 0, "freq --filters %s", list);
    for (k = 0; k < n; ++k) {
        CHECK(tool_pick_find(names[k], &q, NULL) == 0, "%s", names[k]);
        CHECK(!dflt[k] || !q.f->corners, "freq defaults hold no corner entry");
    }
    CHECK(run("freq --filters blinn_newell --quick --m 2 --theta 0 --r 1 --size 16 --step 0.5 --fmax 1 "
              "--width 2 --phases 2 --no-png --out f") == 0, "freq --filters blinn_newell");
    csv = check_slurp_in(dir, "f/freq.csv");
    CHECK(csv && strstr(csv, "blinn-newell") && !strstr(csv, "blinn_newell"), "freq.csv: the canonical name");
    free(csv);
}

static void compare_runs(void)
{
    char names[64][TOOL_FILTER_NAME_MAX], args[4096], list[3072], *csv;
    int dflt[64], n;
    unsigned accept = TOOL_PICK_OIIO | TOOL_PICK_CORNERS;
    CHECK(run("compare --help") == 0, "compare --help");
    csv = check_slurp_in(dir, "out.txt");
    if (csv && strstr(csv, "gl-trilinear")) accept |= TOOL_PICK_GL;
    free(csv);
    n = check_help("compare", "--configs", accept, names, dflt);
    snprintf(args, sizeof args, "compare --scene plane --size 8 --truth-samples 2 --threads 1 --configs %s --out c",
             join_names(names, n, list, sizeof list));
    CHECK(run(args) == 0, "compare --configs %s", list);
    CHECK(run("compare --scene plane --size 8 --truth-samples 2 --threads 1 --configs bn-corners,nmn "
              "--out c") == 0, "compare --configs bn-corners,nmn");
    csv = check_slurp_in(dir, "c/results.csv");
    CHECK(csv && strstr(csv, "plane,nearest_mipmap_nearest,") && strstr(csv, "plane,blinn-newell-corners,") &&
              !strstr(csv, ",nmn,"),
          "results.csv: canonical names, registry order");
    CHECK(csv && strstr(csv, "nearest_mipmap_nearest") < strstr(csv, "blinn-newell-corners"), "registry order");
    free(csv);
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: filter_registry TEXSAMPLE WORKDIR\n");
        return 2;
    }
    exe = argv[1];
    dir = argv[2];
    RUN(names);
    RUN(aliases);
    RUN(mapping);
    RUN(lookup_runs);
    RUN(bench_runs);
    RUN(freq_runs);
    RUN(compare_runs);
    return check_finish();
}
