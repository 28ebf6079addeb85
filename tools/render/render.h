/*
 * render.h — the reference renderer's internal C API (texsample render,
 * texsample compare). Library code of the tools, not of libsample.
 *
 * 1. QUICK START
 *
 *     render_scene *sc;  char err[256];
 *     if (render_scene_builtin("teapot", 512, 512, &sc, err, sizeof err)) ...
 *     render_hit h;
 *     if (render_scene_hit(sc, x + 0.5, y + 0.5, &h)) {   // pixel centre
 *         ... h.s, h.t, h.J (exact d(s,t)/d(x,y)), h.depth, h.N ...
 *     }
 *     render_options o;  render_options_init(&o);  o.threads = 8;
 *     render_image img;
 *     render_image_run(sc, &o, &img, err, sizeof err);      // float RGBA
 *     render_image_free(&img);  render_scene_destroy(sc);
 *
 * 2. COORDINATES
 *
 *   Screen: x to the right, y down, pixel (i, j) covers [i, i+1) × [j, j+1),
 *   its centre is (i + ½, j + ½). World: right-handed, z up (the teapot data
 *   is z-up). (s, t) are the texture coordinates of DESIGN §2 after the
 *   object's (u, v) → (s, t) mapping; (u, v) are the primitive's own surface
 *   parameters (Bézier (u, v), sphere azimuth/polar, plane coordinates ...).
 *   J is in sample_query order: J[0] = ds/dx, J[1] = dt/dx, J[2] = ds/dy,
 *   J[3] = dt/dy, computed from the analytic surface partials and the
 *   projection (never by differencing).
 *
 * 3. THREADS
 *
 *   A scene is immutable after creation: every function taking a
 *   `const render_scene *` may be called from many threads at once.
 *   A render_cache is immutable after render_cache_build().
 */
#ifndef TEXSAMPLE_RENDER_H
#define TEXSAMPLE_RENDER_H

#include "sample/sample.h"

#include <stddef.h>

typedef struct render_scene render_scene;

/* ---- Scenes --------------------------------------------------------- */

/* Built-in scene names, NULL-terminated: "teapot", "plane", "zoneplate",
 * "cylinder", "sphere" (procedural textures), and "teapot-image",
 * "photo-plane" (the photograph testimages/photo.jpg of the source tree,
 * TEXSAMPLE_SOURCE_DIR: they need libsample_io and that file, else they
 * fail with a message saying which). */
extern const char *const render_builtin_names[];

/* Build a built-in scene at width × height (0 = the default 512 × 512).
 * Return 0 on success; on failure a message goes to err. */
int render_scene_builtin(const char *name, int width, int height, render_scene **out,
                         char *err, size_t errlen);
/* Load a scene file (JSON, doc/renderer.md §Scene files). width/height > 0
 * override the file's image size. Image files are relative to the scene
 * file's folder. Only a regular file of at most RENDER_MAX_SCENE_BYTES is
 * read (a FIFO or device is refused without blocking). Messages start
 * with the path, then "line L, column C:" where the text is at fault. */
int render_scene_load(const char *path, int width, int height, render_scene **out,
                      char *err, size_t errlen);
/* Same from a JSON text in memory (tests, fuzzing); image files relative to
 * the working directory, default limits. */
int render_scene_parse(const char *json, size_t len, int width, int height,
                       render_scene **out, char *err, size_t errlen);

/* What the parser may do. Everything a scene makes it compute or allocate
 * up front is bounded by these, so that no scene text can stall or exhaust
 * the process while it is being built. */
typedef struct render_parse_options {
    const char *base_dir; /* image "file"s are relative to it; NULL: working directory */
    int images;           /* 1 (default): load image textures; 0: refuse them */
    /* Procedural evaluations when baking: Σ size²·samples² over textures
     * (times the terms of a Fourier texture, each a cosine as costly as a
     * whole sample of the others), size³·samples³ over solid textures
     * (times the octaves of turbulence and marble), plus 4 per
     * environment-map texel.
     * Default RENDER_MAX_BAKE_WORK. */
    double max_bake_work;
    /* Base-level texels of all textures and maps together (image textures
     * included). Default RENDER_MAX_TEXELS. */
    double max_texels;
    /* JSON values (numbers, strings, arrays, ...) in the text, 16 bytes
     * each while parsing. Default and maximum RENDER_MAX_JSON_VALUES. */
    unsigned max_values;
    /* Image textures open through one texture system (sample/texsys.h)
     * per scene whose tile cache holds this many MiB; 0: each file is
     * read whole into memory (doc/renderer.md, "Image textures").
     * Default RENDER_CACHE_MB. */
    double cache_mb;
} render_parse_options;

#define RENDER_MAX_BAKE_WORK 268435456.0 /* 2^28: 16 × a 4096² bake at 1 sample */
#define RENDER_MAX_TEXELS 67108864.0     /* 2^26: one 8192² texture, 1 GiB as float RGBA */
/* 2^22 values (64 MiB of parse nodes): a 65536-quad polygon object is ~2^21. */
#define RENDER_MAX_JSON_VALUES 4194304u
#define RENDER_MAX_SCENE_BYTES ((size_t)64 << 20) /* scene files: 64 MiB */
#define RENDER_CACHE_MB 1024.0 /* OpenImageIO's max_memory_MB default */

void render_parse_options_init(render_parse_options *po);
/* render_scene_parse with options (po NULL: defaults). */
int render_scene_parse_ex(const char *json, size_t len, int width, int height,
                          const render_parse_options *po, render_scene **out, char *err,
                          size_t errlen);
/* render_scene_builtin and render_scene_load with options (po NULL:
 * defaults); po->base_dir is replaced by the images' folder. */
int render_scene_builtin_ex(const char *name, int width, int height, const render_parse_options *po,
                            render_scene **out, char *err, size_t errlen);
int render_scene_load_ex(const char *path, int width, int height, const render_parse_options *po,
                         render_scene **out, char *err, size_t errlen);
void render_scene_destroy(render_scene *sc); /* accepts NULL */

void render_scene_size(const render_scene *sc, int *width, int *height);
/* The sampler the scene asks for (its "sampler" block; OpenGL defaults
 * plus trilinear otherwise). */
void render_scene_sampler(const render_scene *sc, sample_sampler *out);

/* ---- Visible surface ----------------------------------------------- */

typedef struct render_hit {
    int object;     /* scene object index, −1 for background (nothing hit) */
    int prim;       /* primitive within it: patch or polygon index, else 0 */
    int material;   /* material index (render_scene_material_texture) */
    double u, v;    /* the primitive's surface parameters */
    double s, t;    /* texture coordinates */
    double J[4];    /* ds/dx, dt/dx, ds/dy, dt/dy (sample_query order) */
    double depth;   /* distance along the camera's view axis (> 0) */
    double P[3];    /* world position */
    double N[3];    /* unit geometric normal, turned to face the eye */
    double dNdx[3], dNdy[3]; /* its screen derivatives (Weingarten) */
    double dPdx[3], dPdy[3]; /* position's screen derivatives */
    int converged;  /* 1: (u, v) solved to float precision by Newton or
                       analytically; 0: degenerate point (a patch pole),
                       best estimate, J may be huge or zero */
} render_hit;

/* The visible surface at screen position (x, y) (sub-pixel allowed): the
 * nearest intersection over all objects (a per-sample depth test). Returns
 * 1 on a hit, 0 for background (hit->object = −1). */
int render_scene_hit(const render_scene *sc, double x, double y, render_hit *hit);

/* Fast path for supersampling: Newton on seed's primitive from seed's
 * (u, v) to screen point (x, y). Returns 1 if it converged inside the
 * primitive's domain, 0 otherwise (then call render_scene_hit). It does not
 * test visibility against other primitives: use it only where the seed's
 * primitive is known to be the visible one (see render_cache). */
int render_scene_hit_from(const render_scene *sc, const render_hit *seed, double x, double y,
                          render_hit *hit);

/* The four exact (s, t) corners of the pixel's 2 × 2 footprint: screen
 * offsets (−1,−1), (+1,−1), (+1,+1), (−1,+1) from (x, y), in that order
 * (sample_quad). Returns 1 if all four lie on centre's primitive (then the
 * quad is valid for the Blinn–Newell corner mode), 0 otherwise. */
int render_scene_corners(const render_scene *sc, const render_hit *centre, double x, double y,
                         sample_quad *quad);

/* Per-pixel hit cache for ground-truth supersampling: the pixel-centre hits
 * of the whole image, and for each pixel whether its 3 × 3 neighbourhood
 * sees one single primitive (then any point of the pixel's 2 × 2 footprint
 * is found by Newton from the centre hit, else by a full search). */
typedef struct render_cache render_cache;
render_cache *render_cache_build(const render_scene *sc, int threads);
void render_cache_destroy(render_cache *c); /* accepts NULL */
const render_hit *render_cache_pixel(const render_cache *c, int i, int j);
/* The visible hit at (x, y), which must lie within 1 pixel of the centre of
 * pixel (i, j) = (floor(x), floor(y)) or a neighbour. Same result as
 * render_scene_hit up to Newton's tolerance. */
int render_cache_hit(const render_cache *c, double x, double y, render_hit *hit);

/* ---- Materials and textures ---------------------------------------- */

/* The texture index (into the scene's texture list) of a material's colour
 * texture, or −1 for none. */
int render_scene_material_texture(const render_scene *sc, int material);
int render_scene_texture_count(const render_scene *sc);
/* The texture as libsample sees it (procedural textures baked, 256 × 256
 * unless the scene says otherwise; a solid texture's is its 3D texture,
 * render_scene_texture_solid); never NULL for a valid index. */
const sample_texture *render_scene_texture(const render_scene *sc, int texture);
/* Exact value of a procedural texture at (s, t) (and world position P for
 * solid textures; may be NULL, then (s, t, 0) is used). Returns 1 if the
 * texture is procedural (out filled), 0 for an image texture (then the
 * ground truth is the bilinear base level, DESIGN §8). */
int render_scene_texture_exact(const render_scene *sc, int texture, double s, double t,
                               const double P[3], float out[4]);
/* Texture value for ground truth: exact if procedural, else the bilinear
 * reconstruction of level 0 with the texture's wrap modes. */
void render_scene_texture_truth(const render_scene *sc, int texture, double s, double t,
                                const double P[3], float out[4]);

/* ---- Environment (doc/environment-maps.md, "Renderer") -------------- */

/* Where a hit's material reflects the scene's environment ("reflect" > 0):
 * 1, with q the reflected direction, in the maps' y-up frame, and its
 * exact screen derivatives (what the renderer's own lookup asks); else 0. */
int render_scene_env_query(const render_scene *sc, const render_hit *h, sample_query3 *q);
/* n such queries through the environment map (sample_batch_cube or
 * sample_batch_latlong) with `smp`, unscaled by the environment's strength;
 * 1 on success. */
int render_scene_env_sample(const render_scene *sc, const sample_sampler *smp, const sample_query3 *q, size_t n,
                            float *rgba, sample_stats *stats);
/* The environment map (NULL if the scene has none); *cube: 1 for a cube
 * map, 0 for lat-long. */
const sample_texture *render_scene_env(const render_scene *sc, int *cube);
/* Ground truth at a hit that reflects the environment: the base level of
 * the map, bilinear (LINEAR, seamless across edges, seam and poles), in
 * the exact reflected direction at that point, unscaled by the strength.
 * 0 if the hit does not reflect it. */
int render_scene_env_truth(const render_scene *sc, const render_hit *h, float out[4]);
/* ---- Solid textures (doc/volumes.md, "Renderer") -------------------- */

/* 1 if the texture is a solid texture baked into a 3D texture (its
 * render_scene_texture is then SAMPLE_TEXTURE_3D). */
int render_scene_texture_solid(const render_scene *sc, int texture);
/* A solid texture's wrap mode on s, t and r (its box's, not the scene's
 * sampler's); SAMPLE_WRAP_REPEAT for any other texture. */
sample_wrap render_scene_solid_wrap(const render_scene *sc, int texture);
/* The volume query of a hit on such a texture: (s, t, r) of the surface
 * point P in the solid's box and the columns dP/dx, dP/dy of the exact ray
 * differentials in the same units. 0 if the texture is not a baked solid. */
int render_scene_solid_query(const render_scene *sc, int texture, const render_hit *h,
                             sample_query3 *q);
/* n such queries through sample_batch_3d with smp's filters and the
 * solid's own wrap mode on s, t and r; 1 on success. */
int render_scene_solid_sample(const render_scene *sc, int texture, const sample_sampler *smp,
                              const sample_query3 *q, size_t n, float *rgba, sample_stats *stats);

/* ---- Rendering ------------------------------------------------------ */

/* Progress report: `what` is being done, done of total units. Called from
 * worker threads under a lock (e.g. cli_progress). */
typedef void (*render_progress_fn)(const char *what, size_t done, size_t total);

/* Per-pixel buffers on request (render_options.buffers). */
enum {
    RENDER_BUF_ST = 1u << 0,      /* s, t */
    RENDER_BUF_JACOBIAN = 1u << 1,/* ds/dx, dt/dx, ds/dy, dt/dy */
    RENDER_BUF_LOD = 1u << 2,     /* λ (sample_stats.lod) */
    RENDER_BUF_TEXELS = 1u << 3,  /* texels read (sample_stats.texels) */
    RENDER_BUF_DEPTH = 1u << 4,   /* depth (inf for background) */
    RENDER_BUF_NORMAL = 1u << 5,  /* N x, y, z */
    RENDER_BUF_ID = 1u << 6,      /* object, prim (as floats) */
};

typedef enum render_shade {
    RENDER_SHADE_FULL = 0,    /* Blinn–Newell: diffuse × texture + highlight + reflection */
    RENDER_SHADE_TEXTURE = 1, /* the filtered texture value only (for compare) */
} render_shade;

typedef struct render_options {
    sample_sampler sampler; /* used for every texture lookup */
    int use_scene_sampler;  /* 1 (default): take the scene's sampler instead */
    int threads;            /* ≥ 1; default 1 */
    render_progress_fn progress; /* NULL: silent */
    int corners;            /* 1: pass exact corners (sample_quad) where valid */
    render_shade shade;
    unsigned buffers;       /* RENDER_BUF_* */
    float background[4];    /* unused: the scene's "background" colour is used */
} render_options;

void render_options_init(render_options *o);

typedef struct render_image {
    int width, height;
    float *rgba;  /* width × height × 4, linear, row 0 at the top */
    /* Requested buffers, width × height × n floats each (NULL if not asked):
     * st (2), jacobian (4), lod (1), texels (1), depth (1), normal (3), id (2). */
    float *st, *jacobian, *lod, *texels, *depth, *normal, *id;
} render_image;

/* Render the scene. Deterministic: the same bytes whatever `threads` is.
 * Returns 0 on success. */
int render_image_run(const render_scene *sc, const render_options *o, render_image *out,
                     char *err, size_t errlen);
void render_image_free(render_image *img);

/* ---- Threads -------------------------------------------------------- */

/* fn(ctx, row) for rows 0..rows−1 on `threads` threads (< 1 counts as 1),
 * the calling thread among them; rows are handed out one at a time, so
 * costly rows do not leave threads idle. Each row's work must not depend on
 * which thread runs it. progress (NULL: none) is called every few rows
 * under `what` (NULL: "rows"). Returns 1, or 0 if not every thread could
 * be started (the rows still all ran, on fewer threads). */
int render_parallel_rows(int rows, int threads, void (*fn)(void *ctx, int row), void *ctx,
                         render_progress_fn progress, const char *what);

/* ---- Output (libsample_io; without it these fail with a message) ------ */

/* 1 for a path ending in .exr, 2 for .png, 0 otherwise. */
int render_output_kind(const char *path);
/* The picture: .exr as linear float RGBA, .png as sRGB 8-bit RGB. Written
 * to a temporary file and renamed. Returns 0 on success. */
int render_image_write(const render_image *img, const char *path, char *err, size_t errlen);
/* All seven buffers (render with every RENDER_BUF_* bit) as one float
 * OpenEXR with the channels render_buffer_names, row 0 at the top;
 * background pixels: Z = inf, object = prim = −1, the rest 0. */
#define RENDER_BUFFER_CHANNELS 14
extern const char *const render_buffer_names[RENDER_BUFFER_CHANNELS];
int render_image_write_buffers(const render_image *img, const char *path, char *err,
                               size_t errlen);

#endif
