/* Interrupted writes leave nothing (doc/guarantees.md, "Files and tools"):
 * a process stopped by SIGINT, SIGTERM, SIGHUP or SIGKILL in the middle of
 * writing a mip-mapped OpenEXR file leaves the old file and no temporary.
 * Each case forks a child that writes and signals itself from the writer's
 * progress callback, after the first tile row is on disk: no timing, no
 * sleeping. Both protocols of io_tmp.c are run: the unnamed O_TMPFILE file
 * (every signal, SIGKILL included) and the named file the handler removes
 * (the catchable signals). Where the file system has no O_TMPFILE the
 * unnamed cases are skipped (exit 77).
 * Usage: io_signal TESTIMAGES SCRATCH */
#define _GNU_SOURCE
#include "io_util.h"
#include "io_internal.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>

static const char old_bytes[] = "the old file";
static int signal_to_raise, expect_named;

/* Called after each tile row; the first call is mid-file. Before dying the
 * child checks that the protocol under test is the one in use: a named
 * temporary exists only in the named protocol. Exit 3 tells the parent it
 * was not. */
static void raise_now(void *user, size_t done, size_t total)
{
    int named = io_count_tmp(io_scratch) > 0;
    (void)user;
    (void)total;
    if (done != 1) return;
    if (named != expect_named) _exit(3);
    raise(signal_to_raise);
    _exit(4); /* the signal did not end the process */
}

static void write_old(const char *path)
{
    FILE *f = fopen(path, "wb");
    CHECK(f && fwrite(old_bytes, 1, sizeof old_bytes, f) == sizeof old_bytes, "cannot write %s", path);
    if (f) fclose(f);
}

static int is_old(const char *path)
{
    char buf[64];
    FILE *f = fopen(path, "rb");
    size_t n = f ? fread(buf, 1, sizeof buf, f) : 0;
    if (f) fclose(f);
    return n == sizeof old_bytes && memcmp(buf, old_bytes, n) == 0;
}

static void interrupt_write(int sig, int unnamed)
{
    char out[1024];
    int status = 0;
    pid_t pid;
    io_path(out, sizeof out, io_scratch, "target.exr");
    write_old(out);
    fflush(NULL);
    pid = fork();
    CHECK(pid >= 0, "fork failed");
    if (pid == 0) {
        sample_texture *t = io_test_texture(256, 256, 4, SAMPLE_FORMAT_F32, 7u, SAMPLE_MIPGEN_BOX, 0);
        sample_io_exr_options o;
        sample_error e;
        sample_io_exr_options_init(&o);
        o.tile_w = o.tile_h = 16;
        o.progress = raise_now;
        signal_to_raise = sig;
        expect_named = !unnamed;
        io_tmp_set_unnamed(unnamed);
        if (!t) _exit(5);
        sample_io_write_mip_exr(out, t, &o, &e);
        _exit(6); /* finished without the signal */
    }
    if (pid < 0) return;
    CHECK(waitpid(pid, &status, 0) == pid, "waitpid failed");
    CHECK(WIFSIGNALED(status) && WTERMSIG(status) == sig, "signal %d (%s): child %s %d", sig,
          unnamed ? "unnamed" : "named", WIFSIGNALED(status) ? "died of signal" : "exited with",
          WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status));
    CHECK(io_count_tmp(io_scratch) == 0, "signal %d (%s): a temporary file was left", sig,
          unnamed ? "unnamed" : "named");
    CHECK(is_old(out), "signal %d (%s): the old file was not kept", sig, unnamed ? "unnamed" : "named");
}

static int has_tmpfile(void)
{
    int fd = open(io_scratch, O_TMPFILE | O_WRONLY, 0600);
    if (fd < 0) return 0;
    close(fd);
    return 1;
}

static void test_named_signals(void)
{
    interrupt_write(SIGINT, 0);
    interrupt_write(SIGTERM, 0);
    interrupt_write(SIGHUP, 0);
}

static void test_unnamed_signals(void)
{
    if (!has_tmpfile()) {
        check_skip("the scratch file system has no O_TMPFILE: SIGKILL cannot be survived there");
        return;
    }
    interrupt_write(SIGINT, 1);
    interrupt_write(SIGTERM, 1);
    interrupt_write(SIGHUP, 1);
    interrupt_write(SIGKILL, 1);
}

/* A completed write through either protocol replaces the old file and
 * leaves no temporary. */
static void test_complete_writes(void)
{
    int unnamed;
    for (unnamed = 0; unnamed <= 1; ++unnamed) {
        char out[1024];
        sample_texture *t = io_test_texture(20, 10, 3, SAMPLE_FORMAT_F32, 3u, SAMPLE_MIPGEN_BOX, 0), *b;
        sample_error e;
        io_path(out, sizeof out, io_scratch, "complete.exr");
        write_old(out);
        io_tmp_set_unnamed(unnamed);
        CHECK(t && sample_io_write_mip_exr(out, t, NULL, &e) == SAMPLE_OK, "%s", e.message);
        CHECK(io_count_tmp(io_scratch) == 0, "a temporary file was left");
        b = io_read(out, NULL, 1);
        CHECK(b && io_same_texels(t, b, 5, 0.001f), "the new file does not hold the texture");
        sample_texture_destroy(b);
        sample_texture_destroy(t);
    }
    io_tmp_set_unnamed(1);
}

int main(int argc, char **argv)
{
    if (argc < 3) return fprintf(stderr, "usage: io_signal TESTIMAGES SCRATCH\n"), 2;
    io_images = argv[1];
    io_scratch = argv[2];
    RUN(test_named_signals);
    RUN(test_unnamed_signals);
    RUN(test_complete_writes);
    return check_finish();
}
