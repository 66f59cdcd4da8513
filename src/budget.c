/* budget.c - the run's memory budget: parsing sizes, reserving, and the messages. */
#include "rt_budget.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rt_number.h"

rt_budget rt_budget_make(uint64_t limit_bytes)
{
    rt_budget b = {limit_bytes, 0};
    return b;
}

rt_status rt_budget_parse(const char *text, uint64_t *bytes, char *msg, size_t msg_len)
{
    static const struct {
        const char *unit;
        double scale;
    } units[] = {{"", 1.0},
                 {"B", 1.0},
                 {"K", 1024.0},
                 {"KB", 1024.0},
                 {"KiB", 1024.0},
                 {"M", 1048576.0},
                 {"MB", 1048576.0},
                 {"MiB", 1048576.0},
                 {"G", 1073741824.0},
                 {"GB", 1073741824.0},
                 {"GiB", 1073741824.0},
                 {"T", 1099511627776.0},
                 {"TB", 1099511627776.0},
                 {"TiB", 1099511627776.0}};
    const char *p = text ? text : "";
    size_t digits = 0;
    const char *q = p;
    while ((*q >= '0' && *q <= '9') || *q == '.') digits += *q != '.', q++;
    char number[64];
    size_t n = (size_t)(q - p);
    for (size_t i = 0; digits > 0 && n < sizeof number && i < sizeof units / sizeof units[0]; i++) {
        if (strcmp(q, units[i].unit) != 0) continue;
        memcpy(number, p, n);
        number[n] = '\0';
        double v = 0;
        if (rt_number_real(number, n, &v) != RT_NUMBER_OK) break;
        double b = floor(v * units[i].scale);
        if (!(b < 18446744073709551616.0)) break;
        if (b == 0 && v > 0) { /* 0 is no limit: a size under a byte is not taken as one */
            if (msg && msg_len) snprintf(msg, msg_len, "less than one byte (0 means no limit)");
            return RT_ERR_INVALID;
        }
        *bytes = (uint64_t)b;
        return RT_OK;
    }
    if (msg && msg_len)
        snprintf(msg, msg_len,
                 "expected a size in bytes with an optional unit K, M, G or T "
                 "(powers of 1024), e.g. 512M or 4G; 0 = no limit");
    return RT_ERR_INVALID;
}

uint64_t rt_budget_left(const rt_budget *b)
{
    if (!b || b->limit == 0) return UINT64_MAX;
    return b->used >= b->limit ? 0 : b->limit - b->used;
}

const char *rt_budget_format(uint64_t bytes, char *buf, size_t buf_len)
{
    static const char *names[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
    if (bytes < 1024) {
        snprintf(buf, buf_len, "%llu bytes", (unsigned long long)bytes);
        return buf;
    }
    double v = (double)bytes / 1024.0;
    int u = 0;
    while (v >= 1024.0 && u < 5) v /= 1024.0, u++;
    snprintf(buf, buf_len, v < 10.0 ? "%.2f %s" : v < 100.0 ? "%.1f %s" : "%.0f %s", v, names[u]);
    return buf;
}

rt_status rt_budget_exceeded(const rt_budget *b, const char *what, uint64_t need, char *msg, size_t msg_len)
{
    char need_s[32], over_s[32], left_s[32], limit_s[32];
    uint64_t left = rt_budget_left(b);
    if (msg && msg_len)
        snprintf(msg, msg_len,
                 "memory budget exceeded: %s would take %s, %s more than the %s left of the %s budget "
                 "(raise it with --memory-budget)",
                 what, rt_budget_format(need, need_s, sizeof need_s),
                 rt_budget_format(need > left ? need - left : 0, over_s, sizeof over_s),
                 rt_budget_format(left, left_s, sizeof left_s),
                 rt_budget_format(b ? b->limit : 0, limit_s, sizeof limit_s));
    return RT_ERR_LIMIT;
}

rt_status rt_budget_reserve(rt_budget *b, uint64_t bytes, const char *what, char *msg, size_t msg_len)
{
    if (!b || b->limit == 0) return RT_OK;
    if (bytes > rt_budget_left(b)) return rt_budget_exceeded(b, what, bytes, msg, msg_len);
    b->used += bytes;
    return RT_OK;
}

uint64_t rt_budget_packets_allowed(const rt_budget *b, uint64_t packet_bytes)
{
    uint64_t left = rt_budget_left(b);
    if (left == UINT64_MAX || packet_bytes == 0) return UINT64_MAX;
    return left / packet_bytes;
}

rt_status rt_budget_packets_exceeded(const rt_budget *b, uint64_t outstanding, uint64_t packet_bytes, char *msg,
                                     size_t msg_len)
{
    char what[128];
    snprintf(what, sizeof what, "the outstanding packets (%llu of %llu bytes each)", (unsigned long long)outstanding,
             (unsigned long long)packet_bytes);
    uint64_t need =
        outstanding > UINT64_MAX / (packet_bytes ? packet_bytes : 1) ? UINT64_MAX : outstanding * packet_bytes;
    return rt_budget_exceeded(b, what, need, msg, msg_len);
}
