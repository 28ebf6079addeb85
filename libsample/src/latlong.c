/*
 * Lat-long environment maps (latlong.h, doc/environment-maps.md).
 */
#include "latlong.h"

/* π/2 and π to double precision. */
#define LL_PI 3.14159265358979323846
#define LL_PI_2 1.57079632679489661923

/* atan(u) for |u| ≤ 1: one argument halving, atan(u) = 2·atan(u / (1 +
 * √(1 + u²))), brings |u| below tan(π/8) < 0.42; a second below 0.21,
 * where the Taylor series Σ (−1)^k u^(2k+1)/(2k+1) has its terms fall
 * below 2^−60 by k = 13. sqrt is correctly rounded in IEEE arithmetic, so
 * this is the same everywhere. */
static double atan_unit(double u)
{
    double v = u / (1.0 + sqrt(1.0 + u * u)), w, u2, term, sum;
    int k;
    w = v / (1.0 + sqrt(1.0 + v * v));
    u2 = w * w;
    term = w;
    sum = w;
    for (k = 1; k <= 14; ++k) {
        term *= -u2;
        sum += term / (double)(2 * k + 1);
    }
    return 4.0 * sum;
}

double ls_atan2(double y, double x)
{
    double ax = fabs(x), ay = fabs(y), a;
    if (ax == 0.0 && ay == 0.0) return 0.0;
    /* The angle of (|x|, |y|) in [0, π/2], from the ratio below 1. */
    a = ay <= ax ? atan_unit(ay / ax) : LL_PI_2 - atan_unit(ax / ay);
    if (x < 0.0) a = LL_PI - a;
    return y < 0.0 ? -a : a;
}

static float finite_float(double v)
{
    if (v > FLT_MAX) return FLT_MAX;
    if (v < -FLT_MAX) return -FLT_MAX;
    return (float)v;
}

/* ∂s, ∂t along dr at r = (x, y, z): with φ = atan2(−x, z), θ = atan2(y, ρ),
 * ρ = √(x² + z²): ∂φ = (x·∂z − z·∂x)/ρ², ∂ρ = (x·∂x + z·∂z)/ρ,
 * ∂θ = (ρ·∂y − y·∂ρ)/(ρ² + y²); s = φ/2π + ½, t = ½ − θ/π. */
static void latlong_dst(const double r[3], double rho, const double dr[3], float *ds, float *dt)
{
    double r2, drho, dphi, dtheta;
    if (rho == 0.0) {
        /* On the poles' axis the longitude has no derivative; a step dr
         * leaves the pole along the meridian of dr itself, on which the
         * longitude is constant: ∂s = 0, the limit of ∂φ along that path
         * (doc/environment-maps.md, "Poles"). ρ grows by the step's length
         * in x and z. */
        drho = sample_hypot(dr[0], dr[2]);
        *ds = 0.0f;
        *dt = finite_float(drho / r[1] / LL_PI); /* t grows off the north pole (y > 0) */
        return;
    }
    r2 = rho * rho;
    drho = (r[0] * dr[0] + r[2] * dr[2]) / rho;
    dphi = (r[0] * dr[2] - r[2] * dr[0]) / r2;
    dtheta = (rho * dr[1] - r[1] * drho) / (r2 + r[1] * r[1]);
    *ds = finite_float(dphi / (2.0 * LL_PI));
    *dt = finite_float(-dtheta / LL_PI);
}

int ls_latlong_query(const sample_query3 *q, sample_query *out)
{
    double r[3] = {q->p[0], q->p[1], q->p[2]}, dx[3] = {q->dpdx[0], q->dpdx[1], q->dpdx[2]},
           dy[3] = {q->dpdy[0], q->dpdy[1], q->dpdy[2]};
    double rho = sample_hypot(r[0], r[2]);
    if (r[0] == 0.0 && r[1] == 0.0 && r[2] == 0.0) return -1;
    out->s = (float)(ls_atan2(-r[0], r[2]) / (2.0 * LL_PI) + 0.5);
    out->t = (float)(0.5 - ls_atan2(r[1], rho) / LL_PI);
    latlong_dst(r, rho, dx, &out->dsdx, &out->dtdx);
    latlong_dst(r, rho, dy, &out->dsdy, &out->dtdy);
    return 0;
}
