/* rt_grid.h - the uniform grid over the object space and its cell lists.
 *
 * Usage:
 *   rt_grid *g = rt_grid_new(scene, 24, 24, 24, msg, sizeof msg);
 *   size_t n; const uint32_t *objs = rt_grid_cell_objects(g, cell, &n);
 *   uint64_t serial = rt_grid_units_serial(g);
 *   rt_grid_free(g);
 *
 * The object space is the bounding box of all objects, padded by 1e-6 of its
 * diagonal on every side. Cell lists are built by the paper's recursive
 * factor subdivision (docs/design.md section 4); one preprocessing unit is one test
 * of an object against one half-space of one plane. Lists hold object
 * indices in increasing order. A scene with no objects gives a grid that no
 * ray enters. rt_grid_new returns NULL (with a message) on bad dimensions
 * (each in 1..RT_GRID_MAX_CELLS_PER_AXIS, product <= RT_GRID_MAX_CELLS) or
 * when memory runs out.
 */
#ifndef RT_GRID_H
#define RT_GRID_H

#include <stddef.h>
#include <stdint.h>

#include "rt_budget.h"
#include "rt_scene.h"

#ifdef __cplusplus
extern "C" {
#endif

#define RT_GRID_MAX_CELLS_PER_AXIS 1024
#define RT_GRID_MAX_CELLS (16u * 1024u * 1024u)

typedef struct rt_grid rt_grid;

/* How preprocessing units are counted while an object's slabs are located on one axis
 * (docs/fidelity.md gives each as an algorithm). The cell lists are the same under each. */
typedef enum rt_preprocess_count {
    RT_COUNT_SEQUENTIAL = 0,     /* one unit per one-sided test: low end, then high end */
    RT_COUNT_PER_PLANE = 1,      /* one unit per plane, placing the extent on both sides */
    RT_COUNT_BOUNDING_SPHERE = 2 /* per-plane on the object's bounding sphere */
} rt_preprocess_count;

rt_grid *rt_grid_new(const rt_scene *scene, int nx, int ny, int nz, char *msg, size_t msg_len);
/* The same within a memory budget (NULL: none): the grid's tables and 8 bytes per cell-list
 * entry are reserved before they are allocated; when the lists would pass what is left,
 * listing stops and NULL comes back with a "memory budget exceeded: ..." message. */
rt_grid *rt_grid_new_budget(const rt_scene *scene, int nx, int ny, int nz, rt_budget *budget, char *msg,
                            size_t msg_len);
/* The same with a counting rule (rt_grid_new_budget counts RT_COUNT_SEQUENTIAL); NULL as
 * rt_grid_new_budget. */
rt_grid *rt_grid_new_counted(const rt_scene *scene, int nx, int ny, int nz, rt_preprocess_count rule, rt_budget *budget,
                             char *msg, size_t msg_len);
/* The same over a given object space: `space` is a box every object lies inside, unpadded (the
 * grid pads it as it pads the scene's own box), e.g. a moving scene's box over all its frames
 * (rt_motion_space); NULL = the scene's own box. NULL as rt_grid_new_budget, and also when an
 * object lies outside `space` ("object N lies outside the given object space"). */
rt_grid *rt_grid_new_in_space(const rt_scene *scene, int nx, int ny, int nz, const rt_box *space,
                              rt_preprocess_count rule, rt_budget *budget, char *msg, size_t msg_len);
void rt_grid_free(rt_grid *grid);

/* What one incremental update (rt_grid_update) did. */
typedef struct rt_grid_update_stats {
    uint64_t objects_moved; /* objects whose lists were recomputed */
    uint64_t units;         /* their half-space tests: the update's preprocessing units */
    uint64_t rebuild_units; /* the units of rebuilding every list from scratch (every object's) */
    uint64_t entries;       /* list entries after the update */
} rt_grid_update_stats;

/* Recomputes the cell lists of the objects flagged in moved[] (one byte per object, nonzero =
 * moved) for their geometry in `scene`, by the paper's subdivision and the grid's counting rule;
 * every other object keeps its entries and its units. The grid then equals one built from
 * scratch over the same object space (rt_grid_new_in_space): the same lists, the same units.
 * Removing a moved object from its old cells costs no unit (its cells were listed when it was
 * placed). `scene` must be the grid's scene with moved geometry: the same object count.
 * Returns RT_ERR_INVALID (grid unchanged) for another object count or a moved object outside
 * the object space, RT_ERR_LIMIT when the lists grow past the budget (may be NULL), or
 * RT_ERR_NOMEM, each with a message; stats may be NULL. */
rt_status rt_grid_update(rt_grid *grid, const rt_scene *scene, const uint8_t *moved, rt_budget *budget,
                         rt_grid_update_stats *stats, char *msg, size_t msg_len);

/* Cells per axis. */
void rt_grid_dims(const rt_grid *grid, int dims[3]);
size_t rt_grid_cell_count(const rt_grid *grid);
/* 1 if the scene had no objects (no ray enters the object space). */
int rt_grid_is_empty(const rt_grid *grid);
/* The padded object space. */
rt_box rt_grid_bounds(const rt_grid *grid);
/* Cell edge lengths, scene units. */
rt_vec3 rt_grid_cell_size(const rt_grid *grid);
/* Box of cell (ix, iy, iz); its faces are the DDA's planes. */
rt_box rt_grid_cell_box(const rt_grid *grid, int ix, int iy, int iz);
/* Linear cell index: ix + nx * (iy + ny * iz). */
static inline uint32_t rt_grid_index(const int dims[3], const int32_t cell[3])
{
    return (uint32_t)cell[0] + (uint32_t)dims[0] * ((uint32_t)cell[1] + (uint32_t)dims[1] * (uint32_t)cell[2]);
}

/* Objects listed in one cell (indices ascending); *count receives the length. */
const uint32_t *rt_grid_cell_objects(const rt_grid *grid, size_t cell, size_t *count);
/* Sum of all list lengths. */
uint64_t rt_grid_list_entries(const rt_grid *grid);

/* Half-space tolerance used by the cell-overlap tests: cells are grown by
 * this many scene units on every side so that rounding never drops a hit. */
double rt_grid_overlap_tolerance(const rt_grid *grid);

/* Preprocessing units of the whole scene on one processor. */
uint64_t rt_grid_units_serial(const rt_grid *grid);
/* Units of one object. */
uint64_t rt_grid_units_of_object(const rt_grid *grid, size_t object);
/* Parallel preprocessing on `processors` (>= 1): objects dealt out in turn
 * (object o to processor o mod P) so each handles the same number; returns
 * the largest per-processor unit count. */
uint64_t rt_grid_units_parallel(const rt_grid *grid, int processors);

#ifdef __cplusplus
}
#endif
#endif
