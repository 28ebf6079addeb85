/*
 * An outside program as a backend (backend.h): the `lookup` file protocol
 * of doc/backends.md. For each texture the backend writes the base level
 * and every further level as raw little-endian float32 RGBA (decoded to
 * linear, as libsample samples them); for each batch the queries, 6 float32
 * each; then it runs
 *
 *   /bin/sh -c 'COMMAND "$@"' sh --raw T.raw --w W --h H --levels T
 *       --queries Q.raw --out R.raw --wrap-s MODE --wrap-t MODE --border R,G,B,A
 *
 * — the options of `texsample lookup`, so `texsample lookup` itself is one
 * such program — and reads back 4 float32 per query. Exit status 0 is
 * success, 3 "cannot do this configuration" (the row reads "n/a: " and the
 * first line the program printed), anything else a failure, reported with
 * that line too. The program's stdout and stderr go to a file in the
 * backend's folder so that its chatter does not mix with the tool's output.
 */
#define _POSIX_C_SOURCE 200809L
#include "backend.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#define PROGRAM_NA_STATUS 3
/* How long one run of an outside program may take before it is killed
 * (a program that never exits must not hang the tool): 600 s, or
 * TEXSAMPLE_PROGRAM_TIMEOUT seconds (doc/backends.md). */
#define PROGRAM_TIMEOUT_S 600.0
/* run_program's status for a program killed at its time limit. */
#define PROGRAM_TIMED_OUT (-2)

typedef struct prog_impl {
    char *command;
    char dir[512];
    unsigned serial; /* textures prepared so far: their file names */
} prog_impl;

struct tool_backend_tex {
    char prefix[600]; /* DIR/texN: prefix.raw, prefix.1.raw, ... */
    int w, h, levels;
    sample_sampler smp;
};

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* float32 little-endian, whatever the host's order. */
static int write_floats(const char *path, const float *v, size_t n)
{
    FILE *f = fopen(path, "wb");
    size_t k;
    int ok = f != NULL;
    for (k = 0; ok && k < n; ++k) {
        uint32_t u;
        unsigned char b[4];
        memcpy(&u, &v[k], 4);
        b[0] = (unsigned char)u;
        b[1] = (unsigned char)(u >> 8);
        b[2] = (unsigned char)(u >> 16);
        b[3] = (unsigned char)(u >> 24);
        ok = fwrite(b, 1, 4, f) == 4;
    }
    if (f && fclose(f) != 0) ok = 0;
    return ok ? 0 : -1;
}

/* Exactly n float32 from path; −1 if it holds another count. */
static int read_floats(const char *path, float *v, size_t n, long *bytes)
{
    FILE *f = fopen(path, "rb");
    size_t k;
    unsigned char b[4];
    *bytes = -1;
    if (!f) return -1;
    for (k = 0; k < n && fread(b, 1, 4, f) == 4; ++k) {
        uint32_t u = (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
        memcpy(&v[k], &u, 4);
    }
    fseek(f, 0, SEEK_END);
    *bytes = ftell(f);
    fclose(f);
    return k == n && *bytes == (long)(n * 4) ? 0 : -1;
}

static int prog_prepare(tool_backend *b, const sample_texture *tex, const sample_sampler *smp,
                        tool_backend_tex **out, tool_backend_times *t, char *err, size_t errlen)
{
    prog_impl *p = b->impl;
    sample_texture_info info;
    tool_backend_tex *x;
    float *d;
    double t0 = now_s();
    int k, i, j;
    sample_texture_info_get(tex, &info);
    if (info.kind != SAMPLE_TEXTURE_2D) {
        snprintf(err, errlen, "the lookup protocol carries 2D textures only, not %s",
                 sample_texture_kind_name(info.kind));
        return TOOL_BACKEND_NA;
    }
    x = calloc(1, sizeof *x);
    d = malloc((size_t)info.width * (size_t)info.height * 4 * sizeof *d);
    if (!x || !d) {
        free(x);
        free(d);
        snprintf(err, errlen, "out of memory");
        return TOOL_BACKEND_ERROR;
    }
    snprintf(x->prefix, sizeof x->prefix, "%s/tex%u", p->dir, p->serial++);
    x->w = info.width;
    x->h = info.height;
    x->levels = info.levels;
    x->smp = *smp;
    for (k = 0; k < info.levels; ++k) {
        char path[640];
        int w, h;
        sample_texture_level_size(tex, k, &w, &h);
        for (j = 0; j < h; ++j)
            for (i = 0; i < w; ++i)
                sample_texture_texel(tex, k, i, j, d + 4 * ((size_t)j * (size_t)w + (size_t)i));
        if (k == 0)
            snprintf(path, sizeof path, "%s.raw", x->prefix);
        else
            snprintf(path, sizeof path, "%s.%d.raw", x->prefix, k);
        if (write_floats(path, d, (size_t)w * (size_t)h * 4) != 0) {
            snprintf(err, errlen, "cannot write %s: %s", path, strerror(errno));
            free(d);
            x->levels = k + 1;
            b->ops->release(b, x);
            return TOOL_BACKEND_ERROR;
        }
    }
    free(d);
    t->upload += now_s() - t0;
    *out = x;
    return 0;
}

/* The first line of the program's output (its reason), into buf. */
static void first_line(const char *path, char *buf, size_t len)
{
    FILE *f = fopen(path, "r");
    buf[0] = '\0';
    if (!f) return;
    if (fgets(buf, (int)len, f)) buf[strcspn(buf, "\r\n")] = '\0';
    fclose(f);
}

/* The time limit of one run, in seconds (PROGRAM_TIMEOUT_S). */
static double program_timeout(void)
{
    const char *v = getenv("TEXSAMPLE_PROGRAM_TIMEOUT");
    char *end;
    double s;
    if (!v || !*v) return PROGRAM_TIMEOUT_S;
    s = strtod(v, &end);
    return *end == '\0' && s > 0.0 && s <= 86400.0 ? s : PROGRAM_TIMEOUT_S;
}

/* Run the command with the protocol's arguments; returns its wait status,
 * −1 when it could not be started, or PROGRAM_TIMED_OUT when it ran past
 * program_timeout() and was killed with everything it started (its own
 * process group). Everything the child needs is made
 * before fork: a tool may have threads (OpenImageIO's), and after fork only
 * async-signal-safe calls are safe in the child. */
static int run_program(const prog_impl *p, char *const *args, const char *log)
{
    /* sh -c 'COMMAND "$@"' sh ARGS: the arguments arrive unsplit. */
    static const char tail[] = " \"$@\"";
    size_t len = strlen(p->command) + sizeof tail;
    char *script = malloc(len), *argv[40];
    pid_t pid;
    int status, k = 0, fd;
    if (!script) return -1;
    snprintf(script, len, "%s%s", p->command, tail);
    argv[k++] = "sh";
    argv[k++] = "-c";
    argv[k++] = script;
    argv[k++] = "sh";
    for (; *args && k < 39; ++args) argv[k++] = *args;
    argv[k] = NULL;
    fd = open(log, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    fflush(NULL);
    pid = fork();
    if (pid == 0) {
        (void)setpgid(0, 0);
        if (fd >= 0) {
            dup2(fd, 1);
            dup2(fd, 2);
            close(fd);
        }
        execv("/bin/sh", argv);
        _exit(127);
    }
    if (fd >= 0) close(fd);
    free(script);
    if (pid < 0) return -1;
    (void)setpgid(pid, pid); /* as the child does: whichever runs first */
    {
        const double limit = program_timeout(), t0 = now_s();
        const struct timespec tick = {0, 10 * 1000 * 1000};
        pid_t r;
        while ((r = waitpid(pid, &status, WNOHANG)) == 0 || (r < 0 && errno == EINTR)) {
            if (now_s() - t0 > limit) {
                kill(-pid, SIGKILL);
                while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
                return PROGRAM_TIMED_OUT;
            }
            nanosleep(&tick, NULL);
        }
        if (r < 0) return -1;
    }
    return status;
}

static int prog_sample(tool_backend *b, tool_backend_tex *x, const sample_query *q, size_t n,
                       float *rgba, double *texels, tool_backend_times *t, char *err, size_t errlen)
{
    prog_impl *p = b->impl;
    char qpath[600], opath[600], log[600], raw[640], ws[16], hs[16], border[128], line[200];
    char *args[24];
    float *qv = malloc(n * 6 * sizeof *qv);
    size_t k;
    long bytes;
    double t0, t1;
    int st, a = 0;
    (void)texels;
    if (!qv) {
        snprintf(err, errlen, "out of memory");
        return TOOL_BACKEND_ERROR;
    }
    snprintf(qpath, sizeof qpath, "%s/queries.raw", p->dir);
    snprintf(opath, sizeof opath, "%s/result.raw", p->dir);
    snprintf(log, sizeof log, "%s/output.txt", p->dir);
    snprintf(raw, sizeof raw, "%s.raw", x->prefix);
    snprintf(ws, sizeof ws, "%d", x->w);
    snprintf(hs, sizeof hs, "%d", x->h);
    snprintf(border, sizeof border, "%.9g,%.9g,%.9g,%.9g", (double)x->smp.border_color[0],
             (double)x->smp.border_color[1], (double)x->smp.border_color[2],
             (double)x->smp.border_color[3]);
    for (k = 0; k < n; ++k) memcpy(qv + 6 * k, &q[k], 6 * sizeof *qv);
    t0 = now_s();
    if (write_floats(qpath, qv, n * 6) != 0) {
        free(qv);
        snprintf(err, errlen, "cannot write %s: %s", qpath, strerror(errno));
        return TOOL_BACKEND_ERROR;
    }
    free(qv);
    remove(opath);
    args[a++] = "--raw", args[a++] = raw, args[a++] = "--w", args[a++] = ws;
    args[a++] = "--h", args[a++] = hs, args[a++] = "--levels", args[a++] = x->prefix;
    args[a++] = "--queries", args[a++] = qpath, args[a++] = "--out", args[a++] = opath;
    args[a++] = "--wrap-s", args[a++] = (char *)sample_wrap_name(x->smp.wrap_s);
    args[a++] = "--wrap-t", args[a++] = (char *)sample_wrap_name(x->smp.wrap_t);
    args[a++] = "--border", args[a++] = border;
    args[a] = NULL;
    t1 = now_s();
    st = run_program(p, args, log);
    t->upload += t1 - t0;
    t->sample += now_s() - t1;
    first_line(log, line, sizeof line);
    if (st == -1) {
        snprintf(err, errlen, "cannot start /bin/sh: %s", strerror(errno));
        return TOOL_BACKEND_ERROR;
    }
    if (st == PROGRAM_TIMED_OUT) {
        snprintf(err, errlen, "program '%s' ran past %g s and was killed (TEXSAMPLE_PROGRAM_TIMEOUT)", p->command,
                 program_timeout());
        return TOOL_BACKEND_ERROR;
    }
    if (WIFEXITED(st) && WEXITSTATUS(st) == PROGRAM_NA_STATUS) {
        snprintf(err, errlen, "%s", line[0] ? line : "the program cannot do this configuration");
        return TOOL_BACKEND_NA;
    }
    if (!WIFEXITED(st) || WEXITSTATUS(st) != 0) {
        if (WIFEXITED(st))
            snprintf(err, errlen, "program '%s' exited with status %d%s%s", p->command,
                     WEXITSTATUS(st), line[0] ? ": " : "", line);
        else
            snprintf(err, errlen, "program '%s' was killed by signal %d%s%s", p->command,
                     WTERMSIG(st), line[0] ? ": " : "", line);
        return TOOL_BACKEND_ERROR;
    }
    t0 = now_s();
    if (read_floats(opath, rgba, n * 4, &bytes) != 0) {
        if (bytes < 0)
            snprintf(err, errlen, "program '%s' wrote no result (the --out file)", p->command);
        else
            snprintf(err, errlen, "program '%s' wrote %ld bytes, not %zu (4 float32 per query)",
                     p->command, bytes, n * 16);
        return TOOL_BACKEND_ERROR;
    }
    t->readback += now_s() - t0;
    return 0;
}

static void prog_release(tool_backend *b, tool_backend_tex *x)
{
    char path[640];
    int k;
    (void)b;
    for (k = 0; k < x->levels; ++k) {
        if (k == 0)
            snprintf(path, sizeof path, "%s.raw", x->prefix);
        else
            snprintf(path, sizeof path, "%s.%d.raw", x->prefix, k);
        remove(path);
    }
    free(x);
}

static void prog_close(tool_backend *b)
{
    prog_impl *p = b->impl;
    static const char *const files[] = {"queries.raw", "result.raw", "output.txt"};
    size_t k;
    if (!p) return;
    for (k = 0; k < sizeof files / sizeof files[0] && p->dir[0]; ++k) {
        char path[600];
        snprintf(path, sizeof path, "%s/%s", p->dir, files[k]);
        remove(path);
    }
    if (p->dir[0]) rmdir(p->dir);
    free(p->command);
    free(p);
    b->impl = NULL;
}

static const tool_backend_ops prog_ops = {
    .prepare = prog_prepare, .sample = prog_sample, .release = prog_release, .close = prog_close};

int tool_backend_program_open(tool_backend *b, const char *command, char *err, size_t errlen)
{
    const char *base = getenv("TMPDIR");
    prog_impl *p = calloc(1, sizeof *p);
    memset(b, 0, sizeof *b);
    if (!p || !(p->command = strdup(command))) {
        free(p);
        snprintf(err, errlen, "out of memory");
        return TOOL_BACKEND_ERROR;
    }
    b->ops = &prog_ops;
    b->impl = p;
    snprintf(p->dir, sizeof p->dir, "%s/texsample-program-XXXXXX", base && *base ? base : "/tmp");
    if (!mkdtemp(p->dir)) {
        snprintf(err, errlen, "cannot create a folder %s: %s", p->dir, strerror(errno));
        p->dir[0] = '\0';
        tool_backend_close(b);
        return TOOL_BACKEND_ERROR;
    }
    snprintf(b->driver, sizeof b->driver, "program: %s", command);
    return 0;
}
