/*
 * The OpenEXR header pre-flight (libsample/io/src/exr_guard.c): an attribute
 * that claims more bytes than the file holds is refused with a message
 * before OpenEXR allocates it (fuzz_io found OpenEXR 3.1 allocating 1.8 GB
 * for a 922-byte input); real files, tiled and mip-mapped included, pass.
 */
#define _POSIX_C_SOURCE 200809L
#include "check.h"
#include "sample/sample_io.h"

#include <stdlib.h>
#include <unistd.h>

/* magic, version 2 (scanline), one attribute "x" of type string, then the
 * claimed size and a few bytes of value. */
static size_t make_header(unsigned char *b, unsigned claimed)
{
    static const unsigned char head[] = {0x76, 0x2f, 0x31, 0x01, 2, 0, 0, 0, 'x', 0, 's', 't', 'r', 'i', 'n', 'g', 0};
    size_t n = sizeof head;
    memcpy(b, head, n);
    b[n++] = (unsigned char)(claimed & 255);
    b[n++] = (unsigned char)(claimed >> 8 & 255);
    b[n++] = (unsigned char)(claimed >> 16 & 255);
    b[n++] = (unsigned char)(claimed >> 24 & 255);
    memcpy(b + n, "abcd", 4);
    return n + 4;
}

static void huge_attribute_in_memory(void)
{
    unsigned char b[64];
    size_t n = make_header(b, 0x7ffffff0u);
    sample_texture *t = (sample_texture *)b;
    sample_error err;
    CHECK(sample_io_read_memory(b, n, "exr", NULL, NULL, &t, &err) == SAMPLE_E_CORRUPT, "refused");
    CHECK(t == NULL, "no texture");
    CHECK(strstr(err.message, "claims") && strstr(err.message, "'x'"), "message: %s", err.message);
    n = make_header(b, 0x80000000u); /* negative size */
    CHECK(sample_io_read_memory(b, n, "exr", NULL, NULL, &t, &err) == SAMPLE_E_CORRUPT, "negative size");
    CHECK(sample_io_read_memory(b, 12, "exr", NULL, NULL, &t, &err) == SAMPLE_E_CORRUPT, "truncated");
}

static void huge_attribute_in_file(void)
{
    unsigned char b[64];
    char path[] = "/tmp/exr_guard_XXXXXX";
    size_t n = make_header(b, 1000000u);
    sample_texture *t = NULL;
    sample_error err;
    int fd = mkstemp(path);
    CHECK(fd >= 0 && write(fd, b, n) == (ssize_t)n, "temp file");
    if (fd >= 0) close(fd);
    CHECK(sample_io_read_texture(path, NULL, NULL, &t, &err) == SAMPLE_E_CORRUPT && t == NULL, "file refused");
    CHECK(strstr(err.message, path) != NULL, "message names the file: %s", err.message);
    unlink(path);
}

/* A real half EXR from testimages/ still reads. */
static void real_file_passes(void)
{
    char path[1024];
    sample_texture *t = NULL;
    sample_error err;
    snprintf(path, sizeof path, "%s/testimages/rgba_half.exr", SOURCE_DIR);
    CHECK(sample_io_read_texture(path, NULL, NULL, &t, &err) == SAMPLE_OK, "%s", err.message);
    sample_texture_destroy(t);
}

int main(void)
{
    RUN(huge_attribute_in_memory);
    RUN(huge_attribute_in_file);
    RUN(real_file_passes);
    return check_finish();
}
