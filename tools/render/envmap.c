/*
 * Reflection mapping (Blinn–Newell 1976, "Reflection in Curved Surfaces").
 *
 * The environment is a picture painted inside a large sphere, indexed by the
 * reflected direction: lat-long (azimuth across, polar angle down, as the
 * paper plots its maps) or a cube map (OpenGL's face layout). With a finite
 * radius the lookup uses the surface position as well as the normal — the
 * paper's correction for silhouettes that otherwise all reflect the point
 * opposite the eye: the reflected ray from P is intersected with the
 * environment sphere and the direction to that point indexes the map.
 *
 * The lookup is filtered: the screen derivatives of the map coordinates come
 * from the chain rule through the reflection (dN/dx from the surface's
 * second derivatives, jacobian.c), the sphere intersection and the map's own
 * coordinate functions.
 */
#include "rn_internal.h"

#include <stdlib.h>

void env_reflect(const double N[3], const double V[3], double R[3])
{
    double k = 2.0 * v3_dot(N, V);
    int i;
    for (i = 0; i < 3; ++i) R[i] = k * N[i] - V[i];
}

void env_latlong(const double R[3], double st[2], double dst_dR[2][3])
{
    double rho2 = R[0] * R[0] + R[1] * R[1], z = R[2], phi;
    if (z > 1.0) z = 1.0;
    if (z < -1.0) z = -1.0;
    phi = atan2(R[1], R[0]);
    if (phi < 0.0) phi += 2.0 * RN_PI;
    st[0] = phi / (2.0 * RN_PI);
    if (st[0] >= 1.0) st[0] = 0.0;
    st[1] = acos(z) / RN_PI;
    if (dst_dR) {
        /* ∂φ/∂R = (−y, x, 0)/ρ²; ∂θ/∂z = −1/√(1 − z²) = −1/ρ on the unit
         * sphere. Both blow up at the poles; a floor on ρ keeps the footprint
         * finite (the filter clamps it to its texel budget anyway). */
        double r2 = rho2 > 1e-12 ? rho2 : 1e-12;
        dst_dR[0][0] = -R[1] / (2.0 * RN_PI * r2);
        dst_dR[0][1] = R[0] / (2.0 * RN_PI * r2);
        dst_dR[0][2] = 0.0;
        dst_dR[1][0] = 0.0;
        dst_dR[1][1] = 0.0;
        dst_dR[1][2] = -1.0 / (RN_PI * sqrt(r2));
    }
}

/* OpenGL 4.6 table 8.19: major axis → face, sc, tc. Ties go to x, then y. */
int env_cube(const double R[3], double st[2], double dst_dR[2][3])
{
    static const struct { int is, it; double ss, ts; } tab[6] = {
        {2, 1, -1.0, -1.0}, /* +X: sc = −rz, tc = −ry */
        {2, 1, 1.0, -1.0},  /* −X: sc = +rz, tc = −ry */
        {0, 2, 1.0, 1.0},   /* +Y: sc = +rx, tc = +rz */
        {0, 2, 1.0, -1.0},  /* −Y: sc = +rx, tc = −rz */
        {0, 1, 1.0, -1.0},  /* +Z: sc = +rx, tc = −ry */
        {0, 1, -1.0, -1.0}, /* −Z: sc = −rx, tc = −ry */
    };
    double ax = fabs(R[0]), ay = fabs(R[1]), az = fabs(R[2]), ma, sc, tc;
    int im, face, k;
    if (ax >= ay && ax >= az) im = 0;
    else if (ay >= az) im = 1;
    else im = 2;
    face = 2 * im + (R[im] < 0.0);
    ma = fabs(R[im]);
    if (!(ma > 0.0)) ma = 1e-300;
    sc = tab[face].ss * R[tab[face].is];
    tc = tab[face].ts * R[tab[face].it];
    st[0] = 0.5 * (sc / ma + 1.0);
    st[1] = 0.5 * (tc / ma + 1.0);
    if (dst_dR) {
        double sgn = R[im] < 0.0 ? -1.0 : 1.0;
        for (k = 0; k < 3; ++k) dst_dR[0][k] = dst_dR[1][k] = 0.0;
        /* Quotient rule on ½ (sc/|ma| + 1). */
        dst_dR[0][tab[face].is] = 0.5 * tab[face].ss / ma;
        dst_dR[0][im] = -0.5 * sc * sgn / (ma * ma);
        dst_dR[1][tab[face].it] = 0.5 * tab[face].ts / ma;
        dst_dR[1][im] = -0.5 * tc * sgn / (ma * ma);
    }
    return face;
}

/* A room seen from its centre, like the paper's Figure 8: a sky with a sun
 * above the horizon, a band of bright windows, a checkered floor below. */
void env_sky(const double R[3], float out[4])
{
    double d[3], z, phi;
    v3_copy(d, R);
    v3_normalize(d);
    z = d[2];
    phi = atan2(d[1], d[0]);
    if (z >= 0.0) {
        static const double sun[3] = {0.4850712500726659, 0.2910427500435996, 0.8250286981380937};
        double k = sqrt(z), w = fmod(phi / (2.0 * RN_PI) * 8.0 + 8.0, 1.0);
        out[0] = (float)(0.85 - 0.6 * k);
        out[1] = (float)(0.88 - 0.5 * k);
        out[2] = (float)(0.95 - 0.2 * k);
        if (z > 0.05 && z < 0.3 && w > 0.25 && w < 0.75) out[0] = out[1] = out[2] = 2.0f;
        if (v3_dot(d, sun) > 0.995) out[0] = out[1] = out[2] = 8.0f;
    } else {
        double x = d[0] / -z, y = d[1] / -z;
        int c = (int)(((long long)floor(fmin(fmax(x, -1e6), 1e6)) +
                       (long long)floor(fmin(fmax(y, -1e6), 1e6))) & 1);
        float g = c ? 0.6f : 0.15f;
        out[0] = g;
        out[1] = g * 0.9f;
        out[2] = g * 0.8f;
    }
    out[3] = 1.0f;
}

/* Direction of texel centre (s, t) of a map. */
static void map_dir(rn_env_kind kind, int face, double s, double t, double R[3])
{
    if (kind == RN_ENV_LATLONG) {
        double ph = 2.0 * RN_PI * s, th = RN_PI * t;
        v3_set(R, sin(th) * cos(ph), sin(th) * sin(ph), cos(th));
        return;
    }
    {
        double sc = 2.0 * s - 1.0, tc = 2.0 * t - 1.0;
        switch (face) {
        case 0: v3_set(R, 1.0, -tc, -sc); break;
        case 1: v3_set(R, -1.0, -tc, sc); break;
        case 2: v3_set(R, sc, 1.0, tc); break;
        case 3: v3_set(R, sc, -1.0, -tc); break;
        case 4: v3_set(R, sc, -tc, 1.0); break;
        default: v3_set(R, -sc, -tc, -1.0); break;
        }
    }
}

static sample_texture *bake_map(rn_env_kind kind, int face, int w, int h, char *err, size_t errlen)
{
    float *px = malloc(sizeof *px * 4 * (size_t)w * (size_t)h);
    sample_texture *tex = NULL;
    sample_image img;
    sample_mip_params mip;
    sample_error e;
    int i, j;
    if (!px) {
        rn_seterr(err, errlen, "out of memory for the environment map");
        return NULL;
    }
    for (j = 0; j < h; ++j)
        for (i = 0; i < w; ++i) {
            double acc[4] = {0, 0, 0, 0};
            int a, b, c;
            for (b = 0; b < 2; ++b)
                for (a = 0; a < 2; ++a) {
                    double R[3];
                    float v[4];
                    map_dir(kind, face, (i + 0.25 + 0.5 * a) / w, (j + 0.25 + 0.5 * b) / h, R);
                    env_sky(R, v);
                    for (c = 0; c < 4; ++c) acc[c] += 0.25 * v[c];
                }
            for (c = 0; c < 4; ++c) px[4 * ((size_t)j * w + i) + c] = (float)acc[c];
        }
    img.width = w;
    img.height = h;
    img.channels = 4;
    img.format = SAMPLE_FORMAT_F32;
    img.data = px;
    img.row_stride = 0;
    sample_mip_params_init(&mip);
    mip.wrap_s = kind == RN_ENV_LATLONG ? SAMPLE_WRAP_REPEAT : SAMPLE_WRAP_CLAMP_TO_EDGE;
    mip.wrap_t = SAMPLE_WRAP_CLAMP_TO_EDGE;
    if (sample_texture_create(&img, &mip, &tex, &e) != SAMPLE_OK) {
        rn_seterr(err, errlen, "environment map: %s", e.message);
        tex = NULL;
    }
    free(px);
    return tex;
}

int env_build_sky(rn_env *e, rn_env_kind kind, int w, char *err, size_t errlen)
{
    int f;
    e->kind = kind;
    if (kind == RN_ENV_LATLONG) {
        e->map = bake_map(kind, 0, w, w / 2 > 0 ? w / 2 : 1, err, errlen);
        return e->map != NULL;
    }
    for (f = 0; f < 6; ++f)
        if (!(e->face[f] = bake_map(kind, f, w, w, err, errlen))) return 0;
    return 1;
}

void env_release(rn_env *e)
{
    int f;
    sample_texture_destroy(e->map);
    e->map = NULL;
    for (f = 0; f < 6; ++f) {
        sample_texture_destroy(e->face[f]);
        e->face[f] = NULL;
    }
}

/* Derivative of the unit vector D/|D| given dD. */
static void unit_deriv(const double u[3], const double dD[3], double len, double out[3])
{
    double k = v3_dot(u, dD);
    int i;
    for (i = 0; i < 3; ++i) out[i] = (dD[i] - u[i] * k) / len;
}

void env_lookup(const rn_env *e, const sample_sampler *smp, const render_hit *h,
                const double V[3], const double dVdx[3], const double dVdy[3], float out[4])
{
    double R[3], dR[2][3], dir[3], ddir[2][3], st[2], dst[2][3];
    const double *dN[2] = {h->dNdx, h->dNdy}, *dV[2] = {dVdx, dVdy}, *dP[2] = {h->dPdx, h->dPdy};
    double nv = v3_dot(h->N, V);
    const sample_texture *tex;
    sample_sampler s = *smp;
    sample_query query;
    int a, i, face = 0;
    out[0] = out[1] = out[2] = 0.0f;
    out[3] = 1.0f;
    if (e->kind == RN_ENV_NONE) return;
    env_reflect(h->N, V, R);
    /* dR = 2[(dN·V + N·dV) N + (N·V) dN] − dV */
    for (a = 0; a < 2; ++a) {
        double k = v3_dot(dN[a], V) + v3_dot(h->N, dV[a]);
        for (i = 0; i < 3; ++i) dR[a][i] = 2.0 * (k * h->N[i] + nv * dN[a][i]) - dV[a][i];
    }
    if (e->radius > 0.0) {
        /* Blinn–Newell's correction: D = P − c + λR on |D| = radius. */
        double q[3], qr, disc, lam, D[3], len;
        v3_sub(q, h->P, e->centre);
        qr = v3_dot(q, R);
        disc = qr * qr - (v3_dot(q, q) - e->radius * e->radius);
        lam = disc > 0.0 ? -qr + sqrt(disc) : 0.0;
        if (lam < 0.0) lam = 0.0;
        v3_madd(D, q, R, lam);
        len = v3_len(D);
        if (!(len > 0.0)) {
            v3_copy(D, R);
            len = 1.0;
        }
        v3_scale(dir, D, 1.0 / len);
        for (a = 0; a < 2; ++a) {
            double w[3], dr = v3_dot(D, R), dlam, dD[3];
            for (i = 0; i < 3; ++i) w[i] = dP[a][i] + lam * dR[a][i];
            dlam = fabs(dr) > 1e-300 ? -v3_dot(D, w) / dr : 0.0;
            v3_madd(dD, w, R, dlam);
            unit_deriv(dir, dD, len, ddir[a]);
        }
    } else {
        double len = v3_len(R);
        v3_scale(dir, R, 1.0 / len);
        for (a = 0; a < 2; ++a) unit_deriv(dir, dR[a], len, ddir[a]);
    }
    if (e->kind == RN_ENV_LATLONG) {
        env_latlong(dir, st, dst);
        tex = e->map;
        s.wrap_s = SAMPLE_WRAP_REPEAT; /* the seam at azimuth 0 = 2π */
        s.wrap_t = SAMPLE_WRAP_CLAMP_TO_EDGE;
    } else {
        face = env_cube(dir, st, dst);
        tex = e->face[face];
        s.wrap_s = s.wrap_t = SAMPLE_WRAP_CLAMP_TO_EDGE;
    }
    query.s = (float)st[0];
    query.t = (float)st[1];
    query.dsdx = (float)v3_dot(dst[0], ddir[0]);
    query.dtdx = (float)v3_dot(dst[1], ddir[0]);
    query.dsdy = (float)v3_dot(dst[0], ddir[1]);
    query.dtdy = (float)v3_dot(dst[1], ddir[1]);
    if (sample_one(tex, &s, &query, out) != SAMPLE_OK) out[0] = out[1] = out[2] = 0.0f;
    for (i = 0; i < 3; ++i) out[i] *= e->strength;
}
