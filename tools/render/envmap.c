/*
 * Reflection mapping (Blinn–Newell 1976, "Reflection in Curved Surfaces").
 *
 * The environment is a picture painted inside a large sphere, indexed by the
 * reflected direction: a lat-long map or a cube map, the library's own
 * environment textures (doc/environment-maps.md): a cube map is one
 * texture filtered seamlessly across its face edges (GL 4.6 §8.13.1), a
 * lat-long map filtered across its seam and over its poles. With a finite
 * radius the lookup uses the surface position as well as the normal — the
 * paper's correction for silhouettes that otherwise all reflect the point
 * opposite the eye: the reflected ray from P is intersected with the
 * environment sphere and the direction to that point indexes the map.
 *
 * The lookup is filtered by the exact screen derivatives of the looked-up
 * direction: the chain rule through the reflection (dN/dx from the
 * surface's second derivatives, jacobian.c) and the sphere intersection;
 * the library takes them through its map's own coordinate functions.
 */
#include "rn_internal.h"

#include <stdlib.h>

void env_reflect(const double N[3], const double V[3], double R[3])
{
    double k = 2.0 * v3_dot(N, V);
    int i;
    for (i = 0; i < 3; ++i) R[i] = k * N[i] - V[i];
}

/* The maps' frame is OpenEXR's and OpenImageIO's, y up (ImfEnvmap.h;
 * sample_batch_latlong's convention, and the frame cube files are in); the
 * scenes' world is z up. A proper rotation takes one to the other:
 * map = (x, z, −y), world = (x, −z, y). */
void env_to_map(const double w[3], double m[3])
{
    double y = w[1];
    m[0] = w[0];
    m[1] = w[2];
    m[2] = -y;
}

static void env_to_world(const double m[3], double w[3])
{
    double y = m[1];
    w[0] = m[0];
    w[1] = -m[2];
    w[2] = y;
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

/* World direction of point (s, t) of a map: a lat-long map as
 * sample_batch_latlong reads it (φ = 2π(s − ½), θ = π(½ − t)), a cube
 * face as table 8.19 lays it out, both in the map's frame. */
static void map_dir(rn_env_kind kind, int face, double s, double t, double R[3])
{
    double m[3];
    if (kind == RN_ENV_LATLONG) {
        double ph = 2.0 * RN_PI * (s - 0.5), th = RN_PI * (0.5 - t);
        v3_set(m, -sin(ph) * cos(th), sin(th), cos(ph) * cos(th));
    } else {
        double sc = 2.0 * s - 1.0, tc = 2.0 * t - 1.0;
        switch (face) {
        case 0: v3_set(m, 1.0, -tc, -sc); break;
        case 1: v3_set(m, -1.0, -tc, sc); break;
        case 2: v3_set(m, sc, 1.0, tc); break;
        case 3: v3_set(m, sc, -1.0, -tc); break;
        case 4: v3_set(m, sc, -tc, 1.0); break;
        default: v3_set(m, -sc, -tc, -1.0); break;
        }
    }
    env_to_world(m, R);
}

/* env_sky over a w × h map (or face), 2 × 2 samples a texel, into px. */
static void bake_map(rn_env_kind kind, int face, int w, int h, float *px)
{
    int i, j;
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
}

int env_build_sky(rn_env *e, rn_env_kind kind, int w, char *err, size_t errlen)
{
    int h = kind == RN_ENV_LATLONG ? (w / 2 > 0 ? w / 2 : 1) : w, faces = kind == RN_ENV_LATLONG ? 1 : 6, f;
    size_t plane = 4 * (size_t)w * (size_t)h;
    float *px = malloc(sizeof *px * plane * (size_t)faces);
    sample_image img[6];
    sample_mip_params mip;
    sample_error er;
    sample_status st;
    e->kind = kind;
    if (!px) {
        rn_seterr(err, errlen, "out of memory for the environment map");
        return 0;
    }
    for (f = 0; f < faces; ++f) {
        bake_map(kind, f, w, h, px + (size_t)f * plane);
        img[f].width = w;
        img[f].height = h;
        img[f].channels = 4;
        img[f].format = SAMPLE_FORMAT_F32;
        img[f].data = px + (size_t)f * plane;
        img[f].row_stride = 0;
    }
    sample_mip_params_init(&mip);
    /* Lat-long: periodic across the seam (the library's pyramids of a
     * cube map read across face edges by themselves). */
    mip.wrap_s = SAMPLE_WRAP_REPEAT;
    mip.wrap_t = SAMPLE_WRAP_CLAMP_TO_EDGE;
    st = kind == RN_ENV_LATLONG ? sample_texture_create(img, &mip, &e->tex, &er)
                                : sample_texture_create_cube(img, &mip, &e->tex, &er);
    free(px);
    if (st != SAMPLE_OK) {
        rn_seterr(err, errlen, "environment map: %s", er.message);
        e->tex = NULL;
        return 0;
    }
    return 1;
}

void env_release(rn_env *e)
{
    if (!e->cached) sample_texture_destroy(e->tex);
    e->tex = NULL;
    e->cached = 0;
}

/* Derivative of the unit vector D/|D| given dD. */
static void unit_deriv(const double u[3], const double dD[3], double len, double out[3])
{
    double k = v3_dot(u, dD);
    int i;
    for (i = 0; i < 3; ++i) out[i] = (dD[i] - u[i] * k) / len;
}

void env_query(const rn_env *e, const render_hit *h, const double V[3], const double dVdx[3],
               const double dVdy[3], sample_query3 *q)
{
    double R[3], dR[2][3], dir[3], ddir[2][3], m[3];
    const double *dN[2] = {h->dNdx, h->dNdy}, *dV[2] = {dVdx, dVdy}, *dP[2] = {h->dPdx, h->dPdy};
    double nv = v3_dot(h->N, V);
    int a, i;
    env_reflect(h->N, V, R);
    /* dR = 2[(dN·V + N·dV) N + (N·V) dN] − dV */
    for (a = 0; a < 2; ++a) {
        double k = v3_dot(dN[a], V) + v3_dot(h->N, dV[a]);
        for (i = 0; i < 3; ++i) dR[a][i] = 2.0 * (k * h->N[i] + nv * dN[a][i]) - dV[a][i];
    }
    if (e->radius > 0.0) {
        /* Blinn–Newell's correction: D = P − c + λR on |D| = radius. */
        double c[3], qr, disc, lam, D[3], len;
        v3_sub(c, h->P, e->centre);
        qr = v3_dot(c, R);
        disc = qr * qr - (v3_dot(c, c) - e->radius * e->radius);
        lam = disc > 0.0 ? -qr + sqrt(disc) : 0.0;
        if (lam < 0.0) lam = 0.0;
        v3_madd(D, c, R, lam);
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
    /* In the map's frame: the library maps direction and derivatives to
     * the map's coordinates and their exact Jacobian. */
    env_to_map(dir, m);
    for (i = 0; i < 3; ++i) q->p[i] = (float)m[i];
    env_to_map(ddir[0], m);
    for (i = 0; i < 3; ++i) q->dpdx[i] = (float)m[i];
    env_to_map(ddir[1], m);
    for (i = 0; i < 3; ++i) q->dpdy[i] = (float)m[i];
}

int env_sample(const rn_env *e, const sample_sampler *smp, const sample_query3 *q, size_t n, float *rgba,
               sample_stats *stats)
{
    sample_batch3_args a;
    memset(&a, 0, sizeof a);
    a.count = n;
    a.queries = q;
    a.rgba = rgba;
    a.stats = stats;
    return sample_batch_env(e->tex, smp, &a) ==
           SAMPLE_OK;
}

void env_lookup(const rn_env *e, const sample_sampler *smp, const render_hit *h,
                const double V[3], const double dVdx[3], const double dVdy[3], float out[4])
{
    sample_query3 q;
    int i;
    out[0] = out[1] = out[2] = 0.0f;
    out[3] = 1.0f;
    if (e->kind == RN_ENV_NONE || !e->tex) return;
    env_query(e, h, V, dVdx, dVdy, &q);
    if (!env_sample(e, smp, &q, 1, out, NULL)) out[0] = out[1] = out[2] = 0.0f;
    for (i = 0; i < 3; ++i) out[i] *= e->strength;
}

/* ---- What compare asks of a scene's environment (render.h) --------------- */

/* A hit's material mirrors the environment. */
static const rn_env *mirror_env(const render_scene *sc, const render_hit *h)
{
    if (h->object < 0 || sc->env.kind == RN_ENV_NONE || !sc->env.tex) return NULL;
    if (h->material < 0 || h->material >= sc->nmat || !(sc->mat[h->material].reflect > 0.0f)) return NULL;
    return &sc->env;
}

int render_scene_env_query(const render_scene *sc, const render_hit *h, sample_query3 *q)
{
    const rn_env *e = mirror_env(sc, h);
    double V[3], dV[2][3];
    if (!e) return 0;
    rn_view_vector(sc, h, V, dV);
    env_query(e, h, V, dV[0], dV[1], q);
    return 1;
}

int render_scene_env_sample(const render_scene *sc, const sample_sampler *smp, const sample_query3 *q, size_t n,
                            float *rgba, sample_stats *stats)
{
    return sc->env.tex && env_sample(&sc->env, smp, q, n, rgba, stats);
}

const sample_texture *render_scene_env(const render_scene *sc, int *cube)
{
    if (cube) *cube = sc->env.kind == RN_ENV_CUBE;
    return sc->env.kind != RN_ENV_NONE ? sc->env.tex : NULL;
}

int render_scene_env_truth(const render_scene *sc, const render_hit *h, float out[4])
{
    static const double zero[3] = {0, 0, 0};
    const rn_env *e = mirror_env(sc, h);
    sample_sampler smp;
    sample_query3 q;
    double V[3], dV[2][3];
    if (!e) return 0;
    /* The exact direction (no derivatives: a point), read from the base
     * level by LINEAR alone (λ held at 0 by max_lod: magnification). */
    rn_view_vector(sc, h, V, dV);
    env_query(e, h, V, zero, zero, &q);
    sample_sampler_init(&smp);
    smp.min_filter = smp.mag_filter = SAMPLE_LINEAR;
    smp.max_lod = 0.0f;
    if (!env_sample(e, &smp, &q, 1, out, NULL)) out[0] = out[1] = out[2] = out[3] = 0.0f;
    return 1;
}
