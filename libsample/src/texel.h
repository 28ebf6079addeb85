/*
 * Texel storage and decode (texture.c, color.c): the levels of a texture,
 * the exact 8-bit and half decodes (GL 4.6 §8.24, eq. 2.1), one texel to
 * linear RGBA with OpenGL's channel expansion. The bottom layer: every
 * reader, fast or reference, decodes through tex_decode_v4.
 */
#ifndef SAMPLE_TEXEL_H
#define SAMPLE_TEXEL_H

#include "base.h"

struct sample_level {
    int w, h;
    size_t stride;       /* bytes per row */
    unsigned char *data; /* owned */
};

struct sample_texture {
    int width, height, channels, nlevels;
    sample_format format;
    size_t texel_bytes; /* channels × format bytes */
    size_t bytes;       /* all levels */
    struct sample_level level[SAMPLE_MAX_LEVELS];
};

/* The exact sRGB EOTF for each 8-bit code ([0]) and c / 255 ([1]), one
 * array (color.c). */
extern const float ls_u8_decode[2][256];
#define ls_srgb_table (ls_u8_decode[0])
#define ls_unorm8_table (ls_u8_decode[1])
/* The 8-bit sRGB code of a linear value, rounded to nearest in the encoded
 * domain (color.c; no libm); what the mip builder writes into sRGB8
 * levels. */
unsigned char ls_srgb_encode8(float v);

/* Decode one texel at p to linear RGBA with the OpenGL channel expansion
 * (missing G, B → 0, missing A → 1). With `format` and `nc` constants (the
 * fast path instantiates it per format and channel count) the switches
 * vanish; every reader, fast or general, decodes through this one function.
 * Reads exactly nc channels: shorter texels are copied into a padded buffer
 * first, so the last texel of a level is never over-read. */
SAMPLE_FORCE_INLINE v4f tex_decode_v4(sample_format format, int nc, const unsigned char *p)
{
    switch (format) {
    case SAMPLE_FORMAT_F32: {
        /* Constant-size copies inline to plain loads; a variable-length copy
         * (which GCC also makes of a per-channel loop) is a libc call. */
        float v[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        switch (nc) {
        case 4: memcpy(v, p, 16); break;
        case 3: memcpy(v, p, 12); break;
        case 2: memcpy(v, p, 8); break;
        default: memcpy(v, p, 4); break;
        }
        return v4_load(v);
    }
    case SAMPLE_FORMAT_F16: {
        /* Padding halves: 0, 0, 0, 1.0 (0x3c00). */
        uint16_t h[4] = {0, 0, 0, 0x3c00};
        switch (nc) {
        case 4: return v4_from_f16x4(p);
        case 3: memcpy(h, p, 6); break;
        case 2: memcpy(h, p, 4); break;
        default: memcpy(h, p, 2); break;
        }
        return v4_from_f16x4((const unsigned char *)h);
    }
    case SAMPLE_FORMAT_UNORM8:
        /* c / 255 correctly rounded (GL 4.6 eq. 2.1), from a table. */
        return v4_set(ls_unorm8_table[p[0]], nc > 1 ? ls_unorm8_table[p[1]] : 0.0f,
                      nc > 2 ? ls_unorm8_table[p[2]] : 0.0f,
                      nc > 3 ? ls_unorm8_table[p[3]] : 1.0f);
    case SAMPLE_FORMAT_SRGB8:
        /* Alpha of an sRGB format is linear (GL 4.6 §8.24). */
        return v4_set(ls_srgb_table[p[0]], nc > 1 ? ls_srgb_table[p[1]] : 0.0f,
                      nc > 2 ? ls_srgb_table[p[2]] : 0.0f,
                      nc > 3 ? ls_unorm8_table[p[3]] : 1.0f);
    default:
        return v4_set(0.0f, 0.0f, 0.0f, 1.0f);
    }
}

/* Decode texel (i, j) (both in range) of a level. */
static inline void tex_decode(const sample_texture *tex, const struct sample_level *lv,
                              int i, int j, float out[4])
{
    const unsigned char *p = lv->data + (size_t)j * lv->stride + (size_t)i * tex->texel_bytes;
    v4_store(out, tex_decode_v4(tex->format, tex->channels, p));
}

/* Encode linear RGBA (first `channels` values) into one texel of the
 * texture's format; used by the pyramid builder. */
void ls_tex_encode(const sample_texture *tex, const float in[4], unsigned char *dst);

/* Allocate level k's storage (size from the level rule); tex->bytes updated. */
sample_status ls_tex_alloc_level(sample_texture *tex, int k, sample_error *err);

#endif /* SAMPLE_TEXEL_H */
