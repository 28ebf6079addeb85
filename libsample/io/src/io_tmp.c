/* Temporary files beside the target, renamed into place only when complete:
 * rename(2) within one directory is atomic on POSIX, so readers see either
 * the old file or the whole new one, and a failed write leaves nothing. */
#define _POSIX_C_SOURCE 200809L
#include "io_internal.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

sample_status io_tmp_create(const char *path, char *tmp, size_t tmp_size, sample_error *err)
{
    /* The pid keeps processes apart, the atomic counter threads; O_EXCL
     * catches whatever is left (a stale file from a killed run). */
    static _Atomic unsigned counter;
    int attempt;
    for (attempt = 0; attempt < 100; ++attempt) {
        unsigned n = counter++;
        int fd, len = snprintf(tmp, tmp_size, "%s.tmp%ld-%u", path, (long)getpid(), n);
        if (len < 0 || (size_t)len >= tmp_size)
            return sample_error_set(err, SAMPLE_E_INVALID_ARGUMENT, "path too long: '%s'", path);
        /* 0666 under the umask: the final file gets the usual permissions. */
        fd = open(tmp, O_WRONLY | O_CREAT | O_EXCL, 0666);
        if (fd >= 0) {
            close(fd);
            return SAMPLE_OK;
        }
        if (errno != EEXIST)
            return sample_error_set(err, SAMPLE_E_IO, "cannot create '%s': %s", path, strerror(errno));
    }
    return sample_error_set(err, SAMPLE_E_IO, "cannot create a temporary file beside '%s'", path);
}

sample_status io_tmp_finish(sample_status st, const char *tmp, const char *path, sample_error *err)
{
    if (st == SAMPLE_OK && rename(tmp, path) != 0)
        st = sample_error_set(err, SAMPLE_E_IO, "cannot rename '%s' to '%s': %s", tmp, path, strerror(errno));
    if (st != SAMPLE_OK) remove(tmp);
    return st;
}
