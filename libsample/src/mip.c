/* Pyramid building (DESIGN §6). Placeholder: 2×2 box on linear values,
 * nearest for odd axes — to be replaced by the polyphase builder. */
#include "internal.h"

sample_status mip_build(sample_texture *tex, const sample_mip_params *p, sample_error *err)
{
    int k, full = 1, m = tex->width > tex->height ? tex->width : tex->height;
    while (m > 1) { m >>= 1; ++full; }
    if (p->max_levels > 0 && p->max_levels < full) full = p->max_levels;
    for (k = 1; k < full; ++k) {
        const struct sample_level *S = &tex->level[k - 1];
        struct sample_level *D;
        int i, j, c;
        sample_status st = tex_alloc_level(tex, k, err);
        if (st != SAMPLE_OK) return st;
        tex->nlevels = k + 1;
        D = &tex->level[k];
        for (j = 0; j < D->h; ++j)
            for (i = 0; i < D->w; ++i) {
                float acc[4] = {0, 0, 0, 0}, t[4];
                int di, dj, cnt = 0;
                for (dj = 0; dj < 2; ++dj)
                    for (di = 0; di < 2; ++di) {
                        int x = 2 * i + di, y = 2 * j + dj;
                        if (x >= S->w) x = S->w - 1;
                        if (y >= S->h) y = S->h - 1;
                        tex_decode(tex, S, x, y, t);
                        for (c = 0; c < 4; ++c) acc[c] += t[c];
                        ++cnt;
                    }
                for (c = 0; c < 4; ++c) acc[c] /= (float)cnt;
                tex_encode(tex, acc, D->data + (size_t)j * D->stride + (size_t)i * tex->texel_bytes);
            }
    }
    return SAMPLE_OK;
}
