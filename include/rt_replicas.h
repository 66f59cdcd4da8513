/* rt_replicas.h - cells with several owners: the sparse replica table beside owner[cell].
 *
 * Usage:
 *   rt_replicas r = {first, extra};         // first: cells + 1 offsets, extra: the extra owners
 *   rt_step_params params = rt_step_params_default();
 *   params.replicas = &r;                   // NULL: every cell has its one owner (owner[cell])
 *   if (rt_replicas_holds(&r, owner, cell, node)) ... // node keeps walking the cell
 *
 * owner[cell] stays the primary owner of every cell. A replicated cell has extra owners too:
 * those of cell c are extra[first[c]] .. extra[first[c + 1] - 1], ascending, none equal to
 * owner[c]; first[0] = 0 and first is non-decreasing. A cell with no extra owner costs nothing
 * but its offset; a table with no replicated cell is passed as NULL, and then the kernel does
 * exactly what it does with owner[cell] alone. Every owner of a cell holds the cell's list and
 * the objects it names (rt_memory.h counts the copies).
 *
 * The hash rule of --replica-choice hash spreads the rays entering a replicated cell over its
 * owners by rt_replica_hash(x, y, depth) mod (number of owners), the owners in ascending node
 * order (docs/cell-mappings.md).
 */
#ifndef RT_REPLICAS_H
#define RT_REPLICAS_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Which owner of a replicated cell a packet goes to (--replica-choice; the model applies it). */
typedef enum rt_replica_rule {
    RT_REPLICA_NEAREST = 0, /* the owner fewest hops from the node that hands the packet on */
    RT_REPLICA_HASH = 1     /* the owner rt_replica_hash picks */
} rt_replica_rule;

typedef struct rt_replicas {
    const uint32_t *first; /* per cell, cells + 1 entries: offset of the cell's extra owners in extra */
    const int32_t *extra;  /* extra owners (node ids), ascending within a cell */
} rt_replicas;

/* Extra owners of cell c (0: only its primary owner). r may be NULL. */
static inline uint32_t rt_replicas_extra_count(const rt_replicas *r, uint32_t cell)
{
    return r ? r->first[cell + 1] - r->first[cell] : 0u;
}

/* 1 if `node` owns cell `cell`, as its primary owner or as one of its extra owners. */
static inline int rt_replicas_holds(const rt_replicas *r, const int32_t *owner, uint32_t cell, int32_t node)
{
    if (owner[cell] == node) return 1;
    if (!r) return 0;
    for (uint32_t k = r->first[cell]; k < r->first[cell + 1]; k++)
        if (r->extra[k] == node) return 1;
    return 0;
}

/* The hash of a ray's pixel and depth behind --replica-choice hash (a fixed 32-bit mix:
 * h = x * 0x9E3779B1 + y * 0x85EBCA77 + depth * 0xC2B2AE3D, then h ^= h >> 16,
 * h *= 0x7FEB352D, h ^= h >> 15, h *= 0x846CA68B, h ^= h >> 16, all modulo 2^32). */
uint32_t rt_replica_hash(uint32_t x, uint32_t y, uint32_t depth);

/* Owner number `index` (0 .. extra count) of cell c, the owners in ascending node order. */
int32_t rt_replicas_owner_at(const rt_replicas *r, const int32_t *owner, uint32_t cell, uint32_t index);

/* Cells with extra owners and the extra owners in all (copies beyond the one per cell). */
void rt_replicas_count(const rt_replicas *r, size_t cells, size_t *replicated_cells, size_t *copies);

#ifdef __cplusplus
}
#endif
#endif
