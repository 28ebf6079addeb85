/*
 * Where the heat map's colour scale and its labels go (doc/comparison.md,
 * "Metrics and pictures"): the bar under the image, ticks at 0, ½ and 1 of
 * the scale, each with its value. The placement is computed apart from the
 * drawing so that it can be tested at every width: a label is kept only
 * where it lies inside the picture and clear of the labels already placed
 * (the two ends first, then the middle), so at --size 96 the middle value
 * gives way instead of printing over the last one.
 */
#include "cmp_internal.h"

#include <stdio.h>
#include <string.h>

/* Pixels between two labels, and from the bar to the picture's sides. */
enum { LABEL_GAP = 4, BAR_MARGIN = 8, LABEL_Y = 18, GLYPH_H = 7 };

static int clear_of(const cmp_label *a, const cmp_label *b)
{
    return a->x + a->w + LABEL_GAP <= b->x || b->x + b->w + LABEL_GAP <= a->x;
}

void cmp_heat_legend(int w, float scale, cmp_legend *lg)
{
    /* Placement order: the ends carry the range, the middle is a bonus. */
    static const int order[3] = {0, 2, 1};
    int margin = w >= 4 * BAR_MARGIN ? BAR_MARGIN : w / 4, i, k, l;
    memset(lg, 0, sizeof *lg);
    lg->bar_x = margin;
    lg->bar_w = w - 2 * margin;
    if (lg->bar_w < 2) {
        lg->bar_w = 0;
        return;
    }
    for (i = 0; i < 3; ++i) {
        cmp_label c;
        int ok = 1;
        k = order[i];
        memset(&c, 0, sizeof c);
        c.tick_x = lg->bar_x + k * (lg->bar_w - 1) / 2;
        if (k == 2)
            snprintf(c.text, sizeof c.text, ">=%.3g", scale);
        else
            snprintf(c.text, sizeof c.text, "%.3g", scale * 0.5 * k);
        c.w = cmp_text_width(c.text, 1);
        c.h = GLYPH_H;
        c.y = LABEL_Y;
        /* Left end: text starts at its tick; right end: ends at it; middle:
         * centred on it. */
        c.x = k == 0 ? c.tick_x : k == 2 ? c.tick_x - c.w + 1 : c.tick_x - c.w / 2;
        if (c.x < 0 || c.x + c.w > w) ok = 0;
        for (l = 0; ok && l < lg->n; ++l) ok = clear_of(&c, &lg->label[l]);
        if (ok) lg->label[lg->n++] = c;
    }
}
