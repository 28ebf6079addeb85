/*
 * What the tests of the quality filters (test_quality_*.c) share: extreme
 * queries through sample_batch, checked for finite results, a texel bound
 * and the border colour for non-finite input.
 */
#ifndef SAMPLE_TEST_QUALITY_UTIL_H
#define SAMPLE_TEST_QUALITY_UTIL_H

#include "footprint_util.h"

#include <string.h>

enum { EXTREME_NQ = 600 };

/* EXTREME_NQ queries of a w × h texture: random scales 2^−20 … 2^40 and
 * eccentricities up to 2^30, then hand-made ones (zero, rank one, 1e20,
 * 3.4e38 by 1e−38) and the non-finite 4, 5, 6. */
static void extreme_queries(sample_query *qs, int w, int h)
{
    int n;
    for (n = 0; n < EXTREME_NQ; ++n) {
        double mag = exp2(urand(-20, 40)), ecc = exp2(urand(-30, 0));
        qs[n] = footprint((float)urand(-1e3, 1e3), (float)urand(-3, 3), mag, mag * ecc, urand(0, 6.3), urand(0, 6.3),
                          w, h);
    }
    memset(&qs[0], 0, sizeof qs[0]);
    qs[1].dsdx = qs[1].dtdx = qs[1].dsdy = qs[1].dtdy = 1e20f;
    qs[2].dsdx = 1e20f, qs[2].dtdy = -1e20f;
    qs[3].dsdx = 0.5f, qs[3].dsdy = qs[3].dtdx = qs[3].dtdy = 0.0f;
    qs[4].dsdx = NAN, qs[5].dtdy = INFINITY, qs[6].s = -INFINITY;
    qs[7].dsdx = 3.4e38f, qs[7].dtdy = 1e-38f;
}

/* The queries through sample_batch: every result finite, at most
 * max_texels read, non-finite queries the border colour (0, 0, 0, 0). */
static void extreme_batch(const sample_texture *t, const sample_sampler *s, const sample_query *qs, uint32_t max_texels,
                          const char *what)
{
    static float out[EXTREME_NQ * 4];
    static sample_stats st[EXTREME_NQ];
    sample_batch_args a;
    int n, k, bad = 0, over = 0;
    memset(&a, 0, sizeof a);
    a.count = EXTREME_NQ;
    a.queries = qs;
    a.rgba = out;
    a.stats = st;
    CHECK(sample_batch(t, s, &a) == SAMPLE_OK, "%s: batch", what);
    for (n = 0; n < EXTREME_NQ; ++n) {
        for (k = 0; k < 4; ++k) bad += !isfinite(out[4 * n + k]);
        over += st[n].texels > max_texels;
    }
    CHECK(bad == 0 && over == 0, "%s: %d non-finite, %d over %u texels", what, bad, over, max_texels);
    for (n = 4; n <= 6; ++n) CHECK(out[4 * n] == 0.0f && out[4 * n + 3] == 0.0f, "%s: non-finite -> border", what);
}

#endif
