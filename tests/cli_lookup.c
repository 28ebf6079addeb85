/*
 * texsample lookup end to end: writes a raw texture, a query file and
 * explicit levels, runs the program, and checks the output file against
 * hand-computed values and against the library called directly. Also the
 * exit codes: 0 success, 1 runtime error, 2 usage error, and the shared
 * command-line syntax. It runs the front program (tools/CMakeLists.txt),
 * which runs the image program for `info`.
 */
#define _XOPEN_SOURCE 700
#include "check.h"
#include "cli_util.h"
#include "sample/sample.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

static char *exe;
static const char *source; /* the source tree: testimages/ */
static char dir[256];

static void put(const char *name, const void *data, size_t n) { cli_put(dir, name, data, n); }

static size_t get(const char *name, void *data, size_t n)
{
    char p[512];
    FILE *f;
    size_t r = 0;
    snprintf(p, sizeof p, "%s/%s", dir, name);
    f = fopen(p, "rb");
    if (f) {
        r = fread(data, 1, n, f);
        fclose(f);
    }
    return r;
}

static int run(const char *args)
{
    char cmd[2048];
    int st;
    snprintf(cmd, sizeof cmd, "cd %s && timeout 10 %s %s >out.txt 2>err.txt", dir, exe, args);
    st = system(cmd);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* 2×2 texture R = 1, 2 / 3, 5; queries at the centre and a texel centre. */
static void lookup_values(void)
{
    const float tex[16] = {1, 0, 0, 1, 2, 0, 0, 1, 3, 0, 0, 1, 5, 0, 0, 1};
    const float q[12] = {0.5f, 0.5f, 0, 0, 0, 0, 0.75f, 0.25f, 0, 0, 0, 0};
    float out[8] = {0};
    put("tex.raw", tex, sizeof tex);
    put("q.raw", q, sizeof q);
    CHECK(run("lookup --raw tex.raw --w 2 --h 2 --queries q.raw --out r.raw --wrap clamp_to_edge") == 0, "exit 0");
    CHECK(get("r.raw", out, sizeof out) == sizeof out, "output size");
    CHECK_EQF(out[0], 2.75f); /* (1+2+3+5)/4 */
    CHECK_EQF(out[4], 2.0f);  /* texel (1, 0) */
    CHECK_EQF(out[7], 1.0f);
    CHECK(run("lookup --raw tex.raw --w 2 --h 2 --queries q.raw --out r.raw --mag nearest --wrap repeat") == 0, "nearest");
    get("r.raw", out, sizeof out);
    CHECK_EQF(out[0], 5.0f); /* u = v = 1 → texel (1, 1) */
}

/* Explicit levels: level 1 of a 4×4 is given as a constant 7, and a query
 * with ρ = 2 texels (λ = 1) under NEAREST_MIPMAP_NEAREST reads it. */
static void explicit_levels(void)
{
    float l0[4 * 4 * 4], l1[2 * 2 * 4], l2[4] = {9, 0, 0, 1}, out[4] = {0};
    const float q[6] = {0.5f, 0.5f, 0.5f, 0, 0, 0.5f}; /* 0.5 × 4 = 2 texels */
    int k;
    for (k = 0; k < 64; ++k) l0[k] = 1.0f;
    for (k = 0; k < 16; ++k) l1[k] = (k % 4 == 0) ? 7.0f : 1.0f;
    put("base.raw", l0, sizeof l0);
    put("lv.1.raw", l1, sizeof l1);
    put("lv.2.raw", l2, sizeof l2);
    put("q2.raw", q, sizeof q);
    CHECK(run("lookup --raw base.raw --w 4 --h 4 --levels lv --queries q2.raw --out r2.raw --min nearest_mipmap_nearest") == 0,
          "levels run");
    get("r2.raw", out, sizeof out);
    CHECK_EQF(out[0], 7.0f);
    CHECK(run("lookup --raw base.raw --w 4 --h 4 --levels lv --queries q2.raw --out r2.raw --min nearest_mipmap_nearest --lod-bias 1") == 0,
          "bias run");
    get("r2.raw", out, sizeof out);
    CHECK_EQF(out[0], 9.0f); /* λ = 2 → level 2 */
}

/* --cube and --latlong: a 1 × 1-face cube whose face f holds f, queried
 * along each axis; a cube's levels from --levels; a 2 × 1 lat-long map
 * (left half 1, right half 2) at +x (s = ¼) and −x (s = ¾); and their
 * usage errors. */
static void environment(void)
{
    float cube[6 * 4], lv0[6 * 4 * 4], lv1[6 * 4], ll[8] = {1, 0, 0, 1, 2, 0, 0, 1}, q[6 * 9], out[6 * 4];
    int f, k;
    memset(q, 0, sizeof q);
    for (f = 0; f < 6; ++f) {
        cube[4 * f] = (float)f;
        cube[4 * f + 1] = cube[4 * f + 2] = 0.0f;
        cube[4 * f + 3] = 1.0f;
        q[9 * f + f / 2] = (f & 1) ? -1.0f : 1.0f;
    }
    put("cube.raw", cube, sizeof cube);
    put("dirs.raw", q, sizeof q);
    CHECK(run("lookup --cube cube.raw --size 1 --queries dirs.raw --out rc.raw") == 0, "cube run");
    CHECK(get("rc.raw", out, sizeof out) == sizeof out, "cube output");
    for (f = 0; f < 6; ++f) CHECK_EQF(out[4 * f], (float)f);
    /* Levels: a 2-face cube whose level 1 holds 10 + f; λ = 1 on every axis. */
    for (k = 0; k < 6 * 4 * 4; ++k) lv0[k] = 0.0f;
    for (f = 0; f < 6; ++f) {
        lv1[4 * f] = 10.0f + (float)f;
        lv1[4 * f + 1] = lv1[4 * f + 2] = 0.0f;
        lv1[4 * f + 3] = 1.0f;
        q[9 * f + 3 + (f / 2 + 1) % 3] = 2.0f; /* dR/dx across the face: ∂s = 1, ρ = 2 */
    }
    put("cb.raw", lv0, sizeof lv0);
    put("cl.1.raw", lv1, sizeof lv1);
    put("dirs2.raw", q, sizeof q);
    CHECK(run("lookup --cube cb.raw --size 2 --levels cl --queries dirs2.raw --out rc2.raw --min linear_mipmap_nearest") == 0,
          "cube levels run");
    get("rc2.raw", out, sizeof out);
    for (f = 0; f < 6; ++f) CHECK_EQF(out[4 * f], 10.0f + (float)f);
    memset(q, 0, sizeof q);
    q[0] = 1.0f;  /* +x: s = ¼, the left texel */
    q[9] = -1.0f; /* −x: s = ¾, the right texel */
    put("ll.raw", ll, sizeof ll);
    put("dirs3.raw", q, 18 * sizeof(float));
    CHECK(run("lookup --latlong ll.raw --w 2 --h 1 --queries dirs3.raw --out rl.raw --mag nearest") == 0, "latlong run");
    get("rl.raw", out, 8 * sizeof(float));
    CHECK_EQF(out[0], 1.0f);
    CHECK_EQF(out[4], 2.0f);
    CHECK(run("lookup --cube cube.raw --size 2 --queries dirs.raw") == 1, "cube file of the wrong size");
    CHECK(run("lookup --cube cube.raw --queries dirs.raw") == 2, "--cube without --size");
    CHECK(run("lookup --cube cube.raw --raw tex.raw --size 1 --queries dirs.raw") == 2, "two textures");
    CHECK(run("lookup --raw tex.raw --w 2 --h 2 --size 2 --queries q.raw") == 2, "--size without --cube");
    CHECK(run("lookup --cube cube.raw --size 1 --queries q.raw") == 1, "query file not a multiple of 36");
}

static void exit_codes(void)
{
    CHECK(run("lookup --help") == 0, "help is 0");
    CHECK(run("--help") == 0, "program help is 0");
    CHECK(run("lookup --queries q.raw") == 2, "missing texture is a usage error");
    CHECK(run("lookup --raw tex.raw --w 2 --h 2 --queries q.raw --wrap-s sideways") == 2, "bad wrap name");
    CHECK(run("lookup --raw tex.raw --w 2 --h 2 --queries q.raw --min-lod 3 --max-lod 1") == 2, "inconsistent lods");
    CHECK(run("lookup --raw missing.raw --w 2 --h 2 --queries q.raw") == 1, "unreadable texture is a runtime error");
    CHECK(run("lookup --raw tex.raw --w 3 --h 2 --queries q.raw") == 1, "wrong texture size");
    put("bad.raw", "abc", 3);
    CHECK(run("lookup --raw tex.raw --w 2 --h 2 --queries bad.raw") == 1, "query file not a multiple of 24");
    CHECK(run("nonsense") == 2, "unknown command");
    CHECK(run("lookup --raw tex.raw --w 0 --h 2 --queries q.raw") == 2, "zero width");
}

/* The shared parser (tools/cli.c): --opt=value, "--", a missing value
 * naming its option, usage errors exiting 2 from whichever command, and
 * read errors saying why. */
static void syntax(void)
{
    float out[8] = {0};
    char args[1024];
    CHECK(run("lookup --raw=tex.raw --w=2 --h 2 --queries=q.raw --out=r.raw --wrap=clamp_to_edge") == 0,
          "--opt=value");
    CHECK(get("r.raw", out, sizeof out) == sizeof out, "output size");
    CHECK_EQF(out[0], 2.75f);
    CHECK(run("lookup --raw tex.raw --w 2 --h 2 --queries") == 2 &&
              cli_holds(dir, "err.txt", "option --queries needs a value"),
          "missing value names the option");
    CHECK(run("lookup --raw tex.raw --w 2 --h 2 --queries q.raw --wrap") == 2 &&
              cli_holds(dir, "err.txt", "option --wrap needs a value"),
          "missing sampler value names the option");
    CHECK(run("lookup --raw tex.raw --w 2 --h 2 --queries=") == 2 &&
              cli_holds(dir, "err.txt", "option --queries needs a value"),
          "empty value after = is missing");
    CHECK(run("lookup --raw tex.raw --w 2 --h 2 --queries q.raw --text=yes") == 2 &&
              cli_holds(dir, "err.txt", "option --text takes no value"),
          "a flag given a value");
    CHECK(run("lookup --raw tex.raw --w 2 --h 2 --queries q.raw extra") == 2 &&
              cli_holds(dir, "err.txt", "unexpected argument 'extra'"),
          "an operand lookup does not take");
    CHECK(run("lookup --raw tex.raw --w 2 --h 2 --queries q.raw -- --text") == 2 &&
              cli_holds(dir, "err.txt", "unexpected argument './--text'"),
          "after --, an option-like argument is an operand");
    CHECK(run("info --raw tex.raw") == 2 && cli_holds(dir, "err.txt", "--raw needs --w and --h"),
          "info --raw without a size is a usage error");
    CHECK(run("lookup --raw tex.raw --queries q.raw") == 2, "lookup --raw without a size is a usage error");
    CHECK(run("lookup --raw tex.raw --w 2 --h 2 --queries missing.raw") == 1 &&
              cli_holds(dir, "err.txt", "cannot read query file 'missing.raw': No such file or directory"),
          "missing query file says why");
    CHECK(run("lookup --raw tex.raw --w 2 --h 2 --queries .") == 1 &&
              cli_holds(dir, "err.txt", "cannot read query file '.': Is a directory"),
          "a directory as query file says why");
    CHECK(run("lookup --raw . --w 2 --h 2 --queries q.raw") == 1 &&
              cli_holds(dir, "err.txt", "cannot read '.': Is a directory"),
          "a directory as texture says why");
    /* A FIFO would block open(2) until a writer came, and /dev/zero never
     * ends: both refused at once (timeout: a hang fails, not waits). */
    snprintf(args, sizeof args, "%s/pipe.raw", dir);
    CHECK(mkfifo(args, 0600) == 0, "mkfifo");
    CHECK(run("lookup --raw tex.raw --w 2 --h 2 --queries pipe.raw") == 1 &&
              cli_holds(dir, "err.txt", "cannot read query file 'pipe.raw': not a regular file"),
          "a FIFO as query file is refused");
    CHECK(run("lookup --raw /dev/zero --w 2 --h 2 --queries q.raw") == 1 &&
              cli_holds(dir, "err.txt", "cannot read '/dev/zero': not a regular file"),
          "a device as texture is refused");
    CHECK(run("lookup --raw tex.raw --w 2 --h 2 --queries q.raw --out nodir/r.raw") == 1 &&
              cli_holds(dir, "err.txt", "cannot write 'nodir/r.raw': No such file or directory"),
          "an unwritable output says why");
    /* "--" lets an image file start with '-' (run in the image program). */
    snprintf(args, sizeof args, "cp %s/testimages/rgb8.png %s/-rgb8.png", source, dir);
    CHECK(check_shell(args) == 0, "copy a test image");
    CHECK(run("info -- -rgb8.png") == 0 && cli_holds(dir, "out.txt", "size      19 x 13"), "info -- -rgb8.png");
    CHECK(run("info -rgb8.png") == 2 && cli_holds(dir, "err.txt", "unknown option '-rgb8.png'"),
          "without --, it is an option");
}

int main(int argc, char **argv)
{
    char tmpl[] = "/tmp/texsample_cli_XXXXXX";
    if (argc < 3) return 2;
    exe = realpath(argv[1], NULL); /* the commands run in the scratch dir */
    source = argv[2];
    if (!exe) return 1;
    if (!mkdtemp(tmpl)) return 1;
    snprintf(dir, sizeof dir, "%s", tmpl);
    RUN(lookup_values);
    RUN(explicit_levels);
    RUN(environment);
    RUN(exit_codes);
    RUN(syntax);
    cli_remove_dir(dir);
    free(exe);
    return check_finish();
}
