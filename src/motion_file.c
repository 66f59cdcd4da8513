/* motion_file.c - reading a motion file: `frames`, `objects`, `pivot`, `axis` and `key` lines
 * (rt_motion.h, docs/motion-files.md). */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "motion_internal.h"
#include "rt_file_read.h"
#include "rt_number.h"
#include "rt_text.h"

#define MAX_MAGNITUDE 1e30 /* the NFF reader's limit on coordinates */
#define MAX_TOKENS 16      /* no statement has more words: key F move X Y Z turn D scale S = 10 */

typedef struct reader {
    const char *file;
    size_t line;
    char *msg;
    size_t msg_len;
    rt_motion *m;
    size_t frames_line; /* 0: no `frames` line yet */
    size_t total_keys;
} reader;

/* "FILE:LINE: message" (the file name as rt_escape_bytes shows it) into the caller's buffer. */
static rt_status fail(reader *r, rt_status status, const char *fmt, ...)
{
    if (!r->msg || !r->msg_len) return status;
    char what[RT_MSG_LEN];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    snprintf(r->msg, r->msg_len, "%s:%zu: %s", r->m && r->m->file ? r->m->file : r->file, r->line, what);
    return status;
}

/* A real of the one decimal syntax (rt_number.h), at most 1e30 in magnitude. */
static rt_status parse_real(reader *r, const char *what, const char *tok, double *out)
{
    double v = 0;
    rt_number_fault f = rt_number_real(tok, strlen(tok), &v);
    if (f != RT_NUMBER_OK) return fail(r, RT_ERR_PARSE, "%s '%.40s' %s", what, tok, rt_number_fault_text(f));
    if (fabs(v) > MAX_MAGNITUDE) return fail(r, RT_ERR_PARSE, "%s '%.40s' is above 1e30 in magnitude", what, tok);
    *out = v;
    return RT_OK;
}

/* A whole decimal number in [0, max] (rt_number.h). */
static rt_status parse_count(reader *r, const char *what, const char *tok, unsigned long max, uint32_t *out)
{
    unsigned long long v = 0;
    *out = 0;
    rt_number_fault f = rt_number_whole(tok, strlen(tok), max, &v);
    if (f == RT_NUMBER_TOO_LARGE) return fail(r, RT_ERR_PARSE, "%s %.40s is above %lu", what, tok, max);
    if (f == RT_NUMBER_SYNTAX)
        return fail(r, RT_ERR_PARSE, "%s '%.40s' is not a whole number (digits only)", what, tok);
    if (f != RT_NUMBER_OK) return fail(r, RT_ERR_PARSE, "%s '%.40s' %s", what, tok, rt_number_fault_text(f));
    *out = (uint32_t)v;
    return RT_OK;
}

/* Three numbers after the keyword at tok[at]. */
static rt_status parse_vec(reader *r, const char *what, char **tok, int n, int at, rt_vec3 *out)
{
    if (at + 3 > n) return fail(r, RT_ERR_PARSE, "%s needs three numbers X Y Z", what);
    double v[3];
    for (int i = 0; i < 3; i++) {
        rt_status st = parse_real(r, what, tok[at + i], &v[i]);
        if (st != RT_OK) return st;
    }
    *out = rt_vec(v[0], v[1], v[2]);
    return RT_OK;
}

static motion_entry *current(reader *r, const char *word)
{
    if (r->m->entry_count == 0) {
        fail(r, RT_ERR_PARSE, "'%s' before any 'objects' line (it belongs to an entry)", word);
        return NULL;
    }
    return &r->m->entries[r->m->entry_count - 1];
}

static rt_status grow(void **buf, size_t *capacity, size_t need, size_t size)
{
    if (need <= *capacity) return RT_OK;
    size_t cap = *capacity ? *capacity * 2 : 8;
    void *p = realloc(*buf, cap * size);
    if (!p) return RT_ERR_NOMEM;
    *buf = p;
    *capacity = cap;
    return RT_OK;
}

static rt_status statement_frames(reader *r, char **tok, int n)
{
    if (r->frames_line) return fail(r, RT_ERR_PARSE, "a second 'frames' line (the first is line %zu)", r->frames_line);
    if (n != 2) return fail(r, RT_ERR_PARSE, "'frames' takes one number: frames N");
    uint32_t v;
    rt_status st = parse_count(r, "frames", tok[1], RT_MOTION_MAX_FRAMES, &v);
    if (st != RT_OK) return st;
    if (v == 0) return fail(r, RT_ERR_PARSE, "frames 0: an animation has 1 to %u frames", RT_MOTION_MAX_FRAMES);
    r->m->frames = v;
    r->frames_line = r->line;
    return RT_OK;
}

static rt_status statement_objects(reader *r, char **tok, int n)
{
    if (n != 2 && n != 3) return fail(r, RT_ERR_PARSE, "'objects' takes FIRST [LAST]: object indices from 0");
    uint32_t first, last;
    rt_status st = parse_count(r, "objects FIRST", tok[1], RT_SCENE_MAX_OBJECTS - 1, &first);
    if (st == RT_OK)
        st = n == 3 ? parse_count(r, "objects LAST", tok[2], RT_SCENE_MAX_OBJECTS - 1, &last) : (last = first, RT_OK);
    if (st != RT_OK) return st;
    if (last < first) return fail(r, RT_ERR_PARSE, "objects %u %u: LAST is below FIRST", first, last);
    rt_motion *m = r->m;
    if (m->entry_count == RT_MOTION_MAX_ENTRIES)
        return fail(r, RT_ERR_LIMIT, "more than %u 'objects' lines", RT_MOTION_MAX_ENTRIES);
    if (grow((void **)&m->entries, &m->entry_capacity, m->entry_count + 1, sizeof *m->entries))
        return fail(r, RT_ERR_NOMEM, "out of memory");
    motion_entry *e = &m->entries[m->entry_count++];
    memset(e, 0, sizeof *e);
    e->line = r->line;
    e->first = first;
    e->last = last;
    return RT_OK;
}

static rt_status statement_pivot_axis(reader *r, char **tok, int n, int is_axis)
{
    motion_entry *e = current(r, tok[0]);
    if (!e) return RT_ERR_PARSE;
    size_t *given = is_axis ? &e->axis_line : &e->pivot_line;
    if (*given)
        return fail(r, RT_ERR_PARSE, "a second '%s' line in this entry (the first is line %zu)", tok[0], *given);
    if (n != 4) return fail(r, RT_ERR_PARSE, "'%s' takes three numbers: %s X Y Z", tok[0], tok[0]);
    rt_vec3 v;
    rt_status st = parse_vec(r, tok[0], tok, n, 1, &v);
    if (st != RT_OK) return st;
    if (is_axis) {
        /* Scaled by its largest component first, so that 1e-200 or 1e30 keeps its direction
         * (the squares would underflow or overflow). */
        double big = fmax(fabs(v.x), fmax(fabs(v.y), fabs(v.z)));
        if (!(big > 0.0))
            return fail(r, RT_ERR_PARSE, "axis %.40s %.40s %.40s: a rotation axis needs a direction", tok[1], tok[2],
                        tok[3]);
        rt_vec3 u = rt_vec(v.x / big, v.y / big, v.z / big); /* 1 / big overflows for a subnormal big */
        e->axis = rt_vec_scale(u, 1.0 / rt_vec_length(u));
    } else {
        e->pivot = v;
    }
    *given = r->line;
    return RT_OK;
}

/* The parts after `key FRAME`: move X Y Z, turn D, scale S, each at most once. */
static rt_status key_parts(reader *r, char **tok, int n, rt_motion_key *k)
{
    int seen[3] = {0, 0, 0};
    for (int i = 2; i < n;) {
        int part = !strcmp(tok[i], "move") ? 0 : !strcmp(tok[i], "turn") ? 1 : !strcmp(tok[i], "scale") ? 2 : -1;
        if (part < 0)
            return fail(r, RT_ERR_PARSE, "unknown key part '%.40s' (move X Y Z, turn DEGREES, scale S)", tok[i]);
        if (seen[part]) return fail(r, RT_ERR_PARSE, "'%s' twice in one key", tok[i]);
        seen[part] = 1;
        rt_status st;
        if (part == 0) {
            st = parse_vec(r, "move", tok, n, i + 1, &k->move);
            i += 4;
            if (st != RT_OK) return st;
            continue;
        }
        if (i + 1 >= n) return fail(r, RT_ERR_PARSE, "'%s' needs a number", tok[i]);
        st = parse_real(r, tok[i], tok[i + 1], part == 1 ? &k->turn : &k->scale);
        if (st != RT_OK) return st;
        if (part == 1 && fabs(k->turn) > RT_MOTION_MAX_TURN)
            return fail(r, RT_ERR_PARSE, "turn %.40s: at most %g degrees either way", tok[i + 1], RT_MOTION_MAX_TURN);
        if (part == 2 && !(k->scale >= RT_MOTION_MIN_SCALE && k->scale <= RT_MOTION_MAX_SCALE))
            return fail(r, RT_ERR_PARSE, "scale %.40s: must be from %g to %g (0 and mirror images are refused)",
                        tok[i + 1], RT_MOTION_MIN_SCALE, RT_MOTION_MAX_SCALE);
        i += 2;
    }
    return RT_OK;
}

static rt_status statement_key(reader *r, char **tok, int n)
{
    motion_entry *e = current(r, "key");
    if (!e) return RT_ERR_PARSE;
    if (n < 2) return fail(r, RT_ERR_PARSE, "'key' needs a frame number: key FRAME [move X Y Z] [turn D] [scale S]");
    rt_motion_key k = {0, rt_vec(0, 0, 0), 0.0, 1.0};
    rt_status st = parse_count(r, "key frame", tok[1], RT_MOTION_MAX_KEY_FRAME, &k.frame);
    if (st == RT_OK) st = key_parts(r, tok, n, &k);
    if (st != RT_OK) return st;
    if (e->key_count && k.frame <= e->keys[e->key_count - 1].frame)
        return fail(r, RT_ERR_PARSE, "key %u: frames must increase within an entry (the previous key is frame %u)",
                    k.frame, e->keys[e->key_count - 1].frame);
    if (k.turn != 0.0 && !e->axis_line)
        return fail(r, RT_ERR_PARSE, "key %u turns: give the entry an 'axis X Y Z' line before it", k.frame);
    if (r->total_keys == RT_MOTION_MAX_KEYS) return fail(r, RT_ERR_LIMIT, "more than %u keys", RT_MOTION_MAX_KEYS);
    if (grow((void **)&e->keys, &e->key_capacity, e->key_count + 1, sizeof *e->keys))
        return fail(r, RT_ERR_NOMEM, "out of memory");
    e->keys[e->key_count++] = k;
    r->total_keys++;
    return RT_OK;
}

/* One line (its end removed, NUL-terminated): blank, comment or one statement. */
static rt_status parse_line(reader *r, char *buf)
{
    char *hash = strchr(buf, '#');
    if (hash) *hash = '\0';
    char *tok[MAX_TOKENS];
    int n = 0;
    for (char *save = NULL, *t = strtok_r(buf, " \t", &save); t; t = strtok_r(NULL, " \t", &save)) {
        if (n == MAX_TOKENS) return fail(r, RT_ERR_PARSE, "more than %d words on one line", MAX_TOKENS);
        tok[n++] = t;
    }
    if (n == 0) return RT_OK;
    if (!strcmp(tok[0], "frames")) return statement_frames(r, tok, n);
    if (!strcmp(tok[0], "objects")) return statement_objects(r, tok, n);
    if (!strcmp(tok[0], "pivot")) return statement_pivot_axis(r, tok, n, 0);
    if (!strcmp(tok[0], "axis")) return statement_pivot_axis(r, tok, n, 1);
    if (!strcmp(tok[0], "key")) return statement_key(r, tok, n);
    return fail(r, RT_ERR_PARSE, "unknown statement '%.40s' (frames, objects, pivot, axis, key)", tok[0]);
}

/* Copies the line starting at text[*at] into buf and moves *at past its end ("\n", "\r\n"
 * or a lone "\r"). RT_ERR_LIMIT for a long line, RT_ERR_PARSE for binary data. */
static rt_status next_line(reader *r, const char *text, size_t length, size_t *at, char *buf)
{
    size_t len = 0, i = *at;
    for (; i < length && text[i] != '\n' && text[i] != '\r'; i++) {
        unsigned char ch = (unsigned char)text[i];
        if (len == RT_MOTION_MAX_LINE) return fail(r, RT_ERR_LIMIT, "line longer than %u bytes", RT_MOTION_MAX_LINE);
        if ((ch < 0x20 && ch != '\t') || ch == 0x7f) return fail(r, RT_ERR_PARSE, "binary data (byte 0x%02x)", ch);
        buf[len++] = (char)ch;
    }
    buf[len] = '\0';
    if (i < length && text[i] == '\r' && i + 1 < length && text[i + 1] == '\n') i++;
    *at = i < length ? i + 1 : i;
    return RT_OK;
}

static int by_first_then_line(const void *a, const void *b)
{
    const motion_entry *x = *(const motion_entry *const *)a, *y = *(const motion_entry *const *)b;
    if (x->first != y->first) return x->first < y->first ? -1 : 1;
    return x->line < y->line ? -1 : x->line > y->line;
}

/* An object moves by one entry: sorted by first object, an entry overlaps an earlier one if it
 * starts at or before the furthest end so far. Of the pairs found, the one whose later line comes
 * first is reported, at that line. */
static rt_status check_overlaps(reader *r)
{
    rt_motion *m = r->m;
    if (m->entry_count < 2) return RT_OK;
    const motion_entry **order = malloc(m->entry_count * sizeof *order);
    if (!order) return fail(r, RT_ERR_NOMEM, "out of memory");
    for (size_t i = 0; i < m->entry_count; i++) order[i] = &m->entries[i];
    qsort(order, m->entry_count, sizeof *order, by_first_then_line);
    const motion_entry *furthest = order[0], *early = NULL, *late = NULL;
    for (size_t i = 1; i < m->entry_count; i++) {
        const motion_entry *e = order[i];
        if (e->first <= furthest->last) {
            const motion_entry *a = e->line < furthest->line ? e : furthest, *b = a == e ? furthest : e;
            if (!late || b->line < late->line) early = a, late = b;
        }
        if (e->last > furthest->last) furthest = e;
    }
    free(order);
    if (!late) return RT_OK;
    r->line = late->line;
    return fail(r, RT_ERR_PARSE, "objects %u-%u overlap objects %u-%u of line %zu (an object moves by one entry)",
                late->first, late->last, early->first, early->last, early->line);
}

/* After the last line: entries do not overlap, every entry has a key; the frame count is known. */
static rt_status finish(reader *r)
{
    rt_motion *m = r->m;
    rt_status st = check_overlaps(r);
    if (st != RT_OK) return st;
    uint32_t last_key = 0;
    for (size_t i = 0; i < m->entry_count; i++) {
        const motion_entry *e = &m->entries[i];
        if (e->key_count == 0) {
            r->line = e->line;
            return fail(r, RT_ERR_PARSE, "objects %u-%u have no 'key' line", e->first, e->last);
        }
        if (e->keys[e->key_count - 1].frame > last_key) last_key = e->keys[e->key_count - 1].frame;
    }
    if (r->frames_line) return RT_OK;
    if (m->entry_count == 0) return fail(r, RT_ERR_PARSE, "no 'frames' line and no key: the frame count is unknown");
    if (last_key >= RT_MOTION_MAX_FRAMES)
        return fail(r, RT_ERR_PARSE, "no 'frames' line, and the last key (frame %u) makes more than %u frames",
                    last_key, RT_MOTION_MAX_FRAMES);
    m->frames = last_key + 1;
    return RT_OK;
}

void rt_motion_free(rt_motion *m)
{
    if (!m) return;
    for (size_t i = 0; i < m->entry_count; i++) free(m->entries[i].keys);
    free(m->entries);
    free(m->file);
    free(m);
}

rt_status rt_motion_parse(const char *name, const char *text, size_t length, rt_motion **out, char *msg, size_t msg_len)
{
    *out = NULL;
    reader r = {name, 0, msg, msg_len, calloc(1, sizeof(rt_motion)), 0, 0};
    char *buf = malloc(RT_MOTION_MAX_LINE + 1);
    size_t shown_len = 4 * strlen(name) + 8; /* every byte escaped as \xNN at worst */
    rt_status st = RT_OK;
    if (!r.m || !buf || !(r.m->file = malloc(shown_len))) st = fail(&r, RT_ERR_NOMEM, "out of memory");
    else rt_escape_bytes(name, strlen(name), 0, r.m->file, shown_len); /* the name messages show */
    for (size_t at = 0; st == RT_OK && at < length;) {
        r.line++;
        st = next_line(&r, text, length, &at, buf);
        if (st == RT_OK) st = parse_line(&r, buf);
    }
    free(buf);
    if (st == RT_OK) {
        if (r.line == 0) r.line = 1;
        st = finish(&r);
    }
    if (st != RT_OK) {
        rt_motion_free(r.m);
        return st;
    }
    *out = r.m;
    return RT_OK;
}

rt_status rt_motion_load(const char *file, rt_motion **out, char *msg, size_t msg_len)
{
    *out = NULL;
    char *text = NULL;
    size_t length = 0;
    rt_status st = rt_read_regular_file(file, RT_MOTION_MAX_BYTES, &text, &length, msg, msg_len);
    if (st != RT_OK) return st;
    st = rt_motion_parse(file, text, length, out, msg, msg_len);
    free(text);
    return st;
}

uint32_t rt_motion_frame_count(const rt_motion *m) { return m->frames; }
size_t rt_motion_entry_count(const rt_motion *m) { return m->entry_count; }

rt_motion_entry_info rt_motion_entry(const rt_motion *m, size_t i)
{
    rt_motion_entry_info info = {0, 0, 0, 0};
    if (i >= m->entry_count) return info;
    info.line = m->entries[i].line;
    info.first = m->entries[i].first;
    info.last = m->entries[i].last;
    info.keys = m->entries[i].key_count;
    return info;
}
