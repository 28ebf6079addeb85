/* Hostile files (doc/guarantees.md, "Files and tools"): what is not a
 * regular file is refused before any library sees it, within a second
 * (a FIFO would block open(2), /dev/zero would feed OpenImageIO's format
 * probe for ever); files whose data cannot hold what their header claims
 * are refused before the pixels are allocated; data a reader would make
 * up is an error. Crafted files are written here, byte by byte.
 * Usage: io_hostile TESTIMAGES SCRATCH */
#define _GNU_SOURCE
#include "io_util.h"

#include <signal.h>
#include <stdint.h>
#include <sys/stat.h>
#include <time.h>

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Reading `path` fails with `want` and a message containing `words`, in
 * under a second (the alarm set in main ends a hang). */
static void expect_refused(const char *path, const sample_io_options *o, sample_status want, const char *words,
                           const char *what)
{
    sample_texture *t = NULL;
    sample_error e;
    double t0 = now();
    sample_status st;
    e.message[0] = '\0';
    st = sample_io_read_texture(path, o, NULL, &t, &e);
    CHECK(st == want, "%s: status %s, expected %s (%s)", what, sample_strerror(st), sample_strerror(want), e.message);
    CHECK(!t, "%s: a texture was returned", what);
    CHECK(strstr(e.message, words) != NULL, "%s: message '%s' lacks '%s'", what, e.message, words);
    CHECK(now() - t0 < 1.0, "%s: took %.2f s", what, now() - t0);
    sample_texture_destroy(t);
}

static void test_not_regular(void)
{
    char fifo[1024], cfg[1024], img[1024];
    sample_io_options o;
    sample_error e;
    expect_refused("/dev/zero", NULL, SAMPLE_E_IO, "is a character device", "/dev/zero");
    expect_refused(io_scratch, NULL, SAMPLE_E_IO, "is a directory", "a directory");
    io_path(fifo, sizeof fifo, io_scratch, "fifo.png");
    CHECK(mkfifo(fifo, 0600) == 0, "mkfifo %s failed", fifo);
    expect_refused(fifo, NULL, SAMPLE_E_IO, "is a FIFO", "a FIFO");
    /* The OCIO config too (it is read whatever the image). */
    sample_io_options_init(&o);
    o.ocio_config = io_path(cfg, sizeof cfg, io_scratch, "fifo.png");
    expect_refused(io_path(img, sizeof img, io_images, "rgb8.png"), &o, SAMPLE_E_COLOR, "OCIO config", "config FIFO");
    o.ocio_config = "/dev/zero";
    expect_refused(img, &o, SAMPLE_E_COLOR, "is a character device", "config /dev/zero");
    /* The public check itself, as programs call it for their own files. */
    CHECK(sample_io_check_regular_file(img, "image", &e) == SAMPLE_OK, "%s", e.message);
    CHECK(sample_io_check_regular_file(fifo, "scene", &e) == SAMPLE_E_IO && strstr(e.message, "scene '") &&
              strstr(e.message, "FIFO"),
          "FIFO as a scene: %s", e.message);
    CHECK(sample_io_check_regular_file("/nonexistent/x", NULL, &e) == SAMPLE_E_IO &&
              strstr(e.message, "No such file"),
          "missing: %s", e.message);
    CHECK(sample_io_check_regular_file(NULL, "image", &e) == SAMPLE_E_INVALID_ARGUMENT, "NULL path");
    remove(fifo);
}

int main(int argc, char **argv)
{
    if (argc < 3) return fprintf(stderr, "usage: io_hostile TESTIMAGES SCRATCH\n"), 2;
    io_images = argv[1];
    io_scratch = argv[2];
    /* A hang is a failure, not a stuck test run. */
    alarm(20);
    RUN(test_not_regular);
    return check_finish();
}
