/* rt_load_map.h - the load map: what a mapping does to the nodes.
 *
 * Usage:
 *   double node_us[NODES];
 *   rt_node_work(dims, work_us, owner, nodes, node_us);     // work per node
 *   rt_canvas *c = rt_load_map_draw(dims, work_us, owner, nodes);
 *   ... write c (rt_load_map_write in rt_load_image.h writes it as PNG) ... rt_canvas_free(c);
 *
 * The picture has three panels: the cells' work summed along z (a heat map over x and y, axes
 * and colour bar labelled in us, ms or s), the owners of the middle z slice (a colour per node,
 * a line wherever two neighbouring cells have different owners, the node's number in each cell
 * when it fits), and the work per node, sorted from the busiest down, with the mean and the
 * busiest marked and its axis labelled at 0, each quarter of the busiest and the busiest.
 * rt_load_map_draw returns NULL when memory runs out or the grid is empty.
 */
#ifndef RT_LOAD_MAP_H
#define RT_LOAD_MAP_H

#include <stdint.h>

#include "rt_canvas.h"
#include "rt_replicas.h"

#ifdef __cplusplus
extern "C" {
#endif

/* node_us[n] = the work of the cells owner[] gives node n (0 <= n < nodes; other ids ignored). */
void rt_node_work(const int dims[3], const double *work_us, const int32_t *owner, int nodes, double *node_us);

rt_canvas *rt_load_map_draw(const int dims[3], const double *work_us, const int32_t *owner, int nodes);

/* The same with replicated cells (replicas NULL: none): a cell's work is split evenly over its
 * owners in the work per node; a replicated cell of the slice, and a column of the work panel
 * holding one, is crossed by a white diagonal (top left to bottom right, edged in black), and a
 * small line above each of the two panels says so. A caption (NULL: none; printable ASCII, e.g.
 * the scene, machine and mapping) is written across the top, at (4, 4) in scale-2 glyphs. */
void rt_node_work_replicas(const int dims[3], const double *work_us, const int32_t *owner, const rt_replicas *replicas,
                           int nodes, double *node_us);
rt_canvas *rt_load_map_draw_replicas(const int dims[3], const double *work_us, const int32_t *owner,
                                     const rt_replicas *replicas, int nodes, const char *caption);

#ifdef __cplusplus
}
#endif
#endif
