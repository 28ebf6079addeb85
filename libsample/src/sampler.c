/*
 * Sampler state, validation and the batch dispatch: the state is checked and
 * the per-batch context built once; each query then takes one path.
 */
#include "filter.h"
#include "kernels.h"
#include "sample/testing.h"
#include "stochastic.h"

void sample_sampler_init(sample_sampler *s)
{
    /* OpenGL 4.6 table 23.18 (sampler object state) initial values. */
    if (!s) return;
    memset(s, 0, sizeof *s);
    s->wrap_s = s->wrap_t = s->wrap_r = SAMPLE_WRAP_REPEAT;
    s->min_filter = SAMPLE_NEAREST_MIPMAP_LINEAR;
    s->mag_filter = SAMPLE_LINEAR;
    s->min_lod = -1000.0f;
    s->max_lod = 1000.0f;
    s->base_level = 0;
    s->max_level = 1000;
    s->max_anisotropy = 1.0f;
    /* MAX_TEXTURE_LOD_BIAS: the minimum an implementation must support is
     * 2; 16 is what desktop drivers report. */
    s->max_lod_bias = 16.0f;
    s->footprint = SAMPLE_FOOTPRINT_NONE;
    s->cubic = SAMPLE_CUBIC_CATMULL_ROM;
    s->ewa_kernel = SAMPLE_EWA_GAUSSIAN;
}

void sample_mip_params_init(sample_mip_params *p)
{
    if (!p) return;
    p->filter = SAMPLE_MIPGEN_BOX;
    p->wrap_s = p->wrap_t = SAMPLE_WRAP_CLAMP_TO_EDGE;
    p->max_levels = 0;
    p->wrap_r = SAMPLE_WRAP_CLAMP_TO_EDGE;
}

sample_status sample_sampler_validate(const sample_sampler *s)
{
    if (!s) return SAMPLE_E_INVALID_ARGUMENT;
    if ((unsigned)s->wrap_s >= SAMPLE_WRAP_COUNT || (unsigned)s->wrap_t >= SAMPLE_WRAP_COUNT ||
        (unsigned)s->wrap_r >= SAMPLE_WRAP_COUNT)
        return SAMPLE_E_INVALID_ARGUMENT;
    if ((unsigned)s->min_filter >= SAMPLE_FILTER_COUNT) return SAMPLE_E_INVALID_ARGUMENT;
    if (s->mag_filter != SAMPLE_NEAREST && s->mag_filter != SAMPLE_LINEAR && s->mag_filter != SAMPLE_CUBIC)
        return SAMPLE_E_INVALID_ARGUMENT;
    if ((unsigned)s->footprint >= SAMPLE_FOOTPRINT_COUNT || (unsigned)s->cubic >= SAMPLE_CUBIC_COUNT ||
        (unsigned)s->ewa_kernel >= SAMPLE_EWA_KERNEL_COUNT)
        return SAMPLE_E_INVALID_ARGUMENT;
    /* NaN fails every comparison below, so it is rejected too. */
    if (!(s->max_anisotropy >= 1.0f) || !isfinite(s->max_anisotropy)) return SAMPLE_E_INVALID_ARGUMENT;
    if (!isfinite(s->lod_bias) || !(s->max_lod_bias >= 0.0f)) return SAMPLE_E_INVALID_ARGUMENT;
    if (isnan(s->min_lod) || isnan(s->max_lod) || s->min_lod > s->max_lod) return SAMPLE_E_INVALID_ARGUMENT;
    if (s->base_level < 0 || s->max_level < s->base_level) return SAMPLE_E_INVALID_ARGUMENT;
    return SAMPLE_OK;
}

/* One query of the reference path: the border colour for non-finite
 * input (DESIGN §10), else λ (GL 4.6 §8.14.1), then the footprint filter
 * when one is set and λ > 0, else the level choice of §8.14.2–8.14.3 and
 * the reconstruction of each chosen level. */
void ls_reference_query(const sample_ctx *c, const sample_batch_args *a, size_t i)
{
    const sample_query *q = &a->queries[i];
    float *out = a->rgba + 4 * i;
    float *dds = a->drgba_ds ? a->drgba_ds + 4 * i : NULL;
    float *ddt = a->drgba_dt ? a->drgba_dt + 4 * i : NULL;
    sample_stats local, *st = a->stats ? &a->stats[i] : &local;
    float lam;
    lod_choice ch;

    if (batch_query_finite(a, i)) {
        lam = lod_lambda(c, lod_lambda_base(c, q), a->lod_bias ? a->lod_bias[i] : 0.0f);
        if (c->smp->footprint != SAMPLE_FOOTPRINT_NONE && lam > 0.0f) {
            ls_filter_footprint_query(c, a, i, NULL);
            return;
        }
        ch = lod_select(c, lam);
        /* Stochastic: one of two blended levels, with its weight (its
         * derivatives too: the expectation's are the blend's). */
        if (a->u && ch.level1 >= 0) {
            double u = ls_stochastic_u(a, i);
            if (ls_stochastic_pick2(ch.frac, &u)) ch.level0 = ch.level1;
            ch.level1 = -1;
            ch.frac = 0.0f;
        }
        st->texels = ls_filter_gl_levels(c, q, lam, &ch, out, dds, ddt, st);
        return;
    }
    batch_border(c, a, i);
}

sample_status ls_batch_check(const sample_texture *tex, sample_texture_kind kind, const sample_sampler *smp,
                             size_t count, const void *queries, const float *rgba, int *run)
{
    sample_status st;
    *run = 0;
    if (!tex || tex->kind != kind) return SAMPLE_E_INVALID_ARGUMENT;
    if ((st = sample_sampler_validate(smp)) != SAMPLE_OK) return st;
    if (count == 0) return SAMPLE_OK;
    if (!queries || !rgba) return SAMPLE_E_INVALID_ARGUMENT;
    *run = 1;
    return SAMPLE_OK;
}

/* sample_query is a 2D query (s, t and a 2 × 2 Jacobian): for 2D
 * textures; other kinds have their own entry points. */
static sample_status batch_check(const sample_texture *tex, const sample_sampler *smp,
                                 const sample_batch_args *a, int *run)
{
    *run = 0;
    if (!a) return SAMPLE_E_INVALID_ARGUMENT;
    return ls_batch_check(tex, SAMPLE_TEXTURE_2D, smp, a->count, a->queries, a->rgba, run);
}

static void reference_batch(const sample_ctx *c, const sample_batch_args *a)
{
    size_t i;
    for (i = 0; i < a->count; ++i) ls_reference_query(c, a, i);
}

sample_status sample_batch(const sample_texture *tex, const sample_sampler *smp,
                           const sample_batch_args *a)
{
    sample_ctx c;
    fast_gl_fn fast;
    uintptr_t ticket;
    int run;
    sample_status st = batch_check(tex, smp, a, &run);
    if (!run) return st;
    /* The instruction set is chosen here, once per batch. The fast path
     * forms texel addresses from resident levels or within a source's
     * tiles; a texture with another texel source runs the reference loop,
     * whose results are the fast path's bit for bit (texel.h, struct
     * ls_texel_source). */
    ls_ctx_init(&c, tex, smp, tex_addressable(tex) ? ls_isa_kernels_active() : &ls_isa_kernels_reference);
    fast = c.isa->fast_gl[tex->format][tex->channels - 1];
    ticket = tex_reads_begin(tex);
    /* Stochastic queries have no fast-path kernels: they run the
     * reference path (the same reads; doc/footprint-filters.md). */
    if (fast && !a->u)
        fast(&c, a);
    else
        reference_batch(&c, a);
    tex_reads_end(tex, ticket);
    return SAMPLE_OK;
}

sample_status sample_batch_reference(const sample_texture *tex, const sample_sampler *smp,
                                     const sample_batch_args *a)
{
    sample_ctx c;
    int run;
    sample_status st = batch_check(tex, smp, a, &run);
    uintptr_t ticket;
    if (!run) return st;
    ls_ctx_init(&c, tex, smp, &ls_isa_kernels_reference);
    ticket = tex_reads_begin(tex);
    reference_batch(&c, a);
    tex_reads_end(tex, ticket);
    return SAMPLE_OK;
}
sample_status sample_one(const sample_texture *tex, const sample_sampler *smp,
                         const sample_query *query, float rgba[4])
{
    sample_batch_args a;
    memset(&a, 0, sizeof a);
    a.count = 1;
    a.queries = query;
    a.rgba = rgba;
    return sample_batch(tex, smp, &a);
}
