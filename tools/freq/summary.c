/* The two numbers per filter (DESIGN §9): pass-band fidelity and aliasing,
 * with their worst case over orientations and the cost. */
#include "freq.h"

#include <math.h>

/* Mean amplitude of one curve's points in a band (NaN if none), and its
 * cost summed over all of its points. */
static double curve_mean(const fq_sweep *s, int b, int im, int it, int ir, int pass, int *count,
                         double *texels, double *ns, int *ncost)
{
    const fq_point *p;
    size_t k, n = fq_curve(s, b, im, it, ir, &p);
    double sum = 0.0;
    int c = 0;
    for (k = 0; k < n; ++k) {
        double F = p[k].res.F;
        if (pass) {
            *texels += p[k].res.texels;
            *ns += p[k].res.ns;
            (*ncost)++;
        }
        if (pass ? (F > 0.0 && F < FQ_PASS_BELOW) : (F > FQ_STOP_ABOVE)) {
            sum += p[k].res.amp;
            c++;
        }
    }
    *count = c;
    return c ? sum / c : NAN;
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
