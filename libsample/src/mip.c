/*
 * Pyramid building (DESIGN §6, doc/mip-and-lod.md).
 *
 * Every level is made from the stored level above it by a separable
 * resampler: one tap table per axis (source indices and weights for each
 * output texel), a horizontal pass into a small cache of float rows, a
 * vertical pass that encodes into the level. The box, the odd-axis polyphase box and the
 * windowed-sinc kernels differ only in how the tap table is filled, so the
 * resampling loop exists once.
 *
 * All arithmetic is on decoded linear values (tex_decode / ls_tex_encode):
 * sRGB texels are decoded with the exact EOTF before weighting and the
 * result is re-encoded (averaging codes would darken: black and white give
 * code 128, linear 0.216, not 0.5). Channels are filtered independently (no alpha premultiplication),
 * as glGenerateMipmap does.
 */
#include "mip.h"
#include "wrap.h"

#include <stdlib.h>

/* Kernel half-width in destination texels for Lanczos-3 and Kaiser. */
#define MIP_KERNEL_RADIUS 3.0
/* Kaiser window shape parameter (sample.h: alpha 4). */
#define MIP_KAISER_ALPHA 4.0
/* Most taps one output texel can have: the source/destination ratio is at
 * most 3 (a 3-texel axis becomes 1), so the kernel spans 2·3·3 source
 * texels, plus one for the rounding of its ends. */
#define MIP_MAX_TAPS 20

/* ---- Kernels ------------------------------------------------------------- */

static double sinc(double x)
{
    const double pi = 3.14159265358979323846;
    if (x == 0.0) return 1.0;
    /* sample_sinpi, not libm's sin: the same weights on any machine
     * (portable_math.h), and exact zeros at the integers. */
    return sample_sinpi(x) / (pi * x);
}

/* Modified Bessel function of the first kind, order 0, by its power series
 * Σ ((x/2)^k / k!)²; for x ≤ 4 the terms fall below 1e-17 of the sum long
 * before k = 30. */
static double bessel_i0(double x)
{
    double sum = 1.0, term = 1.0, q = 0.25 * x * x;
    int k;
    for (k = 1; k < 30; ++k) {
        term *= q / ((double)k * (double)k);
        sum += term;
    }
    return sum;
}

/* Kernel value at x destination texels from the output centre. */
static double kernel_eval(sample_mipgen f, double x)
{
    const double R = MIP_KERNEL_RADIUS;
    double r;
    if (fabs(x) >= R) return 0.0;
    if (f == SAMPLE_MIPGEN_LANCZOS3) return sinc(x) * sinc(x / R); /* Lanczos window, a = 3 */
    /* Kaiser window I0(α√(1 − (x/R)²)) / I0(α) on the same sinc. */
    r = x / R;
    return sinc(x) * bessel_i0(MIP_KAISER_ALPHA * sqrt(1.0 - r * r)) / bessel_i0(MIP_KAISER_ALPHA);
}

/* ---- Edges --------------------------------------------------------------- */

/* Source index for a kernel tap at integer position i, or −1 when the tap is
 * dropped. The wrap modes that read a texel (repeat, mirror, clamp to edge)
 * do so through ls_wrap_index, the addressing function every sampler filter
 * uses. The border colour is sampler state the pyramid cannot know, so the
 * border-reading modes drop the tap and the remaining weights are
 * renormalized; the mirror-clamp-to-border modes first mirror about the
 * lower edge (|s| in EXT_texture_mirror_clamp), then drop what lies past the
 * upper one. */
static int tap_index(sample_wrap mode, int i, int n)
{
    switch (mode) {
    case SAMPLE_WRAP_MIRROR_CLAMP:
    case SAMPLE_WRAP_MIRROR_CLAMP_TO_BORDER:
        if (i < 0) i = -1 - i;
        return ls_wrap_index(SAMPLE_WRAP_CLAMP_TO_BORDER, (double)i, n, 1);
    case SAMPLE_WRAP_CLAMP:
    case SAMPLE_WRAP_CLAMP_TO_BORDER:
        return ls_wrap_index(SAMPLE_WRAP_CLAMP_TO_BORDER, (double)i, n, 1);
    default:
        return ls_wrap_index(mode, (double)i, n, 0);
    }
}

/* ---- Tap tables ---------------------------------------------------------- */

/* The box family. n_src = n_dst (an axis already 1 texel) copies. An even
 * axis averages texels 2i and 2i + 1. An odd axis n = 2m + 1 → m: output i
 * covers source texels [i·n/m, (i+1)·n/m) of the box-reconstructed signal,
 * which overlaps texels 2i, 2i + 1, 2i + 2 by (m − i)/n, m/n and (i + 1)/n of
 * its width. Each source texel then contributes m/n in total, so the mean is
 * kept, and output centres sit at (i + ½)·n/m: the texel-centre alignment of
 * the level rule. Only in-range texels are read, so the wrap mode is moot. */
static void fill_box(mip_axis *ax)
{
    int i, n = ax->n_src, m = ax->n_dst;
    for (i = 0; i < m; ++i) {
        int *ix = ax->idx + (size_t)i * ax->taps;
        float *w = ax->w + (size_t)i * ax->taps;
        if (n == m) {
            ix[0] = i; w[0] = 1.0f;
        } else if (n == 2 * m) {
            ix[0] = 2 * i; w[0] = 0.5f;
            ix[1] = 2 * i + 1; w[1] = 0.5f;
        } else {
            ix[0] = 2 * i; w[0] = (float)((double)(m - i) / n);
            ix[1] = 2 * i + 1; w[1] = (float)((double)m / n);
            ix[2] = 2 * i + 2; w[2] = (float)((double)(i + 1) / n);
        }
    }
}

/* A windowed sinc stretched to the destination spacing r = n_src / n_dst,
 * centred on output i's centre in source index space, c = (i + ½)·r − ½.
 * Weights are normalized to sum to 1 over the taps kept, so constants stay
 * constant whatever the edges do. Returns 0 when the kept weights cancel
 * (cannot happen for these kernels, whose central lobe always lands on an
 * in-range texel; checked rather than assumed). */
static int fill_kernel(mip_axis *ax, sample_mipgen f, sample_wrap wrap, int unwrapped)
{
    int i, n = ax->n_src, m = ax->n_dst;
    double r = (double)n / (double)m;
    for (i = 0; i < m; ++i) {
        int *ix = ax->idx + (size_t)i * ax->taps;
        float *w = ax->w + (size_t)i * ax->taps;
        double c = ((double)i + 0.5) * r - 0.5, wd[MIP_MAX_TAPS], sum = 0.0;
        int j, j0, t = 0;
        if (n == m) {
            ix[0] = i; w[0] = 1.0f;
            continue;
        }
        j0 = (int)ceil(c - MIP_KERNEL_RADIUS * r);
        for (j = j0; t < ax->taps && (double)j < c + MIP_KERNEL_RADIUS * r; ++j) {
            int s = unwrapped ? j : tap_index(wrap, j, n);
            double k = kernel_eval(f, ((double)j - c) / r);
            if ((s < 0 && !unwrapped) || k == 0.0) continue;
            ix[t] = s;
            wd[t] = k;
            sum += k;
            ++t;
        }
        if (!(sum > 1e-6)) return 0;
        for (j = 0; j < t; ++j) w[j] = (float)(wd[j] / sum);
    }
    return 1;
}

static void axis_free(mip_axis *ax)
{
    free(ax->idx);
    free(ax->w);
    ax->idx = NULL;
    ax->w = NULL;
}

static int axis_make(mip_axis *ax, int n_src, int n_dst, sample_mipgen f, sample_wrap wrap, int unwrapped)
{
    size_t cells;
    ax->n_src = n_src;
    ax->n_dst = n_dst;
    ax->taps = (f == SAMPLE_MIPGEN_BOX) ? 3 : MIP_MAX_TAPS;
    cells = (size_t)n_dst * (size_t)ax->taps;
    /* Unused taps read texel 0 with weight 0. */
    ax->idx = (int *)calloc(cells, sizeof *ax->idx);
    ax->w = (float *)calloc(cells, sizeof *ax->w);
    if (!ax->idx || !ax->w) {
        axis_free(ax);
        return 0;
    }
    if (f == SAMPLE_MIPGEN_BOX) {
        fill_box(ax);
        return 1;
    }
    if (!fill_kernel(ax, f, wrap, unwrapped)) {
        axis_free(ax);
        return 0;
    }
    return 1;
}

/* ---- Resampling ---------------------------------------------------------- */

/* Scratch memory is bounded by the width, not the area (doc/mip-and-lod.md,
 * "Memory"): the horizontal pass is kept only for the source rows the
 * vertical taps of nearby output rows read, in a direct-mapped cache of
 * MIP_ROW_SLOTS(taps) rows, where source row y lives in slot y mod slots.
 * The vertical taps of one output row are consecutive rows (a window of at
 * most `taps`) except where a wrap mode folds them at an edge, so with
 * twice that many slots the window never evicts itself; a folded tap that
 * collides is recomputed, which costs time, never correctness, because each
 * tap is added to the output row's sums as soon as its row is ready. */
#define MIP_ROW_SLOTS(taps) (2 * (taps))

typedef struct mip_scratch {
    float *row;    /* one decoded source row: n_src(x) RGBA floats */
    float *rows;   /* slots × n_dst(x) RGBA floats, horizontally filtered */
    int *tag;      /* source row held by each slot, −1 for none */
    double *acc;   /* n_dst(x) RGBA sums of the output row being built */
    int slots;
} mip_scratch;

/* Bytes of scratch a pyramid build of a w × h texture holds at most: sized
 * for level 1, the widest destination (every later level is narrower). */
size_t ls_mip_scratch_bytes(int w, sample_mipgen f)
{
    size_t dst = (size_t)(w > 1 ? w / 2 : 1), slots = MIP_ROW_SLOTS(f == SAMPLE_MIPGEN_BOX ? 3 : MIP_MAX_TAPS);
    return (size_t)w * 4 * sizeof(float) + slots * (dst * 4 * sizeof(float) + sizeof(int)) +
           dst * 4 * sizeof(double);
}

static void scratch_free(mip_scratch *s)
{
    free(s->row);
    free(s->rows);
    free(s->tag);
    free(s->acc);
    memset(s, 0, sizeof *s);
}

static int scratch_make(mip_scratch *s, int w, sample_mipgen f)
{
    size_t dst = (size_t)(w > 1 ? w / 2 : 1);
    memset(s, 0, sizeof *s);
    s->slots = MIP_ROW_SLOTS(f == SAMPLE_MIPGEN_BOX ? 3 : MIP_MAX_TAPS);
    s->row = (float *)malloc((size_t)w * 4 * sizeof(float));
    s->rows = (float *)malloc((size_t)s->slots * dst * 4 * sizeof(float));
    s->tag = (int *)malloc((size_t)s->slots * sizeof(int));
    s->acc = (double *)malloc(dst * 4 * sizeof(double));
    if (!s->row || !s->rows || !s->tag || !s->acc) {
        scratch_free(s);
        return 0;
    }
    return 1;
}

/* Source row y of level k − 1, filtered horizontally, from the cache. Sums
 * run in double and round once to float. */
static const float *filtered_row(sample_texture *tex, int k, const mip_axis *ax, mip_scratch *s, int y)
{
    const struct sample_level *S = &tex->level[k - 1];
    int slot = y % s->slots, i, t, c;
    float *out = s->rows + (size_t)slot * (size_t)ax->n_dst * 4;
    if (s->tag[slot] == y) return out;
    for (i = 0; i < S->w; ++i) tex_decode(tex, S, i, y, s->row + 4 * (size_t)i);
    for (i = 0; i < ax->n_dst; ++i) {
        const int *ix = ax->idx + (size_t)i * ax->taps;
        const float *w = ax->w + (size_t)i * ax->taps;
        double acc[4] = {0, 0, 0, 0};
        for (t = 0; t < ax->taps; ++t)
            for (c = 0; c < 4; ++c) acc[c] += (double)w[t] * s->row[4 * (size_t)ix[t] + c];
        for (c = 0; c < 4; ++c) out[4 * (size_t)i + c] = (float)acc[c];
    }
    s->tag[slot] = y;
    return out;
}

/* Level k from level k − 1 through the two tap tables, one output row at a
 * time: horizontal pass (filtered_row), then the vertical taps summed in
 * double in tap order and rounded once, so each pass adds one float
 * rounding per value. */
static void resample(sample_texture *tex, int k, const mip_axis *ax, const mip_axis *ay, mip_scratch *s)
{
    struct sample_level *D = &tex->level[k];
    int i, j, t, c;
    for (t = 0; t < s->slots; ++t) s->tag[t] = -1;
    for (j = 0; j < ay->n_dst; ++j) {
        const int *iy = ay->idx + (size_t)j * ay->taps;
        const float *w = ay->w + (size_t)j * ay->taps;
        for (i = 0; i < 4 * ax->n_dst; ++i) s->acc[i] = 0.0;
        for (t = 0; t < ay->taps; ++t) {
            const float *r;
            if (w[t] == 0.0f) continue; /* unused taps: adding 0·x changes no sum */
            r = filtered_row(tex, k, ax, s, iy[t]);
            for (i = 0; i < 4 * ax->n_dst; ++i) s->acc[i] += (double)w[t] * r[i];
        }
        for (i = 0; i < ax->n_dst; ++i) {
            float v[4];
            for (c = 0; c < 4; ++c) v[c] = (float)s->acc[4 * (size_t)i + c];
            ls_tex_encode(tex, v, D->data + (size_t)j * D->stride + (size_t)i * tex->texel_bytes);
        }
    }
}

/* Drop levels 1 … so that a failed build leaves the texture as it came. */
static void drop_levels(sample_texture *tex)
{
    int k;
    for (k = 1; k < tex->nlevels; ++k) {
        struct sample_level *L = &tex->level[k];
        tex->bytes -= L->stride * (size_t)L->h;
        free(L->data);
        memset(L, 0, sizeof *L);
    }
    tex->nlevels = 1;
}

/* Allocate and fill level k from level k − 1. */
static sample_status build_level(sample_texture *tex, int k, const sample_mip_params *p, mip_scratch *s,
                                 sample_error *err)
{
    const struct sample_level *S = &tex->level[k - 1];
    mip_axis ax, ay;
    sample_status st = ls_tex_alloc_level(tex, k, err);
    if (st != SAMPLE_OK) return st;
    tex->nlevels = k + 1;
    memset(&ax, 0, sizeof ax);
    memset(&ay, 0, sizeof ay);
    if (!axis_make(&ax, S->w, tex->level[k].w, p->filter, p->wrap_s, 0) ||
        !axis_make(&ay, S->h, tex->level[k].h, p->filter, p->wrap_t, 0)) {
        axis_free(&ax);
        axis_free(&ay);
        return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate filter taps for level %d", k);
    }
    resample(tex, k, &ax, &ay, s);
    axis_free(&ax);
    axis_free(&ay);
    return SAMPLE_OK;
}

sample_status ls_mip_build(sample_texture *tex, const sample_mip_params *p, sample_error *err)
{
    int k, full = 1, m = tex->width > tex->height ? tex->width : tex->height;
    sample_status st = SAMPLE_OK;
    mip_scratch s;
    while (m > 1) { m >>= 1; ++full; }
    if (p->max_levels > 0 && p->max_levels < full) full = p->max_levels;
    if (full < 2) return SAMPLE_OK;
    if (!scratch_make(&s, tex->width, p->filter))
        return sample_error_set(err, SAMPLE_E_OUT_OF_MEMORY, "cannot allocate mip scratch for a %d x %d texture",
                                tex->width, tex->height);
    for (k = 1; k < full && st == SAMPLE_OK; ++k) st = build_level(tex, k, p, &s, err);
    scratch_free(&s);
    if (st != SAMPLE_OK) drop_levels(tex);
    return st;
}

int ls_mip_axis_unwrapped(mip_axis *ax, int n_src, int n_dst, sample_mipgen f)
{
    memset(ax, 0, sizeof *ax);
    return axis_make(ax, n_src, n_dst, f, SAMPLE_WRAP_CLAMP_TO_EDGE, 1);
}

void ls_mip_axis_free(mip_axis *ax) { axis_free(ax); }
