/* texsample lookup's and info's 3D textures (cmd_lookup_volume.c,
 * cmd_info_volume.c): each command hands a command line with --volume
 * (vl_given) to its volume function, and lists its options in its --help. */
#ifndef TEXSAMPLE_LOOKUP_VOLUME_H
#define TEXSAMPLE_LOOKUP_VOLUME_H

#include "sample/sample.h"
#include "volload.h"

#include <stddef.h>

/* The --help section of lookup --volume. */
extern const char lookup_volume_help[];
/* lookup --volume ...: the whole command. */
int cmd_lookup_volume(int argc, char **argv);
/* The --help section of info --volume. */
extern const char info_volume_help[];
/* info --volume ...: the whole command. */
int cmd_info_volume(int argc, char **argv);
/* What every lookup does once its texture is made (cmd_lookup.c): read
 * the query file (qfloats floats per query: 6 for a 2D texture, 9 for a
 * cube map, lat-long map or volume) and the corner file (cpath, 2D only;
 * NULL without --corners), sample them through run, write --out, print
 * --text and --stats (texels read per query, mean and max, on stderr). */
typedef struct lookup_job {
    const char *qpath, *cpath, *opath;
    int qfloats, text, want_stats;
    sample_status (*run)(void *ctx, const void *queries, const void *corners, size_t n, float *out,
                         sample_stats *stats);
    void *ctx;
} lookup_job;
/* EXIT_OK, or EXIT_RUNTIME with the error printed. */
int lookup_run(const char *sub, const lookup_job *job);

#endif
