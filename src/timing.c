/* timing.c - the timing table: defaults, `key value` files, and costs. */
#include <ctype.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rt_file_read.h"
#include "rt_number.h"
#include "rt_timing.h"

typedef struct timing_key {
    const char *name; /* as written in files */
    size_t offset;    /* into rt_timing */
    int positive;     /* must be > 0 (a divisor), else >= 0 */
    double default_value;
    const char *unit;    /* of the value: "us", "bytes" or "bytes/us" */
    const char *meaning; /* one line, for help and docs */
} timing_key;

/* One row per field: names, defaults, units and checks live in one place. */
static const timing_key keys[] = {
    {"test_miss", offsetof(rt_timing, test_miss_us), 0, 1300.0, "us", "intersection test, miss"},
    {"test_hit", offsetof(rt_timing, test_hit_us), 0, 1750.0, "us", "intersection test, hit"},
    {"dda_step", offsetof(rt_timing, dda_step_us), 0, 340.0, "us", "next-cell determination"},
    {"shading", offsetof(rt_timing, shading_us), 0, 4600.0, "us", "luminance computation at a hit"},
    {"reflection", offsetof(rt_timing, reflection_us), 0, 680.0, "us", "reflection vector"},
    {"refraction", offsetof(rt_timing, refraction_us), 0, 1100.0, "us", "transmission vector"},
    {"packet_analysis", offsetof(rt_timing, packet_analysis_us), 0, 580.0, "us", "taking up a new packet"},
    {"packet_creation", offsetof(rt_timing, packet_creation_us), 0, 1600.0, "us", "making a new packet at a hit"},
    {"fb_write", offsetof(rt_timing, fb_write_us), 0, 0.0, "us", "one frame-buffer contribution"},
    {"link", offsetof(rt_timing, link_us), 0, 50.0, "us", "one packet over a link"},
    {"link_bytes_per_us", offsetof(rt_timing, link_bytes_per_us), 0, 0.0, "bytes/us",
     "link bandwidth; > 0 overrides link"},
    {"packet_bytes", offsetof(rt_timing, packet_bytes), 1, 28.0, "bytes", "packet size on the wire"},
    {"host_inject", offsetof(rt_timing, host_inject_us), 0, 0.0, "us", "host time to inject one primary packet"},
    {"bus_width_bytes", offsetof(rt_timing, bus_width_bytes), 1, 2.0, "bytes", "cluster bus data width per cycle"},
    /* Bus and memory: the fidelity study's fit on the shared-data penalty (docs/fidelity.md). */
    {"bus_cycle", offsetof(rt_timing, bus_cycle_us), 0, 4.0, "us", "cluster bus cycle"},
    {"bus_arbitration", offsetof(rt_timing, bus_arbitration_us), 0, 0.25, "us", "arbitration before a bus transfer"},
    {"memory_access", offsetof(rt_timing, memory_access_us), 0, 0.5, "us", "2-port memory access from the bus side"},
    /* Calibrated (docs/calibration.md): the paper's claims fit a hand-over that costs the IPs
     * nothing beyond the link; the literal profile charges a creation plus an analysis. */
    {"handover_send", offsetof(rt_timing, handover_send_us), 0, 0.0, "us", "handing a packet on to another IP"},
    {"handover_receive", offsetof(rt_timing, handover_receive_us), 0, 0.0, "us",
     "taking up a packet another IP handed over"},
    /* The paper times no half-space test; a next-cell determination, the nearest operation it
     * measures (coordinates against cell planes), stands for one (docs/timing.md). */
    {"preprocess_unit", offsetof(rt_timing, preprocess_unit_us), 0, 340.0, "us",
     "one half-space test of a moving scene's update"},
    /* The packet is taken up again at every cell it enters (it carries the index of the next
     * cell, docs/paper.md): the fidelity study fitted the table's packet analysis on the work
     * window; 0 in the profiles before that fit. */
    {"cell_step_packet", offsetof(rt_timing, cell_step_packet_us), 0, 580.0, "us",
     "packet work on every move into the next cell"},
    {"link_setup", offsetof(rt_timing, link_setup_us), 0, 0.0, "us",
     "a link's fixed time per packet before the transfer"},
};
#define KEY_COUNT (sizeof keys / sizeof keys[0])

static double *field(rt_timing *t, size_t i) { return (double *)((char *)t + keys[i].offset); }

static const double *cfield(const rt_timing *t, size_t i) { return (const double *)((const char *)t + keys[i].offset); }

void rt_timing_defaults(rt_timing *t)
{
    for (size_t i = 0; i < KEY_COUNT; i++) *field(t, i) = keys[i].default_value;
}

/* Profiles: the defaults with these hand-over costs (send, receive), cluster bus and memory
 * timing (cycle, access) and packet cost per cell step. */
typedef struct timing_profile {
    const char *name;
    double handover_send, handover_receive;
    double bus_cycle, memory_access;
    double cell_step_packet;
} timing_profile;

static const timing_profile profiles[] = {
    {"calibrated", 0.0, 0.0, 0.5, 0.5, 0.0},
    {"literal", 1600.0, 580.0, 0.5, 0.5, 0.0},
    /* The fidelity study's fit (docs/fidelity.md): the packet analysis at every cell step on
     * the work window, bus and memory timing on the shared-data penalty, the hand-over on the
     * 1024-processor times. The defaults. */
    {"fitted", 0.0, 0.0, 4.0, 0.5, 580.0},
    /* The first fit, made without the work window: bus and memory timing only. */
    {"round-one", 0.0, 0.0, 2.0, 2.0, 0.0},
};
#define PROFILE_COUNT (sizeof profiles / sizeof profiles[0])

const char *rt_timing_default_profile(void) { return "fitted"; }

size_t rt_timing_profile_count(void) { return PROFILE_COUNT; }

const char *rt_timing_profile_name(size_t index) { return index < PROFILE_COUNT ? profiles[index].name : NULL; }

rt_status rt_timing_profile(const char *name, rt_timing *t, char *msg, size_t msg_len)
{
    for (size_t i = 0; i < PROFILE_COUNT; i++) {
        if (!name || strcmp(profiles[i].name, name) != 0) continue;
        rt_timing_defaults(t);
        t->handover_send_us = profiles[i].handover_send;
        t->handover_receive_us = profiles[i].handover_receive;
        t->bus_cycle_us = profiles[i].bus_cycle;
        t->memory_access_us = profiles[i].memory_access;
        t->cell_step_packet_us = profiles[i].cell_step_packet;
        return RT_OK;
    }
    if (msg && msg_len)
        snprintf(msg, msg_len, "unknown timing profile '%s' (expected calibrated, literal, fitted or round-one)",
                 name ? name : "");
    return RT_ERR_INVALID;
}

static int find_key(const char *name)
{
    for (size_t i = 0; i < KEY_COUNT; i++)
        if (strcmp(keys[i].name, name) == 0) return (int)i;
    return -1;
}

/* Message for a value outside a key's range (no prefix). */
static void range_msg(size_t i, char *msg, size_t msg_len)
{
    if (msg && msg_len)
        snprintf(msg, msg_len, "'%s' needs a %s number", keys[i].name, keys[i].positive ? "positive" : "non-negative");
}

rt_status rt_timing_set(rt_timing *t, const char *key, double value, char *msg, size_t msg_len)
{
    int i = key ? find_key(key) : -1;
    if (i < 0) {
        char quoted[256];
        if (msg && msg_len)
            snprintf(msg, msg_len, "unknown key '%s'",
                     key ? rt_escape_bytes(key, strlen(key), 1, quoted, sizeof quoted) : "");
        return RT_ERR_INVALID;
    }
    if (!isfinite(value) || value < 0.0 || (keys[i].positive && !(value > 0.0))) {
        range_msg((size_t)i, msg, msg_len);
        return RT_ERR_INVALID;
    }
    *field(t, (size_t)i) = value;
    return RT_OK;
}

static const char *skip_space(const char *p)
{
    while (*p && isspace((unsigned char)*p)) p++;
    return p;
}

/* Applies one line to *t; 0 with a message (no prefix) if malformed. `seen` marks the keys
 * the file has set: a key given twice is an error. */
static int parse_line(char *line, rt_timing *t, unsigned char seen[], char *msg, size_t msg_len)
{
    char *hash = strchr(line, '#');
    if (hash) *hash = '\0';
    const char *p = skip_space(line);
    if (!*p) return 1;

    const char *key = p;
    while (*p && !isspace((unsigned char)*p) && *p != '=') p++;
    size_t key_len = (size_t)(p - key);
    p = skip_space(p);
    if (*p == '=') p = skip_space(p + 1);
    const char *value = p;
    while (*p && !isspace((unsigned char)*p)) p++;
    size_t value_len = (size_t)(p - value);
    p = skip_space(p);
    if (key_len == 0 || value_len == 0 || *p) {
        if (msg && msg_len) snprintf(msg, msg_len, "expected 'key value'");
        return 0;
    }

    char name[64];
    if (key_len >= sizeof name) key_len = sizeof name - 1; /* too long to be a key anyway */
    memcpy(name, key, key_len);
    name[key_len] = '\0';
    int i = find_key(name);
    if (i < 0) {
        char quoted[4 * sizeof name];
        if (msg && msg_len)
            snprintf(msg, msg_len, "unknown key '%s'", rt_escape_bytes(key, key_len, 1, quoted, sizeof quoted));
        return 0;
    }
    if (seen[i]) {
        if (msg && msg_len) snprintf(msg, msg_len, "'%s' given twice", keys[i].name);
        return 0;
    }
    seen[i] = 1;
    double v = 0;
    rt_number_fault f = rt_number_real(value, value_len, &v);
    if (f == RT_NUMBER_SYNTAX || f == RT_NUMBER_HEX) {
        if (msg && msg_len)
            snprintf(msg, msg_len, "'%s' needs a decimal number (such as 12.5 or 1e-3; no hexadecimal)", keys[i].name);
        return 0;
    }
    if (f != RT_NUMBER_OK) {
        char quoted[4 * 64];
        int neg = value[0] == '-';
        size_t first = (size_t)neg; /* the value without its leading zeros, for the hint */
        while (f == RT_NUMBER_LEADING_ZERO && first + 1 < value_len && value[first] == '0' && value[first + 1] >= '0' &&
               value[first + 1] <= '9')
            first++;
        if (msg && msg_len) {
            int n = snprintf(msg, msg_len, "'%s' value '%s' %s", keys[i].name,
                             rt_escape_bytes(value, value_len < 64 ? value_len : 64, 1, quoted, sizeof quoted),
                             rt_number_fault_text(f));
            if (f == RT_NUMBER_LEADING_ZERO && n > 0 && (size_t)n < msg_len)
                snprintf(msg + n, msg_len - (size_t)n, ": write '%s%.*s'", neg ? "-" : "",
                         (int)(value_len - first < 64 ? value_len - first : 64), value + first);
        }
        return 0;
    }
    return rt_timing_set(t, name, v, msg, msg_len) == RT_OK;
}

/* A timing file is a few dozen lines: these bounds are far beyond any real one
 * and keep /dev/zero-like input from costing memory. */
#define TIMING_MAX_FILE_BYTES (1024u * 1024u)
#define TIMING_MAX_LINE_BYTES 4096u

rt_status rt_timing_load(const char *path, rt_timing *timing, char *msg, size_t msg_len)
{
    char *text = NULL;
    size_t length = 0;
    rt_status st = rt_read_regular_file(path, TIMING_MAX_FILE_BYTES, &text, &length, msg, msg_len);
    if (st) return st;
    char shown[256];
    rt_escape_bytes(path, strlen(path), 0, shown, sizeof shown);
    /* Work on a copy: a bad file leaves the caller's table untouched. */
    rt_timing t = *timing;
    char why[256];
    unsigned char seen[KEY_COUNT] = {0};
    long number = 0;
    for (char *line = text; st == RT_OK && line < text + length;) {
        char *nl = memchr(line, '\n', (size_t)(text + length - line));
        char *stop = nl ? nl : text + length;
        number++;
        if ((size_t)(stop - line) > TIMING_MAX_LINE_BYTES) {
            if (msg && msg_len)
                snprintf(msg, msg_len, "%s:%ld: line longer than %u bytes", shown, number, TIMING_MAX_LINE_BYTES);
            st = RT_ERR_PARSE;
        } else if (memchr(line, '\0', (size_t)(stop - line))) {
            if (msg && msg_len)
                snprintf(msg, msg_len, "%s:%ld: binary data (a NUL byte): not a timing file", shown, number);
            st = RT_ERR_PARSE;
        } else {
            *stop = '\0';
            if (!parse_line(line, &t, seen, why, sizeof why)) {
                if (msg && msg_len) snprintf(msg, msg_len, "%s:%ld: %s", shown, number, why);
                st = RT_ERR_PARSE;
            }
        }
        line = stop + 1;
    }
    free(text);
    if (st == RT_OK) *timing = t;
    return st;
}

size_t rt_timing_key_count(void) { return KEY_COUNT; }

const char *rt_timing_key_name(size_t index) { return index < KEY_COUNT ? keys[index].name : NULL; }

const char *rt_timing_key_unit(size_t index) { return index < KEY_COUNT ? keys[index].unit : NULL; }

const char *rt_timing_key_meaning(size_t index) { return index < KEY_COUNT ? keys[index].meaning : NULL; }

int rt_timing_key_positive(size_t index) { return index < KEY_COUNT ? keys[index].positive : 0; }

/* NAN for an index past the table. */
double rt_timing_get(const rt_timing *timing, size_t index) { return index < KEY_COUNT ? *cfield(timing, index) : NAN; }

/* A count as a double: through a signed conversion, one instruction where an unsigned one is a
 * branchy sequence (a step's counts are far below 2^63; measured at 1.3 % of a run's
 * instructions); the same value. */
static double count(uint64_t n) { return (double)(int64_t)n; }

double rt_timing_step_us(const rt_timing *t, const rt_op_counts *ops)
{
    return count(ops->tests_missed) * t->test_miss_us + count(ops->tests_hit) * t->test_hit_us +
           count(ops->dda_steps) * t->dda_step_us + count(ops->shadings) * t->shading_us +
           count(ops->reflection_vectors) * t->reflection_us + count(ops->refraction_vectors) * t->refraction_us +
           count(ops->packets_analysed) * t->packet_analysis_us + count(ops->packets_created) * t->packet_creation_us +
           count(ops->fb_writes) * t->fb_write_us + count(ops->handovers_sent) * t->handover_send_us +
           count(ops->handovers_received) * t->handover_receive_us + count(ops->cell_steps) * t->cell_step_packet_us;
}

double rt_timing_link_packet_us(const rt_timing *t)
{
    return t->link_setup_us + (t->link_bytes_per_us > 0.0 ? t->packet_bytes / t->link_bytes_per_us : t->link_us);
}

double rt_timing_bus_transfer_us(const rt_timing *t, double bytes)
{
    if (!(bytes > 0.0)) return 0.0;
    return ceil(bytes / t->bus_width_bytes) * t->bus_cycle_us;
}
