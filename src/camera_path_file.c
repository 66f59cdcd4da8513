/* camera_path_file.c - reading a camera path file: one `from at up angle` line per frame. */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "camera_path_internal.h"
#include "rt_camera_path.h"
#include "rt_file_read.h"
#include "rt_number.h"

#define FIELDS 10
#define LAYOUT "from_x from_y from_z at_x at_y at_z up_x up_y up_z angle"
#define MAX_MAGNITUDE 1e30 /* the NFF reader's limit on coordinates */

typedef struct reader {
    const char *file;
    FILE *f;
    size_t line;
    char *msg;
    size_t msg_len;
} reader;

static rt_status fail(reader *r, rt_status status, const char *fmt, ...)
{
    if (r->msg && r->msg_len) {
        /* Line 0: the file as a whole is at fault (it cannot be opened). */
        int n = r->line ? snprintf(r->msg, r->msg_len, "%s:%zu: ", r->file, r->line)
                        : snprintf(r->msg, r->msg_len, "%s: ", r->file);
        if (n >= 0 && (size_t)n < r->msg_len) {
            va_list ap;
            va_start(ap, fmt);
            vsnprintf(r->msg + n, r->msg_len - (size_t)n, fmt, ap);
            va_end(ap);
        }
    }
    return status;
}

/* Reads the next line into buf (without its end); 0 at end of file, 1 with a line, or an
 * error status + 2. Control bytes other than tab are binary data. */
static int read_line(reader *r, char *buf, rt_status *error)
{
    size_t len = 0;
    int ch, any = 0;
    while ((ch = getc(r->f)) != EOF) {
        any = 1;
        if (ch == '\n') break;
        if (ch == '\r') { /* "\r\n" and a lone "\r" end a line too, as in NFF files */
            int next = getc(r->f);
            if (next != '\n' && next != EOF) ungetc(next, r->f);
            break;
        }
        if (len == RT_CAMERA_PATH_MAX_LINE) {
            *error = fail(r, RT_ERR_LIMIT, "line longer than %u bytes", RT_CAMERA_PATH_MAX_LINE);
            return 2;
        }
        if ((ch < 0x20 && ch != '\t') || ch == 0x7f) {
            *error = fail(r, RT_ERR_PARSE, "binary data (byte 0x%02x)", ch);
            return 2;
        }
        buf[len++] = (char)ch;
    }
    buf[len] = '\0';
    if (ferror(r->f)) {
        *error = fail(r, RT_ERR_IO, "cannot read: %s", strerror(errno));
        return 2;
    }
    return any;
}

/* A real of the one decimal syntax (rt_number.h), at most 1e30 in magnitude. */
static rt_status parse_number(reader *r, const char *tok, int field, double *out)
{
    static const char *names[FIELDS] = {"from_x", "from_y", "from_z", "at_x", "at_y",
                                        "at_z",   "up_x",   "up_y",   "up_z", "angle"};
    double v = 0;
    rt_number_fault f = rt_number_real(tok, strlen(tok), &v);
    if (f != RT_NUMBER_OK) return fail(r, RT_ERR_PARSE, "%s '%.40s' %s", names[field], tok, rt_number_fault_text(f));
    if (fabs(v) > MAX_MAGNITUDE)
        return fail(r, RT_ERR_PARSE, "%s '%.40s' is above 1e30 in magnitude", names[field], tok);
    *out = v;
    return RT_OK;
}

/* Parses one line; *has_pose is 0 for a blank or comment line. */
static rt_status parse_line(reader *r, char *buf, rt_camera_pose *pose, int *has_pose)
{
    char *hash = strchr(buf, '#');
    if (hash) *hash = '\0';
    double v[FIELDS];
    int n = 0;
    for (char *save = NULL, *tok = strtok_r(buf, " \t", &save); tok; tok = strtok_r(NULL, " \t", &save)) {
        if (n == FIELDS) return fail(r, RT_ERR_PARSE, "more than %d numbers, expected %s", FIELDS, LAYOUT);
        rt_status st = parse_number(r, tok, n, &v[n]);
        if (st != RT_OK) return st;
        n++;
    }
    *has_pose = n > 0;
    if (n == 0) return RT_OK;
    if (n != FIELDS) return fail(r, RT_ERR_PARSE, "%d numbers, expected %d: %s", n, FIELDS, LAYOUT);
    rt_camera_pose p = {rt_vec(v[0], v[1], v[2]), rt_vec(v[3], v[4], v[5]), rt_vec(v[6], v[7], v[8]), v[9]};
    char why[RT_MSG_LEN];
    if (rt_camera_pose_check(&p, why, sizeof why) != RT_OK) return fail(r, RT_ERR_PARSE, "%s", why);
    *pose = p;
    return RT_OK;
}

/* Reads FILE through the one input reader (regular files only, bounded, text) and reads its
 * lines from memory. */
static rt_status open_regular(reader *r, char **text)
{
    size_t length = 0;
    char why[RT_MSG_LEN];
    rt_status st = rt_read_regular_file(r->file, RT_CAMERA_PATH_MAX_BYTES, text, &length, why, sizeof why);
    if (st != RT_OK) {
        if (r->msg && r->msg_len) snprintf(r->msg, r->msg_len, "%s", why);
        return st;
    }
    r->f = length ? fmemopen(*text, length, "rb") : fopen("/dev/null", "rb");
    if (!r->f) {
        free(*text);
        *text = NULL;
        return fail(r, RT_ERR_NOMEM, "out of memory");
    }
    return RT_OK;
}

static rt_status read_poses(reader *r, rt_camera_pose **poses, size_t *count)
{
    char *buf = malloc(RT_CAMERA_PATH_MAX_LINE + 1);
    size_t capacity = 0;
    rt_status st = buf ? RT_OK : fail(r, RT_ERR_NOMEM, "out of memory");
    int got;
    while (st == RT_OK && (r->line++, got = read_line(r, buf, &st)) == 1) {
        rt_camera_pose pose;
        int has_pose = 0;
        st = parse_line(r, buf, &pose, &has_pose);
        if (st != RT_OK || !has_pose) continue;
        if (*count == RT_CAMERA_PATH_MAX_FRAMES) {
            st = fail(r, RT_ERR_LIMIT, "more than %u frames", RT_CAMERA_PATH_MAX_FRAMES);
            break;
        }
        if (*count == capacity) {
            size_t grown = capacity ? capacity * 2 : 64;
            rt_camera_pose *bigger = realloc(*poses, grown * sizeof *bigger);
            if (!bigger) {
                st = fail(r, RT_ERR_NOMEM, "out of memory");
                break;
            }
            *poses = bigger;
            capacity = grown;
        }
        (*poses)[(*count)++] = pose;
    }
    free(buf);
    if (st == RT_OK && *count == 0) {
        r->line = r->line > 1 ? r->line - 1 : 1;
        st = fail(r, RT_ERR_PARSE, "no frame: the file holds no camera line");
    }
    return st;
}

rt_status rt_camera_path_load(const char *file, rt_camera_path **out, char *msg, size_t msg_len)
{
    *out = NULL;
    reader r = {file, NULL, 0, msg, msg_len};
    char *text = NULL;
    rt_status st = open_regular(&r, &text);
    if (st != RT_OK) return st;
    rt_camera_pose *poses = NULL;
    size_t count = 0;
    st = read_poses(&r, &poses, &count);
    fclose(r.f);
    free(text);
    rt_camera_path *path = NULL;
    if (st == RT_OK && camera_path_new(0, &path) != RT_OK) st = fail(&r, RT_ERR_NOMEM, "out of memory");
    if (st != RT_OK) {
        free(poses);
        return st;
    }
    path->poses = poses;
    path->count = count;
    *out = path;
    return RT_OK;
}
