/*
 * Feline: EWA's ellipse approximated by Gaussian-weighted bilinear probes
 * on a lattice along its major axis, on one level finer than the minor
 * axis (footprint_feline.c; McCormack et al. 1999,
 * "Feline: fast elliptical lines for anisotropic texture mapping";
 * Mavridis & Papaioannou 2011). DESIGN §7, doc/footprint-filters.md.
 */
#ifndef SAMPLE_FOOTPRINT_FELINE_H
#define SAMPLE_FOOTPRINT_FELINE_H

#include "aniso.h"
#include "lod.h"

/* The probes of query q (a minified one): its level (a->l1 == a->l0,
 * a->f = 0), λ', and the weighted probe set, which a->set then points to
 * (at least the centre probe, at most FP_PROBES_MAX). */
void ls_fp_feline_setup(const sample_ctx *c, const sample_query *q, float call_bias, fp_aniso_setup *a,
                        fp_probe_set *set);

/* Returns texels read, fills out (and dds/ddt if non-NULL) and stats (if
 * non-NULL); applies the sampler's and the call's bias itself. With u
 * (a uniform in [0, 1)) the stochastic estimate instead: one probe drawn
 * with its weight (dds, ddt untouched). */
uint32_t ls_fp_feline(const sample_ctx *c, const sample_query *q, float call_bias, const double *u, float out[4],
                      float dds[4], float ddt[4], sample_stats *st);

#endif /* SAMPLE_FOOTPRINT_FELINE_H */
