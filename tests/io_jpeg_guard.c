/*
 * The JPEG header pre-flight (libsample/io/src/jpeg_guard.c): an APP13
 * "Photoshop 3.0" IPTC block whose size field claims more bytes than its
 * segment holds is refused with a message before OpenImageIO's JPEG reader
 * reads past the segment (fuzz_io found it under AddressSanitizer); the
 * same block with a true size, and the test images, still read.
 */
#define _POSIX_C_SOURCE 200809L
#include "check.h"
#include "sample/sample_io.h"

#include <stdlib.h>
#include <unistd.h>

/* testimages/rgb8.jpg with an APP13 segment inserted after its SOI: the
 * Photoshop IPTC head, an IPTC size field of `claimed` and `held` bytes of
 * IPTC data (one caption dataset, 1C 02 78, and padding). */
static unsigned char *with_app13(unsigned claimed, unsigned held, size_t *n)
{
    char path[1024];
    static const unsigned char head[] = {'P', 'h', 'o', 't', 'o', 's', 'h', 'o', 'p', ' ', '3', '.', '0', 0,
                                         '8', 'B', 'I', 'M', 0x04, 0x04, 0, 0, 0, 0};
    unsigned char *jpg = NULL, *out = NULL;
    long size;
    size_t seg = sizeof head + 2 + held, k;
    FILE *f;
    snprintf(path, sizeof path, "%s/testimages/rgb8.jpg", SOURCE_DIR);
    f = fopen(path, "rb");
    if (!f || fseek(f, 0, SEEK_END) != 0 || (size = ftell(f)) < 4 || fseek(f, 0, SEEK_SET) != 0) goto done;
    jpg = malloc((size_t)size);
    out = malloc((size_t)size + seg + 4);
    if (!jpg || !out || fread(jpg, 1, (size_t)size, f) != (size_t)size) goto done;
    memcpy(out, jpg, 2); /* SOI */
    out[2] = 0xFF;
    out[3] = 0xED;
    out[4] = (unsigned char)((seg + 2) >> 8);
    out[5] = (unsigned char)((seg + 2) & 255);
    memcpy(out + 6, head, sizeof head);
    out[6 + sizeof head] = (unsigned char)(claimed >> 8);
    out[7 + sizeof head] = (unsigned char)(claimed & 255);
    for (k = 0; k < held; ++k) out[8 + sizeof head + k] = k == 0 ? 0x1C : k == 1 ? 0x02 : k == 2 ? 0x78 : 'a';
    if (held >= 5) {
        out[11 + sizeof head] = 0;
        out[12 + sizeof head] = (unsigned char)(held - 5);
    }
    memcpy(out + 6 + seg, jpg + 2, (size_t)size - 2);
    *n = (size_t)size + seg + 4;
    free(jpg);
    fclose(f);
    return out;
done:
    if (f) fclose(f);
    free(jpg);
    free(out);
    *n = 0;
    return NULL;
}

static void claimed_past_segment(void)
{
    size_t n;
    unsigned char *b = with_app13(120, 20, &n);
    sample_texture *t = NULL;
    sample_error err;
    char path[] = "/tmp/jpeg_guard_XXXXXX";
    int fd;
    CHECK(b != NULL, "test image");
    if (!b) return;
    CHECK(sample_io_read_memory(b, n, "jpg", NULL, NULL, &t, &err) == SAMPLE_E_CORRUPT && t == NULL, "refused");
    CHECK(strstr(err.message, "APP13") != NULL, "message: %s", err.message);
    /* Whatever the hint says. */
    CHECK(sample_io_read_memory(b, n, "png", NULL, NULL, &t, &err) == SAMPLE_E_CORRUPT && t == NULL, "hint png");
    fd = mkstemp(path);
    CHECK(fd >= 0 && write(fd, b, n) == (ssize_t)n, "temp file");
    if (fd >= 0) close(fd);
    CHECK(sample_io_read_texture(path, NULL, NULL, &t, &err) == SAMPLE_E_CORRUPT && t == NULL, "file refused");
    CHECK(strstr(err.message, path) != NULL, "message names the file: %s", err.message);
    unlink(path);
    free(b);
}

/* A segment that ends inside "Photoshop 3.0" (strcmp would read on), and
 * one that ends inside the block head. */
static void short_segments(void)
{
    static const unsigned char prefix[] = {0xFF, 0xD8, 0xFF, 0xED, 0, 7, 'P', 'h', 'o', 't', 'o', 0xFF, 0xD9};
    static const unsigned char head[] = {0xFF, 0xD8, 0xFF, 0xED, 0, 20, 'P', 'h', 'o', 't', 'o', 's', 'h', 'o',
                                         'p', ' ', '3', '.', '0', 0, '8', 'B', 'I', 'M', 0xFF, 0xD9};
    static const unsigned char other[] = {0xFF, 0xD8, 0xFF, 0xED, 0, 7, 'A', 'd', 'o', 'b', 'e', 0xFF, 0xD9};
    sample_texture *t = NULL;
    sample_error err;
    CHECK(sample_io_read_memory(prefix, sizeof prefix, "jpg", NULL, NULL, &t, &err) == SAMPLE_E_CORRUPT, "prefix");
    CHECK(sample_io_read_memory(head, sizeof head, "jpg", NULL, NULL, &t, &err) == SAMPLE_E_CORRUPT, "short head");
    /* Another APP13 is not the guard's business; the reader refuses the
     * image for having no frame. */
    CHECK(sample_io_read_memory(other, sizeof other, "jpg", NULL, NULL, &t, &err) != SAMPLE_OK, "no frame");
    CHECK(strstr(err.message, "APP13") == NULL, "not the guard: %s", err.message);
}

static void true_size_reads(void)
{
    size_t n;
    unsigned char *b = with_app13(20, 20, &n);
    sample_texture *t = NULL;
    sample_error err;
    CHECK(b != NULL, "test image");
    if (!b) return;
    CHECK(sample_io_read_memory(b, n, "jpg", NULL, NULL, &t, &err) == SAMPLE_OK && t != NULL, "%s", err.message);
    sample_texture_destroy(t);
    free(b);
}

static void test_images_read(void)
{
    static const char *const names[] = {"rgb8.jpg", "photo.jpg"};
    int k;
    for (k = 0; k < 2; ++k) {
        char path[1024];
        sample_texture *t = NULL;
        sample_error err;
        snprintf(path, sizeof path, "%s/testimages/%s", SOURCE_DIR, names[k]);
        CHECK(sample_io_read_texture(path, NULL, NULL, &t, &err) == SAMPLE_OK, "%s: %s", names[k], err.message);
        sample_texture_destroy(t);
    }
}

int main(void)
{
    RUN(claimed_past_segment);
    RUN(short_segments);
    RUN(true_size_reads);
    RUN(test_images_read);
    return check_finish();
}
