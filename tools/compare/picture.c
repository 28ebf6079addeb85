/*
 * 8-bit pictures for the page: tone mapping is only the sRGB encoding of
 * the clamped linear value (the numbers live in the table, the pictures are
 * for the eye), heat maps with their colour scale, magnified crops, and the
 * drawing the contact sheet needs; PNG files through libsample_io.
 */
#include "cmp_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef TEXSAMPLE_HAVE_IO
#include "sample/sample_io.h"

int cmp_pic_write(const char *path, const cmp_pic *p, char *err, size_t errlen)
{
    size_t n = (size_t)p->w * (size_t)p->h, px;
    float *rgba = malloc(n * 4 * sizeof *rgba);
    sample_error e;
    sample_status st;
    int c;
    if (!rgba) {
        snprintf(err, errlen, "%s: out of memory for a %d x %d picture", path, p->w, p->h);
        return 1;
    }
    /* The bytes are display-referred sRGB codes already (the encoded image,
     * heat-map colours, label text). sample_io converts from linear to the
     * colour space it is given, so "raw" (data: never converted) writes each
     * code back exactly (code / 255 rounds to the code) and the PNG carries
     * no gAMA/sRGB chunk; viewers show such a file as sRGB. Asking for
     * "srgb" would encode the codes a second time and wash them out. */
    for (px = 0; px < n; ++px) {
        for (c = 0; c < 3; ++c) rgba[4 * px + (size_t)c] = (float)p->rgb[3 * px + (size_t)c] / 255.0f;
        rgba[4 * px + 3] = 1.0f;
    }
    st = sample_io_write_image(path, rgba, p->w, p->h, 3, "raw", &e);
    free(rgba);
    if (st == SAMPLE_OK) return 0;
    snprintf(err, errlen, "%s", e.message);
    return 1;
}
#else
int cmp_pic_write(const char *path, const cmp_pic *p, char *err, size_t errlen)
{
    (void)p;
    snprintf(err, errlen, "cannot write '%s': this build has no image output (libsample_io)", path);
    return 1;
}
#endif

int cmp_pic_alloc(cmp_pic *p, int w, int h)
{
    p->w = w;
    p->h = h;
    p->rgb = calloc((size_t)w * (size_t)h * 3, 1);
    return p->rgb ? 0 : 1;
}

void cmp_pic_free(cmp_pic *p)
{
    free(p->rgb);
    p->rgb = NULL;
}

static unsigned char encode(float v)
{
    if (!(v > 0.0f)) return 0; /* also NaN: a broken pixel shows black, not garbage */
    if (v >= 1.0f) return 255;
    return (unsigned char)lrintf(255.0f * sample_linear_to_srgb(v));
}

int cmp_pic_from_linear(cmp_pic *p, const float *rgba, int w, int h)
{
    size_t px, n = (size_t)w * (size_t)h;
    int c;
    if (cmp_pic_alloc(p, w, h)) return 1;
    for (px = 0; px < n; ++px)
        for (c = 0; c < 3; ++c) p->rgb[px * 3 + (size_t)c] = encode(rgba[px * 4 + (size_t)c]);
    return 0;
}

/* A perceptually ordered dark-to-light scale (after matplotlib's magma):
 * stops at 0, ¼, ½, ¾, 1, sRGB bytes, linear in between. */
void cmp_heat_colour(float v, unsigned char rgb[3])
{
    static const unsigned char stop[5][3] = {
        {0, 0, 4}, {80, 18, 123}, {183, 55, 121}, {252, 137, 97}, {252, 253, 191}};
    float x = v != v ? 0.0f : v < 0.0f ? 0.0f : v > 1.0f ? 4.0f : 4.0f * v;
    int k = x >= 4.0f ? 3 : (int)x, c;
    float f = x - (float)k;
    for (c = 0; c < 3; ++c)
        rgb[c] = (unsigned char)lrintf((1.0f - f) * stop[k][c] + f * stop[k + 1][c]);
}

void cmp_pic_fill(cmp_pic *p, int x, int y, int w, int h, const unsigned char rgb[3])
{
    int i, j;
    for (j = y < 0 ? 0 : y; j < y + h && j < p->h; ++j)
        for (i = x < 0 ? 0 : x; i < x + w && i < p->w; ++i)
            memcpy(p->rgb + ((size_t)j * (size_t)p->w + (size_t)i) * 3, rgb, 3);
}

void cmp_pic_rect(cmp_pic *p, int x, int y, int w, int h, const unsigned char rgb[3])
{
    cmp_pic_fill(p, x, y, w, 1, rgb);
    cmp_pic_fill(p, x, y + h - 1, w, 1, rgb);
    cmp_pic_fill(p, x, y, 1, h, rgb);
    cmp_pic_fill(p, x + w - 1, y, 1, h, rgb);
}

int cmp_pic_text(cmp_pic *p, int x, int y, const char *text, int scale, const unsigned char rgb[3])
{
    int x0 = x, r, b;
    for (; *text; ++text, x += 6 * scale) {
        const unsigned char *g = cmp_font_glyph(*text);
        if (!g) g = cmp_font_glyph('_');
        for (r = 0; r < 7; ++r)
            for (b = 0; b < 5; ++b)
                if (g[r] & (1 << (4 - b))) cmp_pic_fill(p, x + b * scale, y + r * scale, scale, scale, rgb);
    }
    return x - x0;
}

enum { LEGEND_H = 30 };

int cmp_pic_heatmap(cmp_pic *p, const float *err, const unsigned char *mask, int w, int h,
                    float scale)
{
    static const unsigned char grey[3] = {90, 90, 90}, white[3] = {235, 235, 235},
                               black[3] = {20, 20, 20};
    size_t px, n = (size_t)w * (size_t)h;
    cmp_legend lg;
    int i, k;
    if (cmp_pic_alloc(p, w, h + LEGEND_H)) return 1;
    for (px = 0; px < n; ++px) {
        if (mask && !mask[px])
            memcpy(p->rgb + px * 3, grey, 3);
        else
            cmp_heat_colour(err[px] / scale, p->rgb + px * 3);
    }
    /* Legend: the scale as a bar, a tick and a value for each label that
     * fits (legend.c). */
    cmp_pic_fill(p, 0, h, w, LEGEND_H, black);
    cmp_heat_legend(w, scale, &lg);
    for (i = 0; i < lg.bar_w; ++i) {
        unsigned char c[3];
        cmp_heat_colour((float)i / (float)(lg.bar_w - 1), c);
        cmp_pic_fill(p, lg.bar_x + i, h + 4, 1, 9, c);
    }
    for (k = 0; k < lg.n; ++k) {
        cmp_pic_fill(p, lg.label[k].tick_x, h + 13, 1, 3, white);
        cmp_pic_text(p, lg.label[k].x, h + lg.label[k].y, lg.label[k].text, 1, white);
    }
    return 0;
}

int cmp_pic_crop(cmp_pic *p, const cmp_pic *src, int x0, int y0, int size, int zoom)
{
    int i, j;
    if (cmp_pic_alloc(p, size * zoom, size * zoom)) return 1;
    for (j = 0; j < p->h; ++j)
        for (i = 0; i < p->w; ++i) {
            int sx = x0 + i / zoom, sy = y0 + j / zoom;
            if (sx < 0 || sy < 0 || sx >= src->w || sy >= src->h) continue;
            memcpy(p->rgb + ((size_t)j * (size_t)p->w + (size_t)i) * 3,
                   src->rgb + ((size_t)sy * (size_t)src->w + (size_t)sx) * 3, 3);
        }
    return 0;
}

void cmp_pic_blit(cmp_pic *dst, const cmp_pic *src, int x, int y, int down)
{
    int i, j, a, b, c;
    if (down < 1) down = 1;
    for (j = 0; j < src->h / down; ++j)
        for (i = 0; i < src->w / down; ++i) {
            unsigned sum[3] = {0, 0, 0};
            if (x + i < 0 || y + j < 0 || x + i >= dst->w || y + j >= dst->h) continue;
            for (b = 0; b < down; ++b)
                for (a = 0; a < down; ++a)
                    for (c = 0; c < 3; ++c)
                        sum[c] += src->rgb[((size_t)(j * down + b) * (size_t)src->w +
                                            (size_t)(i * down + a)) * 3 + (size_t)c];
            for (c = 0; c < 3; ++c)
                dst->rgb[((size_t)(y + j) * (size_t)dst->w + (size_t)(x + i)) * 3 + (size_t)c] =
                    (unsigned char)((sum[c] + (unsigned)(down * down) / 2) / (unsigned)(down * down));
        }
}
