/*
 * Analytic surfaces: parametric sphere and open cylinder, the unbounded
 * ground plane, and planar polygons (triangles and convex quads with
 * per-vertex (s, t)). Each is a parametric surface P(u, v) with analytic
 * partials, so the one Jacobian routine (jacobian.c) serves them all; each
 * also has a closed-form ray intersection, so no Newton is needed.
 */
#include "rn_internal.h"

#include <float.h>

/* ---- Parametric evaluation ------------------------------------------------ */

/* Combination a·X + b·Y + c·Z of the object's frame. */
static void frame(const rn_object *o, double a, double b, double c, double out[3])
{
    int k;
    for (k = 0; k < 3; ++k) out[k] = a * o->X[k] + b * o->Y[k] + c * o->Z[k];
}

/* u = φ/2π (azimuth from X towards Y), v = θ/π (polar angle from +Z). */
void sphere_eval(const rn_object *o, double u, double v, rn_surf *S)
{
    const double r = o->radius, pu = 2.0 * RN_PI, pv = RN_PI;
    double ph = pu * u, th = pv * v;
    double sp = sin(ph), cp = cos(ph), st = sin(th), ct = cos(th);
    frame(o, r * st * cp, r * st * sp, r * ct, S->P);
    v3_add(S->P, S->P, o->centre);
    frame(o, -pu * r * st * sp, pu * r * st * cp, 0.0, S->Pu);
    frame(o, pv * r * ct * cp, pv * r * ct * sp, -pv * r * st, S->Pv);
    frame(o, -pu * pu * r * st * cp, -pu * pu * r * st * sp, 0.0, S->Puu);
    frame(o, -pu * pv * r * ct * sp, pu * pv * r * ct * cp, 0.0, S->Puv);
    frame(o, -pv * pv * r * st * cp, -pv * pv * r * st * sp, -pv * pv * r * ct, S->Pvv);
}

/* u = φ/2π around Z, v = height / (cylinder height) from the base. */
void cylinder_eval(const rn_object *o, double u, double v, rn_surf *S)
{
    const double r = o->radius, pu = 2.0 * RN_PI;
    double sp = sin(pu * u), cp = cos(pu * u);
    frame(o, r * cp, r * sp, v * o->height, S->P);
    v3_add(S->P, S->P, o->centre);
    frame(o, -pu * r * sp, pu * r * cp, 0.0, S->Pu);
    frame(o, 0.0, 0.0, o->height, S->Pv);
    frame(o, -pu * pu * r * cp, -pu * pu * r * sp, 0.0, S->Puu);
    v3_set(S->Puv, 0, 0, 0);
    v3_set(S->Pvv, 0, 0, 0);
}

/* P = centre + size·(u X + v Y). */
void plane_eval(const rn_object *o, double u, double v, rn_surf *S)
{
    frame(o, o->radius * u, o->radius * v, 0.0, S->P);
    v3_add(S->P, S->P, o->centre);
    frame(o, o->radius, 0.0, 0.0, S->Pu);
    frame(o, 0.0, o->radius, 0.0, S->Pv);
    v3_set(S->Puu, 0, 0, 0);
    v3_set(S->Puv, 0, 0, 0);
    v3_set(S->Pvv, 0, 0, 0);
}

/* A polygon is parametrized by its own (s, t): P = O + a e1 + b e2 with
 * (a, b) = H(s, t) projective. The second partials of that map are not zero,
 * but they lie in the plane, and only their normal component matters to the
 * shading (dN = 0 on a plane), so they are left at zero. */
void poly_eval(const rn_poly *p, double s, double t, rn_surf *S)
{
    const double *H = p->H;
    double nx = H[0] * s + H[1] * t + H[2];
    double ny = H[3] * s + H[4] * t + H[5];
    double w = H[6] * s + H[7] * t + H[8];
    double a = nx / w, b = ny / w;
    double da_s = (H[0] - a * H[6]) / w, da_t = (H[1] - a * H[7]) / w;
    double db_s = (H[3] - b * H[6]) / w, db_t = (H[4] - b * H[7]) / w;
    int k;
    for (k = 0; k < 3; ++k) {
        S->P[k] = p->O[k] + a * p->e1[k] + b * p->e2[k];
        S->Pu[k] = da_s * p->e1[k] + db_s * p->e2[k];
        S->Pv[k] = da_t * p->e1[k] + db_t * p->e2[k];
    }
    v3_set(S->Puu, 0, 0, 0);
    v3_set(S->Puv, 0, 0, 0);
    v3_set(S->Pvv, 0, 0, 0);
}

void obj_eval(const rn_object *o, int prim, double u, double v, rn_surf *S)
{
    switch (o->kind) {
    case RN_PATCHES: patch_eval(&o->patches[prim], u, v, S); break;
    case RN_POLYGONS: poly_eval(&o->polys[prim], u, v, S); break;
    case RN_SPHERE: sphere_eval(o, u, v, S); break;
    case RN_CYLINDER: cylinder_eval(o, u, v, S); break;
    case RN_PLANE: plane_eval(o, u, v, S); break;
    }
}

/* ---- Homographies (Heckbert 1989, "Fundamentals of Texture Mapping") ----- */

void homography_apply(const double H[9], double x, double y, double out[2])
{
    double w = H[6] * x + H[7] * y + H[8];
    out[0] = (H[0] * x + H[1] * y + H[2]) / w;
    out[1] = (H[3] * x + H[4] * y + H[5]) / w;
}

int homography_square_to_quad(double q[4][2], double H[9])
{
    double sx = q[0][0] - q[1][0] + q[2][0] - q[3][0];
    double sy = q[0][1] - q[1][1] + q[2][1] - q[3][1];
    double g = 0.0, h = 0.0;
    if (sx != 0.0 || sy != 0.0) {
        double dx1 = q[1][0] - q[2][0], dx2 = q[3][0] - q[2][0];
        double dy1 = q[1][1] - q[2][1], dy2 = q[3][1] - q[2][1];
        double den = dx1 * dy2 - dx2 * dy1;
        if (!(fabs(den) > 1e-300)) return 0;
        g = (sx * dy2 - dx2 * sy) / den;
        h = (dx1 * sy - sx * dy1) / den;
    }
    H[0] = q[1][0] - q[0][0] + g * q[1][0];
    H[1] = q[3][0] - q[0][0] + h * q[3][0];
    H[2] = q[0][0];
    H[3] = q[1][1] - q[0][1] + g * q[1][1];
    H[4] = q[3][1] - q[0][1] + h * q[3][1];
    H[5] = q[0][1];
    H[6] = g;
    H[7] = h;
    H[8] = 1.0;
    return 1;
}

int mat3_inverse(const double m[9], double out[9])
{
    double c0 = m[4] * m[8] - m[5] * m[7];
    double c1 = m[5] * m[6] - m[3] * m[8];
    double c2 = m[3] * m[7] - m[4] * m[6];
    double det = m[0] * c0 + m[1] * c1 + m[2] * c2, k;
    if (!(fabs(det) > 1e-300)) return 0;
    k = 1.0 / det;
    out[0] = c0 * k;
    out[1] = (m[2] * m[7] - m[1] * m[8]) * k;
    out[2] = (m[1] * m[5] - m[2] * m[4]) * k;
    out[3] = c1 * k;
    out[4] = (m[0] * m[8] - m[2] * m[6]) * k;
    out[5] = (m[2] * m[3] - m[0] * m[5]) * k;
    out[6] = c2 * k;
    out[7] = (m[1] * m[6] - m[0] * m[7]) * k;
    out[8] = (m[0] * m[4] - m[1] * m[3]) * k;
    return 1;
}

static void mat3_mul(const double a[9], const double b[9], double out[9])
{
    int i, j;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j)
            out[3 * i + j] = a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
}

int poly_prepare(rn_poly *p)
{
    double d1[3], d2[3];
    int k;
    if (p->n != 3 && p->n != 4) return 0;
    v3_copy(p->O, p->V[0]);
    v3_sub(d1, p->V[1], p->V[0]);
    v3_sub(d2, p->V[p->n - 1], p->V[0]);
    v3_cross(p->nrm, d1, d2);
    if (!(v3_normalize(p->nrm) > 0.0)) return 0;
    v3_copy(p->e1, d1);
    if (!(v3_normalize(p->e1) > 0.0)) return 0;
    v3_cross(p->e2, p->nrm, p->e1);
    for (k = 0; k < p->n; ++k) {
        double q[3];
        v3_sub(q, p->V[k], p->O);
        p->a[k] = v3_dot(q, p->e1);
        p->b[k] = v3_dot(q, p->e2);
    }
    if (p->n == 3) {
        /* Affine: (a, b, 1)ᵀ = H (s, t, 1)ᵀ through three correspondences. */
        double S[9], Si[9], A[9];
        for (k = 0; k < 3; ++k) {
            S[3 * k] = p->st[k][0];
            S[3 * k + 1] = p->st[k][1];
            S[3 * k + 2] = 1.0;
        }
        if (!mat3_inverse(S, Si)) return 0;
        for (k = 0; k < 3; ++k) {
            int j;
            A[k] = A[3 + k] = 0.0;
            for (j = 0; j < 3; ++j) {
                A[k] += Si[3 * k + j] * p->a[j];
                A[3 + k] += Si[3 * k + j] * p->b[j];
            }
        }
        p->H[0] = A[0]; p->H[1] = A[1]; p->H[2] = A[2];
        p->H[3] = A[3]; p->H[4] = A[4]; p->H[5] = A[5];
        p->H[6] = 0.0; p->H[7] = 0.0; p->H[8] = 1.0;
    } else {
        /* Projective: square → plane quad after (s, t) quad → square. */
        double qs[4][2], qp[4][2], Hs[9], Hsi[9], Hp[9];
        for (k = 0; k < 4; ++k) {
            qs[k][0] = p->st[k][0];
            qs[k][1] = p->st[k][1];
            qp[k][0] = p->a[k];
            qp[k][1] = p->b[k];
        }
        if (!homography_square_to_quad(qs, Hs) || !mat3_inverse(Hs, Hsi) ||
            !homography_square_to_quad(qp, Hp))
            return 0;
        mat3_mul(Hp, Hsi, p->H);
    }
    return mat3_inverse(p->H, p->Hinv);
}

/* ---- Domains ------------------------------------------------------------- */

/* Is (a, b) inside the convex polygon (counter-clockwise or clockwise)? */
static int poly_inside(const rn_poly *p, double a, double b, double eps)
{
    int k, pos = 0, neg = 0;
    for (k = 0; k < p->n; ++k) {
        int l = (k + 1) % p->n;
        double ex = p->a[l] - p->a[k], ey = p->b[l] - p->b[k];
        double c = ex * (b - p->b[k]) - ey * (a - p->a[k]);
        double tol = eps * sqrt(ex * ex + ey * ey);
        if (c > tol) ++pos;
        else if (c < -tol) ++neg;
    }
    return pos == 0 || neg == 0;
}

int obj_in_domain(const rn_object *o, int prim, double u, double v, double eps)
{
    switch (o->kind) {
    case RN_PATCHES:
    case RN_CYLINDER:
        return u >= -eps && u <= 1.0 + eps && v >= -eps && v <= 1.0 + eps;
    case RN_SPHERE:
        return v >= -eps && v <= 1.0 + eps;
    case RN_PLANE:
        return 1;
    case RN_POLYGONS: {
        rn_surf S;
        double q[3];
        poly_eval(&o->polys[prim], u, v, &S);
        v3_sub(q, S.P, o->polys[prim].O);
        return poly_inside(&o->polys[prim], v3_dot(q, o->polys[prim].e1),
                           v3_dot(q, o->polys[prim].e2), eps);
    }
    }
    return 0;
}

/* ---- Ray intersections ---------------------------------------------------- */

/* Roots of A τ² + B τ + C in ascending order, the cancellation-free form. */
static int quadratic(double A, double B, double C, double r[2])
{
    double disc = B * B - 4.0 * A * C, q;
    if (!(disc >= 0.0) || !(A != 0.0)) return 0;
    q = -0.5 * (B + (B >= 0.0 ? sqrt(disc) : -sqrt(disc)));
    r[0] = q / A;
    r[1] = q != 0.0 ? C / q : r[0];
    if (r[0] > r[1]) { double x = r[0]; r[0] = r[1]; r[1] = x; }
    return 1;
}

static double wrap01(double u)
{
    u -= floor(u);
    return u >= 1.0 ? 0.0 : u;
}

static int hit_quadric(const rn_object *o, const double eye[3], const double dir[3], double near,
                       rn_seed *hit)
{
    double q[3], lq[3], ld[3], r[2];
    int k;
    v3_sub(q, eye, o->centre);
    lq[0] = v3_dot(q, o->X); lq[1] = v3_dot(q, o->Y); lq[2] = v3_dot(q, o->Z);
    ld[0] = v3_dot(dir, o->X); ld[1] = v3_dot(dir, o->Y); ld[2] = v3_dot(dir, o->Z);
    if (o->kind == RN_SPHERE) {
        if (!quadratic(v3_dot(ld, ld), 2.0 * v3_dot(lq, ld), v3_dot(lq, lq) - o->radius * o->radius, r))
            return 0;
    } else if (!quadratic(ld[0] * ld[0] + ld[1] * ld[1], 2.0 * (lq[0] * ld[0] + lq[1] * ld[1]),
                          lq[0] * lq[0] + lq[1] * lq[1] - o->radius * o->radius, r)) {
        return 0;
    }
    for (k = 0; k < 2; ++k) {
        double p[3];
        if (!(r[k] > near)) continue;
        v3_madd(p, lq, ld, r[k]);
        hit->prim = 0;
        hit->depth = r[k];
        hit->u = wrap01(atan2(p[1], p[0]) / (2.0 * RN_PI));
        if (o->kind == RN_SPHERE) {
            double c = p[2] / o->radius;
            hit->v = acos(c > 1.0 ? 1.0 : c < -1.0 ? -1.0 : c) / RN_PI;
            return 1;
        }
        hit->v = p[2] / o->height;
        if (hit->v >= 0.0 && hit->v <= 1.0) return 1;
    }
    return 0;
}

int shape_intersect(const rn_object *o, const double eye[3], const double dir[3], double near,
                    rn_seed *hit)
{
    double q[3];
    switch (o->kind) {
    case RN_SPHERE:
    case RN_CYLINDER:
        return hit_quadric(o, eye, dir, near, hit);
    case RN_PLANE: {
        double dn = v3_dot(dir, o->Z), tau, p[3];
        if (!(fabs(dn) > 0.0)) return 0;
        v3_sub(q, o->centre, eye);
        tau = v3_dot(q, o->Z) / dn;
        if (!(tau > near) || !(tau < DBL_MAX)) return 0;
        v3_madd(p, eye, dir, tau);
        v3_sub(p, p, o->centre);
        hit->prim = 0;
        hit->depth = tau;
        hit->u = v3_dot(p, o->X) / o->radius;
        hit->v = v3_dot(p, o->Y) / o->radius;
        return 1;
    }
    case RN_POLYGONS: {
        int k, found = 0;
        for (k = 0; k < o->count; ++k) {
            const rn_poly *pg = &o->polys[k];
            double dn = v3_dot(dir, pg->nrm), tau, p[3], a, b, st[2];
            if (!(fabs(dn) > 0.0)) continue;
            v3_sub(q, pg->O, eye);
            tau = v3_dot(q, pg->nrm) / dn;
            if (!(tau > near) || (found && tau >= hit->depth)) continue;
            v3_madd(p, eye, dir, tau);
            v3_sub(p, p, pg->O);
            a = v3_dot(p, pg->e1);
            b = v3_dot(p, pg->e2);
            if (!poly_inside(pg, a, b, 1e-12)) continue;
            homography_apply(pg->Hinv, a, b, st);
            hit->prim = k;
            hit->depth = tau;
            hit->u = st[0];
            hit->v = st[1];
            found = 1;
        }
        return found;
    }
    case RN_PATCHES:
        break;
    }
    return 0;
}
