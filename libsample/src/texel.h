/*
 * Texel storage and decode (texture.c, color.c): the levels of a texture,
 * the exact 8-bit and half decodes (GL 4.6 §8.24, eq. 2.1), one texel to
 * linear RGBA with OpenGL's channel expansion. The bottom layer: every
 * reader, fast or reference, decodes through tex_decode_v4.
 */
#ifndef SAMPLE_TEXEL_H
#define SAMPLE_TEXEL_H

#include "base.h"

/* Where a texture's texels are: its texel source. A resident texture
 * (source NULL) holds each level as one array, row after row, and readers
 * form addresses from data and stride; that is what the fast paths need
 * and what every texture made by sample_texture_create is. Any other
 * source — tiles held apart (tiled.c), a tile cache — hands out one texel
 * at a time through texel(): a pointer to texel (i, j) of level lv (both
 * in range), valid until the batch ends, or NULL when the source cannot
 * supply it (a tile that failed to load), which reads as `fill`; `layer`
 * is the face of a cube map or the slice of a volume (0 for 2D). The
 * filters do not change with the source: every texel read goes through
 * tex_texel (below), and the only readers that form addresses themselves
 * (the fast path's planners, the footprint filters' in-level spans, the
 * prefetches) do so for resident textures, and for a source that declares
 * its tiles (tile_side), in a tile; sample_batch runs any other texture
 * through the reference loop, whose answers are the fast path's bit for
 * bit. */
struct ls_texel_source {
    const unsigned char *(*texel)(const struct ls_texel_source *src, int lv, int i, int j, int layer);
    void (*destroy)(struct ls_texel_source *src); /* with the texture */
    /* Optional (NULL: nothing to do), for a source that frees texels while
     * other threads read (a tile cache evicting): every entry point that
     * reads a non-resident texture — a batch of any kind, one texel —
     * brackets its reads with tex_reads_begin / tex_reads_end (below).
     * reads_begin returns a ticket that reads_end gets back; between the
     * two, every pointer texel() handed out stays valid. */
    uintptr_t (*reads_begin)(const struct ls_texel_source *src);
    void (*reads_end)(const struct ls_texel_source *src, uintptr_t ticket);
    /* 0, or the side T (a power of two) of the square tiles the source
     * holds each level in: texels [tx·T, tx·T + T) × [ty·T, ty·T + T) lie
     * in one array, row after row, rows T texels apart (a tile past the
     * level's edge keeps that shape), so the pointer texel() returns for
     * one texel of a tile addresses every texel of that tile, valid as
     * long as that pointer is. The fast path's planners then read a 2 × 2
     * or 4 × 4 block inside one tile as a resident level's block, with one
     * texel() call (fast_gl.c, plan_tiles; doc/architecture.md). */
    int tile_side;
    /* With tile_side: 0, every level is held so; else only the levels
     * below tile_levels are, and the planners read the others texel by
     * texel through texel() (a UDIM set's levels where a tile of T texels
     * would span several files: doc/texture-system.md, "UDIM"). */
    int tile_levels;
    float fill[4];
};

/* One level: d layers of w × h texels. A 2D texture's levels have one
 * layer; a kind with more (a cube map's six faces, a volume's slices) keeps
 * them in one array, layer after layer, so that a layer is addressed as a
 * 2D level is. */
struct sample_level {
    int w, h, d;
    size_t stride;       /* bytes per row (resident) */
    size_t slice;        /* bytes per layer (resident) */
    unsigned char *data; /* owned (resident), else NULL */
};

struct sample_texture {
    sample_texture_kind kind;
    int width, height, channels, nlevels;
    int depth; /* layers of level 0 (tex_level_layers); 1 for 2D */
    sample_format format;
    size_t texel_bytes; /* channels × format bytes */
    size_t bytes;       /* all levels */
    struct sample_level level[SAMPLE_MAX_LEVELS];
    struct ls_texel_source *source; /* NULL: resident levels */
};

/* Whether the texture's levels are resident arrays (data, stride). */
static inline int tex_resident(const sample_texture *tex) { return tex->source == NULL; }

/* Bracket the texel reads of one batch (or one texel) of a texture: the
 * source's reads_begin / reads_end where it has them (struct
 * ls_texel_source), nothing for a resident texture. */
static inline uintptr_t tex_reads_begin(const sample_texture *tex)
{
    return tex->source && tex->source->reads_begin ? tex->source->reads_begin(tex->source) : 0;
}
static inline void tex_reads_end(const sample_texture *tex, uintptr_t ticket)
{
    if (tex->source && tex->source->reads_end) tex->source->reads_end(tex->source, ticket);
}

/* The exact sRGB EOTF for each 8-bit code ([0]) and c / 255 ([1]), one
 * array (color.c). */
extern const float ls_u8_decode[2][256];
#define ls_srgb_table (ls_u8_decode[0])
#define ls_unorm8_table (ls_u8_decode[1])
/* The 8-bit sRGB code of a linear value, rounded to nearest in the encoded
 * domain (color.c; no libm); what the mip builder writes into sRGB8
 * levels. */
unsigned char ls_srgb_encode8(float v);

/* Decode one texel at p to linear RGBA with the OpenGL channel expansion
 * (missing G, B → 0, missing A → 1). With `format` and `nc` constants (the
 * fast path instantiates it per format and channel count) the switches
 * vanish; every reader, fast or general, decodes through this one function.
 * Reads exactly nc channels: shorter texels are copied into a padded buffer
 * first, so the last texel of a level is never over-read. */
SAMPLE_FORCE_INLINE v4f tex_decode_v4(sample_format format, int nc, const unsigned char *p)
{
    switch (format) {
    case SAMPLE_FORMAT_F32: {
        /* Constant-size copies inline to plain loads; a variable-length copy
         * (which GCC also makes of a per-channel loop) is a libc call. */
        float v[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        switch (nc) {
        case 4: memcpy(v, p, 16); break;
        case 3: memcpy(v, p, 12); break;
        case 2: memcpy(v, p, 8); break;
        default: memcpy(v, p, 4); break;
        }
        return v4_load(v);
    }
    case SAMPLE_FORMAT_F16: {
        /* Padding halves: 0, 0, 0, 1.0 (0x3c00). */
        uint16_t h[4] = {0, 0, 0, 0x3c00};
        switch (nc) {
        case 4: return v4_from_f16x4(p);
        case 3: memcpy(h, p, 6); break;
        case 2: memcpy(h, p, 4); break;
        default: memcpy(h, p, 2); break;
        }
        return v4_from_f16x4((const unsigned char *)h);
    }
    case SAMPLE_FORMAT_UNORM8:
        /* c / 255 correctly rounded (GL 4.6 eq. 2.1), from a table. */
        return v4_set(ls_unorm8_table[p[0]], nc > 1 ? ls_unorm8_table[p[1]] : 0.0f,
                      nc > 2 ? ls_unorm8_table[p[2]] : 0.0f,
                      nc > 3 ? ls_unorm8_table[p[3]] : 1.0f);
    case SAMPLE_FORMAT_SRGB8:
        /* Alpha of an sRGB format is linear (GL 4.6 §8.24). */
        return v4_set(ls_srgb_table[p[0]], nc > 1 ? ls_srgb_table[p[1]] : 0.0f,
                      nc > 2 ? ls_srgb_table[p[2]] : 0.0f,
                      nc > 3 ? ls_unorm8_table[p[3]] : 1.0f);
    default:
        return v4_set(0.0f, 0.0f, 0.0f, 1.0f);
    }
}

/* Whether the fast path's planners can address the texture's texels: a
 * resident texture, or a source in tiles of tile_side (struct
 * ls_texel_source). */
static inline int tex_addressable(const sample_texture *tex)
{
    return tex->source == NULL || tex->source->tile_side > 0;
}

/* Whether the planners may address level lv of a source in tiles inside
 * one tile (struct ls_texel_source: tile_side, tile_levels). */
static inline int tex_source_level_in_tiles(const struct ls_texel_source *src, int lv)
{
    return src->tile_levels == 0 || lv < src->tile_levels;
}

/* Texel (i, j) of a resident level (its first layer). */
static inline const unsigned char *tex_level_addr(const sample_texture *tex, const struct sample_level *L, int i, int j)
{
    return L->data + (size_t)j * L->stride + (size_t)i * tex->texel_bytes;
}

/* The addressing of every texel read: texel (i, j) of layer `layer` (all
 * in range) of level lv, from the texture's source; NULL when the source
 * cannot supply it. */
static inline const unsigned char *tex_texel_layer(const sample_texture *tex, int lv, int i, int j, int layer)
{
    if (SAMPLE_LIKELY(tex_resident(tex))) {
        const struct sample_level *L = &tex->level[lv];
        return tex_level_addr(tex, L, i, j) + (size_t)layer * L->slice;
    }
    return tex->source->texel(tex->source, lv, i, j, layer);
}

/* Texel (i, j) of a one-layer (2D) level: tex_texel_layer's layer 0. */
static inline const unsigned char *tex_texel(const sample_texture *tex, int lv, int i, int j)
{
    if (SAMPLE_LIKELY(tex_resident(tex))) return tex_level_addr(tex, &tex->level[lv], i, j);
    return tex->source->texel(tex->source, lv, i, j, 0);
}

/* Decode texel (i, j) (both in range) of a resident level: the pyramid
 * builder's reads, of the levels it is making. */
static inline void tex_decode(const sample_texture *tex, const struct sample_level *L, int i, int j,
                              float out[4])
{
    v4_store(out, tex_decode_v4(tex->format, tex->channels, tex_level_addr(tex, L, i, j)));
}

/* Decode what tex_texel_layer addresses, p; the source's fill colour where
 * p is NULL (the source has none). */
static inline void tex_read_at(const sample_texture *tex, const unsigned char *p, float out[4])
{
    if (!p) {
        memcpy(out, tex->source->fill, sizeof tex->source->fill);
        return;
    }
    v4_store(out, tex_decode_v4(tex->format, tex->channels, p));
}

/* Decode texel (i, j) (both in range) of level lv (layer 0), from
 * whatever source. */
static inline void tex_read(const sample_texture *tex, int lv, int i, int j, float out[4])
{
    tex_read_at(tex, tex_texel(tex, lv, i, j), out);
}

/* Decode texel (i, j) of layer `layer` of level lv, from whatever source. */
static inline void tex_read_layer(const sample_texture *tex, int lv, int i, int j, int layer, float out[4])
{
    tex_read_at(tex, tex_texel_layer(tex, lv, i, j, layer), out);
}

/* Layers of level k: one for a 2D texture; a kind with more says how many
 * here (a cube map six at every level, a volume its depth halved). */
static inline int tex_level_layers(const sample_texture *tex, int k)
{
    (void)k;
    switch (tex->kind) {
    case SAMPLE_TEXTURE_CUBE: return 6;
    case SAMPLE_TEXTURE_3D: return (tex->depth >> k) > 0 ? tex->depth >> k : 1;
    case SAMPLE_TEXTURE_2D:
    default: return 1;
    }
}

/* Encode linear RGBA (first `channels` values) into one texel of the
 * texture's format; used by the pyramid builder. */
void ls_tex_encode(const sample_texture *tex, const float in[4], unsigned char *dst);

/* Checks an image description of `layers` layers (each as `im`: a
 * volume's slices), the texel bytes of all of them and their pyramid
 * against the size limit; `what` names it in the message. */
sample_status ls_tex_check_layers(const sample_image *im, int layers, const char *what, sample_error *err);

/* A texture with no levels yet (no source: resident), its texel size set;
 * NULL if out of memory. */
sample_texture *ls_tex_new(sample_texture_kind kind, int width, int height, int channels, sample_format format);

/* Allocate level k's storage (size from the level rule, tex_level_layers
 * layers); tex->bytes updated. */
sample_status ls_tex_alloc_level(sample_texture *tex, int k, sample_error *err);

/* The checks sample_texture_create makes of an image and of mip
 * parameters (texture.c), for the creators of other kinds; `what` names
 * the image in the message. */
sample_status ls_tex_check_image(const sample_image *im, const char *what, sample_error *err);
sample_status ls_tex_check_mip(const sample_mip_params *mip, sample_error *err);

/* Copy an image of level k's size into layer `layer` of level k. */
void ls_tex_copy_layer(sample_texture *tex, int k, int layer, const sample_image *im);

#endif /* SAMPLE_TEXEL_H */
