/* rt_load_image.h - pictures of the load, written as PNG.
 *
 * Usage:
 *   rt_cost_image_write(fp, "cost.png", w, h, cost_us, msg, sizeof msg);
 *   rt_load_map_write(fp, "load.png", dims, work_us, owner, nodes, msg, sizeof msg);
 *
 * The cost image shows each pixel's modelled microseconds as a heat map (black = 0 to
 * white = the largest) with a labelled colour bar. The load map is rt_load_map_draw's picture
 * (rt_load_map.h): the cells' work, the owners of the middle z slice and the work per node.
 * Both write to a stream the caller owns (rt_png.h; `name` is for messages) and return
 * RT_ERR_IO or RT_ERR_NOMEM with a message.
 */
#ifndef RT_LOAD_IMAGE_H
#define RT_LOAD_IMAGE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "rt_replicas.h"
#include "rt_status.h"

#ifdef __cplusplus
extern "C" {
#endif

rt_status rt_cost_image_write(FILE *fp, const char *name, uint32_t width, uint32_t height, const double *cost_us,
                              char *msg, size_t msg_len);
/* The bytes rt_cost_image_write draws the picture of a width x height image in (its canvas). */
uint64_t rt_cost_image_canvas_bytes(uint32_t width, uint32_t height);

rt_status rt_load_map_write(FILE *fp, const char *name, const int dims[3], const double *work_us, const int32_t *owner,
                            int nodes, char *msg, size_t msg_len);
/* The same with replicated cells marked and a caption across the top (rt_load_map_draw_replicas;
 * replicas NULL: none; caption NULL: none). */
rt_status rt_load_map_write_replicas(FILE *fp, const char *name, const int dims[3], const double *work_us,
                                     const int32_t *owner, const rt_replicas *replicas, int nodes, const char *caption,
                                     char *msg, size_t msg_len);

#ifdef __cplusplus
}
#endif
#endif
