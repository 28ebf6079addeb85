/*
 * Pinhole camera with look-at and a vertical field of view, square pixels.
 * Screen x runs right, y down; pixel (i, j) is centred at (i + ½, j + ½).
 */
#include "rn_internal.h"

int cam_init(rn_camera *c, const double eye[3], const double look[3], const double up[3],
             double fovy_deg, int width, int height)
{
    double f[3], r[3], u[3];
    v3_sub(f, look, eye);
    if (!(v3_normalize(f) > 0.0)) return 0;
    v3_cross(r, f, up);
    if (!(v3_normalize(r) > 1e-12)) return 0;
    v3_cross(u, r, f);
    if (!(fovy_deg > 0.0 && fovy_deg < 180.0) || width < 1 || height < 1) return 0;
    v3_copy(c->eye, eye);
    v3_copy(c->fwd, f);
    v3_copy(c->right, r);
    v3_copy(c->up, u);
    c->fovy_deg = fovy_deg;
    c->width = width;
    c->height = height;
    c->tan_y = tan(0.5 * fovy_deg * RN_PI / 180.0);
    c->tan_x = c->tan_y * (double)width / (double)height;
    return 1;
}

void cam_ray(const rn_camera *c, double x, double y, double dir[3])
{
    double a = (2.0 * x / c->width - 1.0) * c->tan_x;
    double b = (1.0 - 2.0 * y / c->height) * c->tan_y;
    int k;
    for (k = 0; k < 3; ++k) dir[k] = c->fwd[k] + a * c->right[k] + b * c->up[k];
}

/* x = W/2 · (1 + (q·r)/(z·tan_x)), y = H/2 · (1 − (q·u)/(z·tan_y)) with
 * q = P − eye, z = q·f; the derivative is the quotient rule on each. */
double cam_project(const rn_camera *c, const double P[3], double xy[2], double dxy_dP[2][3])
{
    double q[3], z, qr, qu, kx, ky;
    int k;
    v3_sub(q, P, c->eye);
    z = v3_dot(q, c->fwd);
    if (!(z > 0.0)) return z;
    qr = v3_dot(q, c->right);
    qu = v3_dot(q, c->up);
    kx = 0.5 * c->width / c->tan_x;
    ky = 0.5 * c->height / c->tan_y;
    xy[0] = 0.5 * c->width + kx * qr / z;
    xy[1] = 0.5 * c->height - ky * qu / z;
    if (dxy_dP)
        for (k = 0; k < 3; ++k) {
            dxy_dP[0][k] = kx * (c->right[k] * z - qr * c->fwd[k]) / (z * z);
            dxy_dP[1][k] = -ky * (c->up[k] * z - qu * c->fwd[k]) / (z * z);
        }
    return z;
}
