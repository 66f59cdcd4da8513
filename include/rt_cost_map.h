/* rt_cost_map.h - measured load and a cost-driven mapping of cells onto the nodes' topology.
 *
 * Usage:
 *   rt_cost_pilot pilot;
 *   rt_cost_pilot_run(scene, grid, &params, &timing, &pilot, msg, sizeof msg);
 *   rt_cost_map(&pilot, &topo, rt_cost_edge_us(&timing), owner, &facts, msg, sizeof msg);
 *   rt_cost_pilot_release(&pilot);
 *
 * The pilot is the reference renderer with every cell its own owner: each step
 * then covers one cell, so its ops (times the timing table, hand-overs
 * excluded) are that cell's work, and each hand-over is a packet crossing the
 * face between two neighbouring cells. The image is that of the renderer.
 *
 * The mapper builds the cell graph (vertex weight = work, edge weight = the
 * packets crossing the face both ways times the cost of one hand-over, both
 * scaled to integers with empty cells and quiet faces weighing 1) and maps it
 * with Scotch (SCOTCH_graphMap) onto the nodes' topology (rt_topology.h),
 * balancing work while keeping traffic few hops long. Scotch's random
 * generator is reset to a fixed seed first, so the mapping is reproducible.
 * Failures return RT_ERR_INVALID / RT_ERR_NOMEM / RT_ERR_LIMIT with a
 * message naming the Scotch call that failed.
 */
#ifndef RT_COST_MAP_H
#define RT_COST_MAP_H

#include <stddef.h>
#include <stdint.h>

#include "rt_grid.h"
#include "rt_memory.h"
#include "rt_replicas.h"
#include "rt_ops.h"
#include "rt_scene.h"
#include "rt_status.h"
#include "rt_step.h"
#include "rt_timing.h"
#include "rt_topology.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Faces of a cell, in this order: -x, +x, -y, +y, -z, +z. */
#define RT_CELL_FACES 6

/* The part of one cell's work that one object caused (rt_cost_pilot_run_by_object). */
typedef struct rt_object_cell_us {
    uint32_t object;
    uint32_t cell;
    double us;
} rt_object_cell_us;

typedef struct rt_cost_pilot {
    int dims[3]; /* grid cells per axis */
    size_t cells;
    double *work_us;   /* per cell: modelled microseconds, hand-overs excluded */
    uint64_t *traffic; /* per cell and face: packets leaving the cell through it */
    double total_us;   /* sum of work_us: T(1) of the pilot image without hand-overs */
    rt_op_counts ops;  /* everything the pilot did, hand-overs between cells included */
    /* NULL (count 0) unless run by object: the work of each (object, cell) pair with any, by
     * object then cell; their sum over a cell is at most the cell's work_us. */
    rt_object_cell_us *object_us;
    size_t object_us_count;
} rt_cost_pilot;

rt_status rt_cost_pilot_run(const rt_scene *scene, const rt_grid *grid, const rt_step_params *params,
                            const rt_timing *timing, rt_cost_pilot *out, char *msg, size_t msg_len);

/* rt_cost_pilot_run that also counts each object's work (object_us): a step's work beyond its
 * next-cell determinations (tests, shading, new packets: what the objects it met cost) is
 * shared by the objects it tested, in proportion to their tests; a step that tested none keeps
 * it in the cell alone. A moving object's work can then move with it (adaptive's `objects`
 * guess, docs/frames.md). params->on_test is replaced during the run. */
rt_status rt_cost_pilot_run_by_object(const rt_scene *scene, const rt_grid *grid, const rt_step_params *params,
                                      const rt_timing *timing, rt_cost_pilot *out, char *msg, size_t msg_len);
void rt_cost_pilot_release(rt_cost_pilot *pilot);

/* Bytes a pilot on `grid` (with `objects` objects) holds while it runs at the scene camera's
 * WIDTH x HEIGHT: its per-cell tables, its frame buffer and, by object, its per-entry counts.
 * A memory budget checks them before the pilot starts. */
uint64_t rt_cost_pilot_bytes(const rt_grid *grid, size_t objects, uint32_t width, uint32_t height, int by_object);

/* Bytes the Scotch mapping (rt_cost_map, rt_cost_map_folded, rt_cost_remap) of `cells` cells
 * holds at most besides the pilot: the cell graph with its weights, the part tables, and as much
 * again for Scotch's coarser graphs. */
uint64_t rt_cost_map_bytes(size_t cells);

/* Bytes rt_cost_map_scatter holds for `cells` cells, one piece a cell (a cut cell's further
 * pieces are within --replicate's budget of the nodes' memory). */
uint64_t rt_cost_scatter_bytes(size_t cells);

/* Microseconds one packet handed across a face costs: send + receive + link. */
double rt_cost_edge_us(const rt_timing *timing);

typedef struct rt_cost_map_facts {
    double max_node_work_us;  /* the busiest node's work under the mapping */
    double mean_node_work_us; /* total work / nodes */
    double cut_packets;       /* packets crossing between different nodes */
    double cut_hops;          /* those packets times the hops between their nodes */
} rt_cost_map_facts;

/* Fills owner[cell] with the topology's node ids; facts' hops are its hops. facts may be NULL. */
rt_status rt_cost_map(const rt_cost_pilot *pilot, const rt_topology *topo, double edge_us, int32_t *owner,
                      rt_cost_map_facts *facts, char *msg, size_t msg_len);

/* The same mapped onto a machine `fold` times larger along every axis of more than one node,
 * each of its terminals then folded onto a node (torus and mesh: x mod PX, y mod PY, z mod PZ;
 * docs/topologies.md): every node gets fold^d balanced pieces spread over the grid (work interleaved in time, as cyclic
 * does), each piece's neighbours on neighbouring nodes. fold 1 is rt_cost_map; 1..64. */
rt_status rt_cost_map_folded(const rt_cost_pilot *pilot, const rt_topology *topo, double edge_us, int fold,
                             int32_t *owner, rt_cost_map_facts *facts, char *msg, size_t msg_len);

/* A remapping from `old_owner` (SCOTCH_graphRemap): the same graph, each cell also weighing
 * move_us[cell], the microseconds moving it to another node costs, against keeping it on its
 * old node (migration ratio 1, in the edge weights' units). Node ids as rt_cost_map's. */
rt_status rt_cost_remap(const rt_cost_pilot *pilot, const rt_topology *topo, double edge_us, const int32_t *old_owner,
                        const double *move_us, int32_t *owner, rt_cost_map_facts *facts, char *msg, size_t msg_len);

/* Copies of the hottest cells on more nodes (docs/cell-mappings.md#replicated-cells), on top of
 * the one-owner table `owner` of the nodes of `topo` (nearest: by its hops). Each node
 * may add `fraction` times its data under `owner` (rt_memory_per_owner_layout with `layout`,
 * NULL: the default). The prediction gives each owner a share of the cell's work by `rule`:
 * hash an even split; nearest the part of the pilot's packets entering the cell through its
 * faces that the rule sends to it (from the neighbouring cell's owner), evenly when none enter.
 * Greedy: the busiest node's hottest cell (its largest share) gets one more owner, the node that
 * leaves the busiest of the cell's owners least loaded and has room (ties: the lowest node), if
 * all of them end below the busiest node's load; a cell no copy helps is left alone, and the
 * rounds stop when no cell of the busiest node helps.
 * Fills first[0 .. cells] and sets *extra to a malloc'd array of *extra_count extra owners
 * (free() it; rt_replicas.h's layout); facts->max_node_work_us (facts may be NULL) becomes the
 * predicted busiest node's work. fraction 0 gives no copies. RT_ERR_INVALID on bad arguments,
 * RT_ERR_LIMIT when nodes x objects marks exceed 2^31 bits, RT_ERR_NOMEM; *extra is NULL then. */
rt_status rt_cost_replicate(const rt_cost_pilot *pilot, const rt_scene *scene, const rt_grid *grid,
                            const rt_topology *topo, rt_replica_rule rule, const int32_t *owner, double fraction,
                            const rt_memory_layout *layout, uint32_t *first, int32_t **extra, size_t *extra_count,
                            rt_cost_map_facts *facts, char *msg, size_t msg_len);

/* The balanced scatter behind --map scatter (docs/cell-mappings.md#scatter): the cells, hottest
 * first (equal work: in cell order), each dealt to the node with the least work so far (ties: the
 * fewest cells, then the lowest node), neighbours not kept together. With fraction > 0 every
 * cell whose work is above half the mean node work is first cut into ceil(work / (mean / 2))
 * equal pieces (at most one per node), dealt the same way to as many different nodes (the first
 * piece's node is the primary owner); then, round by round, each node whose copies take more
 * than `fraction` times its data without them (rt_memory_per_owner_layout with `layout`, NULL:
 * the default) drops its smallest copy and the pieces are dealt again, that cell cut once less,
 * until no node is over. Fills owner[cells], first[0 .. cells] and *extra
 * (malloc'd, *extra_count extra owners, rt_replicas.h's layout; free() it); facts (may be NULL):
 * the predicted busiest node with each cell's work split evenly over its owners, and the pilot's
 * packets the primary table cuts. RT_ERR_INVALID on bad arguments, RT_ERR_NOMEM. */
rt_status rt_cost_map_scatter(const rt_cost_pilot *pilot, const rt_scene *scene, const rt_grid *grid,
                              const rt_topology *topo, double fraction, const rt_memory_layout *layout, int32_t *owner,
                              uint32_t *first, int32_t **extra, size_t *extra_count, rt_cost_map_facts *facts,
                              char *msg, size_t msg_len);

#ifdef __cplusplus
}
#endif
#endif
