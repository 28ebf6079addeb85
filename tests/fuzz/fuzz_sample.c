/*
 * Fuzzes the sampling API: a small texture of any format and channel count,
 * any sampler state (valid or not), and queries with arbitrary float bits,
 * with and without corners, bias and derivatives. The oracle is the
 * sanitizers plus two invariants: a result is finite or exactly the border
 * colour, and no query reads more than SAMPLE_MAX_FOOTPRINT_TEXELS texels.
 */
#include "sample/sample.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

typedef struct { const uint8_t *p; size_t n; } cursor;

static void take(cursor *c, void *dst, size_t k)
{
    size_t m = k < c->n ? k : c->n;
    memset(dst, 0, k);
    memcpy(dst, c->p, m);
    c->p += m;
    c->n -= m;
}

static uint8_t byte(cursor *c) { uint8_t b; take(c, &b, 1); return b; }
static float f32(cursor *c) { float f; take(c, &f, 4); return f; }

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    cursor c = {data, size};
    sample_image im;
    sample_mip_params mp;
    sample_texture *tex = NULL;
    sample_sampler s;
    sample_query q[8];
    sample_quad quad[8];
    float bias[8], out[32], ds[32], dt[32];
    sample_stats st[8];
    sample_batch_args a;
    unsigned char texels[16 * 16 * 16];
    size_t nq, k;
    int use;

    im.width = 1 + byte(&c) % 16;
    im.height = 1 + byte(&c) % 16;
    im.channels = 1 + byte(&c) % 4;
    im.format = (sample_format)(byte(&c) % SAMPLE_FORMAT_COUNT);
    im.row_stride = 0;
    take(&c, texels, (size_t)im.width * im.height * im.channels * sample_format_bytes(im.format));
    im.data = texels;
    sample_mip_params_init(&mp);
    mp.filter = (sample_mipgen)(byte(&c) % SAMPLE_MIPGEN_COUNT);
    mp.wrap_s = (sample_wrap)(byte(&c) % SAMPLE_WRAP_COUNT);
    mp.wrap_t = (sample_wrap)(byte(&c) % SAMPLE_WRAP_COUNT);
    if (sample_texture_create(&im, &mp, &tex, NULL) != SAMPLE_OK) return 0;

    sample_sampler_init(&s);
    s.wrap_s = (sample_wrap)(byte(&c) % 9); /* 8 is invalid on purpose */
    s.wrap_t = (sample_wrap)(byte(&c) % SAMPLE_WRAP_COUNT);
    s.min_filter = (sample_filter)(byte(&c) % SAMPLE_FILTER_COUNT);
    s.mag_filter = (sample_filter)(byte(&c) % 7);
    s.footprint = (sample_footprint)(byte(&c) % SAMPLE_FOOTPRINT_COUNT);
    s.cubic = (sample_cubic)(byte(&c) % SAMPLE_CUBIC_COUNT);
    s.options = byte(&c) & 0x0f;
    s.lod_bias = f32(&c);
    s.min_lod = f32(&c);
    s.max_lod = f32(&c);
    s.base_level = byte(&c) % 20;
    s.max_level = s.base_level + byte(&c) % 20;
    s.max_anisotropy = 1.0f + (float)(byte(&c) % 32);
    for (k = 0; k < 4; ++k) s.border_color[k] = (float)byte(&c) / 255.0f;
    use = byte(&c);

    nq = 1 + byte(&c) % 8;
    for (k = 0; k < nq; ++k) {
        take(&c, &q[k], sizeof q[k]);
        take(&c, &quad[k], sizeof quad[k]);
        bias[k] = (use & 4) ? f32(&c) : 0.0f;
    }
    memset(&a, 0, sizeof a);
    a.count = nq;
    a.queries = q;
    a.rgba = out;
    a.stats = st;
    a.corners = (use & 1) ? quad : NULL;
    a.drgba_ds = (use & 2) ? ds : NULL;
    a.drgba_dt = (use & 2) ? dt : NULL;
    a.lod_bias = (use & 4) ? bias : NULL;
    if (sample_batch(tex, &s, &a) == SAMPLE_OK) {
        for (k = 0; k < nq; ++k) {
            int finite = isfinite(out[4 * k]) && isfinite(out[4 * k + 1]) && isfinite(out[4 * k + 2]) &&
                         isfinite(out[4 * k + 3]);
            /* Texels may themselves be inf/NaN (float and half formats):
             * then only the cap is checked. */
            int texels_finite = im.format == SAMPLE_FORMAT_UNORM8 || im.format == SAMPLE_FORMAT_SRGB8;
            if (texels_finite && !finite && memcmp(&out[4 * k], s.border_color, sizeof s.border_color) != 0)
                abort();
            if (st[k].texels > SAMPLE_MAX_FOOTPRINT_TEXELS) abort();
        }
    }
    sample_texture_destroy(tex);
    return 0;
}
