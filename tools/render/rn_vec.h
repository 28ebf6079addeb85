/* Double-precision 3-vector helpers for the renderer. */
#ifndef TEXSAMPLE_RN_VEC_H
#define TEXSAMPLE_RN_VEC_H

#include <math.h>

static inline void v3_set(double r[3], double x, double y, double z)
{
    r[0] = x; r[1] = y; r[2] = z;
}
static inline void v3_copy(double r[3], const double a[3])
{
    r[0] = a[0]; r[1] = a[1]; r[2] = a[2];
}
static inline double v3_dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static inline void v3_sub(double r[3], const double a[3], const double b[3])
{
    r[0] = a[0] - b[0]; r[1] = a[1] - b[1]; r[2] = a[2] - b[2];
}
static inline void v3_add(double r[3], const double a[3], const double b[3])
{
    r[0] = a[0] + b[0]; r[1] = a[1] + b[1]; r[2] = a[2] + b[2];
}
static inline void v3_scale(double r[3], const double a[3], double k)
{
    r[0] = a[0] * k; r[1] = a[1] * k; r[2] = a[2] * k;
}
/* r = a + k·b */
static inline void v3_madd(double r[3], const double a[3], const double b[3], double k)
{
    r[0] = a[0] + k * b[0]; r[1] = a[1] + k * b[1]; r[2] = a[2] + k * b[2];
}
static inline void v3_cross(double r[3], const double a[3], const double b[3])
{
    double x = a[1] * b[2] - a[2] * b[1];
    double y = a[2] * b[0] - a[0] * b[2];
    double z = a[0] * b[1] - a[1] * b[0];
    r[0] = x; r[1] = y; r[2] = z;
}
static inline double v3_len(const double a[3]) { return sqrt(v3_dot(a, a)); }
/* Returns the length before normalizing; a zero vector stays zero. */
static inline double v3_normalize(double a[3])
{
    double l = v3_len(a);
    if (l > 0.0) v3_scale(a, a, 1.0 / l);
    return l;
}

#endif
