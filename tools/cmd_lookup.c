/*
 * texsample lookup: evaluate a query file against a texture. This is how
 * anyone checks the engine against another implementation (Mesa, OIIO):
 * same texels, same sampler state, same queries, compare the floats.
 */
#include "cli.h"
#include "sample/testing.h"
#include "commands.h"
#include "lookup_volume.h"
#include "texload.h"
#ifdef TEXSAMPLE_FRONT
#include "image_program.h"
#endif
#ifdef TEXSAMPLE_HAVE_IO
#include "sample/texsys.h"
#endif

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
    "usage: texsample lookup (--raw FILE --w W --h H | --image FILE) --queries FILE\n"
    "                        [--out FILE] [--text] [sampler options]\n"
    "       texsample lookup (--cube FILE --size N | --latlong FILE --w W --h H)\n"
    "                        --queries FILE [--out FILE] [--text] [sampler options]\n\n"
    "Samples a texture at every query of a query file and writes the results.\n\n"
    "Texture:\n"
    "  --raw FILE --w W --h H  little-endian float32 RGBA texels, row 0 (t = 0) first\n"
    "  --image FILE            any image OpenImageIO reads (and .exr/.tx mip files)\n"
    "  --colorspace NAME       colour space of the --image file (an OCIO name; default:\n"
    "                          the file's metadata, else 8/16-bit = sRGB, half/float =\n"
    "                          linear)\n"
    "  --levels PREFIX         explicit mip levels PREFIX.1.raw, PREFIX.2.raw, ... (raw\n"
    "                          float32 RGBA, sizes max(1, W>>k) x max(1, H>>k)); as many\n"
    "                          as exist are used, and no pyramid is generated\n"
    "  --cube FILE --size N    a cube map: six N x N faces of float32 RGBA in OpenGL's\n"
    "                          order +X -X +Y -Y +Z -Z, each row 0 (t = 0) first; with\n"
    "                          --levels, PREFIX.L.raw holds the six faces of level L.\n"
    "                          Queries are directions (below); filtering is seamless\n"
    "                          across faces, wrap modes are ignored\n"
    "  --latlong FILE --w W --h H\n"
    "                          a lat-long (equirectangular) map, float32 RGBA, row 0\n"
    "                          (t = 0, up = +y) first, sampled by direction with\n"
    "                          OpenImageIO's convention (doc/environment-maps.md);\n"
    "                          --levels as for --raw\n"
    "  --mipgen box|lanczos3|kaiser|none\n"
    "                          how to build the pyramid otherwise (default box)\n"
    "  --cache-mb N            read the --image file through a texture system whose tile\n"
    "                          cache holds at most N MiB (sample/texsys.h; UDIM names\n"
    "                          such as tex.<UDIM>.exr too): tiles load as queries touch\n"
    "                          them, the results are the same; --stats adds the cache's\n"
    "                          (doc/texture-system.md)\n"
    "  An --image file's stored wrap modes (wrapmodes, as mip writes them) are used\n"
    "  unless --wrap, --wrap-s or --wrap-t is given.\n\n"
    "Queries:\n"
    "  --queries FILE          float32, 6 per query: s t ds/dx dt/dx ds/dy dt/dy\n"
    "                          (--cube, --latlong: 9 per query: x y z, dR/dx, dR/dy)\n"
    "  --corners FILE          float32, 8 per query: the (s,t) images of the pixel's 2x2\n"
    "                          footprint corners (-1,-1) (+1,-1) (+1,+1) (-1,+1)\n"
    "                          (used by --filter blinn-newell)\n"
    "  --out FILE              float32 RGBA per query (default: none)\n"
    "  --text                  print 's t -> r g b a' per query on stdout\n"
    "  --stats                 print texels read per query (mean, max) on stderr\n"
    "  --reference-path        sample through the reference path (the same results,\n"
    "                          slower; sample/testing.h)\n\n";

/* Whether arg is option `name`, as NAME or NAME=VALUE. */
static int is_option(const char *arg, const char *name)
{
    size_t n = strlen(name);
    return strncmp(arg, name, n) == 0 && (arg[n] == '\0' || arg[n] == '=');
}

/* Direction queries of an environment map (a cube map, or a 2D texture
 * as a lat-long map). */
static sample_status lookup_env(const sample_texture *tex, const sample_sampler *smp, const void *queries, size_t n,
                                float *out, sample_stats *stats)
{
    sample_batch3_args a;
    memset(&a, 0, sizeof a);
    a.count = n;
    a.queries = (const sample_query3 *)queries;
    a.rgba = out;
    a.stats = stats;
    return sample_batch_env(tex, smp, &a);
}
#ifdef TEXSAMPLE_HAVE_IO
/* The --image file through a texture system of cache_mb MiB (and the file's
 * wrap modes into src, as tl_load gives them). */
static int open_cached(const char *sub, tl_source *src, double cache_mb, sample_texsys **sys,
                       const sample_texture **tex)
{
    sample_texsys_options o;
    sample_texsys_info info;
    sample_error err;
    sample_texsys_options_init(&o);
    o.max_memory_mb = cache_mb;
    o.colorspace = src->colorspace;
    if (sample_texsys_create(&o, sys, &err) != SAMPLE_OK || sample_texsys_open(*sys, src->image, tex, &err) != SAMPLE_OK ||
        sample_texsys_texture_info(*sys, *tex, &info, &err) != SAMPLE_OK)
        return cli_runtime_error(sub, "%s: %s", src->image, err.message), -1;
    src->has_wrap = info.has_wrap;
    src->wrap_s = info.wrap_s;
    src->wrap_t = info.wrap_t;
    return 0;
}

/* What the cache did (--stats), and the tiles that read as the fill. */
static void report_cache(const char *sub, sample_texsys *sys, const sample_texture *tex, int want_stats)
{
    sample_texsys_stats st;
    sample_error first;
    unsigned long bad = sample_texsys_texture_error(sys, tex, &first);
    sample_texsys_stats_get(sys, &st);
    if (bad)
        fprintf(stderr, "texsample %s: warning: %lu tiles could not be read and read as the fill colour (first: %s)\n",
                sub, bad, first.message);
    if (want_stats)
        fprintf(stderr, "cache: tiles read %llu, bytes read %llu, misses %llu, evictions %llu, peak memory %zu bytes, "
                        "files opened %llu\n",
                (unsigned long long)st.tiles_read, (unsigned long long)st.bytes_read, (unsigned long long)st.misses,
                (unsigned long long)st.evictions, st.peak_memory, (unsigned long long)st.files_opened);
}
#endif

/* --stats: texels read per query (mean, max) on stderr. */
static void lookup_stats_print(const sample_stats *stats, size_t n)
{
    double sum = 0;
    uint32_t mx = 0;
    size_t k;
    for (k = 0; k < n; ++k) {
        sum += stats[k].texels;
        if (stats[k].texels > mx) mx = stats[k].texels;
    }
    fprintf(stderr, "queries %zu, texels/query mean %.2f max %u (cap %d)\n", n, n ? sum / (double)n : 0.0, mx,
            SAMPLE_MAX_FOOTPRINT_TEXELS);
}

int lookup_run(const char *sub, const lookup_job *job)
{
    void *qdata = NULL, *cdata = NULL;
    size_t qsize = 0, csize = 0, n, k;
    const size_t qbytes = (size_t)job->qfloats * sizeof(float);
    float *out = NULL;
    sample_stats *stats = NULL;
    sample_status st;
    const char *why;
    int rc = EXIT_RUNTIME;
    if (!cli_read_file(job->qpath, &qdata, &qsize, &why)) {
        cli_runtime_error(sub, "cannot read query file '%s': %s", job->qpath, why);
        goto done;
    }
    if (qsize % qbytes != 0) {
        cli_runtime_error(sub, "query file '%s' is %zu bytes, not a multiple of %zu (%d floats)", job->qpath, qsize,
                          qbytes, job->qfloats);
        goto done;
    }
    n = qsize / qbytes;
    if (job->cpath) {
        if (!cli_read_file(job->cpath, &cdata, &csize, &why)) {
            cli_runtime_error(sub, "cannot read corner file '%s': %s", job->cpath, why);
            goto done;
        }
        if (csize != n * 8 * sizeof(float)) {
            cli_runtime_error(sub, "corner file '%s' holds %zu bytes; %zu queries need %zu", job->cpath, csize, n,
                              n * 8 * sizeof(float));
            goto done;
        }
    }
    out = (float *)malloc((n ? n : 1) * 4 * sizeof(float));
    stats = (sample_stats *)malloc((n ? n : 1) * sizeof(sample_stats));
    if (!out || !stats) {
        cli_runtime_error(sub, "out of memory for %zu queries", n);
        goto done;
    }
    if ((st = job->run(job->ctx, qdata, cdata, n, out, stats)) != SAMPLE_OK) {
        cli_runtime_error(sub, "sampling failed: %s", sample_strerror(st));
        goto done;
    }
    if (job->opath && !cli_write_file(job->opath, out, n * 4 * sizeof(float))) {
        cli_runtime_error(sub, "cannot write '%s': %s", job->opath, strerror(errno));
        goto done;
    }
    for (k = 0; job->text && k < n; ++k) {
        const float *q = (const float *)qdata + (size_t)job->qfloats * k;
        if (job->qfloats == 9) printf("%.9g %.9g %.9g", q[0], q[1], q[2]);
        else printf("%.9g %.9g", q[0], q[1]);
        printf(" -> %.9g %.9g %.9g %.9g\n", out[4 * k], out[4 * k + 1], out[4 * k + 2], out[4 * k + 3]);
    }
    if (job->want_stats) lookup_stats_print(stats, n);
    rc = EXIT_OK;
done:
    free(qdata);
    free(cdata);
    free(out);
    free(stats);
    return rc;
}

/* How a 2D, cube or lat-long lookup samples (lookup_job.run). */
typedef struct lookup_2d {
    const tl_source *src;
    const sample_texture *tex;
    const sample_sampler *smp;
    int reference;
    void *sys; /* sample_texsys * under --cache-mb, else NULL */
} lookup_2d;

static sample_status lookup_2d_run(void *ctx, const void *queries, const void *corners, size_t n, float *out,
                                   sample_stats *stats)
{
    const lookup_2d *l = (const lookup_2d *)ctx;
    sample_batch_args a;
    /* Environment maps always run the reference path. */
    if (l->src->cube || l->src->latlong) return lookup_env(l->tex, l->smp, queries, n, out, stats);
    memset(&a, 0, sizeof a);
    a.count = n;
    a.queries = (const sample_query *)queries;
    a.corners = (const sample_quad *)corners;
    a.rgba = out;
    a.stats = stats;
#ifdef TEXSAMPLE_HAVE_IO
    if (l->sys) return sample_texsys_batch((sample_texsys *)l->sys, l->tex, l->smp, &a);
#endif
    return (l->reference ? sample_batch_reference : sample_batch)(l->tex, l->smp, &a);
}

int cmd_lookup(int argc, char **argv)
{
    const char *sub = "lookup";
    tl_source src;
    sample_sampler smp;
    sample_mip_params mip;
    const char *qpath = NULL, *cpath = NULL, *opath = NULL, *v;
    int text = 0, want_stats = 0, reference = 0, wrap_s_given = 0, wrap_t_given = 0, i, r, rc = EXIT_RUNTIME;
    int textures = 0, qfloats;
    sample_texture *tex = NULL;
    const sample_texture *use = NULL;
    float cache_mb = 0.0f;
    int mipgen_given = 0;
#ifdef TEXSAMPLE_HAVE_IO
    sample_texsys *sys = NULL; /* where --cache-mb reads through one */
#endif

    if (vl_given(argc, argv)) return cmd_lookup_volume(argc, argv);
    tl_source_init(&src);
    sample_sampler_init(&smp);
    sample_mip_params_init(&mip);
    for (i = 1; i < argc; ++i) {
        if (cli_is_help(argv[i])) {
            fputs(help, stdout);
            fputs(lookup_volume_help, stdout);
            cli_sampler_help_print();
            return EXIT_OK;
        }
        if (cli_opt(argc, argv, &i, "--reference-path", NULL)) {
            reference = 1;
            continue;
        }
        /* --wrap, --wrap-s, --wrap-t (and their --opt=value forms) override
         * the wrap modes an image file stores, axis by axis. */
        if (strncmp(argv[i], "--wrap", 6) == 0) {
            wrap_s_given |= argv[i][6] != '-' || argv[i][7] == 's';
            wrap_t_given |= argv[i][6] != '-' || argv[i][7] == 't';
        }
        if (is_option(argv[i], "--raw") || is_option(argv[i], "--image")) ++textures;
        if ((r = cli_sampler_flag(sub, argc, argv, &i, &smp)) != 0) {
            if (r < 0) return EXIT_USAGE;
            continue;
        }
        if ((r = tl_source_flag(sub, argc, argv, &i, &src)) != 0) {
            if (r < 0) return EXIT_USAGE;
            continue;
        }
        if (cli_opt(argc, argv, &i, "--cube", &v)) {
            src.raw = v;
            src.cube = 1;
            ++textures;
            continue;
        }
        if (cli_opt(argc, argv, &i, "--latlong", &v)) {
            src.raw = v;
            src.latlong = 1;
            ++textures;
            continue;
        }
        if (cli_opt(argc, argv, &i, "--size", &v)) {
            if (!cli_parse_int(v, &src.size) || src.size <= 0 || src.size > SAMPLE_MAX_SIZE)
                return cli_usage_error(sub, "--size needs a size from 1 to %d, not '%s'", SAMPLE_MAX_SIZE, v);
            continue;
        }
        if (cli_opt(argc, argv, &i, "--queries", &qpath)) continue;
        if (cli_opt(argc, argv, &i, "--corners", &cpath)) continue;
        if (cli_opt(argc, argv, &i, "--out", &opath)) continue;
        if (cli_opt(argc, argv, &i, "--text", NULL)) { text = 1; continue; }
        if (cli_opt(argc, argv, &i, "--stats", NULL)) { want_stats = 1; continue; }
        if (cli_opt(argc, argv, &i, "--mipgen", &v)) {
            int m = sample_mipgen_parse(v);
            if (m < 0) return cli_usage_error(sub, "--mipgen: unknown kernel '%s'", v);
            mip.filter = (sample_mipgen)m;
            mipgen_given = 1;
            continue;
        }
        if (cli_opt(argc, argv, &i, "--cache-mb", &v)) {
            if (!cli_parse_float(v, &cache_mb) || !(cache_mb > 0.0f) || cache_mb > 1048576.0f)
                return cli_usage_error(sub, "--cache-mb: '%s' is not a size in MiB (above 0, at most 1048576)", v);
            continue;
        }
        if (argv[i][0] != '-')
            return cli_usage_error(sub, "unexpected argument '%s' (files are given by options)", argv[i]);
        return cli_usage_error(sub, "unknown option '%s'", argv[i]);
    }
    if (!qpath) return cli_usage_error(sub, "--queries FILE is required");
    if (!tl_source_given(&src)) return cli_usage_error(sub, "a texture is required (--raw, --image, --cube or --latlong)");
    if (textures > 1) return cli_usage_error(sub, "give one texture: --raw, --image, --cube or --latlong");
    if (src.cube && (src.w || src.h)) return cli_usage_error(sub, "--cube takes --size N, not --w/--h");
    if (src.size && !src.cube) return cli_usage_error(sub, "--size is for --cube");
    if ((src.cube || src.latlong) && cpath) return cli_usage_error(sub, "--corners is for 2D queries (--raw, --image)");
    qfloats = (src.cube || src.latlong) ? 9 : 6;
    if (sample_sampler_validate(&smp) != SAMPLE_OK)
        return cli_usage_error(sub, "inconsistent sampler state (min-lod > max-lod, base-level > max-level, or aniso < 1)");
    if (cache_mb > 0.0f && (!src.image || src.levels || (mipgen_given && mip.filter != SAMPLE_MIPGEN_BOX)))
        return cli_usage_error(sub, "--cache-mb reads an --image file, tiled and mip-mapped (box) as the texture "
                                    "system does: not with --raw, --levels or another --mipgen");

    /* The pyramid's edges follow the sampler's wrap modes: the file's when
     * it stores them and the command line names none. */
    mip.wrap_s = smp.wrap_s;
    mip.wrap_t = smp.wrap_t;
    src.wrap_from_file = !wrap_s_given && !wrap_t_given;
    if (cache_mb > 0.0f) {
#ifdef TEXSAMPLE_HAVE_IO
        if (open_cached(sub, &src, cache_mb, &sys, &use) != 0) goto done;
#elif defined(TEXSAMPLE_FRONT)
        return image_program_run(argc, argv);
#else
        return cli_runtime_error(sub, "--cache-mb needs libsample_io, which this build lacks");
#endif
    } else if ((r = tl_load(sub, &src, &mip, &tex)) != 0) {
#ifdef TEXSAMPLE_FRONT
        if (r == TL_IMAGE_PROGRAM) return image_program_run(argc, argv);
#endif
        return EXIT_RUNTIME;
    } else {
        use = tex;
    }
    if (src.has_wrap) {
        if (!wrap_s_given) smp.wrap_s = src.wrap_s;
        if (!wrap_t_given) smp.wrap_t = src.wrap_t;
    }

    {
        lookup_2d ctx = {&src, use, &smp, reference, NULL};
        lookup_job job = {qpath, cpath, opath, qfloats, text, want_stats, lookup_2d_run, &ctx};
#ifdef TEXSAMPLE_HAVE_IO
        ctx.sys = sys;
#endif
        if (lookup_run(sub, &job) != EXIT_OK) goto done;
    }
#ifdef TEXSAMPLE_HAVE_IO
    if (sys) report_cache(sub, sys, use, want_stats);
#endif
    rc = EXIT_OK;
done:
    sample_texture_destroy(tex);
#ifdef TEXSAMPLE_HAVE_IO
    sample_texsys_destroy(sys);
#endif
    return rc;
}
