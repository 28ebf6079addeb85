/*
 * The batch loops of environment maps (doc/environment-maps.md): each
 * direction query is mapped to a 2D query on a level's plane — a cube
 * face's (s, t) and Jacobian, or a lat-long map's — and filtered by the
 * reference path (ls_reference_query) with the context's addressing set
 * to the kind's (env_addr.h), so that every filter, from NEAREST to EWA,
 * serves environment maps unchanged.
 */
#include "cube.h"
#include "filter.h"
#include "kernels.h"
#include "latlong.h"

/* Maps query q to its 2D query; returns the layer (cube face) or −1 where
 * the query has no direction (the zero vector). */
typedef int (*env_map_fn)(const sample_texture *tex, const sample_query3 *q, sample_query *out);

static sample_status env_batch(const sample_texture *tex, const sample_sampler *smp, const sample_batch3_args *a,
                               sample_texture_kind kind, ls_env_mode mode, env_map_fn map)
{
    sample_sampler s;
    sample_ctx c;
    sample_status st;
    uintptr_t ticket;
    size_t i;
    int run;
    if (!a) return SAMPLE_E_INVALID_ARGUMENT;
    if ((st = ls_batch_check(tex, kind, smp, a->count, a->queries, a->rgba, &run)) != SAMPLE_OK || !run) return st;
    /* The kind's addressing replaces the wrap modes (GL 4.6 §8.13.1
     * ignores them for seamless cube maps); CLAMP_TO_EDGE is the one mode
     * that leaves a coordinate untouched (ls_wrap_coord). */
    s = *smp;
    s.wrap_s = s.wrap_t = SAMPLE_WRAP_CLAMP_TO_EDGE;
    ls_ctx_init(&c, tex, &s, &ls_isa_kernels_reference);
    c.env = mode;
    ticket = tex_reads_begin(tex);
    for (i = 0; i < a->count; ++i) {
        const sample_query3 *q = &a->queries[i];
        const float *bias = a->lod_bias ? &a->lod_bias[i] : NULL;
        sample_stats *st3 = a->stats ? &a->stats[i] : NULL;
        sample_query q2;
        sample_batch_args one;
        sample_ctx fc = c;
        int layer = -1;
        if (floats_finite(q, 9) && (!bias || floats_finite(bias, 1))) layer = map(tex, q, &q2);
        if (layer < 0) {
            memcpy(a->rgba + 4 * i, c.border, sizeof c.border);
            if (st3) stats_clear(st3);
            continue;
        }
        fc.face = layer;
        if (mode == LS_ENV_CUBE) fc.q3 = q;
        memset(&one, 0, sizeof one);
        one.count = 1;
        one.queries = &q2;
        one.lod_bias = bias;
        one.rgba = a->rgba + 4 * i;
        one.stats = st3;
        ls_reference_query(&fc, &one, 0);
    }
    tex_reads_end(tex, ticket);
    return SAMPLE_OK;
}

static int cube_map(const sample_texture *tex, const sample_query3 *q, sample_query *out)
{
    (void)tex;
    return ls_cube_query(q, out);
}

sample_status sample_batch_cube(const sample_texture *tex, const sample_sampler *smp, const sample_batch3_args *a)
{
    return env_batch(tex, smp, a, SAMPLE_TEXTURE_CUBE, LS_ENV_CUBE, cube_map);
}

static int latlong_map(const sample_texture *tex, const sample_query3 *q, sample_query *out)
{
    (void)tex;
    return ls_latlong_query(q, out);
}

sample_status sample_batch_latlong(const sample_texture *tex, const sample_sampler *smp, const sample_batch3_args *a)
{
    return env_batch(tex, smp, a, SAMPLE_TEXTURE_2D, LS_ENV_LATLONG, latlong_map);
}

sample_status sample_batch_env(const sample_texture *tex, const sample_sampler *smp, const sample_batch3_args *a)
{
    if (tex && tex->kind == SAMPLE_TEXTURE_CUBE) return sample_batch_cube(tex, smp, a);
    return sample_batch_latlong(tex, smp, a);
}
