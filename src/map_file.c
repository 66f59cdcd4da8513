/* map_file.c - reading and writing `torusrt-map 1` and `torusrt-map 2` cell-to-node tables. */
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rt_file_read.h"
#include "rt_map_file.h"
#include "rt_number.h"

/* A word-at-a-time reader over the file's text that knows its line number and skips `#`
 * comments. */
typedef struct words {
    const char *p, *end;
    long line;
    int cut; /* the last word was longer than RT_MAP_FILE_MAX_WORD */
    char word[RT_MAP_FILE_MAX_WORD + 1];
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
    w->cut = 0;
    while (c != EOF && !isspace(c) && c != '#') {
        if (n + 1 < sizeof w->word) w->word[n++] = (char)c;
        else w->cut = 1;
        c = next_char(w);
    }
    w->word[n] = '\0';
    if (c != EOF) w->p--;
    return 1;
}

/* 1 and *v if the word is a whole decimal number (rt_number.h) in [lo, hi]. */
static int word_int(const char *s, long lo, long hi, long *v)
{
    unsigned long long x = 0;
    if (rt_number_whole(s, strlen(s), (unsigned long long)hi, &x) != RT_NUMBER_OK || x < (unsigned long long)lo)
        return 0;
    *v = (long)x;
    return 1;
}

static rt_status fail(char *msg, size_t msg_len, const char *path, long line, const char *what, const char *word)
{
    if (msg && msg_len)
        snprintf(msg, msg_len, "%s:%ld: %s%s%s%s", path, line, what, word ? " '" : "", word ? word : "",
                 word ? "'" : "");
    return RT_ERR_PARSE;
}

/* Reads and checks the header: magic, version, grid and node count. */
static rt_status read_header(words *w, const char *path, const int dims[3], int nodes, long *version, char *msg,
                             size_t msg_len)
{
    if (!next_word(w))
        return fail(msg, msg_len, path, w->line, "empty map file: expected 'torusrt-map 1 NX NY NZ NODES'", NULL);
    if (strcmp(w->word, "torusrt-map") != 0)
        return fail(msg, msg_len, path, w->line, "expected the header 'torusrt-map 1 NX NY NZ NODES', found", w->word);
    long v;
    if (!next_word(w) || !word_int(w->word, 1, 2, version))
        return fail(msg, msg_len, path, w->line,
                    "unsupported map format version (expected 1 or 2, decimal without a leading zero)", NULL);
    const long want[4] = {dims[0], dims[1], dims[2], nodes};
    const char *what[4] = {"NX", "NY", "NZ", "NODES"};
    for (int i = 0; i < 4; i++) {
        if (!next_word(w) || !word_int(w->word, 1, 1L << 30, &v))
            return fail(msg, msg_len, path, w->line,
                        "header: expected a positive decimal number (no sign, no leading zero) for", what[i]);
        if (v != want[i]) {
            char why[160];
            snprintf(why, sizeof why, "header %s = %ld, but the run has %ld (cells %dx%dx%d, %d nodes)", what[i], v,
                     want[i], dims[0], dims[1], dims[2], nodes);
            return fail(msg, msg_len, path, w->line, why, NULL);
        }
    }
    return RT_OK;
}

size_t rt_map_file_max_bytes(const int dims[3])
{
    return (size_t)dims[0] * (size_t)dims[1] * (size_t)dims[2] * 16u + 1024u * 1024u;
}

/* The extra owners read so far: a growing array (rt_replicas.h's `extra`). */
typedef struct extras {
    int32_t *node;
    size_t count, cap;
} extras;

static int extras_add(extras *e, int32_t node)
{
    if (e->count == e->cap) {
        size_t cap = e->cap ? 2 * e->cap : 64;
        int32_t *grown = realloc(e->node, cap * sizeof *grown);
        if (!grown) return 0;
        e->node = grown;
        e->cap = cap;
    }
    e->node[e->count++] = node;
    return 1;
}

/* One cell's entry: `N` (version 1 and 2) or `N,M,...` (version 2: the primary owner first,
 * then its extra owners, all different); the extra owners go in ascending order. */
static rt_status read_entry(words *w, const char *name, size_t cell, int nodes, long version, int32_t *owner, extras *e,
                            char *msg, size_t msg_len)
{
    size_t start = e->count;
    char *item = w->word;
    if (w->cut)
        return fail(msg, msg_len, name, w->line, "an entry longer than " RT_MAP_FILE_MAX_WORD_TEXT " bytes", NULL);
    for (int k = 0;; k++) {
        char *comma = strchr(item, ',');
        if (comma) *comma = '\0';
        long v;
        char why[128];
        if ((comma || k > 0) && version < 2)
            return fail(msg, msg_len, name, w->line, "several owners of a cell need 'torusrt-map 2', found", item);
        if (!word_int(item, 0, nodes - 1, &v)) {
            snprintf(why, sizeof why, "cell %zu: expected a node id 0..%d, found", cell, nodes - 1);
            return fail(msg, msg_len, name, w->line, why, item);
        }
        int twice = k > 0 && owner[cell] == v;
        for (size_t i = start; i < e->count && !twice; i++) twice = e->node[i] == v;
        if (twice) {
            snprintf(why, sizeof why, "cell %zu: node %ld listed twice", cell, v);
            return fail(msg, msg_len, name, w->line, why, NULL);
        }
        if (k == 0) owner[cell] = (int32_t)v;
        else if (!extras_add(e, (int32_t)v)) return fail(msg, msg_len, name, w->line, "out of memory", NULL);
        for (size_t i = e->count - 1; k > 0 && i > start && e->node[i - 1] > e->node[i]; i--) {
            int32_t t = e->node[i];
            e->node[i] = e->node[i - 1];
            e->node[i - 1] = t;
        }
        if (!comma) return RT_OK;
        item = comma + 1;
    }
}

rt_status rt_map_file_parse_replicas(const char *name, const char *text, size_t length, const int dims[3], int nodes,
                                     int32_t *owner, uint32_t *first, int32_t **extra, size_t *extra_count, char *msg,
                                     size_t msg_len)
{
    words w = {text, text + length, 1, 0, ""};
    long version = 1;
    extras e = {NULL, 0, 0};
    rt_status st = read_header(&w, name, dims, nodes, &version, msg, msg_len);
    if (st == RT_OK && version == 2 && !first)
        st = fail(msg, msg_len, name, w.line, "a 'torusrt-map 2' table is read with its replicas only", NULL);
    size_t cells = (size_t)dims[0] * (size_t)dims[1] * (size_t)dims[2], i = 0;
    if (first) first[0] = 0;
    while (st == RT_OK && next_word(&w)) {
        if (i == cells)
            st = fail(msg, msg_len, name, w.line, "more node ids than the grid's cells, first extra", w.word);
        else st = read_entry(&w, name, i, nodes, version, owner, &e, msg, msg_len);
        if (st == RT_OK && first) first[i + 1] = (uint32_t)e.count;
        i++;
    }
    if (st == RT_OK && i < cells) {
        char why[96];
        snprintf(why, sizeof why, "only %zu node ids for %zu cells", i, cells);
        st = fail(msg, msg_len, name, w.line, why, NULL);
    }
    if (extra) *extra = st == RT_OK ? e.node : NULL;
    if (extra_count) *extra_count = st == RT_OK ? e.count : 0;
    if (st != RT_OK || !extra) free(e.node);
    return st;
}

rt_status rt_map_file_parse(const char *name, const char *text, size_t length, const int dims[3], int nodes,
                            int32_t *owner, char *msg, size_t msg_len)
{
    return rt_map_file_parse_replicas(name, text, length, dims, nodes, owner, NULL, NULL, NULL, msg, msg_len);
}

rt_status rt_map_file_read_replicas(const char *path, const int dims[3], int nodes, int32_t *owner, uint32_t *first,
                                    int32_t **extra, size_t *extra_count, char *msg, size_t msg_len)
{
    char *text = NULL;
    size_t length = 0;
    if (extra) *extra = NULL;
    if (extra_count) *extra_count = 0;
    rt_status st = rt_read_regular_file(path, rt_map_file_max_bytes(dims), &text, &length, msg, msg_len);
    if (st != RT_OK) return st;
    char shown[256];
    rt_escape_bytes(path, strlen(path), 0, shown, sizeof shown);
    st = rt_map_file_parse_replicas(shown, text, length, dims, nodes, owner, first, extra, extra_count, msg, msg_len);
    free(text);
    return st;
}

rt_status rt_map_file_read(const char *path, const int dims[3], int nodes, int32_t *owner, char *msg, size_t msg_len)
{
    return rt_map_file_read_replicas(path, dims, nodes, owner, NULL, NULL, NULL, msg, msg_len);
}

rt_status rt_map_file_write_replicas(FILE *f, const char *name, const int dims[3], int nodes, const int32_t *owner,
                                     const rt_replicas *replicas, char *msg, size_t msg_len)
{
    size_t cells = (size_t)dims[0] * (size_t)dims[1] * (size_t)dims[2];
    if (replicas && replicas->first[cells] == 0) replicas = NULL; /* nothing replicated: version 1 */
    if (replicas)
        fprintf(f,
                "torusrt-map 2 %d %d %d %d\n# per cell, x fastest, its owners: the primary first, then the "
                "extra owners, separated by commas; a line per (y, z) row\n",
                dims[0], dims[1], dims[2], nodes);
    else
        fprintf(f, "torusrt-map 1 %d %d %d %d\n# one node id per cell, x fastest; a line per (y, z) row\n", dims[0],
                dims[1], dims[2], nodes);
    size_t i = 0;
    for (int z = 0; z < dims[2]; z++)
        for (int y = 0; y < dims[1]; y++)
            for (int x = 0; x < dims[0]; x++, i++) {
                fprintf(f, "%d", owner[i]);
                for (uint32_t k = 0; k < rt_replicas_extra_count(replicas, (uint32_t)i); k++)
                    fprintf(f, ",%d", replicas->extra[replicas->first[i] + k]);
                fputc(x + 1 < dims[0] ? ' ' : '\n', f);
            }
    if (fflush(f) != 0 || ferror(f)) {
        if (msg && msg_len) snprintf(msg, msg_len, "%s: cannot write: %s", name, strerror(errno ? errno : EIO));
        return RT_ERR_IO;
    }
    return RT_OK;
}

rt_status rt_map_file_write(FILE *f, const char *name, const int dims[3], int nodes, const int32_t *owner, char *msg,
                            size_t msg_len)
{
    return rt_map_file_write_replicas(f, name, dims, nodes, owner, NULL, msg, msg_len);
}
