/* libFuzzer target for every libsample_io reader path: the first byte picks
 * the format hint (and so the OpenImageIO reader), the rest is the file.
 * Seeds: tests/fuzz/corpus_io/ (the test images with their hint byte). */
#include "sample/sample_io.h"

#include <stddef.h>
#include <stdint.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const hints[] = {"png", "jpg", "tif", "exr", "hdr", "tga", "bmp", "tx", NULL};
    sample_io_options o;
    sample_mip_params mip;
    sample_texture *t = NULL;
    if (size < 1) return 0;
    sample_io_options_init(&o);
    /* Keep allocations below libFuzzer's malloc limit: a claimed size over
     * the budget must be refused, not allocated. */
    o.max_bytes = (size_t)64 << 20;
    sample_mip_params_init(&mip);
    if (sample_io_read_memory(data + 1, size - 1, hints[data[0] % (sizeof hints / sizeof hints[0])], &o, &mip, &t,
                              NULL) == SAMPLE_OK &&
        !t)
        __builtin_trap(); /* OK must come with a texture */
    sample_texture_destroy(t);
    return 0;
}
