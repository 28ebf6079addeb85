/*
 * Stochastic filtering (sample_batch_args.u; stochastic.c,
 * doc/footprint-filters.md, "Stochastic filtering"): one random estimate
 * per query whose expectation over a uniform u is the deterministic
 * filter's result (Pharr et al. 2024, "Filtering after shading with
 * stochastic texture filtering").
 */
#ifndef SAMPLE_STOCHASTIC_H
#define SAMPLE_STOCHASTIC_H

#include "lod.h"

/* Query i's u reduced to [0, 1) (fractional part; NaN and ±inf read as
 * 0); a->u must be set. */
double ls_stochastic_u(const sample_batch_args *a, size_t i);

/* Choose one of two levels blended with weight f on the second: returns 1
 * (the second) with probability f, and rescales *u to a fresh uniform in
 * [0, 1) for what the caller draws next. */
int ls_stochastic_pick2(double f, double *u);

/* The anisotropic filter's estimate: one of its N probes (each with
 * probability 1/N), that probe's level chosen with its blend weight: one
 * bilinear read. Fills out and st; returns texels read. */
uint32_t ls_fp_aniso_draw(const sample_ctx *c, const sample_query *q, float call_bias, double u, float out[4],
                          sample_stats *st);

#endif /* SAMPLE_STOCHASTIC_H */
