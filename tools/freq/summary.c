/* The two numbers per filter (DESIGN §9): pass-band fidelity and aliasing,
 * with their worst case over orientations and the cost. */
#include "freq.h"

#include <math.h>

/* Mean amplitude of one curve's points in a band; 0 points → NaN. */
static double curve_mean(const fq_sweep *s, int b, int im, int it, int ir, int pass, int *count,
                         double *texels, double *ns, int *ncost)
{
    double sum = 0.0;
    int n = 0;
    size_t k;
    for (k = 0; k < s->count; ++k) {
        const fq_point *p = &s->pts[k];
        double F = p->res.F;
        if (p->backend != b || p->im != im || p->itheta != it || p->ir != ir) continue;
        /* Cost over every point of the curve, band or not. */
        if (pass) {
            *texels += p->res.texels;
            *ns += p->res.ns;
            (*ncost)++;
        }
        if (pass ? (F > 0.0 && F < FQ_PASS_BELOW) : (F > FQ_STOP_ABOVE)) {
            sum += p->res.amp;
            n++;
        }
    }
    *count = n;
    return n ? sum / n : NAN;
}

fq_stat fq_summarize(const fq_plan *plan, const fq_sweep *s, int backend, int im, int ir)
{
    fq_stat st = {0};
    double psum = 0.0, asum = 0.0, texels = 0.0, ns = 0.0;
    int npc = 0, nac = 0, ncost = 0, m, r, t;
    st.pass_worst = INFINITY;
    st.alias_worst = -INFINITY;
    /* Each curve weighs the same in the means, whatever its point count
     * (m = 1 has fewer points than m = 16). */
    for (m = 0; m < plan->nm; ++m) {
        if (im >= 0 && m != im) continue;
        for (r = 0; r < plan->nr; ++r) {
            if (ir >= 0 && r != ir) continue;
            for (t = 0; t < plan->ntheta; ++t) {
                int np, na;
                double pm = curve_mean(s, backend, m, t, r, 1, &np, &texels, &ns, &ncost);
                double am = curve_mean(s, backend, m, t, r, 0, &na, &texels, &ns, &ncost);
                if (np) {
                    psum += pm;
                    npc++;
                    st.npass += np;
                    if (pm < st.pass_worst) st.pass_worst = pm;
                }
                if (na) {
                    asum += am;
                    nac++;
                    st.nstop += na;
                    if (am > st.alias_worst) st.alias_worst = am;
                }
            }
        }
    }
    st.pass = npc ? psum / npc : NAN;
    st.alias = nac ? asum / nac : NAN;
    if (!npc) st.pass_worst = NAN;
    if (!nac) st.alias_worst = NAN;
    st.texels = ncost ? texels / ncost : NAN;
    st.ns = ncost ? ns / ncost : NAN;
    return st;
}
