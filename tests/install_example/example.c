/* Samples a 2×2 texture halfway between its texels: prints 2.5. */
#include <sample/sample.h>
#include <stdio.h>

int main(void)
{
    const float px[16] = {1, 0, 0, 1, 2, 0, 0, 1, 3, 0, 0, 1, 4, 0, 0, 1};
    sample_image im = {2, 2, 4, SAMPLE_FORMAT_F32, px, 0};
    sample_texture *tex;
    sample_sampler s;
    sample_query q = {0.5f, 0.5f, 0, 0, 0, 0};
    float out[4];
    sample_error err;
    if (sample_texture_create(&im, NULL, &tex, &err) != SAMPLE_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    sample_sampler_init(&s);
    sample_one(tex, &s, &q, out);
    printf("%g\n", out[0]);
    sample_texture_destroy(tex);
    return out[0] == 2.5f ? 0 : 1;
}
