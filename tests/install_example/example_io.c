/* Reads an image file through libsample_io and prints its size and
 * channel count ("19x13 3" for testimages/rgb8.png). */
#include <sample/sample_io.h>
#include <stdio.h>

int main(int argc, char **argv)
{
    sample_io_options o;
    sample_texture *tex;
    sample_texture_info info;
    sample_error err;
    if (argc != 2) {
        fprintf(stderr, "usage: example_io IMAGE\n");
        return 2;
    }
    sample_io_options_init(&o);
    if (sample_io_read_texture(argv[1], &o, NULL, &tex, &err) != SAMPLE_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    sample_texture_info_get(tex, &info);
    printf("%dx%d %d\n", info.width, info.height, info.channels);
    sample_texture_destroy(tex);
    return 0;
}
