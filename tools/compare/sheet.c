/*
 * A scene's pictures: the ground truth (with the crop's outline), and for
 * each configuration its image, error heat map and magnified crop; then the
 * contact sheet that lays them out in three rows (images, heat maps,
 * crops), one column per configuration, labelled, so that one PNG tells the
 * whole story of a scene. The truth's column shows the metric mask where the
 * others show their heat maps.
 */
#include "cmp_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { SHEET_TILE = 256, SHEET_LABEL = 19, SHEET_GAP = 4 };

static int write_pic(const char *dir, const cmp_scene_result *s, const char *what,
                     const char *suffix, const cmp_pic *p)
{
    char rel[512], path[1024], err[512];
    cmp_pic_path(rel, sizeof rel, s, what, suffix);
    snprintf(path, sizeof path, "%s/%s", dir, rel);
    if (cmp_pic_write(path, p, err, sizeof err) == 0) return 0;
    fprintf(stderr, "texsample compare: cannot write %s: %s\n", path, err);
    return 1;
}

/* The metric mask for the truth's column: measured pixels white, the rest
 * grey as in the heat maps. */
static int mask_pic(cmp_pic *p, const unsigned char *mask, int w, int h)
{
    static const unsigned char on[3] = {235, 235, 235}, off[3] = {90, 90, 90};
    size_t px;
    if (cmp_pic_alloc(p, w, h)) return 1;
    for (px = 0; px < (size_t)w * (size_t)h; ++px) memcpy(p->rgb + px * 3, mask[px] ? on : off, 3);
    return 0;
}

/* Image, heat map (err == NULL: the mask instead) and crop of one column. */
static int column_pics(const cmp_scene_result *s, const float *rgba, const float *err,
                       const unsigned char *mask, cmp_pic pic[3])
{
    memset(pic, 0, 3 * sizeof *pic);
    if (cmp_pic_from_linear(&pic[0], rgba, s->w, s->h)) return 1;
    if (err ? cmp_pic_heatmap(&pic[1], err, mask, s->w, s->h, CMP_HEAT_SCALE)
            : mask_pic(&pic[1], mask, s->w, s->h))
        return 1;
    return cmp_pic_crop(&pic[2], &pic[0], s->crop_x, s->crop_y, s->crop_size, s->crop_zoom);
}

static void free_pics(cmp_pic *p, int n)
{
    int k;
    for (k = 0; k < n; ++k) cmp_pic_free(&p[k]);
}

int cmp_scene_pictures(const char *dir, const cmp_scene_result *s, const cmp_truth *t,
                       float *const *images)
{
    static const unsigned char bg[3] = {32, 32, 32}, fg[3] = {240, 240, 240},
                               frame[3] = {255, 64, 32};
    size_t n = (size_t)s->w * (size_t)s->h;
    int down = (s->w + SHEET_TILE - 1) / SHEET_TILE, tw = s->w / down, cols = 1, col, r, rc = 1;
    int rowh[3], y[3];
    float *err = malloc(sizeof *err * n);
    cmp_pic pic[3], sheet = {0, 0, NULL};
    memset(pic, 0, sizeof pic);
    for (r = 0; r < s->nrows; ++r) cols += s->rows[r].ok;
    /* Rows: image, heat map with its legend, crop shrunk to the tile width. */
    rowh[0] = s->h / down;
    rowh[1] = s->h / down + 30 / down;
    rowh[2] = s->crop_size * s->crop_zoom / ((s->crop_size * s->crop_zoom + tw - 1) / tw);
    y[0] = SHEET_LABEL;
    y[1] = y[0] + rowh[0] + SHEET_GAP;
    y[2] = y[1] + rowh[1] + SHEET_GAP;
    if (!err || cmp_pic_alloc(&sheet, cols * (tw + SHEET_GAP), y[2] + rowh[2] + SHEET_GAP)) goto out;
    cmp_pic_fill(&sheet, 0, 0, sheet.w, sheet.h, bg);
    for (col = 0, r = -1; r < s->nrows; ++r) {
        const char *name = r < 0 ? "truth" : s->rows[r].cfg->name;
        int x = col * (tw + SHEET_GAP), k;
        if (r >= 0 && !s->rows[r].ok) continue;
        if (r >= 0) cmp_error_map(images[r], t->rgba, n, err);
        if (column_pics(s, r < 0 ? t->rgba : images[r], r < 0 ? NULL : err, t->mask, pic)) goto out;
        if (write_pic(dir, s, name, "_crop", &pic[2])) goto out;
        if (r < 0)
            cmp_pic_rect(&pic[0], s->crop_x - 1, s->crop_y - 1, s->crop_size + 2, s->crop_size + 2,
                         frame);
        if (write_pic(dir, s, name, "", &pic[0]) ||
            write_pic(dir, s, name, r < 0 ? "_mask" : "_err", &pic[1]))
            goto out;
        {
            /* The name in the column's width: two lines of the label band. */
            char lines[2][CMP_LINE_MAX];
            int nl = cmp_text_wrap(name, tw - 2, 1, lines, 2), l;
            for (l = 0; l < nl; ++l) cmp_pic_text(&sheet, x + 2, nl == 1 ? 6 : 1 + 9 * l, lines[l], 1, fg);
        }
        for (k = 0; k < 3; ++k)
            if (pic[k].rgb)
                cmp_pic_blit(&sheet, &pic[k], x, y[k],
                             k == 2 ? (pic[2].w + tw - 1) / tw : down);
        free_pics(pic, 3);
        ++col;
    }
    rc = write_pic(dir, s, "contact", "", &sheet);
out:
    free_pics(pic, 3);
    cmp_pic_free(&sheet);
    free(err);
    return rc;
}
