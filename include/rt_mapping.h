/* rt_mapping.h - which processor owns which cell.
 *
 * Usage:
 *   int32_t *owner = malloc(cells * sizeof *owner);
 *   rt_mapping_fill(dims, procs, RT_MAP_CYCLIC, 0, owner, msg, sizeof msg);
 *
 * Processors form a PX x PY x PZ array (id = px + PX * (py + PY * pz)); each
 * axis is mapped on its own: block gives processor floor(c * P / N) (even
 * when P does not divide N), cyclic gives c mod P, block-cyclic with block
 * size B gives (c / B) mod P. Returns RT_ERR_INVALID for P < 1 or B < 1.
 * More processors than cells along an axis is allowed: the extra
 * processors own no cells. These are the axis-wise mappings; the model's
 * others (a map file, the cost mappings) make tables of their own.
 */
#ifndef RT_MAPPING_H
#define RT_MAPPING_H

#include <stddef.h>
#include <stdint.h>

#include "rt_status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum rt_map_kind {
    RT_MAP_BLOCK = 0,       /* contiguous blocks (paper Fig. 2a) */
    RT_MAP_CYCLIC = 1,      /* interleaved, load-balancing (paper Fig. 2b) */
    RT_MAP_BLOCK_CYCLIC = 2 /* blocks of B cells dealt cyclically */
} rt_map_kind;

/* Owner of cell index c along one axis of N cells over P processors. */
int rt_mapping_axis_owner(rt_map_kind kind, int block, int c, int cells, int procs);

/* Fills owner[cell] for every cell (linear index as rt_grid_index). */
rt_status rt_mapping_fill(const int cells[3], const int procs[3], rt_map_kind kind, int block, int32_t *owner,
                          char *msg, size_t msg_len);

#ifdef __cplusplus
}
#endif
#endif
