/*
 * Files the renderer reads (scenes, image textures, environments) must be
 * regular files: /dev/zero never ends and a FIFO blocks in open(2) until a
 * writer comes, so both would hang the process before any parser sees a
 * byte. libsample_io's check (sample_io_check_regular_file) judges the path
 * and says what it is instead; the file is then opened again with
 * O_NONBLOCK (POSIX open(2): it returns at once on a FIFO, and has no
 * effect on a regular file's reads) and judged once more by fstat, since
 * the path may name something else by then, and the size is needed.
 */
#define _POSIX_C_SOURCE 200809L
#include "rn_internal.h"

#include <errno.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#ifdef TEXSAMPLE_HAVE_IO
#include "sample/sample_io.h"
#endif

int rn_open_regular(const char *path, const char *what, size_t max_bytes, size_t *size, char *err,
                    size_t errlen)
{
    struct stat st;
    int fd;
#ifdef TEXSAMPLE_HAVE_IO
    sample_error e;
#endif
    *size = 0;
#ifdef TEXSAMPLE_HAVE_IO
    if (sample_io_check_regular_file(path, what, &e) != SAMPLE_OK) {
        rn_seterr(err, errlen, "%s", e.message);
        return -1;
    }
#endif
    fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        rn_seterr(err, errlen, "cannot open %s '%s': %s", what, path, strerror(errno));
        return -1;
    }
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        close(fd);
        rn_seterr(err, errlen, "%s '%s' is not a regular file; only regular files are read", what, path);
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
