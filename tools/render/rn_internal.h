/*
 * The renderer's private header: where its pieces meet.
 *
 *   rn_vec.h        small double 3-vector helpers
 *   camera.c        pinhole look-at camera: rays and the projection's derivative
 *   teapot_data.c   the Newell teapot: 32 bicubic Bézier patches, 306 points
 *   patch.c         Bézier evaluation, tessellation, ray seeds, Newton
 *   shapes.c        sphere, cylinder, ground plane, polygons (homography)
 *   jacobian.c      exact d(s,t)/d(x,y), normals and their derivatives
 *   hit.c           visible-surface search over objects, corners, cache
 *   proc.c          procedural textures (exact functions) and baking
 *   solid.c         solid textures baked into 3D textures, their lookups
 *   imagetex.c      image textures through libsample_io
 *   noise.c         Perlin gradient noise, periodic, seeded
 *   envmap.c        lat-long and cube environment maps, reflection lookup
 *   shade.c         Blinn–Newell shading, bump and normal mapping
 *   scene.c         scene objects, built-in scenes, destruction
 *   json.c          strict JSON into compact nodes (rn_json.h)
 *   scene_json.c    scene files: schema, keys, names
 *   file.c          opening regular files only, without blocking
 *   parallel.c      rows over pthreads, progress
 *   image.c         threaded rendering into float buffers
 *   output.c        pictures and buffers to files (libsample_io)
 *   cmd_render.c    the texsample subcommand
 */
#ifndef TEXSAMPLE_RN_INTERNAL_H
#define TEXSAMPLE_RN_INTERNAL_H

#include "render.h"
#include "rn_vec.h"

#include <stdint.h>
#include <string.h>

#define RN_PI 3.14159265358979323846

/* ---- Camera (camera.c) ------------------------------------------------ */

typedef struct rn_camera {
    double eye[3], fwd[3], right[3], up[3]; /* orthonormal frame */
    double fovy_deg;
    int width, height;
    double tan_x, tan_y; /* tangents of the half field of view */
} rn_camera;

/* Returns 0 if eye == look or up is parallel to the view direction. */
int cam_init(rn_camera *c, const double eye[3], const double look[3], const double up[3],
             double fovy_deg, int width, int height);
/* Direction through screen point (x, y), scaled so that dir·fwd = 1: then a
 * ray parameter equals the depth along the view axis. */
void cam_ray(const rn_camera *c, double x, double y, double dir[3]);
/* Screen position of P and its derivative d(x, y)/dP (rows x, y). Returns the
 * depth (≤ 0: behind the eye, outputs undefined). */
double cam_project(const rn_camera *c, const double P[3], double xy[2], double dxy_dP[2][3]);

/* ---- Surfaces ----------------------------------------------------------- */

/* A point of a parametric surface with its first and second partials. */
typedef struct rn_surf {
    double P[3], Pu[3], Pv[3], Puu[3], Puv[3], Pvv[3];
} rn_surf;

enum { RN_TESS = 16, RN_BLOCK = 4 }; /* patch tessellation for ray seeds */

typedef struct rn_patch {
    double cp[4][4][3]; /* cp[i][j]: row i along u, column j along v */
    double (*grid)[3];  /* (RN_TESS+1)^2 points for seeding */
    double bmin[3], bmax[3];
    double blo[RN_TESS / RN_BLOCK][RN_TESS / RN_BLOCK][3];
    double bhi[RN_TESS / RN_BLOCK][RN_TESS / RN_BLOCK][3];
} rn_patch;

typedef struct rn_poly {
    int n;                 /* 3 or 4 vertices, convex, planar */
    double V[4][3], st[4][2];
    double O[3], e1[3], e2[3], nrm[3]; /* plane frame: V = O + a e1 + b e2 */
    double H[9], Hinv[9];  /* (s, t, 1) → (a, b, w) homography and inverse */
    double a[4], b[4];     /* vertices in plane coordinates */
} rn_poly;

typedef enum rn_kind {
    RN_PATCHES = 0,
    RN_POLYGONS = 1,
    RN_SPHERE = 2,
    RN_CYLINDER = 3,
    RN_PLANE = 4,
} rn_kind;

typedef struct rn_object {
    rn_kind kind;
    int material;
    double st_scale[2], st_offset[2]; /* (s, t) = offset + scale·(u, v) */
    /* Quadrics and the plane: centre and orthonormal frame (X, Y, Z). */
    double centre[3], X[3], Y[3], Z[3];
    double radius, height; /* sphere/cylinder radius, cylinder height;
                              plane: world size of one unit of (u, v) */
    rn_patch *patches;
    rn_poly *polys;
    int count; /* patches or polygons */
} rn_object;

/* Surface point of primitive `prim` of an object at (u, v). */
void obj_eval(const rn_object *o, int prim, double u, double v, rn_surf *S);
/* Is (u, v) inside the primitive's domain (with tolerance eps)? */
int obj_in_domain(const rn_object *o, int prim, double u, double v, double eps);

/* ---- Patches (patch.c) -------------------------------------------------- */

void patch_eval(const rn_patch *p, double u, double v, rn_surf *S);
/* Fill grid and bounding boxes; returns 0 on allocation failure. */
int patch_prepare(rn_patch *p);
void patch_release(rn_patch *p);

/* Newton on screen position: solve proj(P(u, v)) = (x, y) for the surface
 * of o's primitive from (u, v); in/out. Returns 1 on convergence. */
int newton_screen(const rn_camera *c, const rn_object *o, int prim, double x, double y,
                  double *u, double *v);

/* Ray seeds: every tessellation triangle of the patches of o hit by the ray
 * (eye + τ dir), nearest first, at most max; returns the count. */
typedef struct rn_seed {
    int prim;
    double u, v, depth;
} rn_seed;
int patch_seeds(const rn_object *o, const double eye[3], const double dir[3], rn_seed *seeds,
                int max);

/* The tessellation grid point of p nearest P: its (u, v) and squared distance. */
void patch_nearest_grid(const rn_patch *p, const double P[3], double *u, double *v, double *d2);

/* Teapot data (teapot_data.c): 1-based indices as published. */
#define TEAPOT_PATCHES 32
#define TEAPOT_POINTS 306
extern const unsigned short teapot_index[TEAPOT_PATCHES][16];
extern const double teapot_point[TEAPOT_POINTS][3];

/* ---- Analytic shapes (shapes.c) ----------------------------------------- */

/* Nearest intersection of the ray with a quadric, the plane or a polygon
 * with depth > near: fills prim, u, v, depth. Returns 1 on a hit. */
int shape_intersect(const rn_object *o, const double eye[3], const double dir[3], double near,
                    rn_seed *hit);
void sphere_eval(const rn_object *o, double u, double v, rn_surf *S);
void cylinder_eval(const rn_object *o, double u, double v, rn_surf *S);
void plane_eval(const rn_object *o, double u, double v, rn_surf *S);
void poly_eval(const rn_poly *p, double s, double t, rn_surf *S);
/* Set up a polygon's plane frame and homography; 0 if degenerate. */
int poly_prepare(rn_poly *p);
/* Homography helpers: out = H·(x, y, 1) dehomogenized. */
void homography_apply(const double H[9], double x, double y, double out[2]);
/* H mapping the unit square's corners (0,0),(1,0),(1,1),(0,1) to q[0..3];
 * returns 0 if degenerate (Heckbert 1989, §2.2.3). */
int homography_square_to_quad(double q[4][2], double H[9]);
int mat3_inverse(const double m[9], double out[9]);

/* ---- Jacobian (jacobian.c) ---------------------------------------------- */

/* Complete a hit from the surface point at (u, v): position, normal facing
 * the eye, exact d(s,t)/d(x,y) by inverting d(x,y)/d(u,v) (projection
 * derivative times the surface partials), dP/dx, dN/dx (Weingarten).
 * Returns 0 if the projection is singular (silhouette, pole). */
int jacobian_complete(const rn_camera *c, const rn_object *o, const rn_surf *S, render_hit *h);
/* d(x, y)/d(u, v) as a 2 × 2 row-major matrix; returns the depth. */
double jacobian_screen_uv(const rn_camera *c, const rn_surf *S, double xy[2], double M[4]);

/* ---- Textures (proc.c, noise.c) ----------------------------------------- */

typedef enum rn_tex_kind {
    RN_TEX_IMAGE = 0,
    RN_TEX_GRID,
    RN_TEX_CHECKER,
    RN_TEX_TILES,
    RN_TEX_BRICKS,
    RN_TEX_NOISE,
    RN_TEX_TURBULENCE,
    RN_TEX_MARBLE,
    RN_TEX_SOLID,
    RN_TEX_FOURIER,
    RN_TEX_ZONEPLATE,
    RN_TEX_KIND_COUNT
} rn_tex_kind;

extern const char *const rn_tex_kind_names[RN_TEX_KIND_COUNT];

#define RN_FOURIER_MAX 64

typedef struct rn_noise {
    unsigned char perm[512];
    int period; /* lattice period (noise repeats every `period` cells); 0: none */
} rn_noise;

void noise_init(rn_noise *n, uint32_t seed, int period);
/* Improved gradient noise (Perlin 2002) in [−1, 1]. */
double noise3(const rn_noise *n, double x, double y, double z);
/* Σ_k |noise(2^k p)| / 2^k, k < octaves (Perlin 1985 turbulence). */
double turbulence3(const rn_noise *n, double x, double y, double z, int octaves);

/* A solid texture (doc/volumes.md, "Renderer"): the pattern is a function
 * of the surface point P in world space (where the objects are placed;
 * the scene's object space), baked over the box [lo, hi] into a
 * size[0] × size[1] × size[2] 3D texture, (s, t, r) = (P − lo)/(hi − lo). */
typedef struct rn_solid {
    int on;              /* 1: the texture has a "solid" block */
    double lo[3], hi[3];
    int size[3];
    int samples;         /* samples³ box samples per texel */
    sample_mipgen mip;   /* the pyramid's filter */
    sample_wrap wrap;    /* on s, t and r of the volume */
} rn_solid;

typedef struct rn_texture {
    rn_tex_kind kind;
    float a[4], b[4];   /* the two colours a procedural pattern blends */
    double freq;        /* repeats (cells, lines, noise periods) per unit s, t */
    double width;       /* line / grout / mortar width as a fraction of a cell */
    int octaves;
    double amount;      /* marble turbulence strength, zone plate k */
    uint32_t seed;
    rn_noise noise;
    int nfourier;       /* Fourier synthesis: integer frequencies and amplitudes */
    int fk[RN_FOURIER_MAX][2];
    double famp[RN_FOURIER_MAX], fphase[RN_FOURIER_MAX];
    int bake_size, bake_samples;
    sample_wrap wrap_s, wrap_t;
    sample_texture *tex; /* baked or loaded; owned unless `cached` */
    int cached;          /* 1: tex belongs to the scene's texture system */
    char path[512];      /* image textures: "file" as written in the scene */
    char colorspace[64]; /* image textures: OCIO name, "" = by file and rule */
    unsigned use;        /* RN_USE_*: what the materials use it for */
    rn_solid solid;      /* a solid texture baked into a 3D texture (solid.c) */
} rn_texture;

/* How materials use a texture: colour (an image's grey broadcast to RGB,
 * its file decoded by metadata and rule) or data (bump, normal map: an
 * image read raw unless its "colorspace" says otherwise). */
enum { RN_USE_COLOUR = 1u, RN_USE_DATA = 2u };

/* Defaults for a kind (colours black/white, freq 8, ...). */
void proc_defaults(rn_texture *t, rn_tex_kind kind);
/* Exact value at (s, t) (solid textures use P when given). */
void proc_eval(const rn_texture *t, double s, double t_, const double P[3], float out[4]);
/* Bake a procedural texture into t->tex (bake_samples² box per texel). */
int proc_bake(rn_texture *t, char *err, size_t errlen);
/* Solid textures (solid.c): defaults of a "solid" block; the bake into
 * t->tex (a 3D texture); the volume query of a hit (0 if t is not a baked
 * solid); n queries through the volume with smp's filters and the solid's
 * wrap mode on all three axes (1 on success). */
void solid_defaults(rn_solid *s);
int solid_bake(rn_texture *t, char *err, size_t errlen);
int solid_query(const rn_texture *t, const render_hit *h, sample_query3 *q);
int solid_sample(const rn_texture *t, const sample_sampler *smp, const sample_query3 *q, size_t n,
                 float *rgba, sample_stats *stats);
/* Read an image texture into t->tex (imagetex.c): t->path relative to
 * base_dir (NULL: as given), refused if it holds more than max_texels
 * (base level); *texels gets its base-level texel count. By t->use: data
 * only is read raw unless t->colorspace names a space; colour gets one or
 * two channels (grey, grey + alpha) as (Y, Y, Y, 1) and (Y, Y, Y, A). */
/* With sc->cache_mb > 0 the file opens through the scene's texture system
 * (sc->texsys, made on first use; t->cached set) and its tiles load as
 * filters touch them; else it is read whole. */
int image_load(rn_texture *t, render_scene *sc, const char *base_dir, double max_texels, double *texels,
               char *err, size_t errlen);
/* The scene's texture system (a sample_texsys, NULL: none). */
void image_texsys_destroy(void *texsys);

/* ---- Environment maps (envmap.c) ---------------------------------------- */

typedef enum rn_env_kind { RN_ENV_NONE = 0, RN_ENV_LATLONG = 1, RN_ENV_CUBE = 2 } rn_env_kind;

typedef struct rn_env {
    rn_env_kind kind;
    /* A cube map (SAMPLE_TEXTURE_CUBE) or a lat-long 2D texture, in the
     * maps' y-up frame (env_to_map); owned unless `cached`. */
    sample_texture *tex;
    int cached; /* 1: tex belongs to the scene's texture system */
    double radius;            /* > 0: the paper's position correction, the
                                 environment painted on a sphere this big
                                 around `centre`; 0: infinitely far */
    double centre[3];
    float strength;
    /* An environment file: the layout to resample it into (NONE: the
     * file's own) and the size (0: from the file). */
    rn_env_kind file_kind;
    int file_size;
} rn_env;

/* A world (z-up) direction in the maps' frame (y up, OpenEXR's and
 * OpenImageIO's): (x, y, z) → (x, z, −y). */
void env_to_map(const double w[3], double m[3]);
/* Mirror reflection of the unit view vector V (surface → eye) about N. */
void env_reflect(const double N[3], const double V[3], double R[3]);
/* The procedural environment of the built-in scenes, exact. */
void env_sky(const double R[3], float out[4]);
/* Bake env_sky into a lat-long map (w × w/2) or a cube map (w × w faces). */
int env_build_sky(rn_env *e, rn_env_kind kind, int w, char *err, size_t errlen);
/* The lookup of the reflected ray at a hit: the direction (in the maps'
 * frame) and its exact screen derivatives, from dN/dx, dP/dx and the view
 * vector V (surface → eye, unit) with its derivatives. */
void env_query(const rn_env *e, const render_hit *h, const double V[3], const double dVdx[3],
               const double dVdy[3], sample_query3 *q);
/* n such queries through the map (sample_batch_cube / _latlong); 1 on
 * success. The result is not scaled by e->strength. */
int env_sample(const rn_env *e, const sample_sampler *smp, const sample_query3 *q, size_t n, float *rgba,
               sample_stats *stats);
/* Filtered lookup in direction of the reflected ray at a hit, scaled by
 * the environment's strength. */
void env_lookup(const rn_env *e, const sample_sampler *smp, const render_hit *h,
                const double V[3], const double dVdx[3], const double dVdy[3], float out[4]);
void env_release(rn_env *e);
/* An environment file (t->path, t->colorspace) into e->tex: its own layout
 * (sample_io_read_env), resampled into e->file_kind at e->file_size where
 * that is set; *texels as image_load (imagetex.c). Unresampled, a cube or
 * 2:1 lat-long map opens through the scene's texture system (as
 * image_load) where sc->cache_mb > 0. */
int env_image_load(const rn_texture *t, rn_env *e, render_scene *sc, const char *base_dir, double max_texels,
                   double *texels, char *err, size_t errlen);

/* ---- Scene (scene.c) ---------------------------------------------------- */

typedef struct rn_material {
    int texture;      /* colour texture or −1 */
    int bump;         /* height texture (its red channel) or −1 */
    int normal_map;   /* tangent-space normal texture or −1 */
    double bump_scale;
    float diffuse[3]; /* s of i = s(L·N): scales the texture */
    float ambient;
    float gloss;      /* g: highlight weight, not scaled by the texture */
    double exponent;  /* n */
    float reflect;    /* mirror reflection weight of the environment */
} rn_material;

typedef struct rn_light {
    double dir[3]; /* unit, towards the light */
    float color[3];
} rn_light;

#define RN_MAX_LIGHTS 8
/* Scene-file limits: far above what a texture test scene needs,
 * low enough that memory and the per-sample search (linear in objects and
 * polygons) stay bounded. A teapot holds ~250 KB of patch data. */
#define RN_MAX_OBJECTS 1024
#define RN_MAX_TEAPOTS 64
#define RN_MAX_POLYGONS 65536
#define RN_MAX_TEXTURES 256
#define RN_MAX_MATERIALS 1024

struct render_scene {
    rn_camera cam;
    rn_object *obj;
    int nobj;
    rn_material *mat;
    int nmat;
    rn_texture *tex;
    int ntex;
    rn_light light[RN_MAX_LIGHTS];
    int nlight;
    rn_env env;
    rn_texture env_image; /* an environment "file" until read into env.tex */
    float background[4];
    sample_sampler sampler;
    double cache_mb; /* render_parse_options.cache_mb */
    void *texsys;    /* image textures' sample_texsys (imagetex.c); NULL: none */
};

/* The unit view vector at a hit (surface → eye) and its screen
 * derivatives dV = −(dP − V (V·dP)) / |E − P| (shade.c). */
void rn_view_vector(const render_scene *sc, const render_hit *h, double V[3], double dV[2][3]);

/* Allocation helpers for builders (scene.c); 0 on failure. */
int scene_add_object(render_scene *sc, const rn_object *o);
int scene_add_material(render_scene *sc, const rn_material *m);
int scene_add_texture(render_scene *sc, const rn_texture *t);
render_scene *scene_new(void);
void material_defaults(rn_material *m);
void object_defaults(rn_object *o, rn_kind kind);
/* The Newell teapot as an object (patches prepared), scaled and moved. */
int scene_teapot_object(rn_object *o, double scale, const double offset[3]);
/* Finish: bake procedural textures, read image textures (relative to
 * po->base_dir, at most texels_left base-level texels together, through a
 * texture system of po->cache_mb MiB). */
int scene_finish(render_scene *sc, const render_parse_options *po, double texels_left, char *err,
                 size_t errlen);

/* Fill a hit from (object, prim, u, v) (hit.c). Returns h->converged. */
int hit_finish(const render_scene *sc, int object, int prim, double u, double v, int converged,
               render_hit *h);

/* Shading of one visible point (shade.c). */
void shade_hit(const render_scene *sc, const render_options *o, const render_hit *h,
               const sample_quad *quad, float out[4], sample_stats *stats);

/* Open path for reading if it is a regular file of at most max_bytes
 * (file.c): O_NONBLOCK, so that a FIFO cannot block the open, then fstat.
 * Returns the descriptor (size in *size), or −1 with a message in err
 * naming `what` and the path. */
int rn_open_regular(const char *path, const char *what, size_t max_bytes, size_t *size, char *err,
                    size_t errlen);

void rn_seterr(char *err, size_t errlen, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

#endif
