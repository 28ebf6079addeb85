/*
 * Anisotropic filtering, GPU style (DESIGN §7; OpenGL 4.6 §8.14.1 with
 * ARB/EXT_texture_filter_anisotropic, whose reference implementation this
 * follows):
 *
 *   Px = |dP/dx|, Py = |dP/dy| in base-level texels
 *   N  = min(⌈Pmax / Pmin⌉, maxAniso)       λ = log2(Pmax / N)
 *   τ  = 1/N · Σ_{i=1..N} τ_trilinear(P + (i/(N + 1) − ½)·dP_major, λ)
 *
 * so the probes are spread over one pixel step along the major column
 * (offsets from −½ + 1/(N + 1) to ½ − 1/(N + 1)), not over the 2 × 2 region.
 */
#include "aniso.h"
#include "cube.h"
#include "kernels.h"

/* At most this many probes: 8 texels each (two bilinear levels) stay within
 * SAMPLE_MAX_FOOTPRINT_TEXELS whatever max_anisotropy says. */
#define ANISO_MAX_PROBES (SAMPLE_MAX_FOOTPRINT_TEXELS / 8)

/* N for a footprint (exposed to the tests through ls_fp_aniso_count). */
int ls_fp_aniso_count(const sample_sampler *smp, double pmax, double pmin)
{
    /* maxAniso is a float state; probes are whole, so its integer part. */
    double maxa = floor((double)smp->max_anisotropy), ratio;
    int n, p2;
    if (maxa > ANISO_MAX_PROBES) maxa = ANISO_MAX_PROBES;
    if (maxa < 1.0) maxa = 1.0;
    /* Pmin = 0 (a rank-one footprint) is the limit of an unbounded ratio. */
    ratio = pmin > 0.0 ? ceil(pmax / pmin) : maxa;
    n = (int)(ratio < maxa ? (ratio < 1.0 ? 1.0 : ratio) : maxa);
    if (smp->options & SAMPLE_OPT_ANISO_POW2) {
        /* Round up, as hardware with power-of-two probe counts does; this
         * may exceed maxAniso (by less than 2×) but never the texel cap. */
        for (p2 = 1; p2 < n; p2 <<= 1) {
        }
        n = p2 > ANISO_MAX_PROBES ? ANISO_MAX_PROBES : p2;
    }
    return n;
}

/* log2 k for k = 1 … ANISO_MAX_PROBES, to 17 significant digits (the
 * nearest doubles): λ' = log2(Pmax / N) = log2 ρ − log2 N reuses the log2 ρ
 * that decided minification, so a query costs one logarithm, not two. */
static const double log2_probes[ANISO_MAX_PROBES] = {
    0, 1, 1.5849625007211561, 2,
    2.3219280948873622, 2.5849625007211561, 2.8073549220576042, 3,
    3.1699250014423122, 3.3219280948873622, 3.4594316186372973, 3.5849625007211561,
    3.7004397181410922, 3.8073549220576042, 3.9068905956085187, 4,
    4.0874628412503391, 4.1699250014423122, 4.2479275134435852, 4.3219280948873626,
    4.3923174227787607, 4.4594316186372973, 4.5235619560570131, 4.5849625007211561,
    4.6438561897747244, 4.7004397181410917, 4.7548875021634682, 4.8073549220576037,
    4.8579809951275719, 4.9068905956085187, 4.9541963103868749, 5,
    5.0443941193584534, 5.0874628412503391, 5.1292830169449664, 5.1699250014423122,
    5.2094533656289501, 5.2479275134435852, 5.2854022188622487, 5.3219280948873626,
    5.3575520046180838, 5.3923174227787607, 5.4262647547020979, 5.4594316186372973,
    5.4918530963296748, 5.5235619560570131, 5.5545888516776376, 5.5849625007211561,
    5.6147098441152083, 5.6438561897747244, 5.6724253419714952, 5.7004397181410917,
    5.7279204545631988, 5.7548875021634682, 5.7813597135246599, 5.8073549220576037,
    5.8328900141647413, 5.8579809951275719, 5.8826430493618416, 5.9068905956085187,
    5.9307373375628867, 5.9541963103868749, 5.9772799234999168, 6,
    6.0223678130284544, 6.0443941193584534, 6.0660891904577721, 6.0874628412503391,
    6.1085244567781691, 6.1292830169449664, 6.1497471195046822, 6.1699250014423122,
    6.1898245588800176, 6.2094533656289501, 6.2288186904958804, 6.2479275134435852,
    6.266786540694901, 6.2854022188622487, 6.3037807481771031, 6.3219280948873626,
    6.3398500028846243, 6.3575520046180838, 6.3750394313469245, 6.3923174227787607,
    6.4093909361377017, 6.4262647547020979, 6.4429434958487279, 6.4594316186372973,
    6.4757334309663976, 6.4918530963296748, 6.5077946401986964, 6.5235619560570131,
    6.539158811108031, 6.5545888516776376, 6.5698556083309478, 6.5849625007211561,
    6.5999128421871278, 6.6147098441152083, 6.6293566200796095, 6.6438561897747244,
    6.6582114827517946, 6.6724253419714952, 6.6865005271832185, 6.7004397181410917,
    6.7142455176661224, 6.7279204545631988, 6.7414669864011474, 6.7548875021634682,
    6.768184324776926, 6.7813597135246599, 6.7944158663501062, 6.8073549220576037,
    6.8201789624151878, 6.8328900141647413, 6.8454900509443748, 6.8579809951275719,
    6.8703647195834048, 6.8826430493618416, 6.8948177633079437, 6.9068905956085187,
    6.9188632372745946, 6.9307373375628867, 6.9425145053392399, 6.9541963103868749,
    6.965784284662087, 6.9772799234999168, 6.9886846867721655, 7,
};
_Static_assert(ANISO_MAX_PROBES == 128, "log2_probes has one entry per probe count");

void ls_fp_aniso_setup_of(const sample_ctx *c, const sample_query *q, const double rho2[2],
                       double log2_rho, float call_bias, fp_aniso_setup *a)
{
    /* Px, Py: the column lengths in base texels (lod_log2_rho). */
    int xmajor = rho2[0] >= rho2[1];
    double pmax = sqrt(xmajor ? rho2[0] : rho2[1]), pmin = sqrt(xmajor ? rho2[1] : rho2[0]), lb;
    a->set = NULL;
    a->ms = xmajor ? q->dsdx : q->dsdy;
    a->mt = xmajor ? q->dtdx : q->dtdy;
    a->n = ls_fp_aniso_count(c->smp, pmax, pmin);
    lb = log2_rho - log2_probes[a->n - 1];
    a->lam = lod_lambda(c, lb < -1e4 ? -1e4f : (float)lb, call_bias);
    /* Each probe is trilinear (LINEAR_MIPMAP_LINEAR, eqs. 8.17–8.18) at λ';
     * λ' ≤ 0 reads the base level bilinearly. */
    ls_lod_split(c, a->lam, &a->l0, &a->l1, &a->f);
    if (a->f == 0.0f) a->l1 = a->l0;
}

/* Ask for the lines the probes of one level will read, so that their
 * misses overlap (the queries whose probes fast_gl.c's aniso_address does
 * not address: more than 16 probes, clamping wraps, blocks across an edge).
 * Only a hint, so the probes' texel positions are stepped along the major
 * axis in float (no per-probe division or double); every probe's block is
 * asked for, repeats included (ctx_prefetch_block). Inline: GCC deletes
 * calls to a function whose only effect is a prefetch
 * (doc/performance.md). */
SAMPLE_FORCE_INLINE void prefetch_probes(const sample_ctx *c, int lv, float s0, float t0, float s1, float t1, int n)
{
    const struct sample_level *L = &c->tex->level[lv];
    float u = s0 * (float)L->w - 0.5f, v = t0 * (float)L->h - 0.5f;
    float du = n > 1 ? (s1 - s0) * (float)L->w / (float)(n - 1) : 0.0f;
    float dv = n > 1 ? (t1 - t0) * (float)L->h / (float)(n - 1) : 0.0f;
    int k;
    for (k = 0; k < n; ++k, u += du, v += dv) ctx_prefetch_block(c, L, u, v);
}

void ls_fp_aniso_prefetch(const sample_ctx *c, const sample_query *q, const fp_aniso_setup *a)
{
    float s0, t0, s1, t1;
    fp_aniso_probe(q, a, 1, &s0, &t0);
    fp_aniso_probe(q, a, a->n, &s1, &t1);
    prefetch_probes(c, a->l0, s0, t0, s1, t1, a->n);
    /* On the coarser level the probes are half as far apart in texels. */
    if (a->l1 != a->l0) prefetch_probes(c, a->l1, s0, t0, s1, t1, a->n / 2 + 1);
}

/* Whether some probe of a cube-map query leaves its face: the probes lie
 * on a segment, so whether one of its ends does. */
static int probes_leave_face(const sample_query *q, const fp_aniso_setup *a)
{
    float s0, t0, s1, t1;
    fp_aniso_probe(q, a, 1, &s0, &t0);
    fp_aniso_probe(q, a, a->n, &s1, &t1);
    return !(s0 >= 0.0f && s0 <= 1.0f && t0 >= 0.0f && t0 <= 1.0f && s1 >= 0.0f && s1 <= 1.0f && t1 >= 0.0f &&
             t1 <= 1.0f);
}

/* A probe of a cube-map query placed by direction (by_direction): c->q3
 * holds the query's direction R and the probes' axis dR (in dpdx), and s
 * the probe's offset along it; the probe is the bilinear value of the face
 * that R + s·dR selects, at its (s, t) there — the seamless LINEAR of that
 * direction (GL 4.6 §8.13.1). */
static uint32_t probe_at_direction(const sample_ctx *c, int lv, float s, float t, float out[4], float dds[4],
                                   float ddt[4])
{
    const sample_query3 *a = c->q3;
    sample_ctx d = *c;
    double r[3], ps, pt;
    int k;
    (void)t;
    for (k = 0; k < 3; ++k) r[k] = (double)a->p[k] + (double)s * a->dpdx[k];
    d.face = cube_face_of(r);
    /* R + s·dR = 0 (dR = −R/s: no direction) reads the centre's. */
    if (!(cube_dot(d.face, 0, r) > 0.0)) {
        for (k = 0; k < 3; ++k) r[k] = a->p[k];
        d.face = cube_face_of(r);
    }
    cube_face_st(d.face, r, &ps, &pt);
    return ctx_readers(c)->bilinear(&d, lv, (float)ps, (float)pt, out, dds, ddt);
}

/* The probes of a cube-map query whose probes leave its face, placed by
 * direction: probe i at R + oᵢ·dR (oᵢ = i/(N + 1) − ½, dR the major
 * derivative of the query's own direction), not at the face-plane point
 * s + oᵢ·∂s. Those are the same directions to first order; but the
 * face-plane points past an edge are mapped onto the neighbour by the
 * unfolding, which near a corner is sheared against the neighbour's own
 * coordinates and leaves the quadrant past the corner without a face. The
 * probes' directions depend on the query alone, not on the face its
 * centre selects, so the result does not jump where the centre changes
 * face (doc/environment-maps.md, "Footprint filters"). The offsets reach
 * probe_at_direction as its s (a query at s = 0 with the axis (1, 0)). */
static uint32_t by_direction(const sample_ctx *c, const fp_aniso_setup *a, int xmajor, float out[4], float dds[4],
                             float ddt[4])
{
    sample_query3 axis;
    sample_query q0;
    fp_aniso_setup b = *a;
    sample_ctx d = *c;
    memset(&axis, 0, sizeof axis);
    memset(&q0, 0, sizeof q0);
    memcpy(axis.p, c->q3->p, sizeof axis.p);
    memcpy(axis.dpdx, xmajor ? c->q3->dpdx : c->q3->dpdy, sizeof axis.dpdx);
    d.q3 = &axis;
    b.ms = 1.0;
    b.mt = 0.0;
    return fp_aniso_probes(&d, &q0, &b, probe_at_direction, out, dds, ddt);
}

uint32_t ls_fp_anisotropic(const sample_ctx *c, const sample_query *q, float call_bias,
                        float out[4], float dds[4], float ddt[4], sample_stats *st)
{
    double rho2[2], lr = lod_log2_rho(c, q, rho2);
    fp_aniso_setup a;
    uint32_t texels;
    ls_fp_aniso_setup_of(c, q, rho2, lr, call_bias, &a);
    /* ls_recon_level's bilinear, as the batch's kernels read it (the same
     * bits in every table). */
    if (c->q3 && probes_leave_face(q, &a))
        texels = by_direction(c, &a, rho2[0] >= rho2[1], out, dds, ddt);
    else
        texels = fp_aniso_probes(c, q, &a, ctx_readers(c)->bilinear, out, dds, ddt);
    if (st) fp_aniso_stats(&a, st);
    return texels;
}
