/*
 * Footprint filters in 3D textures (DESIGN §7, §11; doc/volumes.md).
 *
 * A surface pixel that cuts through a volume covers a flat patch of it:
 * the parallelogram P + x·dP/dx + y·dP/dy, (x, y) ∈ [−1, 1]², a 2D
 * footprint lying in a plane of the 3D texel grid. The filters are the 2D
 * ones carried over to that patch:
 *
 *   - anisotropic: N trilinear probes (each eq. 8.11 on two levels) along
 *     the longer derivative, N and λ as ARB_texture_filter_anisotropic
 *     says with P measured in 3D texels;
 *   - EWA and Blinn–Newell: the patch's Jacobian J (3 × 2, texels of the
 *     level) factored as J = U·diag(σ0, σ1)·Vᵀ (U: two orthonormal
 *     3-vectors spanning the patch's plane, n = u0 × u1 its normal), σ1
 *     raised to σ0 / FP_MAX_ECCENTRICITY as in 2D, and widened by the
 *     reconstruction term as in 2D (σ → √(σ² + 1)) — and across the
 *     plane by one texel, the width of the trilinear tent the patch is
 *     seen through. The footprint is then K = [u0 u1 n]·diag(√(σ0² + 1),
 *     √(σ1² + 1), 1)·[V 0; 0 1]ᵀ, and a texel at offset d from the centre
 *     has footprint coordinates (x, y, z) = K⁻¹·d: x, y the screen
 *     position (V) of its projection on the patch, z its distance from
 *     the plane in texels. EWA weighs it by the truncated Gaussian of
 *     r² = x² + y² + z² (its covariance KKᵀ = JJᵀ + I, Heckbert's
 *     unit-variance term in 3D); Blinn–Newell by the pyramid
 *     (1 − |x|)(1 − |y|) times the tent (1 − |z|). A zero Jacobian gives
 *     K = I: Blinn–Newell's weights are then the trilinear ones.
 *
 * Level choice, blend and texel cap are the 2D filters' (ls_fp_run_count,
 * ls_fp_run_read): the level where σ1 spans FP_MINOR_TEXELS texels, moved
 * coarser while the two levels' texels exceed the cap, the trilinear value
 * of the coarsest level when none fits.
 */
#include "aniso.h"
#include "footprint.h"
#include "volume.h"

/* Anisotropic probes are trilinear on two levels, 16 texels each. */
#define VOL_ANISO_MAX_PROBES (SAMPLE_MAX_FOOTPRINT_TEXELS / 16)
/* Most texel rows (j, k) one level's count visits: well above what a
 * footprint within the cap and the eccentricity clamp crosses (its
 * bounding box is at most about 70 × 70 rows), so that a huge footprint
 * is sent coarser after bounded work. */
#define VOL_MAX_ROWS 16384.0

/* ---- Anisotropic ----------------------------------------------------- */

static uint32_t vol_aniso(const sample_ctx *c, const sample_query3 *q, float call_bias, float out[4],
                          sample_stats *st)
{
    double rho2[2], lr = vol_log2_rho(c, q, rho2), acc[4] = {0, 0, 0, 0}, lb;
    int xmajor = rho2[0] >= rho2[1], i, a;
    const float *major = xmajor ? q->dpdx : q->dpdy;
    fp_aniso_setup s;
    uint32_t texels = 0;
    /* Px, Py: the columns' lengths in base texels, all three components. */
    s.n = ls_fp_aniso_count(c->smp, sqrt(xmajor ? rho2[0] : rho2[1]), sqrt(xmajor ? rho2[1] : rho2[0]));
    if (s.n > VOL_ANISO_MAX_PROBES) s.n = VOL_ANISO_MAX_PROBES;
    s.ms = major[0];
    s.mt = major[1];
    /* λ' = log2(Pmax / N), then biases and clamps. */
    lb = lr - sample_log2((double)s.n);
    s.lam = lod_lambda(c, lb < -1e4 ? -1e4f : (float)lb, call_bias);
    ls_lod_split(c, s.lam, &s.l0, &s.l1, &s.f);
    if (s.f == 0.0f) s.l1 = s.l0;
    for (i = 1; i <= s.n; ++i) {
        /* Probe i at offset i/(N + 1) − ½ of the major column. */
        double off = (double)i / (s.n + 1) - 0.5;
        float p[3], o0[4], o1[4];
        for (a = 0; a < 3; ++a) p[a] = (float)(q->p[a] + off * major[a]);
        texels += ls_vol_recon_level(c, s.l0, SAMPLE_LINEAR, p, o0);
        if (s.l1 != s.l0)
            texels += ls_vol_recon_level(c, s.l1, SAMPLE_LINEAR, p, o1);
        else
            memcpy(o1, o0, sizeof o1);
        fp_aniso_add(acc, (double)s.f, o0, o1);
    }
    fp_aniso_mean(acc, s.n, out);
    fp_aniso_stats(&s, st);
    return texels;
}

/* ---- The patch's frame (EWA, Blinn–Newell) ---------------------------- */

/* J = U·diag(σ)·Vᵀ for a 3 × 2 J (rows u, v, w; columns x, y), from the
 * eigen-decomposition of the Gram matrix JᵀJ = V·diag(σ²)·Vᵀ (closed
 * form, no trigonometry), u_i = J·v_i / σ_i. Where J has rank below 2 the
 * missing directions are chosen, deterministically: for rank 1 the second
 * axis is perpendicular to the first, towards the texel axis the first is
 * least aligned with; for rank 0 the texel axes. σ1 is then raised to
 * σ0 / FP_MAX_ECCENTRICITY as in 2D. J is only read (not const-qualified
 * because C before C23 does not convert double (*)[2] to that). */
typedef struct vol_shape {
    double u[3][3]; /* u0, u1 and the normal n = u0 × u1 */
    double v[2][2]; /* v0, v1 */
    double s[2];    /* σ0 ≥ σ1, after the clamp */
} vol_shape;

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void cross3(const double a[3], const double b[3], double o[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

static int normalize3(double a[3])
{
    double l = sqrt(dot3(a, a));
    if (!(l > 0.0)) return 0;
    a[0] /= l;
    a[1] /= l;
    a[2] /= l;
    return 1;
}

static void vol_shape_of(double J[3][2], vol_shape *o)
{
    double g00 = 0.0, g11 = 0.0, g01 = 0.0, h, dd, l0, l1, vx, vy, vl;
    int m;
    for (m = 0; m < 3; ++m) {
        g00 += J[m][0] * J[m][0];
        g11 += J[m][1] * J[m][1];
        g01 += J[m][0] * J[m][1];
    }
    /* Eigenvalues of [[g00, g01], [g01, g11]]: mean ± dd; the smaller as
     * det / larger, which keeps its digits when it is tiny. */
    h = 0.5 * (g00 - g11);
    dd = sqrt(h * h + g01 * g01);
    l0 = 0.5 * (g00 + g11) + dd;
    l1 = l0 > 0.0 ? (g00 * g11 - g01 * g01) / l0 : 0.0;
    o->s[0] = sqrt(l0);
    o->s[1] = l1 > 0.0 ? sqrt(l1) : 0.0;
    /* v0: (λ0 − g11, g01) or (g01, λ0 − g00), the longer of the two. */
    vx = h >= 0.0 ? h + dd : g01;
    vy = h >= 0.0 ? g01 : dd - h;
    vl = sqrt(vx * vx + vy * vy);
    if (vl > 0.0) {
        o->v[0][0] = vx / vl;
        o->v[0][1] = vy / vl;
    } else {
        o->v[0][0] = 1.0;
        o->v[0][1] = 0.0;
    }
    o->v[1][0] = -o->v[0][1];
    o->v[1][1] = o->v[0][0];
    for (m = 0; m < 3; ++m) {
        o->u[0][m] = J[m][0] * o->v[0][0] + J[m][1] * o->v[0][1];
        o->u[1][m] = J[m][0] * o->v[1][0] + J[m][1] * o->v[1][1];
    }
    if (!normalize3(o->u[0])) {
        /* Rank 0: the texel axes. */
        memset(o->u, 0, sizeof o->u);
        o->u[0][0] = o->u[1][1] = o->u[2][2] = 1.0;
    } else {
        double p = dot3(o->u[1], o->u[0]);
        for (m = 0; m < 3; ++m) o->u[1][m] -= p * o->u[0][m];
        if (!(o->s[1] > 1e-9 * o->s[0]) || !normalize3(o->u[1])) {
            /* Rank 1: perpendicular to u0, towards the texel axis e it is
             * least aligned with (u0 × e, then made unit). */
            double e[3] = {0.0, 0.0, 0.0};
            int a = 0;
            for (m = 1; m < 3; ++m)
                if (fabs(o->u[0][m]) < fabs(o->u[0][a])) a = m;
            e[a] = 1.0;
            cross3(o->u[0], e, o->u[1]);
            normalize3(o->u[1]);
        }
        cross3(o->u[0], o->u[1], o->u[2]);
    }
    if (o->s[1] < o->s[0] / FP_MAX_ECCENTRICITY) o->s[1] = o->s[0] / FP_MAX_ECCENTRICITY;
}

/* What a query hands the level loop: its centre, its Jacobian (normalized)
 * and which filter weighs. */
typedef struct vol_fp_geom {
    float p[3];
    double J[3][2]; /* rows s, t, r; columns x, y */
    int pyramid;    /* 1: Blinn–Newell, 0: EWA */
} vol_fp_geom;

/* One level's footprint: the centre (texel centres at integers), M = K⁻¹
 * (texel offset → footprint coordinates) and the half-extents of the
 * support along each texel axis. */
typedef struct vol_frame {
    double c[3], M[3][3], ext[3];
} vol_frame;

static void vol_frame_of(const sample_ctx *c, const vol_fp_geom *g, int lv, vol_frame *f)
{
    const sample_wrap modes[3] = {c->smp->wrap_s, c->smp->wrap_t, c->smp->wrap_r};
    double J[3][2], K[3][3], sp[2];
    vol_shape sh;
    int n[3], a, m, flip;
    vol_level_dims(c, lv, n);
    for (a = 0; a < 3; ++a) {
        /* A mirror-clamp that reflects the centre reflects the footprint
         * with it (ls_fp_center_axis, as in 2D). */
        f->c[a] = ls_fp_center_axis(modes[a], g->p[a], n[a], &flip);
        J[a][0] = g->J[a][0] * (flip ? -n[a] : n[a]);
        J[a][1] = g->J[a][1] * (flip ? -n[a] : n[a]);
    }
    vol_shape_of(J, &sh);
    sp[0] = sqrt(sh.s[0] * sh.s[0] + 1.0);
    sp[1] = sqrt(sh.s[1] * sh.s[1] + 1.0);
    for (m = 0; m < 3; ++m) {
        /* M = [V 0; 0 1]·diag(1/sp0, 1/sp1, 1)·[u0 u1 n]ᵀ and K = M⁻¹. */
        f->M[0][m] = sh.v[0][0] * sh.u[0][m] / sp[0] + sh.v[1][0] * sh.u[1][m] / sp[1];
        f->M[1][m] = sh.v[0][1] * sh.u[0][m] / sp[0] + sh.v[1][1] * sh.u[1][m] / sp[1];
        f->M[2][m] = sh.u[2][m];
        K[m][0] = sh.u[0][m] * sp[0] * sh.v[0][0] + sh.u[1][m] * sp[1] * sh.v[1][0];
        K[m][1] = sh.u[0][m] * sp[0] * sh.v[0][1] + sh.u[1][m] * sp[1] * sh.v[1][1];
        K[m][2] = sh.u[2][m];
    }
    /* The support's reach along texel axis m: the unit ball through K
     * (EWA) reaches ‖K's row m‖, the unit cube (Blinn–Newell) Σ|K_mj|. */
    for (m = 0; m < 3; ++m)
        f->ext[m] = g->pyramid ? fabs(K[m][0]) + fabs(K[m][1]) + fabs(K[m][2])
                               : sqrt(K[m][0] * K[m][0] + K[m][1] * K[m][1] + K[m][2] * K[m][2]);
}

/* The texels of row (dy, dz) inside the support: offsets dx with
 * M·(dx, dy, dz) inside the unit ball (EWA) or cube (Blinn–Newell), as the
 * interval [*lo, *hi]; 0 when empty. M·d = a·dx + b with a = M's column 0. */
static int vol_row_interval(const vol_frame *f, int pyramid, double dy, double dz, double *lo, double *hi)
{
    double a[3], b[3];
    int m;
    for (m = 0; m < 3; ++m) {
        a[m] = f->M[m][0];
        b[m] = f->M[m][1] * dy + f->M[m][2] * dz;
    }
    if (!pyramid) {
        /* |a|²·dx² + 2(a·b)·dx + |b|² − 1 < 0; |a| > 0 (M is invertible). */
        double A = dot3(a, a), B = dot3(a, b), C = dot3(b, b) - 1.0, disc = B * B - A * C, r;
        if (!(disc > 0.0) || !(A > 0.0)) return 0;
        r = sqrt(disc);
        *lo = (-B - r) / A;
        *hi = (-B + r) / A;
        return 1;
    }
    *lo = -INFINITY;
    *hi = INFINITY;
    for (m = 0; m < 3; ++m) {
        /* |a_m·dx + b_m| < 1. */
        if (a[m] != 0.0) {
            double t1 = (-1.0 - b[m]) / a[m], t2 = (1.0 - b[m]) / a[m];
            if (t1 > t2) {
                double t = t1;
                t1 = t2;
                t2 = t;
            }
            if (t1 > *lo) *lo = t1;
            if (t2 < *hi) *hi = t2;
        } else if (!(fabs(b[m]) < 1.0)) {
            return 0;
        }
    }
    return *lo < *hi;
}

/* The weight of footprint coordinates x = M·d; 0 outside the support. */
static double vol_weight(int pyramid, const double x[3])
{
    if (pyramid) {
        double ax = fabs(x[0]), ay = fabs(x[1]), az = fabs(x[2]);
        return ax < 1.0 && ay < 1.0 && az < 1.0 ? (1.0 - ax) * (1.0 - ay) * (1.0 - az) : 0.0;
    } else {
        double r2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
        return r2 < 1.0 ? fp_ewa_weight(r2, NULL) : 0.0;
    }
}

/* One level (fp_level_fn): count the texels of the rows the support
 * crosses, or weigh and add them (vol_texel, the LINEAR addressing rule).
 * Every loop runs on counters bounded before it starts (VOL_MAX_ROWS, the
 * cap), never on an unbounded float. */
static double vol_level(const sample_ctx *c, const void *geom, int lv, fp_accum *acc, int count_only)
{
    const vol_fp_geom *g = (const vol_fp_geom *)geom;
    const double cap = (double)SAMPLE_MAX_FOOTPRINT_TEXELS;
    vol_frame f;
    double jlo, klo, nj, nk, total = 0.0;
    long r, nrows;
    vol_frame_of(c, g, lv, &f);
    jlo = ceil(f.c[1] - f.ext[1]);
    klo = ceil(f.c[2] - f.ext[2]);
    nj = floor(f.c[1] + f.ext[1]) - jlo + 1.0;
    nk = floor(f.c[2] + f.ext[2]) - klo + 1.0;
    if (!(nj >= 0.0 && nk >= 0.0 && nj * nk <= VOL_MAX_ROWS)) return INFINITY;
    nrows = (long)(nj * nk);
    for (r = 0; r < nrows; ++r) {
        double j = jlo + (double)(r % (long)nj), k = klo + (double)(r / (long)nj);
        double dy = j - f.c[1], dz = k - f.c[2], lo, hi, ilo, ncol;
        long x;
        if (!vol_row_interval(&f, g->pyramid, dy, dz, &lo, &hi)) continue;
        ilo = ceil(f.c[0] + lo);
        ncol = floor(f.c[0] + hi) - ilo + 1.0;
        if (!(ncol > 0.0)) continue;
        total += ncol;
        if (!(total <= cap)) return INFINITY;
        if (count_only) continue;
        for (x = 0; x < (long)ncol; ++x) {
            double i = ilo + (double)x, d[3] = {i - f.c[0], dy, dz}, u[3], w;
            float T[4];
            int m;
            for (m = 0; m < 3; ++m) u[m] = dot3(f.M[m], d);
            w = vol_weight(g->pyramid, u);
            if (w > 0.0) {
                vol_texel(c, lv, i, j, k, 1, T);
                fp_accum_add(acc, w, 0.0, 0.0, T);
            }
        }
    }
    return count_only ? total : (double)acc->texels;
}

/* No level fits the cap: the trilinear value of level lv at the centre. */
static uint32_t vol_fallback(const sample_ctx *c, const void *geom, int lv, float out[4])
{
    return ls_vol_recon_level(c, lv, SAMPLE_LINEAR, ((const vol_fp_geom *)geom)->p, out);
}

/* EWA and Blinn–Newell: the level loop of the 2D filters over vol_level. */
static uint32_t vol_area(const sample_ctx *c, const sample_query3 *q, float call_bias, float out[4],
                         sample_stats *st)
{
    vol_fp_geom g;
    vol_shape base;
    fp_run_state rs;
    double Jb[3][2];
    int n[3], a;
    vol_level_dims(c, c->base, n);
    for (a = 0; a < 3; ++a) {
        g.p[a] = q->p[a];
        g.J[a][0] = q->dpdx[a];
        g.J[a][1] = q->dpdy[a];
        Jb[a][0] = g.J[a][0] * n[a];
        Jb[a][1] = g.J[a][1] * n[a];
    }
    g.pyramid = c->smp->footprint == SAMPLE_FOOTPRINT_BLINN_NEWELL;
    /* The level from the minor semi-axis in base texels, after the clamp. */
    vol_shape_of(Jb, &base);
    ls_fp_run_count(c, &g, vol_level, base.s[1], q->p[0], q->p[1], call_bias, &rs);
    rs.fallback = vol_fallback;
    return ls_fp_run_read(c, &rs, out, NULL, NULL, st);
}

/* The volume footprint filters by sample_footprint value; NONE has none
 * (its queries take the OpenGL filters, volume_sample.c). */
typedef uint32_t (*vol_footprint_fn)(const sample_ctx *c, const sample_query3 *q, float call_bias, float out[4],
                                     sample_stats *st);
static const vol_footprint_fn vol_footprints[] = {
    [SAMPLE_FOOTPRINT_NONE] = NULL,
    [SAMPLE_FOOTPRINT_ANISOTROPIC] = vol_aniso,
    [SAMPLE_FOOTPRINT_BLINN_NEWELL] = vol_area,
    [SAMPLE_FOOTPRINT_EWA] = vol_area,
    /* Feline approximates EWA's ellipse by probes; in a volume the patch
     * filter serves it (doc/volumes.md). */
    [SAMPLE_FOOTPRINT_FELINE] = vol_area,
};
_Static_assert(sizeof vol_footprints / sizeof vol_footprints[0] == SAMPLE_FOOTPRINT_COUNT,
               "one entry per footprint filter");

uint32_t ls_vol_footprint(const sample_ctx *c, const sample_query3 *q, float call_bias, float out[4],
                          sample_stats *st)
{
    vol_footprint_fn f = vol_footprints[c->smp->footprint];
    if (!f) return ls_vol_recon_level(c, c->base, SAMPLE_LINEAR, q->p, out);
    return f(c, q, call_bias, out, st);
}
