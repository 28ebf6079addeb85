/* Interrupted writes leave nothing (doc/guarantees.md, "Files and tools"):
 * a process stopped by SIGINT, SIGTERM, SIGHUP or SIGKILL in the middle of
 * writing a mip-mapped OpenEXR file leaves the old file and no temporary.
 * Each case forks a child that writes and signals itself from the writer's
 * progress callback, after the first tile row is on disk: no timing, no
 * sleeping. Both protocols of io_tmp.c are run: the unnamed O_TMPFILE file
 * (every signal, SIGKILL included) and the named file the handler removes
 * (the catchable signals). Then `texsample mip` itself is killed by each
 * signal from outside, once its first progress line shows it writing (its
 * stderr is a one-page pipe that is not read further, so it cannot finish
 * first). Where the file system has no O_TMPFILE the unnamed cases are
 * skipped (exit 77).
 * Usage: io_signal TESTIMAGES SCRATCH [TEXSAMPLE] */
#define _GNU_SOURCE
#include "io_util.h"
#include "io_internal.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>

static const char old_bytes[] = "the old file";
static const char *texsample;
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

/* texsample mip of a 16 × 512 picture with 1 × 1 tiles (1023 tile rows,
 * 48 bytes of progress each) into a file that exists, killed by `sig`
 * after its first progress line; the old file is kept, nothing else is
 * left. All four signals run at once (each its own target). */
static void test_cli_killed(void)
{
    static const int sigs[] = {SIGINT, SIGTERM, SIGHUP, SIGKILL};
    enum { N = sizeof sigs / sizeof sigs[0] };
    static float px[16 * 512 * 4];
    char in[1024], out[N][1024], name[64];
    int fds[N][2], n = has_tmpfile() ? N : N - 1, k;
    pid_t pid[N];
    sample_error e;
    if (!texsample || !*texsample) {
        check_skip("texsample not built: the program itself not killed");
        return;
    }
    for (k = 0; k < 16 * 512 * 4; ++k) px[k] = (float)(k % 7) / 7.0f;
    CHECK(sample_io_write_image(io_path(in, sizeof in, io_scratch, "tall.png"), px, 16, 512, 3, NULL, &e) ==
              SAMPLE_OK,
          "%s", e.message);
    fflush(NULL);
    for (k = 0; k < n; ++k) {
        snprintf(name, sizeof name, "killed%d.exr", k);
        write_old(io_path(out[k], sizeof out[k], io_scratch, name));
        CHECK(pipe(fds[k]) == 0, "pipe failed");
        fcntl(fds[k][1], F_SETPIPE_SZ, 4096); /* the smallest pipe: one page */
        pid[k] = fork();
        if (pid[k] == 0) {
            dup2(fds[k][1], 2);
            setenv("TEXSAMPLE_PROGRESS", "1", 1);
            execl(texsample, "texsample", "mip", in, out[k], "--tile", "1", (char *)NULL);
            _exit(127);
        }
        close(fds[k][1]);
    }
    for (k = 0; k < n; ++k) {
        char buf[64];
        int status = 0;
        CHECK(read(fds[k][0], buf, sizeof buf) > 0, "signal %d: no progress from texsample", sigs[k]);
        kill(pid[k], sigs[k]);
        CHECK(waitpid(pid[k], &status, 0) == pid[k], "waitpid failed");
        close(fds[k][0]);
        CHECK(WIFSIGNALED(status) && WTERMSIG(status) == sigs[k], "texsample mip: signal %d, but %s %d", sigs[k],
              WIFSIGNALED(status) ? "died of" : "exited with",
              WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status));
        CHECK(is_old(out[k]), "signal %d: the old file was not kept", sigs[k]);
    }
    CHECK(io_count_tmp(io_scratch) == 0, "a killed texsample mip left a temporary file");
    if (n < N) check_skip("no O_TMPFILE here: texsample mip not killed by SIGKILL");
}

int main(int argc, char **argv)
{
    if (argc < 3) return fprintf(stderr, "usage: io_signal TESTIMAGES SCRATCH [TEXSAMPLE]\n"), 2;
    io_images = argv[1];
    io_scratch = argv[2];
    texsample = argc > 3 ? argv[3] : "";
    RUN(test_named_signals);
    RUN(test_unnamed_signals);
    RUN(test_complete_writes);
    RUN(test_cli_killed);
    return check_finish();
}
