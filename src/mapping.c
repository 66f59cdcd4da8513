/* mapping.c - which processor owns which cell (block, cyclic, block-cyclic). */
#include <stdint.h>
#include <stdio.h>

#include "rt_mapping.h"

/* -1 for arguments outside the documented ranges (P < 1, B < 1 for
 * block-cyclic, c outside 0..N-1, unknown kind). */
int rt_mapping_axis_owner(rt_map_kind kind, int block, int c, int cells, int procs)
{
    if (procs < 1 || cells < 1 || c < 0 || c >= cells) return -1;
    switch (kind) {
    case RT_MAP_BLOCK:
        /* 64-bit product: c * P overflows int for large grids and arrays. */
        return (int)(((int64_t)c * procs) / cells);
    case RT_MAP_CYCLIC: return c % procs;
    case RT_MAP_BLOCK_CYCLIC:
        if (block < 1) return -1;
        return (c / block) % procs;
    }
    return -1;
}

rt_status rt_mapping_fill(const int cells[3], const int procs[3], rt_map_kind kind, int block, int32_t *owner,
                          char *msg, size_t msg_len)
{
    if (kind != RT_MAP_BLOCK && kind != RT_MAP_CYCLIC && kind != RT_MAP_BLOCK_CYCLIC) {
        if (msg && msg_len) snprintf(msg, msg_len, "unknown mapping kind %d", (int)kind);
        return RT_ERR_INVALID;
    }
    if (procs[0] < 1 || procs[1] < 1 || procs[2] < 1) {
        if (msg && msg_len)
            snprintf(msg, msg_len, "processors %dx%dx%d: each axis needs at least 1", procs[0], procs[1], procs[2]);
        return RT_ERR_INVALID;
    }
    if ((int64_t)procs[0] * procs[1] * procs[2] > INT32_MAX) {
        if (msg && msg_len)
            snprintf(msg, msg_len, "processors %dx%dx%d: more than %ld in all", procs[0], procs[1], procs[2],
                     (long)INT32_MAX);
        return RT_ERR_INVALID;
    }
    if (cells[0] < 1 || cells[1] < 1 || cells[2] < 1) {
        if (msg && msg_len)
            snprintf(msg, msg_len, "cells %dx%dx%d: each axis needs at least 1", cells[0], cells[1], cells[2]);
        return RT_ERR_INVALID;
    }
    if (kind == RT_MAP_BLOCK_CYCLIC && block < 1) {
        if (msg && msg_len) snprintf(msg, msg_len, "block size %d: needs at least 1", block);
        return RT_ERR_INVALID;
    }
    if (!owner) {
        if (msg && msg_len) snprintf(msg, msg_len, "no owner array given");
        return RT_ERR_INVALID;
    }
    size_t i = 0;
    for (int z = 0; z < cells[2]; z++) {
        int32_t pz = rt_mapping_axis_owner(kind, block, z, cells[2], procs[2]);
        for (int y = 0; y < cells[1]; y++) {
            int32_t py = rt_mapping_axis_owner(kind, block, y, cells[1], procs[1]);
            for (int x = 0; x < cells[0]; x++) {
                int32_t px = rt_mapping_axis_owner(kind, block, x, cells[0], procs[0]);
                owner[i++] = px + procs[0] * (py + procs[1] * pz);
            }
        }
    }
    return RT_OK;
}
