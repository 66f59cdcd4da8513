/* rt_timing.h - the timing table: what each operation costs (paper's V30/8087 figures).
 *
 * Usage:
 *   rt_timing t;
 *   rt_timing_defaults(&t);
 *   if (rt_timing_load("fast.timing", &t, msg, sizeof msg) != RT_OK) ...
 *   double us = rt_timing_step_us(&t, &result.ops);
 *
 * Timing file format: one `key value` pair per line (also `key = value`),
 * `#` starts a comment, keys as the field names below without the unit
 * suffix (e.g. `test_miss 1300`). Loading overrides only the keys given.
 * Failures return RT_ERR_IO or RT_ERR_PARSE with "FILE:LINE: message".
 */
#ifndef RT_TIMING_H
#define RT_TIMING_H

#include <stddef.h>
#include <stdint.h>

#include "rt_ops.h"
#include "rt_status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rt_timing {
    double test_miss_us;        /* intersection test, miss (1300) */
    double test_hit_us;         /* intersection test, hit (1750) */
    double dda_step_us;         /* next-cell determination (340) */
    double shading_us;          /* luminance computation at a hit (4600) */
    double reflection_us;       /* reflection vector (680) */
    double refraction_us;       /* transmission vector (1100) */
    double packet_analysis_us;  /* taking up a new packet: a primary or one made at a hit (580) */
    double packet_creation_us;  /* making a new packet at a hit (1600) */
    double fb_write_us;         /* one frame-buffer contribution (0) */
    double link_us;             /* one packet over a link (50); see link_bytes_per_us */
    double link_bytes_per_us;   /* > 0: link time = packet_bytes / this, overriding link_us (0) */
    double packet_bytes;        /* packet size on the wire, bytes (28) */
    double host_inject_us;      /* host time to inject one primary packet (0) */
    double bus_width_bytes;     /* cluster bus data width, bytes per cycle (2) */
    double bus_cycle_us;        /* cluster bus cycle (2) */
    double bus_arbitration_us;  /* arbitration before each bus transfer (0.25) */
    double memory_access_us;    /* 2-port memory access latency from the bus side (2) */
    double handover_send_us;    /* sending IP: hand a packet on to the next cell's owner */
    double handover_receive_us; /* receiving IP: take up a packet another IP handed over */
    double preprocess_unit_us;  /* one half-space test of a moving scene's cell-list update (340) */
    double cell_step_packet_us; /* packet work on every move into the next cell, T(1) included (580) */
    double link_setup_us;       /* a link's fixed time per packet on top of its transfer time (0) */
} rt_timing;

void rt_timing_defaults(rt_timing *timing);

/* A named profile (the files in timing/): "literal" (a hand-over costs a packet
 * creation plus an analysis), "calibrated" (the hand-over cost the calibration
 * study supports), "fitted" (calibrated with the packet cost per cell step and the bus
 * and memory timing the fidelity study fitted; the defaults) or "round-one" (calibrated
 * with the first fit's bus and memory timing). RT_ERR_INVALID naming an unknown profile. */
rt_status rt_timing_profile(const char *name, rt_timing *timing, char *msg, size_t msg_len);

/* Number of built-in profiles and the i-th one's name (NULL past the end). */
size_t rt_timing_profile_count(void);
const char *rt_timing_profile_name(size_t index);

/* The name of the built-in profile the defaults are. */
const char *rt_timing_default_profile(void);

/* Sets one key (name as in the file). RT_ERR_INVALID for an unknown key or a
 * negative / non-finite value (widths and packet size must be > 0). */
rt_status rt_timing_set(rt_timing *timing, const char *key, double value, char *msg, size_t msg_len);

rt_status rt_timing_load(const char *path, rt_timing *timing, char *msg, size_t msg_len);

/* The largest value of any key (and of a link or bus transfer's time): 1e6 us, 1 s. */
#define RT_TIMING_MAX_VALUE 1e6

/* Number of keys and the i-th key's name (for help text and echoing); NULL past the end. */
size_t rt_timing_key_count(void);
const char *rt_timing_key_name(size_t index);
/* The i-th key's unit ("us", "bytes" or "bytes/us") and one-line meaning; NULL past the end. */
const char *rt_timing_key_unit(size_t index);
const char *rt_timing_key_meaning(size_t index);
/* 1 if the i-th key must be > 0 (a divisor), 0 if >= 0 (or past the end). */
int rt_timing_key_positive(size_t index);
double rt_timing_get(const rt_timing *timing, size_t index);

/* Microseconds an IP spends on the operations in `ops` (frame-buffer writes included). */
double rt_timing_step_us(const rt_timing *timing, const rt_op_counts *ops);

/* Microseconds a link is busy with one packet: link_setup plus the transfer (link, or packet_bytes
 * over link_bytes_per_us). */
double rt_timing_link_packet_us(const rt_timing *timing);

/* Microseconds one bus transfer of `bytes` occupies the bus (arbitration excluded). */
double rt_timing_bus_transfer_us(const rt_timing *timing, double bytes);

#ifdef __cplusplus
}
#endif
#endif
