/* The part of `texsample freq` that lives in the executable (not in the
 * texsample_freq library): file output. */
#ifndef TEXSAMPLE_FREQ_CLI_H
#define TEXSAMPLE_FREQ_CLI_H

#include "freq.h"

/* Write every output of a finished sweep into `dir` (created if missing):
 * freq.csv, summary.csv, summary.md, plot_r*_t*.svg, zone_*.png (when
 * built with libsample_io and png is set), index.html. `zone` holds
 * one zone-plate picture per backend (may be NULL or hold NULLs). Returns
 * 0, or −1 with a message in err. */
int fq_write_outputs(const char *dir, const fq_plan *plan, const fq_sweep *s, float *const *zone,
                     int png, const char *command, char *err, size_t errlen);

#endif
