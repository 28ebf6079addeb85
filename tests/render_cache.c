/*
 * Image textures through the scene's texture system (doc/renderer.md,
 * "Image textures"): the pictures are those of the files read whole, bit
 * for bit — the built-in photo-plane (an untiled JPEG, tiled and
 * mip-mapped on first use) and the same photograph as a tiled, mip-mapped
 * OpenEXR, through the default cache and through one that holds a fraction
 * of its tiles (evicting while two threads render), the same file as
 * colour and as a bump map (two textures of the system); a mirror sphere
 * under a cube and a lat-long environment file; --cache-mb's usage error.
 */
#define _POSIX_C_SOURCE 200809L
#include "check.h"
#include "render.h"

#include <stdint.h>
#include <stdlib.h>
#include <unistd.h>

#ifdef TEXSAMPLE_HAVE_IO
#include "sample/sample_io.h"

static char dir[64];
static const char *texsample;

static int render(const char *scene_file, const char *builtin, double cache_mb, int threads, render_image *img)
{
    render_parse_options po;
    render_options o;
    render_scene *sc = NULL;
    char err[512] = "";
    int r;
    render_parse_options_init(&po);
    po.cache_mb = cache_mb;
    r = builtin ? render_scene_builtin_ex(builtin, 48, 32, &po, &sc, err, sizeof err)
                : render_scene_load_ex(scene_file, 48, 32, &po, &sc, err, sizeof err);
    memset(img, 0, sizeof *img);
    CHECK(r == 0, "%s", err);
    if (r != 0) return 0;
    render_options_init(&o);
    o.threads = threads;
    r = render_image_run(sc, &o, img, err, sizeof err);
    CHECK(r == 0, "%s", err);
    render_scene_destroy(sc);
    return r == 0;
}

static void same_picture(const render_image *a, const render_image *b, const char *what)
{
    CHECK(a->width == b->width && a->height == b->height, "%s: sizes differ", what);
    if (a->width == b->width && a->height == b->height)
        CHECK(memcmp(a->rgba, b->rgba, sizeof(float) * 4 * (size_t)a->width * (size_t)a->height) == 0,
              "%s: the pictures differ", what);
}

/* The untiled photograph: the texture system tiles it and builds its
 * box pyramid, which must be what sample_io_read_texture builds. */
static void test_builtin(void)
{
    render_image whole, cached;
    if (render(NULL, "photo-plane", 0.0, 1, &whole) && render(NULL, "photo-plane", RENDER_CACHE_MB, 1, &cached))
        same_picture(&whole, &cached, "photo-plane");
    render_image_free(&whole);
    render_image_free(&cached);
}

/* The photograph as a tiled mip-mapped OpenEXR (sample_io_make_mip, 64²
 * tiles): tiles read one by one, through a cache of 0.25 MiB (about a
 * sixth of the file's texels with its levels) on two threads. */
static void test_tiled(void)
{
    char exr[128], scene[128];
    sample_io_exr_options wo;
    sample_mip_params mip;
    sample_error e;
    render_image whole, cached, small;
    FILE *f;
    snprintf(exr, sizeof exr, "%s/photo.exr", dir);
    snprintf(scene, sizeof scene, "%s/scene.json", dir);
    sample_io_exr_options_init(&wo);
    sample_mip_params_init(&mip);
    if (sample_io_make_mip(TEXSAMPLE_SOURCE_DIR "/testimages/photo.jpg", exr, NULL, &mip, &wo, &e) != SAMPLE_OK) {
        CHECK(0, "%s", e.message);
        return;
    }
    CHECK((f = fopen(scene, "w")) != NULL, "%s", scene);
    if (!f) return;
    fprintf(f, "{\"camera\":{\"eye\":[0,-1.6,0.75],\"look\":[0,1.2,0],\"up\":[0,0,1],\"fov\":50},"
               "\"sampler\":{\"min\":\"linear_mipmap_linear\",\"mag\":\"linear\"},"
               "\"textures\":[{\"name\":\"photo\",\"type\":\"image\",\"file\":\"photo.exr\"},"
               "{\"name\":\"bumps\",\"type\":\"image\",\"file\":\"photo.exr\",\"colorspace\":\"data\"}],"
               "\"materials\":[{\"name\":\"m\",\"texture\":\"photo\",\"bump\":\"bumps\",\"gloss\":0.3}],"
               "\"objects\":[{\"type\":\"polygons\",\"material\":\"m\",\"polygons\":[{\"v\":[[-1,-1.2,0],"
               "[1,-1.2,0],[1,3.5,0],[-1,3.5,0]],\"st\":[[0,1],[1,1],[1,0],[0,0]]}]}]}");
    CHECK(fclose(f) == 0, "%s", scene);
    if (render(scene, NULL, 0.0, 1, &whole) && render(scene, NULL, RENDER_CACHE_MB, 1, &cached) &&
        render(scene, NULL, 0.25, 2, &small)) {
        same_picture(&whole, &cached, "tiled file, default cache");
        same_picture(&whole, &small, "tiled file, 0.25 MiB cache, 2 threads");
    }
    render_image_free(&whole);
    render_image_free(&cached);
    render_image_free(&small);
    remove(exr);
    remove(scene);
}

/* A mirror sphere under an environment file: a cube map (16² faces) and a
 * 2:1 lat-long map, both written by sample_io_write_env, through the
 * texture system and read whole: the same pictures. */
static void test_environment(void)
{
    static const char *const names[2] = {"cube.exr", "latlong.exr"};
    float *px = malloc(sizeof(float) * 4 * 16 * 16 * 6);
    sample_image faces[6], img;
    sample_mip_params mip;
    sample_texture *env[2] = {NULL, NULL};
    sample_error e;
    char path[128], scene[128];
    uint64_t r = 88172645463325252ull;
    int k;
    if (!px) return;
    for (k = 0; k < 4 * 16 * 16 * 6; ++k) {
        r ^= r << 13, r ^= r >> 7, r ^= r << 17;
        px[k] = (float)(r >> 40) / 16777216.0f;
    }
    for (k = 0; k < 6; ++k) {
        faces[k].width = faces[k].height = 16;
        faces[k].channels = 4;
        faces[k].format = SAMPLE_FORMAT_F32;
        faces[k].data = px + (size_t)k * 4 * 16 * 16;
        faces[k].row_stride = 0;
    }
    img = faces[0];
    img.width = 32; /* the first two faces' texels as a 32 x 16 map */
    sample_mip_params_init(&mip);
    CHECK(sample_texture_create_cube(faces, &mip, &env[0], &e) == SAMPLE_OK, "%s", e.message);
    CHECK(sample_texture_create(&img, &mip, &env[1], &e) == SAMPLE_OK, "%s", e.message);
    for (k = 0; k < 2; ++k) {
        render_image whole, cached;
        FILE *f;
        snprintf(path, sizeof path, "%s/%s", dir, names[k]);
        snprintf(scene, sizeof scene, "%s/mirror.json", dir);
        CHECK(env[k] && sample_io_write_env(path, env[k], NULL, &e) == SAMPLE_OK, "%s", e.message);
        if (!(f = fopen(scene, "w"))) continue;
        fprintf(f, "{\"camera\":{\"eye\":[0,-3,0.5],\"look\":[0,0,0],\"up\":[0,0,1],\"fov\":45},"
                   "\"environment\":{\"file\":\"%s\"},"
                   "\"materials\":[{\"diffuse\":[0,0,0],\"ambient\":0,\"reflect\":1}],"
                   "\"objects\":[{\"type\":\"sphere\"}]}",
                names[k]);
        fclose(f);
        if (render(scene, NULL, 0.0, 1, &whole) && render(scene, NULL, RENDER_CACHE_MB, 1, &cached))
            same_picture(&whole, &cached, names[k]);
        render_image_free(&whole);
        render_image_free(&cached);
        remove(path);
        remove(scene);
        sample_texture_destroy(env[k]);
    }
    free(px);
}

static int exit_code(int status) { return WIFEXITED(status) ? WEXITSTATUS(status) : -1; }

static void test_usage(void)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "%s render --cache-mb -1 --out %s/x.png 2>/dev/null", texsample, dir);
    CHECK(exit_code(system(cmd)) == 2, "render --cache-mb -1 is a usage error");
}

int main(int argc, char **argv)
{
    snprintf(dir, sizeof dir, "/tmp/render_cache_XXXXXX");
    if (!mkdtemp(dir)) {
        fprintf(stderr, "cannot create a folder in /tmp\n");
        return 1;
    }
    texsample = argc > 1 ? argv[1] : "texsample";
    RUN(test_builtin);
    RUN(test_tiled);
    RUN(test_environment);
    RUN(test_usage);
    rmdir(dir);
    return check_finish();
}

#else

int main(void)
{
    printf("no libsample_io in this build\n");
    return CHECK_SKIP_CODE;
}

#endif
