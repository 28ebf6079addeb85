/*
 * Image textures through the scene's texture system (doc/renderer.md,
 * "Image textures"): the pictures are those of the files read whole, bit
 * for bit — the built-in photo-plane (an untiled JPEG, tiled and
 * mip-mapped on first use) and the same photograph as a tiled, mip-mapped
 * OpenEXR, through the default cache and through one that holds a fraction
 * of its tiles (evicting while two threads render). Also: the same file
 * as colour and as data is two textures, and --cache-mb's usage error.
 */
#define _POSIX_C_SOURCE 200809L
#include "check.h"
#include "render.h"

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
