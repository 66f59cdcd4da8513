/* map_file.c - reading and writing `torusrt-map 1` cell-to-node tables. */
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rt_file_read.h"
#include "rt_map_file.h"

/* A word-at-a-time reader over the file's text that knows its line number and skips `#`
 * comments. */
typedef struct words {
    const char *p, *end;
    long line;
    char word[64];
} words;

static int next_char(words *w) { return w->p < w->end ? (unsigned char)*w->p++ : EOF; }

/* Next word into w->word; 0 at end of file. A word too long to be a number is cut
 * (and then fails to parse). */
static int next_word(words *w)
{
    int c;
    for (;;) {
        c = next_char(w);
        if (c == EOF) return 0;
        if (c == '\n') w->line++;
        else if (c == '#') {
            while ((c = next_char(w)) != EOF && c != '\n') {}
            if (c == EOF) return 0;
            w->line++;
        } else if (!isspace(c)) break;
    }
    size_t n = 0;
    while (c != EOF && !isspace(c) && c != '#') {
        if (n + 1 < sizeof w->word) w->word[n++] = (char)c;
        c = next_char(w);
    }
    w->word[n] = '\0';
    if (c != EOF) w->p--;
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

size_t rt_map_file_max_bytes(const int dims[3])
{
    return (size_t)dims[0] * (size_t)dims[1] * (size_t)dims[2] * 16u + 1024u * 1024u;
}

rt_status rt_map_file_parse(const char *name, const char *text, size_t length, const int dims[3], int nodes,
                            int32_t *owner, char *msg, size_t msg_len)
{
    words w = {text, text + length, 1, ""};
    rt_status st = read_header(&w, name, dims, nodes, msg, msg_len);
    size_t cells = (size_t)dims[0] * (size_t)dims[1] * (size_t)dims[2], i = 0;
    while (st == RT_OK && next_word(&w)) {
        long v;
        if (i == cells) {
            st = fail(msg, msg_len, name, w.line, "more node ids than the grid's cells, first extra", w.word);
        } else if (!word_int(w.word, 0, nodes - 1, &v)) {
            char why[96];
            snprintf(why, sizeof why, "cell %zu: expected a node id 0..%d, found", i, nodes - 1);
            st = fail(msg, msg_len, name, w.line, why, w.word);
        } else {
            owner[i++] = (int32_t)v;
        }
    }
    if (st == RT_OK && i < cells) {
        char why[96];
        snprintf(why, sizeof why, "only %zu node ids for %zu cells", i, cells);
        st = fail(msg, msg_len, name, w.line, why, NULL);
    }
    return st;
}

rt_status rt_map_file_read(const char *path, const int dims[3], int nodes, int32_t *owner, char *msg,
                           size_t msg_len)
{
    char *text = NULL;
    size_t length = 0;
    rt_status st = rt_read_regular_file(path, rt_map_file_max_bytes(dims), &text, &length, msg, msg_len);
    if (st != RT_OK) return st;
    char shown[256];
    rt_escape_bytes(path, strlen(path), 0, shown, sizeof shown);
    st = rt_map_file_parse(shown, text, length, dims, nodes, owner, msg, msg_len);
    free(text);
    return st;
}

rt_status rt_map_file_write(FILE *f, const char *name, const int dims[3], int nodes, const int32_t *owner,
                            char *msg, size_t msg_len)
{
    fprintf(f, "torusrt-map 1 %d %d %d %d\n# one node id per cell, x fastest; a line per (y, z) row\n",
            dims[0], dims[1], dims[2], nodes);
    size_t i = 0;
    for (int z = 0; z < dims[2]; z++)
        for (int y = 0; y < dims[1]; y++)
            for (int x = 0; x < dims[0]; x++) fprintf(f, "%d%c", owner[i++], x + 1 < dims[0] ? ' ' : '\n');
    if (fflush(f) != 0 || ferror(f)) {
        if (msg && msg_len) snprintf(msg, msg_len, "%s: cannot write: %s", name, strerror(errno ? errno : EIO));
        return RT_ERR_IO;
    }
    return RT_OK;
}
