/*
 * The filter registry: every filter configuration the tools name (compare,
 * freq, bench, and lookup's and render's --filter), one table, so that a
 * name means the same sampler state in every tool (doc/comparison.md,
 * "Filter names").
 *
 * An entry is libsample's sampler settings (the fields of sample_sampler a
 * filter choice sets; wrap modes, border and LOD state stay the caller's)
 * plus, where one exists, its OpenImageIO TextureSystem twin. A name selects
 * a "pick": the entry on libsample, or — spelled "oiio-" + name — its
 * OpenImageIO twin, or — spelled "gl-" + name — the same sampler state on
 * an OpenGL driver (tools/backend.h), for the entries OpenGL has: the six
 * min filters of GL 4.6 §8.14, no footprint filter but GL_TEXTURE_MAX_ANISOTROPY
 * (tool_filter_gl_twin).
 *
 * Names: an entry that is one library enum is called by the library's name
 * for it (sample_footprint_name for a footprint filter, else
 * sample_filter_name of its min filter); the composites have names of their
 * own (tool_filter_name). Older spellings that scripts may hold are read as
 * aliases of the same entries; tools print only the canonical names.
 */
#ifndef TEXSAMPLE_FILTERS_H
#define TEXSAMPLE_FILTERS_H

#include "oiio/oiio_ts.h"
#include "sample/sample.h"

#include <stddef.h>
#include <stdio.h>

typedef struct tool_filter {
    /* NULL: the entry is named by the library (tool_filter_name). */
    const char *name;
    const char *label; /* for tables, plots and pictures (ASCII: compare's font) */
    sample_filter min, mag;
    sample_footprint footprint;
    sample_cubic cubic;
    sample_ewa_kernel ewa_kernel; /* EWA's radial weight (0: the Gaussian) */
    /* 0 reads as 1, OpenGL's initial value (GL 4.6 table 23.18). */
    float max_aniso;
    unsigned options; /* SAMPLE_OPT_*, added to the caller's */
    /* 1: pass the exact footprint corners (Blinn–Newell corner mode,
     * DESIGN §7); only a tool that has them can run the entry. */
    int corners;
    /* The OpenImageIO twin: the TextureOpt modes closest to these settings
     * (tools/oiio/oiio_ts.h), with TextureOpt::anisotropic = max_aniso. */
    struct {
        int twin; /* 0: none */
        oiio_ts_mode mode;
    } oiio;
} tool_filter;

extern const tool_filter tool_filters[];
extern const int tool_filter_count;

/* Longest name a pick can have, with its terminating NUL. */
#define TOOL_FILTER_NAME_MAX 48
/* Longest label a pick can have, with its terminating NUL. */
#define TOOL_FILTER_LABEL_MAX 96

const char *tool_filter_name(const tool_filter *f);
/* The entry's settings onto a sampler: min and mag filter, footprint,
 * cubic kind, EWA kernel, max anisotropy; options are added. */
void tool_filter_apply(const tool_filter *f, sample_sampler *s);
/* The twin's settings onto OIIO options made by oiio_ts_opts_init: the
 * mode, and TextureOpt::anisotropic where the entry sets max_aniso (else
 * the shim's default stays). */
void tool_filter_oiio_opts(const tool_filter *f, oiio_ts_opts *o);
/* The entry called `name` (canonical or alias, libsample only), or NULL. */
const tool_filter *tool_filter_by_name(const char *name);

/* 1 when OpenGL has the entry's sampler state: a GL min and mag filter
 * (not cubic), no footprint filter but the anisotropic one (read as
 * GL_TEXTURE_MAX_ANISOTROPY, GL 4.6 §8.14.1), no options, no corners. */
int tool_filter_gl_twin(const tool_filter *f);

/* One selectable row: an entry on libsample, on its OIIO twin, or on an
 * OpenGL driver (gl). At most one of oiio and gl is set. */
typedef struct tool_pick {
    const tool_filter *f;
    int oiio;
    int gl;
} tool_pick;

/* Look a name up: an entry's canonical name, "oiio-" + one for its twin, or
 * an alias of either. Returns 0 (canonical), 1 (an alias: *canonical, when
 * not NULL, gets the name to print) or −1 (unknown). */
int tool_pick_find(const char *name, tool_pick *out, const char **canonical);
/* tool_pick_find for a tool's command line: an alias is noted on stderr
 * with its canonical name ("texsample SUB: 'nmn' is read as
 * 'nearest_mipmap_nearest'"). Returns 0, or −1 for an unknown name. */
int tool_pick_read(const char *sub, const char *name, tool_pick *out);
/* The pick's canonical name and label ("oiio-trilinear", "OpenImageIO
 * trilinear"), into buf; returns buf. */
const char *tool_pick_name(const tool_pick *p, char *buf, size_t len);
const char *tool_pick_label(const tool_pick *p, char *buf, size_t len);

/* The old spellings and the entries they name, for the tests and the
 * documentation. */
typedef struct tool_filter_alias {
    const char *alias, *name;
} tool_filter_alias;
extern const tool_filter_alias tool_filter_aliases[];
extern const int tool_filter_alias_count;

/* What a tool can run, for tool_picks_parse and tool_picks_help. */
enum {
    TOOL_PICK_OIIO = 1u << 0,    /* OIIO twins, by their own names */
    TOOL_PICK_CORNERS = 1u << 1, /* entries that need the exact corners */
    TOOL_PICK_GL = 1u << 2,      /* OpenGL twins, "gl-" + name */
};

/* Is the pick one a tool with these capabilities runs? */
int tool_pick_allowed(const tool_pick *p, unsigned accept);

/* Parse a comma-separated list of names (or "all": the tool's defaults,
 * NULL-terminated names) into picks: libsample picks in registry order,
 * then OIIO twins, then OpenGL twins, each in registry order and once; names are read by
 * tool_pick_read. Returns the count, or −1 with what is wrong
 * in err (an unknown name, one the tool cannot run, more than max). */
int tool_picks_parse(const char *sub, const char *list, const char *const *defaults,
                     unsigned accept, tool_pick *out, int max, char *err, size_t errlen);

/* The names a tool accepts, one a line with its label, defaults marked
 * '*', each line starting with `indent`. */
void tool_picks_help(FILE *out, const char *indent, const char *const *defaults, unsigned accept);

#endif
