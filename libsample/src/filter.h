/*
 * The filters of one query (filter.c), above the level-of-detail and
 * reconstruction layers and below the batch loops: the OpenGL filters'
 * chosen levels reconstructed and blended (GL 4.6 §8.14.2–8.14.3), and
 * the footprint filters (DESIGN §7), each registered once in
 * filter.c's table by its sample_footprint value.
 */
#ifndef SAMPLE_FILTER_H
#define SAMPLE_FILTER_H

#include "aniso.h"
#include "footprint.h"

/* Reconstruct and blend the levels an OpenGL filter chose for λ (lod_select):
 * the result, its derivatives (dds/ddt may be NULL) and the level stats
 * (st may be NULL). Returns texels read. */
uint32_t ls_filter_gl_levels(const sample_ctx *c, const sample_query *q, float lam, const lod_choice *ch,
                          float out[4], float dds[4], float ddt[4], sample_stats *st);

/* Query i of a batch (finite, λ > 0) through the sampler's footprint
 * filter, its result and stats written to the batch's arrays. Both batch
 * loops hand their footprint queries here; their λ ≤ 0 queries are the mag
 * filter's. With `pl` (Blinn–Newell, EWA: ls_fp_footprint_plan of query i,
 * made earlier) only the accumulating pass runs; NULL runs the whole
 * filter. */
void ls_filter_footprint_query(const sample_ctx *c, const sample_batch_args *a, size_t i, const fp_plan *pl);

/* Query i of a batch through the reference path (sampler.c): the border
 * colour for non-finite input, else λ, then the footprint filter or the
 * OpenGL filters' levels. The environment maps' loops (env_batch.c) hand
 * it the 2D query their direction maps to. */
void ls_reference_query(const sample_ctx *c, const sample_batch_args *a, size_t i);

/* The checks every batch entry point makes, whatever its query type: a
 * texture of the entry point's kind, a valid sampler, and the query and
 * result arrays where count > 0 (SAMPLE_E_INVALID_ARGUMENT, or the
 * sampler's status, otherwise). *run is 0 when there is nothing to do. */
sample_status ls_batch_check(const sample_texture *tex, sample_texture_kind kind, const sample_sampler *smp,
                             size_t count, const void *queries, const float *rgba, int *run);

#endif /* SAMPLE_FILTER_H */
