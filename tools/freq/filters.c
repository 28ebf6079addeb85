/* freq's default rows: the filter configurations under test (DESIGN §9)
 * are the filter registry's entries (tools/filters.h), each sampled through
 * a backend of tools/backend.h (backends.c). */
#include "freq.h"

const char *const fq_default_filters[] = {
    "nearest", "bilinear", "nearest_mipmap_nearest", "trilinear", "aniso16",
    "cubic_mipmap_linear", "blinn-newell", "ewa", "oiio-trilinear", "oiio-aniso16", NULL,
};
