/* A growable text buffer for the reports: text is built in memory and the
 * command writes it atomically (cli_write_file), so a failed run never
 * leaves half a file. */
#include "freq.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

void fq_buf_printf(fq_buf *b, const char *fmt, ...)
{
    va_list ap;
    int need;
    if (b->failed) return;
    va_start(ap, fmt);
    need = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (need < 0) {
        b->failed = 1;
        return;
    }
    if (b->len + (size_t)need + 1 > b->cap) {
        size_t cap = b->cap ? b->cap : 4096;
        char *d;
        while (cap < b->len + (size_t)need + 1) cap *= 2;
        d = (char *)realloc(b->data, cap);
        if (!d) {
            b->failed = 1;
            return;
        }
        b->data = d;
        b->cap = cap;
    }
    va_start(ap, fmt);
    vsnprintf(b->data + b->len, (size_t)need + 1, fmt, ap);
    va_end(ap);
    b->len += (size_t)need;
}

void fq_buf_free(fq_buf *b)
{
    free(b->data);
    b->data = NULL;
    b->len = b->cap = 0;
    b->failed = 0;
}
