/* Volumes (3D textures) from raw files or volume images, for the
 * subcommands that take --volume (lookup, info): the options, the loading
 * and a description. */
#ifndef TEXSAMPLE_VOLLOAD_H
#define TEXSAMPLE_VOLLOAD_H

#include "sample/sample.h"

typedef struct vl_source {
    const char *path;   /* --volume FILE: raw float32 RGBA, x fastest, then y, then
                         * z, with --w --h --d; without them a volume image */
    const char *levels; /* --levels PREFIX: PREFIX.k.raw for k ≥ 1 */
    int dims[3];        /* --w, --h, --d */
} vl_source;

/* Whether the command line names --volume. */
int vl_given(int argc, char **argv);
/* Consumes --volume, --levels, --w, --h, --d. Returns 1 if consumed, 0 if
 * not ours, −1 on a bad value (reported). */
int vl_source_flag(const char *sub, int argc, char **argv, int *i, vl_source *src);
/* Consumes --mipgen KERNEL into mip->filter: 1 if consumed, 0 if not
 * ours, −1 on an unknown kernel (reported). */
int vl_mipgen_flag(const char *sub, int argc, char **argv, int *i, sample_mip_params *mip);
/* Usage errors of an incomplete source (reported): EXIT_USAGE, else 0. */
int vl_source_check(const char *sub, const vl_source *src);
/* The volume and its levels (as many PREFIX.k.raw as exist), or its
 * pyramid built by `mip`; a volume image (sample_io_read_volume) where no
 * size is given. Errors reported. 0 on success, −1 after an error, and in
 * the front program (no image support) TL_IMAGE_PROGRAM for a volume
 * image (texload.h). */
int vl_load(const char *sub, const vl_source *src, const sample_mip_params *mip, sample_texture **out);
/* What `info` prints of a 3D texture: kind, size, format, channels,
 * levels (each w x h x d) and bytes; origin says where the levels came
 * from. */
void vl_print_texture(const sample_texture *tex, const char *origin);

#endif
