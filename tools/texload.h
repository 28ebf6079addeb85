/* Where a subcommand's texture comes from: raw float files or an image file. */
#ifndef TEXSAMPLE_TEXLOAD_H
#define TEXSAMPLE_TEXLOAD_H

#include "sample/sample.h"
#ifdef TEXSAMPLE_HAVE_IO
#include "sample/sample_io.h"
#endif

typedef struct tl_source {
    const char *raw;        /* --raw FILE: float32 RGBA (also --cube, --latlong) */
    int w, h;               /* --w, --h */
    /* Environment maps (lookup's --cube, --latlong; doc/environment-maps.md):
     * raw holds six size x size faces in GL order (a cube map), or a 2D
     * texture sampled by direction (latlong). */
    int cube, size, latlong;
    const char *levels;     /* --levels PREFIX: PREFIX.k.raw for k ≥ 1 */
    const char *image;      /* --image FILE (libsample_io) */
    const char *colorspace; /* --colorspace NAME for --image */
    /* In: a pyramid built for an image file takes its edges from the
     * file's wrap modes where it stores them. */
    int wrap_from_file;
    /* Out (tl_load of an image file): the wrap modes the file stores. */
    int has_wrap;
    sample_wrap wrap_s, wrap_t;
} tl_source;

void tl_source_init(tl_source *src);
/* Consumes --raw, --w, --h, --levels, --image, --colorspace. Returns 1 if
 * consumed, 0 if not ours, −1 on a bad value (reported). */
int tl_source_flag(const char *sub, int argc, char **argv, int *i, tl_source *src);
int tl_source_given(const tl_source *src);
/* Loads the texture; errors are reported on stderr, and so is a file that
 * names a colour space the OCIO config does not know (a warning: which
 * name, and the space used instead). Returns 0 on success,
 * −1 after reporting an error, and in the front program (which reads no
 * image files: tools/CMakeLists.txt) TL_IMAGE_PROGRAM for an image file:
 * the command is then run again in the image program (image_program.h). */
enum { TL_IMAGE_PROGRAM = 1 };
int tl_load(const char *sub, tl_source *src, const sample_mip_params *mip, sample_texture **out);

#ifdef TEXSAMPLE_HAVE_IO
/* The warning tl_load gives for an image file naming a colour space the
 * OCIO config does not know (which name, and the space used instead), for
 * commands that read files otherwise (info). */
void tl_warn_colorspace(const char *sub, const char *path, const sample_io_file_info *file);
#endif

#endif
