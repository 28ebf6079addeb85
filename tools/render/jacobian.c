/*
 * The exact screen Jacobian of texture coordinates.
 *
 * With the projection π: P → (x, y) and the surface P(u, v), the chain rule
 * gives M = d(x, y)/d(u, v) = dπ/dP · [Pu Pv] (2 × 2), and by the inverse
 * function theorem d(u, v)/d(x, y) = M⁻¹ at the visible point. The object's
 * affine (u, v) → (s, t) map scales the rows. No differencing anywhere: the
 * only inputs are the analytic partials of the surface and of π.
 *
 * The normal's screen derivatives (for the filtered reflection lookup) use
 * the Weingarten relation on n = Pu × Pv: ∂n/∂u = Puu × Pv + Pu × Puv,
 * ∂N/∂u = (∂n/∂u − N (N·∂n/∂u)) / |n|, then the chain rule through M⁻¹.
 */
#include "rn_internal.h"

double jacobian_screen_uv(const rn_camera *c, const rn_surf *S, double xy[2], double M[4])
{
    double D[2][3];
    double z = cam_project(c, S->P, xy, D);
    if (!(z > 0.0)) return z;
    M[0] = v3_dot(D[0], S->Pu); /* dx/du */
    M[1] = v3_dot(D[0], S->Pv); /* dx/dv */
    M[2] = v3_dot(D[1], S->Pu); /* dy/du */
    M[3] = v3_dot(D[1], S->Pv); /* dy/dv */
    return z;
}

/* ∂N/∂(param) from ∂n/∂(param), N unit and |n| = nl. */
static void normal_deriv(const double N[3], const double dn[3], double nl, double out[3])
{
    double k = v3_dot(N, dn);
    int i;
    for (i = 0; i < 3; ++i) out[i] = (dn[i] - N[i] * k) / nl;
}

int jacobian_complete(const rn_camera *c, const rn_object *o, const rn_surf *S, render_hit *h)
{
    double xy[2], M[4], det, Ji[4], n[3], dnu[3], dnv[3], a[3], b[3], Nu[3], Nv[3], toeye[3];
    double nl, sign = 1.0;
    int k, ok = 1;
    h->depth = jacobian_screen_uv(c, S, xy, M);
    v3_copy(h->P, S->P);
    det = M[0] * M[3] - M[1] * M[2];
    if (!(fabs(det) > 1e-300)) {
        ok = 0;
        Ji[0] = Ji[1] = Ji[2] = Ji[3] = 0.0;
    } else {
        /* Ji = M⁻¹: [du/dx du/dy; dv/dx dv/dy] */
        Ji[0] = M[3] / det;
        Ji[1] = -M[1] / det;
        Ji[2] = -M[2] / det;
        Ji[3] = M[0] / det;
    }
    h->J[0] = o->st_scale[0] * Ji[0]; /* ds/dx */
    h->J[1] = o->st_scale[1] * Ji[2]; /* dt/dx */
    h->J[2] = o->st_scale[0] * Ji[1]; /* ds/dy */
    h->J[3] = o->st_scale[1] * Ji[3]; /* dt/dy */
    for (k = 0; k < 3; ++k) {
        h->dPdx[k] = S->Pu[k] * Ji[0] + S->Pv[k] * Ji[2];
        h->dPdy[k] = S->Pu[k] * Ji[1] + S->Pv[k] * Ji[3];
    }

    v3_cross(n, S->Pu, S->Pv);
    nl = v3_len(n);
    if (!(nl > 0.0)) {
        /* A degenerate point (patch pole): no normal from the partials. */
        v3_scale(h->N, c->fwd, -1.0);
        v3_set(h->dNdx, 0, 0, 0);
        v3_set(h->dNdy, 0, 0, 0);
        return 0;
    }
    v3_scale(h->N, n, 1.0 / nl);
    v3_cross(a, S->Puu, S->Pv);
    v3_cross(b, S->Pu, S->Puv);
    v3_add(dnu, a, b);
    v3_cross(a, S->Puv, S->Pv);
    v3_cross(b, S->Pu, S->Pvv);
    v3_add(dnv, a, b);
    normal_deriv(h->N, dnu, nl, Nu);
    normal_deriv(h->N, dnv, nl, Nv);
    /* Shade the side the eye sees (open surfaces: rim, cylinder). */
    v3_sub(toeye, c->eye, S->P);
    if (v3_dot(toeye, h->N) < 0.0) sign = -1.0;
    for (k = 0; k < 3; ++k) {
        h->N[k] *= sign;
        h->dNdx[k] = sign * (Nu[k] * Ji[0] + Nv[k] * Ji[2]);
        h->dNdy[k] = sign * (Nu[k] * Ji[1] + Nv[k] * Ji[3]);
    }
    return ok;
}
