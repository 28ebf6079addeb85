/* texsample lookup's 3D textures (cmd_lookup_volume.c): cmd_lookup hands
 * a command line with --volume to cmd_lookup_volume, and lists its options
 * in its --help. */
#ifndef TEXSAMPLE_LOOKUP_VOLUME_H
#define TEXSAMPLE_LOOKUP_VOLUME_H

#include "sample/sample.h"

#include <stddef.h>

/* The --help section of lookup --volume. */
extern const char lookup_volume_help[];
/* Whether the command line names --volume. */
int lookup_is_volume(int argc, char **argv);
/* lookup --volume ...: the whole command. */
int cmd_lookup_volume(int argc, char **argv);
/* --stats of a lookup: texels read per query (mean, max) on stderr. */
void lookup_stats_print(const sample_stats *stats, size_t n);

#endif
