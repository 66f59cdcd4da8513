/* rt_render.h - the sequential reference renderer: one work queue, one owner for every cell.
 *
 * Usage:
 *   rt_render_options o = rt_render_options_default();
 *   rt_render_stats st;
 *   rt_framebuffer *fb = rt_framebuffer_new(w, h);
 *   if (rt_render(scene, grid, &o, fb, &st, msg, sizeof msg) != RT_OK) ...
 *
 * Pixels are processed in order; each pixel's primary packet and every
 * packet it spawns go through one FIFO queue of packet steps. The image it
 * makes is the golden image for every model run. Returns RT_ERR_NOMEM, or
 * RT_ERR_INVALID if packets were not conserved (a bug, reported loudly).
 */
#ifndef RT_RENDER_H
#define RT_RENDER_H

#include <stddef.h>
#include <stdint.h>

#include "rt_budget.h"
#include "rt_framebuffer.h"
#include "rt_grid.h"
#include "rt_ops.h"
#include "rt_packet.h"
#include "rt_scene.h"
#include "rt_step.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rt_render_options {
    rt_step_params step; /* depth/weight limits, brute force */
    /* Called now and then with pixels done out of total (NULL: not called). */
    void (*progress)(void *ctx, uint64_t done, uint64_t total);
    void *progress_ctx;
    /* Memory budget for the work queue (NULL: none): the queue grows only while its
     * packets fit in what is left; past that rt_render fails with RT_ERR_LIMIT. */
    rt_budget *budget;
    /* NULL (default): one owner for every cell. Else each step runs as the owner of the
     * packet's cell and a handed-over packet is stepped again at once by the next owner,
     * so the step order (and the image) stays that of one owner. */
    const int32_t *cell_owner;
    /* Called after every step with the cell the packet was in (NULL: not called); the
     * load pilot and the cost image attribute each step's ops through it. */
    void (*on_step)(void *ctx, uint32_t cell, const rt_packet *packet, const rt_step_result *result);
    void *on_step_ctx;
} rt_render_options;

typedef struct rt_render_stats {
    rt_op_counts ops;          /* all operations */
    rt_packet_totals packets;  /* packet bookkeeping */
    uint64_t queue_high_water; /* longest the work queue got */
} rt_render_stats;

rt_render_options rt_render_options_default(void);

rt_status rt_render(const rt_scene *scene, const rt_grid *grid, const rt_render_options *options, rt_framebuffer *fb,
                    rt_render_stats *stats, char *msg, size_t msg_len);

#ifdef __cplusplus
}
#endif
#endif
