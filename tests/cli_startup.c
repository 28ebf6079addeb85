/*
 * The front program starts without OpenImageIO (doc/cli.md, "Start-up"):
 * `texsample --help`, `lookup --help` and a lookup on a raw file load none
 * of its libraries (the dynamic loader's own account, LD_DEBUG=files,
 * ld.so(8)), and `lookup --help` takes well under the 0.4 s that loading
 * them took; `info` on an image file does load them (in the image program),
 * which shows that the account is read right. Skipped (77) where the loader
 * gives no such account (not glibc).
 *
 *   cli_startup TEXSAMPLE IMAGE
 */
#define _XOPEN_SOURCE 700
#include "check.h"
#include "cli_util.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static char *exe;
static char dir[256];

/* Run texsample with LD_DEBUG=files; its loader account in dir/ld.txt. */
static int run_traced(const char *args)
{
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "cd %s && LD_DEBUG=files %s %s >out.txt 2>ld.txt", dir, exe, args);
    return check_shell(cmd);
}

/* How many libraries the last traced run loaded, and how many of them are
 * OpenImageIO's. */
static void loaded(int *total, int *oiio)
{
    char *s = check_slurp_in(dir, "ld.txt"), *p;
    *total = *oiio = 0;
    for (p = s; p && (p = strstr(p, "file=")) != NULL; ++p) {
        char *end = strchr(p, '\n');
        ++*total;
        if (end) *end = '\0';
        if (strstr(p, "libOpenImageIO")) ++*oiio;
        if (end) *end = '\n';
    }
    free(s);
}

static double seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int main(int argc, char **argv)
{
    char tmpl[] = "/tmp/texsample_startup_XXXXXX", cmd[2048];
    static const char *const light[] = {"--help", "lookup --help",
                                        "lookup --raw tex.raw --w 1 --h 1 --queries q.raw --text"};
    const float texel[4] = {0.25f, 0.5f, 0.75f, 1.0f}, query[6] = {0.5f, 0.5f, 0, 0, 0, 0};
    double best = 1e9;
    int total, oiio, k;
    FILE *f;
    if (argc < 3) return 2;
    exe = realpath(argv[1], NULL);
    if (!exe || !mkdtemp(tmpl)) return 1;
    snprintf(dir, sizeof dir, "%s", tmpl);
    snprintf(cmd, sizeof cmd, "%s/tex.raw", dir);
    if ((f = fopen(cmd, "wb")) != NULL) fwrite(texel, sizeof texel, 1, f), fclose(f);
    snprintf(cmd, sizeof cmd, "%s/q.raw", dir);
    if ((f = fopen(cmd, "wb")) != NULL) fwrite(query, sizeof query, 1, f), fclose(f);

    snprintf(cmd, sizeof cmd, "info %s", argv[2]);
    CHECK(run_traced(cmd) == 0, "info on an image file");
    loaded(&total, &oiio);
    if (total == 0) {
        check_skip("the dynamic loader gives no LD_DEBUG=files account");
    } else {
        CHECK(oiio > 0, "info loads OpenImageIO (%d of %d libraries)", oiio, total);
        for (k = 0; k < (int)(sizeof light / sizeof light[0]); ++k) {
            CHECK(run_traced(light[k]) == 0, "texsample %s", light[k]);
            loaded(&total, &oiio);
            CHECK(total > 0 && oiio == 0, "texsample %s: %d libraries, %d of OpenImageIO", light[k], total, oiio);
        }
        {
            char *out = check_slurp_in(dir, "out.txt");
            CHECK(out && strcmp(out, "0.5 0.5 -> 0.25 0.5 0.75 1\n") == 0, "the raw lookup's result: %s",
                  out ? out : "");
            free(out);
        }
    }
    /* Best of five: the machine may be busy; one quiet run is enough. */
    snprintf(cmd, sizeof cmd, "%s lookup --help >/dev/null", exe);
    for (k = 0; k < 5; ++k) {
        double t0 = seconds();
        CHECK(check_shell(cmd) == 0, "lookup --help");
        if (seconds() - t0 < best) best = seconds() - t0;
    }
    printf("lookup --help: best of 5 %.3f s\n", best);
    CHECK(best < 0.2, "lookup --help starts in under 0.2 s (%.3f s)", best);
    cli_remove_dir(dir);
    free(exe);
    return check_finish();
}
