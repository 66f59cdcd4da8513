/* map_file.c - reading and writing `torusrt-map 1` cell-to-node tables. */
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rt_map_file.h"

/* A word-at-a-time reader that knows its line number and skips `#` comments. */
typedef struct words {
    FILE *f;
    long line;
    char word[64];
} words;

/* Next word into w->word; 0 at end of file. A word too long to be a number is cut
 * (and then fails to parse). */
static int next_word(words *w)
{
    int c;
    for (;;) {
        c = fgetc(w->f);
        if (c == EOF) return 0;
        if (c == '\n') w->line++;
        else if (c == '#') {
            while ((c = fgetc(w->f)) != EOF && c != '\n') {}
            if (c == EOF) return 0;
            w->line++;
        } else if (!isspace(c)) break;
    }
    size_t n = 0;
    while (c != EOF && !isspace(c) && c != '#') {
        if (n + 1 < sizeof w->word) w->word[n++] = (char)c;
        c = fgetc(w->f);
    }
    w->word[n] = '\0';
    if (c != EOF) ungetc(c, w->f);
    return 1;
}

/* 1 and *v if the word is a whole decimal integer in [lo, hi]. */
static int word_int(const char *s, long lo, long hi, long *v)
{
    char *end;
    errno = 0;
    long x = strtol(s, &end, 10);
    if (end == s || *end || errno == ERANGE || x < lo || x > hi) return 0;
    *v = x;
    return 1;
}

static rt_status fail(char *msg, size_t msg_len, const char *path, long line, const char *what,
                      const char *word)
{
    if (msg && msg_len) snprintf(msg, msg_len, "%s:%ld: %s%s%s%s", path, line, what,
                                 word ? " '" : "", word ? word : "", word ? "'" : "");
    return RT_ERR_PARSE;
}

/* Reads and checks the header: magic, version, grid and node count. */
static rt_status read_header(words *w, const char *path, const int dims[3], int nodes, char *msg,
                             size_t msg_len)
{
    if (!next_word(w)) return fail(msg, msg_len, path, w->line, "empty map file: expected 'torusrt-map 1 NX NY NZ NODES'", NULL);
    if (strcmp(w->word, "torusrt-map") != 0)
        return fail(msg, msg_len, path, w->line, "expected the header 'torusrt-map 1 NX NY NZ NODES', found", w->word);
    long v;
    if (!next_word(w) || !word_int(w->word, 1, 1, &v))
        return fail(msg, msg_len, path, w->line, "unsupported map format version (expected 1)", NULL);
    const long want[4] = {dims[0], dims[1], dims[2], nodes};
    const char *what[4] = {"NX", "NY", "NZ", "NODES"};
    for (int i = 0; i < 4; i++) {
        if (!next_word(w) || !word_int(w->word, 1, 1L << 30, &v))
            return fail(msg, msg_len, path, w->line, "header: expected a positive number for", what[i]);
        if (v != want[i]) {
            char why[160];
            snprintf(why, sizeof why, "header %s = %ld, but the run has %ld (cells %dx%dx%d, %d nodes)",
                     what[i], v, want[i], dims[0], dims[1], dims[2], nodes);
            return fail(msg, msg_len, path, w->line, why, NULL);
        }
    }
    return RT_OK;
}

rt_status rt_map_file_read(const char *path, const int dims[3], int nodes, int32_t *owner, char *msg,
                           size_t msg_len)
{
    words w = {fopen(path, "r"), 1, ""};
    if (!w.f) {
        if (msg && msg_len) snprintf(msg, msg_len, "%s: cannot open: %s", path, strerror(errno));
        return RT_ERR_IO;
    }
    rt_status st = read_header(&w, path, dims, nodes, msg, msg_len);
    size_t cells = (size_t)dims[0] * (size_t)dims[1] * (size_t)dims[2], i = 0;
    while (st == RT_OK && next_word(&w)) {
        long v;
        if (i == cells) {
            st = fail(msg, msg_len, path, w.line, "more node ids than the grid's cells, first extra", w.word);
        } else if (!word_int(w.word, 0, nodes - 1, &v)) {
            char why[96];
            snprintf(why, sizeof why, "cell %zu: expected a node id 0..%d, found", i, nodes - 1);
            st = fail(msg, msg_len, path, w.line, why, w.word);
        } else {
            owner[i++] = (int32_t)v;
        }
    }
    if (st == RT_OK && i < cells) {
        char why[96];
        snprintf(why, sizeof why, "only %zu node ids for %zu cells", i, cells);
        st = fail(msg, msg_len, path, w.line, why, NULL);
    }
    if (st == RT_OK && ferror(w.f)) {
        if (msg && msg_len) snprintf(msg, msg_len, "%s: read error", path);
        st = RT_ERR_IO;
    }
    fclose(w.f);
    return st;
}

rt_status rt_map_file_write(const char *path, const int dims[3], int nodes, const int32_t *owner,
                            char *msg, size_t msg_len)
{
    FILE *f = fopen(path, "w");
    if (!f) {
        if (msg && msg_len) snprintf(msg, msg_len, "%s: cannot write: %s", path, strerror(errno));
        return RT_ERR_IO;
    }
    fprintf(f, "torusrt-map 1 %d %d %d %d\n# one node id per cell, x fastest; a line per (y, z) row\n",
            dims[0], dims[1], dims[2], nodes);
    size_t i = 0;
    for (int z = 0; z < dims[2]; z++)
        for (int y = 0; y < dims[1]; y++)
            for (int x = 0; x < dims[0]; x++) fprintf(f, "%d%c", owner[i++], x + 1 < dims[0] ? ' ' : '\n');
    int bad = ferror(f);
    if (fclose(f) != 0 || bad) {
        if (msg && msg_len) snprintf(msg, msg_len, "%s: write error", path);
        remove(path);
        return RT_ERR_IO;
    }
    return RT_OK;
}
