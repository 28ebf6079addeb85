/*
 * The reference kernels (internal.h, ls_isa_kernels_reference): what
 * sample_batch_reference() runs, and what every instruction set's kernels
 * must reproduce bit for bit. No batch loop of their own — the reference
 * path is sampler.c's one-query-at-a-time loop — and readers that go
 * texel by texel: rows through tex_decode_v4, bilinear reads through
 * ls_recon_level and ctx_texel's wrap rule (DESIGN §3–§4). The footprint
 * filters' row walks are the scalar build's (footprint_rows.c compiled
 * with SAMPLE_NO_SIMD: plain C loops).
 */
#include "kernels.h"
#include "recon.h"

static void ref_row(sample_format fmt, int nc, const unsigned char *p, size_t pitch, int n,
                    float (*out)[4])
{
    int k;
    for (k = 0; k < n; ++k) v4_store(out[k], tex_decode_v4(fmt, nc, p + (size_t)k * pitch));
}

static uint32_t ref_bilinear(const sample_ctx *c, int lv, float s, float t, float out[4], float dds[4],
                             float ddt[4])
{
    return ls_recon_level(c, lv, SAMPLE_LINEAR, s, t, out, dds, ddt);
}

#define REF_READERS {ref_row, ref_bilinear}
#define REF_READERS_ROW {REF_READERS, REF_READERS, REF_READERS, REF_READERS}

extern const fp_row_kernels ls_fp_row_kernels_scalar; /* footprint_rows.c */

const isa_kernels ls_isa_kernels_reference = {
    .fast_gl = {{NULL}},
    .readers = {
        [SAMPLE_FORMAT_F32] = REF_READERS_ROW,
        [SAMPLE_FORMAT_F16] = REF_READERS_ROW,
        [SAMPLE_FORMAT_UNORM8] = REF_READERS_ROW,
        [SAMPLE_FORMAT_SRGB8] = REF_READERS_ROW,
    },
    .rows = &ls_fp_row_kernels_scalar,
};
_Static_assert(SAMPLE_FORMAT_COUNT == 4, "one row of readers per format");
