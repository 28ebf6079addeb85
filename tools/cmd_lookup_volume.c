/*
 * texsample lookup --volume: evaluate a file of 9-float queries against a
 * 3D texture held as raw float32 RGBA (doc/volumes.md, README). The same
 * sampler options as a 2D lookup, and --wrap-r for the third axis; the
 * check against Mesa's 3D textures goes through this.
 */
#include "cli.h"
#include "lookup_volume.h"
#include "texload.h"
#include "volload.h"
#ifdef TEXSAMPLE_FRONT
#include "image_program.h"
#endif

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char lookup_volume_help[] =
    "3D textures (lookup --volume):\n"
    "  --volume FILE --w W --h H --d D\n"
    "                          little-endian float32 RGBA texels, x fastest, then y,\n"
    "                          then z (slice 0, r = 0, first)\n"
    "  --volume FILE           a volume image: the pages of a TIFF or the parts of an\n"
    "                          OpenEXR as slices, or a volumetric TIFF; first 4\n"
    "                          channels as stored (no colour conversion)\n"
    "  --levels PREFIX         raw volumes: explicit levels PREFIX.1.raw, PREFIX.2.raw, ... of\n"
    "                          max(1, W>>k) x max(1, H>>k) x max(1, D>>k); as many as\n"
    "                          exist are used, and no pyramid is generated\n"
    "  --mipgen box|lanczos3|kaiser|none       the pyramid otherwise (default box)\n"
    "  --wrap-r MODE           wrap mode on r (default repeat; --wrap sets s and t)\n"
    "  --queries FILE          float32, 9 per query: s t r, ds/dx dt/dx dr/dx,\n"
    "                          ds/dy dt/dy dr/dy\n"
    "  --out FILE, --text, --stats             as for 2D queries\n"
    "  Volumes are always sampled one query at a time (--reference-path is accepted).\n\n";

/* How a volume lookup samples (lookup_job.run). */
typedef struct lookup_volume {
    const sample_texture *tex;
    const sample_sampler *smp;
} lookup_volume;

static sample_status lookup_volume_run(void *ctx, const void *queries, const void *corners, size_t n, float *out,
                                       sample_stats *stats)
{
    const lookup_volume *l = (const lookup_volume *)ctx;
    sample_batch3_args a;
    (void)corners;
    memset(&a, 0, sizeof a);
    a.count = n;
    a.queries = (const sample_query3 *)queries;
    a.rgba = out;
    a.stats = stats;
    return sample_batch_3d(l->tex, l->smp, &a);
}

int cmd_lookup_volume(int argc, char **argv)
{
    const char *sub = "lookup", *qpath = NULL, *opath = NULL, *v;
    int text = 0, want_stats = 0, i, r, rc = EXIT_RUNTIME;
    vl_source src = {NULL, NULL, {0, 0, 0}};
    sample_sampler smp;
    sample_mip_params mip;
    sample_texture *tex = NULL;

    sample_sampler_init(&smp);
    sample_mip_params_init(&mip);
    for (i = 1; i < argc; ++i) {
        if (cli_is_help(argv[i])) {
            fputs(lookup_volume_help, stdout);
            cli_sampler_help_print();
            return EXIT_OK;
        }
        if (cli_opt(argc, argv, &i, "--reference-path", NULL)) continue;
        if (cli_opt(argc, argv, &i, "--wrap-r", &v)) {
            int m = sample_wrap_parse(v);
            if (m < 0) return cli_usage_error(sub, "--wrap-r: unknown wrap mode '%s'", v);
            smp.wrap_r = (sample_wrap)m;
            continue;
        }
        if ((r = cli_sampler_flag(sub, argc, argv, &i, &smp)) != 0) {
            if (r < 0) return EXIT_USAGE;
            continue;
        }
        if ((r = vl_source_flag(sub, argc, argv, &i, &src)) != 0) {
            if (r < 0) return EXIT_USAGE;
            continue;
        }
        if (cli_opt(argc, argv, &i, "--queries", &qpath)) continue;
        if (cli_opt(argc, argv, &i, "--out", &opath)) continue;
        if (cli_opt(argc, argv, &i, "--text", NULL)) { text = 1; continue; }
        if (cli_opt(argc, argv, &i, "--stats", NULL)) { want_stats = 1; continue; }
        if ((r = vl_mipgen_flag(sub, argc, argv, &i, &mip)) != 0) {
            if (r < 0) return EXIT_USAGE;
            continue;
        }
        if (argv[i][0] != '-')
            return cli_usage_error(sub, "unexpected argument '%s' (files are given by options)", argv[i]);
        return cli_usage_error(sub, "unknown option '%s' (with --volume)", argv[i]);
    }
    if (vl_source_check(sub, &src) != 0) return EXIT_USAGE;
    if (!qpath) return cli_usage_error(sub, "--queries FILE is required");
    if (sample_sampler_validate(&smp) != SAMPLE_OK)
        return cli_usage_error(sub, "inconsistent sampler state (min-lod > max-lod, base-level > max-level, or aniso < 1)");
    /* The pyramid's edges follow the sampler's wrap modes. */
    mip.wrap_s = smp.wrap_s;
    mip.wrap_t = smp.wrap_t;
    mip.wrap_r = smp.wrap_r;
    if ((r = vl_load(sub, &src, &mip, &tex)) != 0) {
#ifdef TEXSAMPLE_FRONT
        if (r == TL_IMAGE_PROGRAM) return image_program_run(argc, argv);
#endif
        return EXIT_RUNTIME;
    }

    {
        lookup_volume ctx = {tex, &smp};
        lookup_job job = {qpath, NULL, opath, 9, text, want_stats, lookup_volume_run, &ctx};
        if (lookup_run(sub, &job) != EXIT_OK) goto done;
    }
    rc = EXIT_OK;
done:
    sample_texture_destroy(tex);
    return rc;
}
