/* The parts of `texsample freq` that live in the executable (not in the
 * texsample_freq library): OpenImageIO backend and file output. */
#ifndef TEXSAMPLE_FREQ_CLI_H
#define TEXSAMPLE_FREQ_CLI_H

#include "freq.h"

/* The TextureSystem and texture file the OpenImageIO backends share: one
 * file per grating, written once (the backends are prepared one after the
 * other on the same texels) under a new name whenever the texels change;
 * the files go in `dir`. */
typedef struct fq_oiio_file {
    char dir[1024];
    char path[1100];
    float *texels; /* copy of what the current file holds; NULL: none */
    size_t count;
    unsigned serial;
    struct oiio_ts *ts;         /* created on first use */
    struct oiio_ts_tex *handle; /* the current file, opened in ts */
} fq_oiio_file;
/* One OpenImageIO backend's caller-owned configuration: the registry entry
 * whose twin it runs, and its names. */
typedef struct fq_oiio_cfg {
    const tool_filter *f;
    fq_oiio_file *file;
    char name[TOOL_FILTER_NAME_MAX], label[TOOL_FILTER_LABEL_MAX];
} fq_oiio_cfg;
/* 1 when texsample was built with the shim (tools/oiio). */
int fq_oiio_available(void);
/* An empty file record whose texture files will go in `tmp`. */
void fq_oiio_file_init(fq_oiio_file *file, const char *tmp);
/* The twin of pick p (p->oiio set, p->f has a twin) as a backend sampling
 * through `file`; cfg is its storage and must outlive it. */
void fq_oiio_backend(const tool_pick *p, fq_oiio_file *file, fq_oiio_cfg *cfg, fq_backend *out);
/* Remove the current file, free the copy and the TextureSystem. */
void fq_oiio_file_clear(fq_oiio_file *file);

/* A row on a backend of tools/backend.h (backends.c): the OpenGL twin of
 * a registry entry, or an outside program (f NULL: the program's own
 * filter). Caller-owned, must outlive the fq_backend. */
typedef struct fq_tool_cfg {
    struct tool_backend *tb;
    const tool_filter *f;
    char name[TOOL_FILTER_NAME_MAX], label[TOOL_FILTER_LABEL_MAX];
} fq_tool_cfg;
/* The row as a backend of the sweep: REPEAT on both axes, f's settings. */
void fq_tool_backend(struct tool_backend *tb, const tool_filter *f, const char *name,
                     const char *label, fq_tool_cfg *cfg, fq_backend *out);
/* Try the row on a small texture and one query: 0 (it runs),
 * TOOL_BACKEND_NA or TOOL_BACKEND_ERROR with the reason in err. */
int fq_tool_probe(const fq_backend *b, char *err, size_t errlen);

/* Write every output of a finished sweep into `dir` (created if missing):
 * freq.csv, summary.csv, summary.md, plot_r*_t*.svg, zone_*.png (when
 * built with libsample_io and png is set), index.html. `zone` holds
 * one zone-plate picture per backend (may be NULL or hold NULLs). Returns
 * 0, or −1 with a message in err. */
int fq_write_outputs(const char *dir, const fq_plan *plan, const fq_sweep *s, float *const *zone,
                     int png, const char *command, char *err, size_t errlen);

#endif
