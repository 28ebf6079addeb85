/*
 * texsample compare end to end (doc/comparison.md, DESIGN §8):
 *   - the ground truth converges: 32 × 32 and 64 × 64 samples per footprint
 *     agree within a stated bound on every scene of the comparison set
 *     (32 × 32 images; max |Δ| < 0.06 and RMS Δ < 0.015 over R, G, B of the
 *     measured pixels — the plane's horizon, with dozens of checks per
 *     pixel, is the worst: 0.046 and 0.010 when written, the zone plate
 *     0.040 and 0.0095);
 *   - the ground truth is the same bytes at any thread count;
 *   - ordering on the plane (64 × 64): nearest without mips has the largest
 *     error, trilinear beats nearest-mipmap-nearest, Blinn–Newell (both
 *     modes) and EWA beat trilinear;
 *   - footprints across an occlusion edge inside one object are left out
 *     of the metrics;
 *   - the face-on zone plate ties four mip filters, the oblique one does not;
 *   - the outputs exist (PNG signatures, CSV, JSON, HTML; pictures linked to
 *     full size, the median of 3 runs reported) and the exit codes;
 *   - OpenImageIO's rows are n/a with the reason on a cube environment map,
 *     a wrap mode it lacks and a solid texture (tools/backends/oiio.c);
 *   - --spp: the stochastic sweep's table (stochastic.csv), plot (spp.png)
 *     and page section; on the mirrors scene it is n/a with the reason
 *     (direction queries take no u).
 * Usage: compare_cli TEXSAMPLE WORKDIR
 */
#define _POSIX_C_SOURCE 200809L
#include "check.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

static const char *exe, *dir;
static const char *const scenes[] = {"plane",     "teapot",            "teapot-image",
                                     "zoneplate", "zoneplate-oblique", "photo-plane", "mirrors"};
enum { NSCENES = sizeof scenes / sizeof scenes[0] };

static int run(const char *args)
{
    char cmd[4096];
    int st;
    snprintf(cmd, sizeof cmd, "mkdir -p %s && cd %s && %s compare %s >out.txt 2>err.txt", dir, dir,
             exe, args);
    st = system(cmd);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* Whole file into a malloc'd buffer; NULL if missing. */
static void *slurp(const char *sub, const char *name, size_t *len)
{
    char p[1024];
    snprintf(p, sizeof p, "%s/%s/%s", dir, sub, name);
    return check_slurp(p, len);
}

static void exit_codes(void)
{
    CHECK(run("--help") == 0, "--help exits 0");
    CHECK(run("--bogus") == 2, "unknown option exits 2");
    CHECK(run("--truth-samples 33") == 2, "odd sample count exits 2");
    CHECK(run("--size 0") == 2, "size 0 exits 2");
    CHECK(run("--runs 0") == 2, "--runs 0 exits 2");
    CHECK(run("--runs") == 2, "--runs without a value exits 2");
    CHECK(run("--configs trilinear,nope") == 2, "unknown configuration exits 2");
    CHECK(run("--spp 4,2") == 2, "--spp counts that do not increase exit 2");
    CHECK(run("--spp 0") == 2, "--spp 0 exits 2");
    CHECK(run("--draws 65") == 2, "--draws past 64 exits 2");
    CHECK(run("--scene no-such-scene.json --size 16 --out bad") == 1, "missing scene exits 1");
}

static void converges(void)
{
    int k;
    CHECK(run("--scene all --size 32 --truth-samples 32 --configs trilinear --no-oiio --raw "
              "--out t32") == 0, "32x32 run");
    CHECK(run("--scene all --size 32 --truth-samples 64 --configs trilinear --no-oiio --raw "
              "--out t64") == 0, "64x64 run");
    for (k = 0; k < NSCENES; ++k) {
        char a[256], b[256];
        size_t la, lb, ma, mb, px, n = 0;
        float *ta, *tb;
        unsigned char *ka, *kb;
        double worst = 0.0, sq = 0.0;
        snprintf(a, sizeof a, "t32/%s", scenes[k]);
        snprintf(b, sizeof b, "t64/%s", scenes[k]);
        ta = slurp(a, "truth.f32", &la);
        tb = slurp(b, "truth.f32", &lb);
        ka = slurp(a, "mask.u8", &ma);
        kb = slurp(b, "mask.u8", &mb);
        CHECK(ta && tb && ka && kb && la == 32 * 32 * 16 && lb == la && ma == 32 * 32 && mb == ma,
              "%s: raw outputs present", scenes[k]);
        if (ta && tb && ka && kb && la == 32 * 32 * 16 && lb == la && ma == 32 * 32 && mb == ma) {
            for (px = 0; px < ma; ++px) {
                int c;
                if (!ka[px] || !kb[px]) continue;
                for (c = 0; c < 3; ++c) {
                    double d = fabs((double)ta[px * 4 + (size_t)c] - (double)tb[px * 4 + (size_t)c]);
                    if (d > worst) worst = d;
                    sq += d * d;
                    ++n;
                }
            }
            /* A scene where nothing is measured would pass vacuously. */
            CHECK(n >= 3 * 100, "%s: only %zu values measured", scenes[k], n);
            CHECK(worst < 0.06, "%s: max |truth32 - truth64| = %g", scenes[k], worst);
            CHECK(sqrt(sq / (double)(n ? n : 1)) < 0.015, "%s: RMS difference %g", scenes[k],
                  sqrt(sq / (double)(n ? n : 1)));
            printf("%-12s truth 32 vs 64: max %.5f RMS %.6f over %zu values\n", scenes[k], worst,
                   sqrt(sq / (double)(n ? n : 1)), n);
        }
        free(ta);
        free(tb);
        free(ka);
        free(kb);
    }
}

/* One object, two parallel squares: the near one covers the left half of
 * the far one, and its right edge (x = 0.5, under the eye) falls on the
 * line between pixel columns 15 and 16 of 32. The footprints of columns 15
 * and 16 straddle that occlusion edge, so the metric mask leaves them out
 * although every sample is on the same object; columns two or more pixels
 * away from the edge (and from the squares' borders) are measured. */
static void occlusion_edge(void)
{
    static const char scene[] =
        "{\"camera\":{\"eye\":[0.5,0.5,2],\"look\":[0.5,0.5,0],\"up\":[0,1,0],\"fov\":20},"
        "\"textures\":[{\"name\":\"c\",\"type\":\"checker\",\"freq\":4}],"
        "\"materials\":[{\"name\":\"m\",\"texture\":\"c\"}],"
        "\"objects\":[{\"type\":\"polygons\",\"material\":\"m\",\"polygons\":["
        "{\"v\":[[-1,-1,0],[2,-1,0],[2,2,0],[-1,2,0]],\"st\":[[0,0],[1,0],[1,1],[0,1]]},"
        "{\"v\":[[-1,-1,0.3],[0.5,-1,0.3],[0.5,2,0.3],[-1,2,0.3]],\"st\":[[0,0],[1,0],[1,1],[0,1]]}"
        "]}]}";
    char path[1024];
    unsigned char *mask;
    size_t len;
    int i, j, edge = 0, off = 0;
    FILE *f;
    snprintf(path, sizeof path, "%s/steps.json", dir);
    f = fopen(path, "w");
    CHECK(f && fputs(scene, f) >= 0 && fclose(f) == 0, "write %s", path);
    CHECK(run("--scene steps.json --size 32 --truth-samples 8 --configs trilinear --no-oiio --runs 1 "
              "--raw --out steps") == 0, "steps run");
    mask = slurp("steps/steps", "mask.u8", &len);
    CHECK(mask && len == 32 * 32, "mask.u8 written");
    if (!mask || len != 32 * 32) {
        free(mask);
        return;
    }
    for (j = 2; j < 30; ++j) {
        edge += mask[j * 32 + 15] + mask[j * 32 + 16];
        for (i = 2; i < 30; ++i)
            if (i < 14 || i > 17) off += !mask[j * 32 + i];
    }
    CHECK(edge == 0, "%d pixels measured across the occlusion edge", edge);
    CHECK(off == 0, "%d pixels away from the edge left out", off);
    free(mask);
}

static void threads_identical(void)
{
    size_t la, lb;
    void *a, *b;
    CHECK(run("--scene teapot --size 32 --configs ewa --no-oiio --raw --threads 1 --out th1") == 0,
          "1 thread");
    CHECK(run("--scene teapot --size 32 --configs ewa --no-oiio --raw --threads 3 --out th3") == 0,
          "3 threads");
    a = slurp("th1/teapot", "truth.f32", &la);
    b = slurp("th3/teapot", "truth.f32", &lb);
    CHECK(a && b && la == lb && la > 0 && memcmp(a, b, la) == 0, "truth identical across threads");
    free(a);
    free(b);
    a = slurp("th1/teapot", "ewa.f32", &la);
    b = slurp("th3/teapot", "ewa.f32", &lb);
    CHECK(a && b && la == lb && la > 0 && memcmp(a, b, la) == 0, "EWA image identical across threads");
    free(a);
    free(b);
}

/* RMSE of a configuration in results.csv (scene,config,label,rmse,...). */
static double csv_rmse(const char *csv, const char *scene, const char *config)
{
    char key[128];
    const char *p;
    snprintf(key, sizeof key, "\n%s,%s,", scene, config);
    p = strstr(csv, key);
    if (!p) return NAN;
    p += strlen(key);
    if (*p == '"') p = strchr(p + 1, '"');
    if (!p || !(p = strchr(p, ','))) return NAN;
    return strtod(p + 1, NULL);
}

/* The face-on zone plate asks every pixel for the same isotropic
 * footprint at λ = 2 (at 256 x 256; λ = 4 at 64 x 64), so every isotropic
 * mip filter reads one level alone and the four score the same to the
 * last digit; on the oblique plate, where λ and the anisotropy vary, no
 * two of the five filters tie. */
static void zoneplate_ties(void)
{
    static const char *const configs[] = {"nearest_mipmap_nearest", "trilinear", "aniso16",
                                          "cubic_mipmap_linear", "ewa"};
    double face[5], oblique[5];
    size_t len;
    char *csv;
    int k, l;
    CHECK(run("--scene zoneplate --scene zoneplate-oblique --size 64 --truth-samples 16 --runs 1 "
              "--no-oiio --configs nearest_mipmap_nearest,trilinear,aniso16,cubic_mipmap_linear,ewa "
              "--out zp") == 0, "zone plates run");
    csv = slurp("zp", "results.csv", &len);
    CHECK(csv != NULL, "results.csv written");
    if (!csv) return;
    for (k = 0; k < 5; ++k) {
        face[k] = csv_rmse(csv, "zoneplate", configs[k]);
        oblique[k] = csv_rmse(csv, "zoneplate-oblique", configs[k]);
        printf("zone plate 64x64 %-24s RMSE face-on %.5f oblique %.5f\n", configs[k], face[k],
               oblique[k]);
        CHECK(oblique[k] > 0.0 && oblique[k] < 1.0, "%s oblique RMSE %g", configs[k], oblique[k]);
    }
    for (k = 1; k < 4; ++k) CHECK(face[k] == face[0], "face-on %s %g vs %g", configs[k], face[k], face[0]);
    for (k = 0; k < 5; ++k)
        for (l = k + 1; l < 5; ++l)
            CHECK(fabs(oblique[k] - oblique[l]) > 0.02 * fmin(oblique[k], oblique[l]),
                  "oblique: %s %g and %s %g tie", configs[k], oblique[k], configs[l], oblique[l]);
    free(csv);
}

/* Mirrors in an environment map: the reflected direction's footprint,
 * strongly minified and anisotropic at the sphere's rim and on the
 * teapot's curves, orders the filters (EWA below trilinear below bilinear
 * without mips), and OpenImageIO's environment() without mips, reading the
 * same map, gives bilinear's image: the same texels at the same directions
 * (y up, centres at (i + ½)/w, the seam and poles). Where the build has no
 * OpenImageIO that row is not run and the check is skipped. */
static void mirrors(void)
{
    double bil, tri, ewa, oiio;
    size_t len;
    char *csv;
    CHECK(run("--scene mirrors --size 48 --truth-samples 8 --runs 1 "
              "--configs bilinear,trilinear,ewa,oiio-bilinear --out mir") == 0, "mirrors run");
    if (!(csv = slurp("mir", "results.csv", &len))) {
        CHECK(0, "results.csv written");
        return;
    }
    bil = csv_rmse(csv, "mirrors", "bilinear");
    tri = csv_rmse(csv, "mirrors", "trilinear");
    ewa = csv_rmse(csv, "mirrors", "ewa");
    oiio = csv_rmse(csv, "mirrors", "oiio-bilinear");
    printf("mirrors 48x48 RMSE bilinear %.5f trilinear %.5f ewa %.5f oiio-bilinear %.5f\n", bil, tri, ewa, oiio);
    CHECK(ewa > 0.0 && ewa < tri && tri < bil, "ordering: ewa %g, trilinear %g, bilinear %g", ewa, tri, bil);
    if (strstr(csv, "\nmirrors,oiio-bilinear,") && oiio > 0.0)
        CHECK(fabs(oiio - bil) <= 1e-5 * bil, "OpenImageIO bilinear %g vs bilinear %g", oiio, bil);
    else
        printf("no OpenImageIO in this build: its environment() not compared\n");
    free(csv);
}

static void ordering_and_outputs(void)
{
    static const char *const configs[] = {"nearest", "bilinear", "nearest_mipmap_nearest", "trilinear",
                                          "aniso16", "cubic_mipmap_linear", "blinn-newell",
                                          "blinn-newell-corners", "ewa"};
    static const char *const files[] = {"truth.png", "truth_crop.png", "contact.png", "cost.png",
                                        "trilinear.png", "trilinear_err.png", "trilinear_crop.png"};
    double e[9];
    size_t len;
    char *csv, *json, *html;
    int k;
    CHECK(run("--scene plane --size 64 --no-oiio --out ord") == 0, "plane run");
    csv = slurp("ord", "results.csv", &len);
    CHECK(csv != NULL, "results.csv written");
    if (!csv) return;
    for (k = 0; k < 9; ++k) {
        e[k] = csv_rmse(csv, "plane", configs[k]);
        CHECK(e[k] > 0.0 && e[k] < 1.0, "%s RMSE %g", configs[k], e[k]);
        printf("plane 64x64 %-12s RMSE %.5f\n", configs[k], e[k]);
    }
    for (k = 1; k < 9; ++k)
        CHECK(e[0] > e[k], "nearest (%g) must be worst, %s has %g", e[0], configs[k], e[k]);
    CHECK(e[3] < e[2], "trilinear %g vs nearest-mipmap-nearest %g", e[3], e[2]);
    CHECK(e[6] < e[3], "Blinn-Newell (Jacobian) %g vs trilinear %g", e[6], e[3]);
    CHECK(e[7] < e[3], "Blinn-Newell (corners) %g vs trilinear %g", e[7], e[3]);
    CHECK(e[8] < e[3], "EWA %g vs trilinear %g", e[8], e[3]);
    free(csv);
    for (k = 0; k < (int)(sizeof files / sizeof files[0]); ++k) {
        unsigned char *png = slurp("ord/plane", files[k], &len);
        CHECK(png && len > 8 && memcmp(png, "\x89PNG\r\n\x1a\n", 8) == 0, "%s is a PNG", files[k]);
        free(png);
    }
    json = slurp("ord", "results.json", &len);
    CHECK(json && strstr(json, "\"config\": \"ewa\"") && strstr(json, "\"error_map\": \"plane/ewa_err.png\""),
          "results.json lists the configurations and pictures");
    /* The times are medians of 3 runs by default, and the outputs say so. */
    CHECK(json && strstr(json, "\"runs\": 3,"), "results.json gives the number of runs");
    free(json);
    html = slurp("ord", "index.html", &len);
    CHECK(html && strstr(html, "<a href=\"plane/blinn-newell-corners_err.png\"><img "
                               "src=\"plane/blinn-newell-corners_err.png\"") &&
              strstr(html, "</html>"),
          "index.html shows the pictures, each a link to itself at full size");
    CHECK(html && strstr(html, "median of 3 runs</th>"), "the table header says how many runs");
    CHECK(html && strstr(html, "<img src=\"plane/cost.png\""), "index.html shows RMSE against ns/sample");
    free(html);
    csv = slurp(".", "out.txt", &len);
    CHECK(csv && strstr(csv, "ord/index.html") && strstr(csv, "ord/results.csv"),
          "prints where the page and the table are");
    free(csv);
}

/* Write `text` to dir/name. */
static void put(const char *name, const char *text)
{
    char p[1024];
    FILE *f;
    snprintf(p, sizeof p, "%s/%s", dir, name);
    f = fopen(p, "w");
    CHECK(f != NULL, "cannot write %s", p);
    if (!f) return;
    fputs(text, f);
    fclose(f);
}

/* What OpenImageIO's backend cannot do is an n/a row with the reason. */
static void oiio_na(void)
{
    static const char *const want[] = {
        "\ncube,oiio-trilinear,\"OpenImageIO trilinear\",,,,,,,42,2,1,\"n/a: OpenImageIO's environment() "
        "reads lat-long maps only, not cube maps\"\n",
        "\nwrap,oiio-trilinear,\"OpenImageIO trilinear\",,,,,,,256,2,1,\"n/a: OpenImageIO has no equivalent "
        "of wrap modes mirror_clamp_to_edge/repeat\"\n",
        "\nsolid,oiio-trilinear,\"OpenImageIO trilinear\",,,,,,,42,2,1,\"n/a: OpenImageIO's texture3d has no "
        "mip or footprint filtering for a solid texture's volume\"\n"};
    size_t len;
    char *csv;
    int k;
    put("cube.json", "{\"camera\":{\"eye\":[0,-5,1],\"look\":[0,0,0.5],\"up\":[0,0,1],\"fov\":40},"
                     "\"materials\":[{\"name\":\"mirror\",\"reflect\":1}],"
                     "\"environment\":{\"type\":\"cube\",\"size\":16},"
                     "\"objects\":[{\"type\":\"sphere\",\"centre\":[0,0,0.5],\"radius\":1,\"material\":\"mirror\"}]}");
    put("wrap.json", "{\"camera\":{\"eye\":[0,-5,3],\"look\":[0,0,0],\"up\":[0,0,1],\"fov\":40},"
                     "\"sampler\":{\"wrap_s\":\"mirror_clamp_to_edge\",\"wrap_t\":\"repeat\"},"
                     "\"textures\":[{\"name\":\"g\",\"type\":\"checker\",\"freq\":4,\"size\":32}],"
                     "\"materials\":[{\"name\":\"m\",\"texture\":\"g\"}],"
                     "\"objects\":[{\"type\":\"plane\",\"centre\":[0,0,0],\"axis\":[0,0,1],\"size\":2,"
                     "\"material\":\"m\"}]}");
    put("solid.json", "{\"camera\":{\"eye\":[0,-5,1],\"look\":[0,0,0.5],\"up\":[0,0,1],\"fov\":40},"
                      "\"textures\":[{\"name\":\"w\",\"type\":\"wood\",\"freq\":2,"
                      "\"solid\":{\"min\":[-1,-1,-0.5],\"max\":[1,1,1.5],\"size\":8}}],"
                      "\"materials\":[{\"name\":\"w\",\"texture\":\"w\"}],"
                      "\"objects\":[{\"type\":\"sphere\",\"centre\":[0,0,0.5],\"radius\":1,\"material\":\"w\"}]}");
    if (run("--scene cube.json --scene wrap.json --scene solid.json --size 16 --truth-samples 2 --runs 1 "
            "--configs trilinear,oiio-trilinear --out na") == 2) {
        check_skip("no OpenImageIO in this build");
        return;
    }
    csv = slurp("na", "results.csv", &len);
    CHECK(csv != NULL, "results.csv written");
    for (k = 0; csv && k < 3; ++k) CHECK(strstr(csv, want[k]) != NULL, "n/a row %d", k);
    CHECK(csv && strstr(csv, "\nsolid,trilinear,\"trilinear\",0."), "libsample's row runs beside it");
    free(csv);
}

/* The stochastic sweep end to end, on a 16 x 16 plane and mirrors. */
static void stochastic(void)
{
    size_t len;
    char *csv, *html;
    unsigned char *png;
    CHECK(run("--scene plane --scene mirrors --size 16 --truth-samples 2 --runs 1 --configs "
              "bilinear,trilinear --spp 1,4 --out spp") == 0,
          "sweep run");
    csv = slurp("spp", "stochastic.csv", &len);
    CHECK(csv && strstr(csv, "scene,config,label,spp,draws,rmse,deterministic_rmse,ns_per_sample,note\n") &&
              strstr(csv, "\nplane,trilinear,\"trilinear\",4,1,0.") && !strstr(csv, "bilinear"),
          "stochastic.csv holds trilinear's sweep, not bilinear (u changes nothing)");
    CHECK(csv && strstr(csv, "\nmirrors,trilinear,\"trilinear\",1,1,,,,\"n/a: direction"),
          "the sweep on an environment map is n/a with the reason");
    free(csv);
    png = slurp("spp/plane", "spp.png", &len);
    CHECK(png && len > 8 && memcmp(png, "\x89PNG\r\n\x1a\n", 8) == 0, "spp.png is a PNG");
    free(png);
    html = slurp("spp", "index.html", &len);
    CHECK(html && strstr(html, "<img src=\"plane/spp.png\"") && strstr(html, "<th>4 spp</th>") &&
              !strstr(html, "<img src=\"mirrors/spp.png\""),
          "index.html shows the sweep's table and plot where it ran");
    free(html);
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: compare_cli TEXSAMPLE WORKDIR\n");
        return 2;
    }
    exe = argv[1];
    dir = argv[2];
    RUN(exit_codes);
    RUN(converges);
    RUN(occlusion_edge);
    RUN(threads_identical);
    RUN(zoneplate_ties);
    RUN(ordering_and_outputs);
    RUN(mirrors);
    RUN(oiio_na);
    RUN(stochastic);
    return check_finish();
}
