/* Temporary files beside the target, renamed into place only when complete:
 * rename(2) within one directory is atomic on POSIX, so readers see either
 * the old file or the whole new one, and a failed write leaves nothing
 * (doc/guarantees.md, "Files and tools").
 *
 * A process can also be stopped while it writes. Two defences:
 *
 * - Unnamed first. Where the file system supports it, the temporary is made
 *   with Linux's O_TMPFILE (open(2)): an inode with no name, which the
 *   kernel frees when the process dies however it dies, SIGKILL included.
 *   Writers open it as /proc/self/fd/N; when it is complete it is given a
 *   name with linkat(2) through that same /proc link (open(2), "O_TMPFILE":
 *   the documented way without CAP_DAC_READ_SEARCH) and renamed over the
 *   target at once. Only that window of two system calls has a name.
 * - Named temporaries (where O_TMPFILE is refused, and during that window)
 *   are listed in a fixed table that a handler for SIGINT, SIGTERM and
 *   SIGHUP unlinks before the signal takes its default course. The handler
 *   is installed only for signals whose disposition is still SIG_DFL, i.e.
 *   where the process would die anyway: a program with its own handler, or
 *   one ignoring the signal, keeps it.
 */
#define _GNU_SOURCE /* O_TMPFILE, linkat's AT_SYMLINK_FOLLOW */
#include "io_internal.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

/* ---- Named temporaries a signal must remove ------------------------------ */

/* Slots: 0 free, 1 being filled, 2 holds a name the handler may unlink. A
 * process writing more files at once than there are slots still writes
 * them; the extra names are just not removed on a signal. */
#define IO_TMP_SLOTS 32
static char tmp_names[IO_TMP_SLOTS][IO_TMP_NAME_MAX];
static _Atomic int tmp_state[IO_TMP_SLOTS];
static _Atomic int handlers_installed;
static _Atomic int unnamed_off;

static const int cleanup_signals[] = {SIGINT, SIGTERM, SIGHUP};

/* Only async-signal-safe calls (POSIX.1-2017, 2.4.3): unlink, sigaction,
 * raise. The default action then runs as if we had never been there. */
static void on_signal(int sig)
{
    struct sigaction dfl;
    int k;
    for (k = 0; k < IO_TMP_SLOTS; ++k)
        if (atomic_load(&tmp_state[k]) == 2) unlink(tmp_names[k]);
    memset(&dfl, 0, sizeof dfl);
    dfl.sa_handler = SIG_DFL;
    sigemptyset(&dfl.sa_mask);
    sigaction(sig, &dfl, NULL);
    raise(sig);
}

static void install_handlers(void)
{
    size_t k;
    if (atomic_exchange(&handlers_installed, 1)) return;
    for (k = 0; k < sizeof cleanup_signals / sizeof cleanup_signals[0]; ++k) {
        struct sigaction old, sa;
        if (sigaction(cleanup_signals[k], NULL, &old) != 0 || old.sa_handler != SIG_DFL ||
            (old.sa_flags & SA_SIGINFO))
            continue;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_signal;
        sigemptyset(&sa.sa_mask);
        sigaction(cleanup_signals[k], &sa, NULL);
    }
}

static int remember(const char *name)
{
    int k;
    for (k = 0; k < IO_TMP_SLOTS; ++k) {
        int expect = 0;
        if (atomic_compare_exchange_strong(&tmp_state[k], &expect, 1)) {
            snprintf(tmp_names[k], sizeof tmp_names[k], "%s", name);
            atomic_store(&tmp_state[k], 2);
            return k;
        }
    }
    return -1;
}

static void forget(int slot)
{
    if (slot >= 0) atomic_store(&tmp_state[slot], 0);
}

/* ---- Creating and finishing ---------------------------------------------- */

void io_tmp_set_unnamed(int on) { atomic_store(&unnamed_off, !on); }

/* A fresh name PATH.tmpPID-N: the pid keeps processes apart, the counter
 * threads; O_EXCL / EEXIST catch whatever is left (a stale file). */
static int next_name(const char *path, char *name, size_t size)
{
    static _Atomic unsigned counter;
    int len = snprintf(name, size, "%s.tmp%ld-%u", path, (long)getpid(), atomic_fetch_add(&counter, 1));
    return len >= 0 && (size_t)len < size;
}

static sample_status create_named(const char *path, io_tmp *t, sample_error *err)
{
    int attempt;
    for (attempt = 0; attempt < 100; ++attempt) {
        int fd;
        if (!next_name(path, t->name, sizeof t->name))
            return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "path too long: '%s'", path);
        /* 0666 under the umask: the final file gets the usual permissions. */
        t->slot = remember(t->name);
        fd = open(t->name, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            close(fd);
            snprintf(t->write_path, sizeof t->write_path, "%s", t->name);
            return SAMPLE_OK;
        }
        forget(t->slot);
        t->slot = -1;
        if (errno != EEXIST) return sample_error_set(err, SAMPLE_E_IO, "cannot create '%s': %s", path, strerror(errno));
    }
    return sample_error_set(err, SAMPLE_E_IO, "cannot create a temporary file beside '%s'", path);
}

#ifdef O_TMPFILE
/* The directory part of path ("." when there is none). */
static int dir_of(const char *path, char *dir, size_t size)
{
    const char *slash = strrchr(path, '/');
    size_t n = slash ? (size_t)(slash - path) : 0;
    if (!slash) return snprintf(dir, size, ".") > 0;
    if (n == 0) n = 1; /* "/name": the root */
    if (n >= size) return 0;
    memcpy(dir, path, n);
    dir[n] = '\0';
    return 1;
}

/* An unnamed file in path's directory, or 0 where there is none to have. */
static int create_unnamed(const char *path, io_tmp *t)
{
    char dir[IO_TMP_NAME_MAX];
    int fd;
    if (atomic_load(&unnamed_off) || !dir_of(path, dir, sizeof dir)) return 0;
    /* EOPNOTSUPP, EISDIR or EINVAL: no O_TMPFILE in this file system or
     * kernel. A missing or read-only directory fails again in
     * create_named, with the message that names the target. */
    if ((fd = open(dir, O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666)) < 0) return 0;
    /* The writers open it again through /proc; without /proc (a chroot)
     * the named protocol is used instead. */
    snprintf(t->write_path, sizeof t->write_path, "/proc/self/fd/%d", fd);
    if (access(t->write_path, W_OK) != 0) {
        close(fd);
        return 0;
    }
    t->fd = fd;
    return 1;
}
#endif

sample_status io_tmp_create(const char *path, io_tmp *t, sample_error *err)
{
    memset(t, 0, sizeof *t);
    t->fd = -1;
    t->slot = -1;
    install_handlers();
#ifdef O_TMPFILE
    if (create_unnamed(path, t)) return SAMPLE_OK;
#endif
    return create_named(path, t, err);
}

/* Give the finished unnamed file a name beside the target. */
static sample_status link_unnamed(const char *path, io_tmp *t, sample_error *err)
{
    int attempt;
    for (attempt = 0; attempt < 100; ++attempt) {
        if (!next_name(path, t->name, sizeof t->name))
            return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "path too long: '%s'", path);
        t->slot = remember(t->name);
        if (linkat(AT_FDCWD, t->write_path, AT_FDCWD, t->name, AT_SYMLINK_FOLLOW) == 0) return SAMPLE_OK;
        forget(t->slot);
        t->slot = -1;
        if (errno != EEXIST)
            return sample_error_set(err, SAMPLE_E_IO, "cannot name the new '%s': %s", path, strerror(errno));
    }
    return sample_error_set(err, SAMPLE_E_IO, "cannot name the new '%s'", path);
}

sample_status io_tmp_finish(sample_status st, io_tmp *t, const char *path, sample_error *err)
{
    int named = t->fd < 0;
    if (st == SAMPLE_OK && !named) {
        st = link_unnamed(path, t, err);
        named = st == SAMPLE_OK;
    }
    if (st == SAMPLE_OK && rename(t->name, path) != 0)
        st = sample_error_set(err, SAMPLE_E_IO, "cannot rename '%s' to '%s': %s", t->name, path, strerror(errno));
    if (st != SAMPLE_OK && named) remove(t->name);
    forget(t->slot);
    t->slot = -1;
    if (t->fd >= 0) close(t->fd); /* an unnamed file that was not linked vanishes here */
    t->fd = -1;
    return st;
}
