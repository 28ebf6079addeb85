/*
 * texsample lookup --volume end to end (doc/volumes.md): writes a raw
 * volume, explicit levels and a query file, runs the front program, and
 * checks its output against sample_batch_3d on the same texels, bit for
 * bit; `texsample info --volume` (depth and levels); and the exit codes of
 * bad command lines (2) and bad files (1).
 *
 *   cli_volume TEXSAMPLE
 */
#define _XOPEN_SOURCE 700
#include "check.h"
#include "cli_util.h"
#include "sample/sample.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

enum { W = 8, H = 4, D = 2, NQ = 64 };

static char *exe;
static char dir[256];

static void put(const char *name, const void *data, size_t n) { cli_put(dir, name, data, n); }
static int run(const char *args) { return cli_run_in(dir, exe, args); }

static uint32_t rng = 7u;
static float urand(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 17;
    rng ^= rng << 5;
    return (float)(rng >> 8) / 16777216.0f;
}

static float vol[W * H * D * 4], lv1[4 * 2 * 1 * 4];
static sample_query3 q[NQ];

/* The library on the same texels, levels (0 and 1 given) and sampler. */
static void expected(const sample_sampler *s, float *out)
{
    sample_volume lv[2] = {{W, H, D, 4, SAMPLE_FORMAT_F32, vol, 0, 0}, {4, 2, 1, 4, SAMPLE_FORMAT_F32, lv1, 0, 0}};
    sample_texture *tex = NULL;
    sample_batch3_args a = {NQ, q, NULL, out, NULL};
    CHECK(sample_texture_create_3d_levels(lv, 2, &tex, NULL) == SAMPLE_OK, "levels");
    CHECK(sample_batch_3d(tex, s, &a) == SAMPLE_OK, "batch");
    sample_texture_destroy(tex);
}

static void matches_library(void)
{
    float got[NQ * 4], want[NQ * 4];
    char p[512];
    FILE *f;
    sample_sampler s;
    size_t i, k;
    for (i = 0; i < sizeof vol / sizeof vol[0]; ++i) vol[i] = urand();
    for (i = 0; i < sizeof lv1 / sizeof lv1[0]; ++i) lv1[i] = urand();
    for (i = 0; i < NQ; ++i)
        for (k = 0; k < 3; ++k) {
            q[i].p[k] = urand() * 1.4f - 0.2f;
            q[i].dpdx[k] = (urand() - 0.5f) * 0.5f;
            q[i].dpdy[k] = (urand() - 0.5f) * 0.2f;
        }
    put("vol.raw", vol, sizeof vol);
    put("vol.1.raw", lv1, sizeof lv1);
    put("q.raw", q, sizeof q);
    CHECK(run("lookup --volume vol.raw --w 8 --h 4 --d 2 --levels vol --queries q.raw --out r.raw "
              "--wrap-r mirrored_repeat --wrap clamp_to_border --border 0.5,0,0,1 --min linear_mipmap_linear") == 0,
          "exit 0");
    snprintf(p, sizeof p, "%s/r.raw", dir);
    f = fopen(p, "rb");
    CHECK(f && fread(got, sizeof got, 1, f) == 1, "output");
    if (f) fclose(f);
    sample_sampler_init(&s);
    s.wrap_r = SAMPLE_WRAP_MIRRORED_REPEAT;
    s.wrap_s = s.wrap_t = SAMPLE_WRAP_CLAMP_TO_BORDER;
    s.border_color[0] = 0.5f;
    s.border_color[3] = 1.0f;
    s.min_filter = SAMPLE_LINEAR_MIPMAP_LINEAR;
    expected(&s, want);
    CHECK(memcmp(got, want, sizeof got) == 0, "lookup --volume gives sample_batch_3d's bits");
    /* A pyramid built by the program (box) is not the given level 1. */
    CHECK(run("lookup --volume vol.raw --w 8 --h 4 --d 2 --queries q.raw --text --stats") == 0, "text, stats");
    CHECK(cli_holds(dir, "out.txt", " -> ") && cli_holds(dir, "err.txt", "texels/query"), "text and stats printed");
}

static void info_depth(void)
{
    /* info runs in the image program (the front program starts it), which
     * loads OpenImageIO: two runs only (the loading's errors are lookup's,
     * above and below: one function, volload.c). */
    CHECK(run("info --volume vol.raw --w 8 --h 4 --d 2") == 0, "info exit 0");
    CHECK(cli_holds(dir, "out.txt", "kind      3d\nsize      8 x 4 x 2\n"), "kind and size with depth");
    CHECK(cli_holds(dir, "out.txt", "levels    4 (box)"), "levels");
    CHECK(cli_holds(dir, "out.txt", "level  1  4 x 2 x 1\n  level  2  2 x 1 x 1\n  level  3  1 x 1 x 1"),
          "every level w x h x d");
    CHECK(run("info --help") == 0 && cli_holds(dir, "out.txt", "--volume FILE"), "info --help lists --volume");
}

static void bad_command_lines(void)
{
    CHECK(run("lookup --volume vol.raw --w 8 --h 4 --queries q.raw") == 2, "no --d: usage");
    CHECK(cli_holds(dir, "err.txt", "--d"), "names --d");
    CHECK(run("lookup --volume vol.raw --w 8 --h 4 --d 0 --queries q.raw") == 2, "--d 0: usage");
    CHECK(run("lookup --volume vol.raw --w 8 --h 4 --d 2 --wrap-r sideways --queries q.raw") == 2, "bad --wrap-r");
    CHECK(run("lookup --volume vol.raw --w 8 --h 4 --d 2") == 2, "no queries: usage");
    CHECK(run("lookup --volume vol.raw --w 8 --h 4 --d 2 --queries q.raw --corners c.raw") == 2, "--corners: usage");
    CHECK(run("lookup --volume vol.raw --w 8 --h 4 --d 3 --queries q.raw") == 1, "wrong size: runtime");
    CHECK(cli_holds(dir, "err.txt", "8 x 4 x 3"), "says the size");
    put("q5.raw", q, 5 * sizeof(float));
    CHECK(run("lookup --volume vol.raw --w 8 --h 4 --d 2 --queries q5.raw") == 1, "partial query: runtime");
    CHECK(cli_holds(dir, "err.txt", "36"), "says 36");
    put("vol.1.raw", lv1, sizeof lv1 - 4);
    CHECK(run("lookup --volume vol.raw --w 8 --h 4 --d 2 --levels vol --queries q.raw") == 1, "short level");
    CHECK(run("lookup --volume vol.raw --help") == 0 && cli_holds(dir, "out.txt", "--wrap-r"), "--volume FILE --help");
    CHECK(run("lookup --help") == 0 && cli_holds(dir, "out.txt", "--volume FILE"), "lookup --help lists --volume");
}

int main(int argc, char **argv)
{
    if (argc < 2) return 2;
    exe = argv[1];
    snprintf(dir, sizeof dir, "/tmp/cli_volume_XXXXXX");
    if (!mkdtemp(dir)) return 1;
    RUN(matches_library);
    RUN(info_depth);
    RUN(bad_command_lines);
    cli_remove_dir(dir);
    return check_finish();
}
