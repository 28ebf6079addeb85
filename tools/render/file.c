/*
 * Files the renderer reads (scenes, image textures, environments) must be
 * regular files: /dev/zero never ends and a FIFO blocks in open(2) until a
 * writer comes, so both would hang the process before any parser sees a
 * byte. O_NONBLOCK makes open return at once on a FIFO (POSIX open(2)); it
 * has no effect on a regular file's reads.
 */
#define _POSIX_C_SOURCE 200809L
#include "rn_internal.h"

#include <errno.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

int rn_open_regular(const char *path, const char *what, size_t max_bytes, size_t *size, char *err,
                    size_t errlen)
{
    struct stat st;
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    *size = 0;
    if (fd < 0) {
        rn_seterr(err, errlen, "%s '%s': %s", what, path,
                  errno == ENOENT ? "not found" : strerror(errno));
        return -1;
    }
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        close(fd);
        rn_seterr(err, errlen, "%s '%s': not a regular file", what, path);
        return -1;
    }
    if (st.st_size < 0 || (unsigned long long)st.st_size > (unsigned long long)max_bytes) {
        close(fd);
        rn_seterr(err, errlen, "%s '%s': larger than %zu MiB (the limit)", what, path,
                  max_bytes >> 20);
        return -1;
    }
    *size = (size_t)st.st_size;
    return fd;
}
