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
/* --stats of a lookup: texels read per query (mean, max) on stderr. */
void lookup_stats_print(const sample_stats *stats, size_t n);

#endif
