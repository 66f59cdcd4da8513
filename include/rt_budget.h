/* rt_budget.h - the run's memory budget: the allocations a small input file can make huge
 * (cell-list entries, the frame buffer, outstanding packets) are checked against it before
 * they are made.
 *
 * Usage:
 *   rt_budget b = rt_budget_make(RT_BUDGET_DEFAULT_BYTES);
 *   if (rt_budget_parse("512M", &bytes, msg, sizeof msg) != RT_OK) ...;   // 512 MiB
 *   if (rt_budget_reserve(&b, need, "the frame buffer of 64x64 pixels", msg, sizeof msg)) ...;
 *   uint64_t most = rt_budget_packets_allowed(&b, sizeof(rt_packet));
 *
 * A budget with limit 0 has no limit. Failures are RT_ERR_LIMIT with a message naming what
 * exceeded the budget and by how much ("memory budget exceeded: ...").
 */
#ifndef RT_BUDGET_H
#define RT_BUDGET_H

#include <stddef.h>
#include <stdint.h>

#include "rt_status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* 4 GiB: what every run may take unless told otherwise. */
#define RT_BUDGET_DEFAULT_BYTES (4ull * 1024ull * 1024ull * 1024ull)

typedef struct rt_budget {
    uint64_t limit; /* bytes; 0 = no limit */
    uint64_t used;  /* bytes reserved so far */
} rt_budget;

rt_budget rt_budget_make(uint64_t limit_bytes);

/* Parses a size: a number with an optional binary unit K, M, G or T (also KiB, MB, ...;
 * K = 1024), e.g. "512M", "4G", "1.5G", "1000000"; "0" is no limit. RT_ERR_INVALID with a
 * message otherwise. */
rt_status rt_budget_parse(const char *text, uint64_t *bytes, char *msg, size_t msg_len);

/* Bytes left (UINT64_MAX without a limit). */
uint64_t rt_budget_left(const rt_budget *budget);

/* Reserves `bytes` for `what`; RT_ERR_LIMIT (nothing reserved) if they do not fit. */
rt_status rt_budget_reserve(rt_budget *budget, uint64_t bytes, const char *what, char *msg, size_t msg_len);

/* Writes "memory budget exceeded: WHAT would take NEED, OVER more than the LEFT left of the
 * LIMIT budget (--memory-budget)" and returns RT_ERR_LIMIT. */
rt_status rt_budget_exceeded(const rt_budget *budget, const char *what, uint64_t need, char *msg, size_t msg_len);

/* How many packets of `packet_bytes` each fit in what is left (UINT64_MAX without a limit). */
uint64_t rt_budget_packets_allowed(const rt_budget *budget, uint64_t packet_bytes);

/* The message for `outstanding` packets of `packet_bytes` each that exceed what is left. */
rt_status rt_budget_packets_exceeded(const rt_budget *budget, uint64_t outstanding, uint64_t packet_bytes, char *msg,
                                     size_t msg_len);

/* "512 MiB", "6.0 GiB", "100 bytes": a size for messages. */
const char *rt_budget_format(uint64_t bytes, char *buf, size_t buf_len);

#ifdef __cplusplus
}
#endif
#endif
