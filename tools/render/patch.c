/*
 * Bicubic Bézier patches: evaluation with first and second partials, a
 * tessellation that only seeds the search, and Newton's method on the
 * screen projection that gives the exact (u, v) of a screen point.
 *
 * Catmull (1974) and Blinn–Newell (1976) found the visible point of a patch
 * by subdivision down to pixel size; we do the equivalent in two steps: a
 * fixed tessellation finds which patch and roughly where (to within a
 * tessellation cell), then Newton converges quadratically to the exact point.
 */
#include "rn_internal.h"

#include <stdlib.h>

/* Cubic Bernstein basis at t with first and second derivatives. */
static void bernstein(double t, double b[4], double db[4], double ddb[4])
{
    double s = 1.0 - t;
    b[0] = s * s * s;
    b[1] = 3.0 * t * s * s;
    b[2] = 3.0 * t * t * s;
    b[3] = t * t * t;
    db[0] = -3.0 * s * s;
    db[1] = 3.0 * s * s - 6.0 * t * s;
    db[2] = 6.0 * t * s - 3.0 * t * t;
    db[3] = 3.0 * t * t;
    ddb[0] = 6.0 * s;
    ddb[1] = 18.0 * t - 12.0;
    ddb[2] = 6.0 - 18.0 * t;
    ddb[3] = 6.0 * t;
}

/* u runs along a row of control points (cp[i][0..3]), v down the rows. On
 * the teapot body that is: u around the axis, v from the top down. */
void patch_eval(const rn_patch *p, double u, double v, rn_surf *S)
{
    double bu[4], dbu[4], ddbu[4], bv[4], dbv[4], ddbv[4];
    int i, j, k;
    bernstein(u, bu, dbu, ddbu);
    bernstein(v, bv, dbv, ddbv);
    for (k = 0; k < 3; ++k) {
        double P = 0, Pu = 0, Pv = 0, Puu = 0, Puv = 0, Pvv = 0;
        for (i = 0; i < 4; ++i) {
            double r = 0, ru = 0, ruu = 0; /* the row's cubic in u */
            for (j = 0; j < 4; ++j) {
                double c = p->cp[i][j][k];
                r += bu[j] * c;
                ru += dbu[j] * c;
                ruu += ddbu[j] * c;
            }
            P += bv[i] * r;
            Pu += bv[i] * ru;
            Puu += bv[i] * ruu;
            Pv += dbv[i] * r;
            Puv += dbv[i] * ru;
            Pvv += ddbv[i] * r;
        }
        S->P[k] = P; S->Pu[k] = Pu; S->Pv[k] = Pv;
        S->Puu[k] = Puu; S->Puv[k] = Puv; S->Pvv[k] = Pvv;
    }
}

static void box_grow(double lo[3], double hi[3], const double p[3])
{
    int k;
    for (k = 0; k < 3; ++k) {
        if (p[k] < lo[k]) lo[k] = p[k];
        if (p[k] > hi[k]) hi[k] = p[k];
    }
}

int patch_prepare(rn_patch *p)
{
    const int n = RN_TESS, nb = RN_TESS / RN_BLOCK;
    int i, j, k;
    p->grid = malloc(sizeof *p->grid * (size_t)(n + 1) * (size_t)(n + 1));
    if (!p->grid) return 0;
    for (j = 0; j <= n; ++j)
        for (i = 0; i <= n; ++i) {
            rn_surf S;
            patch_eval(p, (double)i / n, (double)j / n, &S);
            v3_copy(p->grid[j * (n + 1) + i], S.P);
        }
    /* Block boxes bound the tessellation, not the patch; seeds come from the
     * tessellation only, so that is what they must bound. */
    for (k = 0; k < 3; ++k) {
        p->bmin[k] = HUGE_VAL;
        p->bmax[k] = -HUGE_VAL;
    }
    for (j = 0; j < nb; ++j)
        for (i = 0; i < nb; ++i) {
            int a, b;
            for (k = 0; k < 3; ++k) {
                p->blo[j][i][k] = HUGE_VAL;
                p->bhi[j][i][k] = -HUGE_VAL;
            }
            for (b = j * RN_BLOCK; b <= (j + 1) * RN_BLOCK; ++b)
                for (a = i * RN_BLOCK; a <= (i + 1) * RN_BLOCK; ++a)
                    box_grow(p->blo[j][i], p->bhi[j][i], p->grid[b * (n + 1) + a]);
            box_grow(p->bmin, p->bmax, p->blo[j][i]);
            box_grow(p->bmin, p->bmax, p->bhi[j][i]);
        }
    return 1;
}

void patch_release(rn_patch *p)
{
    free(p->grid);
    p->grid = NULL;
}

/* Slab test (Kay–Kajiya); inv = 1/dir with ±inf for zero components. The
 * box is padded so that a ray grazing a flat (zero-thickness) box counts. */
static int ray_box(const double lo[3], const double hi[3], const double eye[3],
                   const double inv[3])
{
    double t0 = 0.0, t1 = HUGE_VAL;
    int k;
    for (k = 0; k < 3; ++k) {
        double pad = 1e-9 * (1.0 + fabs(lo[k]) + fabs(hi[k]));
        double a = (lo[k] - pad - eye[k]) * inv[k], b = (hi[k] + pad - eye[k]) * inv[k];
        if (a > b) { double x = a; a = b; b = x; }
        /* NaN (0 · inf, a ray in the slab's plane) means "inside this slab". */
        if (a == a && a > t0) t0 = a;
        if (b == b && b < t1) t1 = b;
        if (t0 > t1) return 0;
    }
    return 1;
}

/* Möller–Trumbore with a small tolerance on the barycentrics: the triangles
 * of adjacent cells and patches share edges exactly, and the tolerance
 * closes the cracks that rounding would leave between them. */
static int ray_tri(const double eye[3], const double dir[3], const double A[3], const double B[3],
                   const double C[3], double *tau, double *b1, double *b2)
{
    const double tol = 1e-4;
    double e1[3], e2[3], pv[3], tv[3], qv[3], det, inv;
    v3_sub(e1, B, A);
    v3_sub(e2, C, A);
    v3_cross(pv, dir, e2);
    det = v3_dot(e1, pv);
    if (fabs(det) < 1e-300) return 0;
    inv = 1.0 / det;
    v3_sub(tv, eye, A);
    *b1 = v3_dot(tv, pv) * inv;
    if (*b1 < -tol || *b1 > 1.0 + tol) return 0;
    v3_cross(qv, tv, e1);
    *b2 = v3_dot(dir, qv) * inv;
    if (*b2 < -tol || *b1 + *b2 > 1.0 + tol) return 0;
    *tau = v3_dot(e2, qv) * inv;
    return *tau > 0.0;
}

static int seed_insert(rn_seed *seeds, int count, int max, const rn_seed *s)
{
    int k = count < max ? count : max - 1;
    if (count >= max && s->depth >= seeds[max - 1].depth) return count;
    while (k > 0 && seeds[k - 1].depth > s->depth) {
        seeds[k] = seeds[k - 1];
        --k;
    }
    seeds[k] = *s;
    return count < max ? count + 1 : count;
}

int patch_seeds(const rn_object *o, const double eye[3], const double dir[3], rn_seed *seeds,
                int max)
{
    const int n = RN_TESS, nb = RN_TESS / RN_BLOCK;
    double inv[3];
    int count = 0, pi, k;
    for (k = 0; k < 3; ++k) inv[k] = 1.0 / dir[k];
    for (pi = 0; pi < o->count; ++pi) {
        const rn_patch *p = &o->patches[pi];
        int bi, bj;
        if (!ray_box(p->bmin, p->bmax, eye, inv)) continue;
        for (bj = 0; bj < nb; ++bj)
            for (bi = 0; bi < nb; ++bi) {
                int i, j;
                if (!ray_box(p->blo[bj][bi], p->bhi[bj][bi], eye, inv)) continue;
                for (j = bj * RN_BLOCK; j < (bj + 1) * RN_BLOCK; ++j)
                    for (i = bi * RN_BLOCK; i < (bi + 1) * RN_BLOCK; ++i) {
                        const double *q00 = p->grid[j * (n + 1) + i];
                        const double *q10 = p->grid[j * (n + 1) + i + 1];
                        const double *q01 = p->grid[(j + 1) * (n + 1) + i];
                        const double *q11 = p->grid[(j + 1) * (n + 1) + i + 1];
                        double tau, b1, b2;
                        rn_seed s;
                        s.prim = pi;
                        /* Cell split along its q10–q01 diagonal; (u, v) of
                         * the hit from the barycentrics of each half. */
                        if (ray_tri(eye, dir, q00, q10, q01, &tau, &b1, &b2)) {
                            s.u = (i + b1) / n;
                            s.v = (j + b2) / n;
                            s.depth = tau;
                            count = seed_insert(seeds, count, max, &s);
                        }
                        if (ray_tri(eye, dir, q11, q01, q10, &tau, &b1, &b2)) {
                            s.u = (i + 1 - b1) / n;
                            s.v = (j + 1 - b2) / n;
                            s.depth = tau;
                            count = seed_insert(seeds, count, max, &s);
                        }
                    }
            }
    }
    return count;
}

void patch_nearest_grid(const rn_patch *p, const double P[3], double *u, double *v, double *d2)
{
    const int n = RN_TESS;
    int i, j;
    *d2 = HUGE_VAL;
    for (j = 0; j <= n; ++j)
        for (i = 0; i <= n; ++i) {
            double d[3], e;
            v3_sub(d, p->grid[j * (n + 1) + i], P);
            e = v3_dot(d, d);
            if (e < *d2) {
                *d2 = e;
                *u = (double)i / n;
                *v = (double)j / n;
            }
        }
}

/* Newton's method on f(u, v) = proj(P(u, v)) − (x, y): its Jacobian is
 * d(x, y)/d(u, v), whose inverse at the solution is the exact
 * d(u, v)/d(x, y) the texture lookup needs — the same matrix serves both.
 * Converged means the screen residual is below 1e-9 pixel, far below what
 * float (s, t) can resolve. Steps are limited to half the domain so that a
 * poor start near a silhouette cannot jump to a far-away fold. */
int newton_screen(const rn_camera *c, const rn_object *o, int prim, double x, double y,
                  double *u, double *v)
{
    double uu = *u, vv = *v;
    int it;
    for (it = 0; it < 24; ++it) {
        rn_surf S;
        double xy[2], M[4], det, fx, fy, du, dv, depth, len;
        obj_eval(o, prim, uu, vv, &S);
        depth = jacobian_screen_uv(c, &S, xy, M);
        if (!(depth > 0.0)) return 0;
        fx = xy[0] - x;
        fy = xy[1] - y;
        if (fabs(fx) < 1e-9 && fabs(fy) < 1e-9) {
            *u = uu;
            *v = vv;
            return 1;
        }
        det = M[0] * M[3] - M[1] * M[2];
        if (!(fabs(det) > 1e-300)) return 0;
        du = (M[3] * fx - M[1] * fy) / det;
        dv = (M[0] * fy - M[2] * fx) / det;
        len = sqrt(du * du + dv * dv);
        if (!(len == len)) return 0;
        if (len > 0.5) {
            du *= 0.5 / len;
            dv *= 0.5 / len;
        }
        uu -= du;
        vv -= dv;
        if (fabs(uu) > 4.0 || fabs(vv) > 4.0) return 0;
    }
    return 0;
}
