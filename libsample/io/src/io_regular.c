/* Only regular files are read (doc/guarantees.md, "Files and tools").
 *
 * OpenImageIO's format probe reads /dev/zero forever, and open(2) of a FIFO
 * blocks until a writer appears. So every path a reader is given is opened
 * here first with O_NONBLOCK (POSIX open(2): a FIFO opened for reading with
 * O_NONBLOCK returns at once) and judged by fstat(2) on that descriptor,
 * before any library sees the name. The descriptor is closed again: the
 * libraries open the file themselves. */
#define _POSIX_C_SOURCE 200809L
#include "io_internal.h"

#include <errno.h>
#include <fcntl.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const char *kind_of(mode_t m)
{
    if (S_ISDIR(m)) return "a directory";
    if (S_ISFIFO(m)) return "a FIFO";
    if (S_ISCHR(m)) return "a character device";
    if (S_ISBLK(m)) return "a block device";
    if (S_ISSOCK(m)) return "a socket";
    return "not a regular file";
}

sample_status sample_io_check_regular_file(const char *path, const char *what, sample_error *err)
{
    struct stat st;
    int fd, e;
    if (!what || !*what) what = "file";
    if (!path || !*path) return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "no %s name given", what);
    fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) return sample_error_set(err, SAMPLE_E_IO, "cannot open %s '%s': %s", what, path, strerror(errno));
    e = fstat(fd, &st) != 0 ? errno : 0;
    close(fd);
    if (e) return sample_error_set(err, SAMPLE_E_IO, "cannot examine %s '%s': %s", what, path, strerror(e));
    if (!S_ISREG(st.st_mode))
        return sample_error_set(err, SAMPLE_E_IO, "%s '%s' is %s; only regular files are read", what, path,
                                kind_of(st.st_mode));
    return SAMPLE_OK;
}
