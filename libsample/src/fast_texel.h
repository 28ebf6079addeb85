/*
 * How the fast path (fast_gl.c) decodes texels: per format and channel
 * count, inlined into each instantiation, with the same results as
 * tex_decode_v4 (texel.h) and recon_bilerp (recon.h) — fewer instructions,
 * the same bits (tests/test_fastpath.c).
 */
#ifndef SAMPLE_FAST_TEXEL_H
#define SAMPLE_FAST_TEXEL_H

#include "recon.h"
#include "simd.h"
#include "texel.h"

#include <stdint.h>
#include <string.h>

/* Bytes per texel, a constant in each instantiation. */
SAMPLE_FORCE_INLINE size_t texel_bytes(sample_format fmt, int nc)
{
    return (size_t)nc * (fmt == SAMPLE_FORMAT_F32 ? 4u : (fmt == SAMPLE_FORMAT_F16 ? 2u : 1u));
}

/* Whether the fast path decodes this format's texels by gathers from
 * ls_u8_decode (texel_v4, texel_pair): 8-bit RGBA with AVX2. Per
 * texel the plain decode is four byte loads, four table loads and three
 * inserts; the gather reads the same table entries (the same bits). */
#if SAMPLE_VEC_AVX2
#define GATHER8(fmt, nc) ((nc) == 4 && ((fmt) == SAMPLE_FORMAT_SRGB8 || (fmt) == SAMPLE_FORMAT_UNORM8))

/* The row of ls_u8_decode each channel's code indexes, as an offset:
 * c / 255 (+256) for every UNORM8 channel and an sRGB texel's alpha. */
SAMPLE_FORCE_INLINE __m128i gather8_rows(sample_format fmt)
{
    return fmt == SAMPLE_FORMAT_SRGB8 ? _mm_setr_epi32(0, 0, 0, 256) : _mm_set1_epi32(256);
}
#endif

/* Texel p decoded as tex_decode_v4 decodes it. */
SAMPLE_FORCE_INLINE v4f texel_v4(sample_format fmt, int nc, const unsigned char *p)
{
#if SAMPLE_VEC_AVX2
    if (GATHER8(fmt, nc)) {
        int32_t w;
        memcpy(&w, p, 4);
        return _mm_i32gather_ps(&ls_u8_decode[0][0],
                                _mm_add_epi32(_mm_cvtepu8_epi32(_mm_cvtsi32_si128(w)), gather8_rows(fmt)), 4);
    }
#endif
    return tex_decode_v4(fmt, nc, p);
}

/* Texels p and p + tb (adjacent in a row) decoded as tex_decode_v4
 * decodes them: with GATHER8, one gather for both; RGBA halves with AVX2
 * in one 256-bit conversion. */
SAMPLE_FORCE_INLINE void texel_pair(sample_format fmt, int nc, const unsigned char *p, v4f *a, v4f *b)
{
#if SAMPLE_VEC_AVX2
    if (GATHER8(fmt, nc)) {
        const __m128i r = gather8_rows(fmt);
        const __m256i codes = _mm256_cvtepu8_epi32(_mm_loadl_epi64((const __m128i *)(const void *)p));
        const __m256 v = _mm256_i32gather_ps(&ls_u8_decode[0][0], _mm256_add_epi32(codes, _mm256_set_m128i(r, r)), 4);
        *a = _mm256_castps256_ps128(v);
        *b = _mm256_extractf128_ps(v, 1);
        return;
    }
#if defined(__F16C__)
    if (fmt == SAMPLE_FORMAT_F16 && nc == 4) {
        v4_pair_from_f16x8(p, a, b);
        return;
    }
#endif
#endif
    *a = tex_decode_v4(fmt, nc, p);
    *b = tex_decode_v4(fmt, nc, p + texel_bytes(fmt, nc));
}

/* n texels p, p + pitch, … decoded into out[0 … n − 1]: a level row
 * (pitch = texel size) in pairs, or a column; tex_readers.row, and the
 * rows of a bicubic block. */
SAMPLE_FORCE_INLINE void decode_row(sample_format fmt, int nc, const unsigned char *p, size_t pitch, int n,
                                    float (*out)[4])
{
    const size_t tb = texel_bytes(fmt, nc);
    int k;
    /* A level row (pitch = texel size, a constant the loop is compiled
     * for) or a column. */
    if (pitch == tb) {
        for (k = 0; k + 1 < n; k += 2) {
            v4f a, b;
            texel_pair(fmt, nc, p + (size_t)k * tb, &a, &b);
            v4_store(out[k], a);
            v4_store(out[k + 1], b);
        }
        if (k < n) v4_store(out[k], texel_v4(fmt, nc, p + (size_t)k * tb));
    } else {
        for (k = 0; k < n; ++k) v4_store(out[k], texel_v4(fmt, nc, p + (size_t)k * pitch));
    }
}

/* The 2 × 2 block at p (rows stride apart) reconstructed bilinearly
 * (recon_bilerp): the LINEAR taps of a query whose block lies in the
 * level. */
SAMPLE_FORCE_INLINE void bilerp_block(sample_format fmt, int nc, const unsigned char *p,
                                      size_t stride, float fu, float fv, float out[4], float dds[4],
                                      float ddt[4])
{
    v4f T[4];
    texel_pair(fmt, nc, p, &T[0], &T[1]);
    texel_pair(fmt, nc, p + stride, &T[2], &T[3]);
    recon_bilerp(T, fu, fv, out, dds, ddt);
}

#endif
