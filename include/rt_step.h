/* rt_step.h - the packet step: what one intersection processor does with one packet.
 *
 * Usage:
 *   rt_step_result r;
 *   rt_step_result_init(&r, scene);
 *   rt_step(scene, grid, owner, my_id, &params, &packet, &r);
 *   // r.ops: what it cost; r.contrib: frame-buffer writes; r.created: new packets
 *   // r.fate: absorbed, left, or forwarded (packet updated to its next cell)
 *
 * The packet walks the cells owned by my_id (cell_owner NULL: every cell; with
 * params.replicas, the cells it holds as primary or extra owner),
 * testing each cell's objects. A ray hit is accepted in a cell only if it
 * lies within the cell's t-interval, so the nearest hit equals that of
 * testing every object (params.brute_force does exactly that, ignoring
 * the grid). On a hit the step shades (docs/design.md section 3) and creates shadow,
 * reflected and transmitted packets. Secondary rays start off the surface
 * by RT_SURFACE_OFFSET x max(|P|, |origin|, t) along the geometric normal
 * (outside for reflection and shadows, inside for transmission; off a `pp`
 * triangle on the side of its plane each ray heads for). Returns
 * RT_ERR_CAPACITY if a buffer is too small (nothing is then done).
 */
#ifndef RT_STEP_H
#define RT_STEP_H

#include <stddef.h>
#include <stdint.h>

#include "rt_grid.h"
#include "rt_ops.h"
#include "rt_packet.h"
#include "rt_replicas.h"
#include "rt_scene.h"
#include "rt_status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Most packets one step creates: a shadow per light, a reflection and a transmission. */
#define RT_STEP_MAX_CREATED(lights) ((size_t)(lights) + 2u)

typedef struct rt_step_params {
    int max_depth;     /* deepest shade-tree depth a new ray packet may have (default 8) */
    double min_weight; /* smallest largest-channel weight of a new ray packet (default 1/512) */
    int brute_force;   /* 1: test every object once, ignore the grid (the oracle) */
    /* Called for every intersection test with the object's index (NULL: not called);
     * the cluster model uses it to charge remote object reads. */
    void (*on_test)(void *ctx, uint32_t object);
    void *on_test_ctx;
    /* Extra owners of replicated cells (NULL: each cell has only cell_owner[cell]); a packet
     * keeps walking while my_id holds its cell, as primary or extra owner (rt_replicas.h). */
    const rt_replicas *replicas;
} rt_step_params;

/* Defaults: max_depth 8, min_weight 1/512, grid traversal, no callback, no replicas. */
rt_step_params rt_step_params_default(void);

typedef enum rt_fate {
    RT_FATE_ABSORBED = 0, /* hit an object, was blocked, or (shadow) reached its light */
    RT_FATE_LEFT = 1,     /* left the object space */
    RT_FATE_FORWARDED = 2 /* next cell belongs to another owner: send the packet on */
} rt_fate;

typedef struct rt_contribution {
    uint32_t x, y; /* pixel */
    rt_vec3 rgb;   /* linear colour to add */
} rt_contribution;

typedef struct rt_step_result {
    rt_op_counts ops;         /* operations performed by this step */
    rt_contribution *contrib; /* frame-buffer contributions of this step (buffer) */
    size_t contrib_count;
    size_t contrib_capacity;
    rt_packet *created; /* new packets, each with the cell it starts in (buffer) */
    size_t created_count;
    size_t created_capacity;
    rt_fate fate;       /* what became of the input packet */
    uint32_t next_cell; /* forwarded: linear index of the cell it goes to */
} rt_step_result;

/* Most contributions one step makes: ambient, plus every new packet whose
 * ray never meets the object space (its light or background is added at once). */
#define RT_STEP_MAX_CONTRIB(lights) ((size_t)(lights) + 3u)

/* Allocates both buffers with enough room for any step in `scene`.
 * Returns RT_ERR_NOMEM on failure (the result is then empty). */
rt_status rt_step_result_init(rt_step_result *result, const rt_scene *scene);
void rt_step_result_release(rt_step_result *result);

/* Relative distance secondary rays start off the surface: 2^-32, about
 * 10^6 times the rounding error of a hit point, and 2^-32 of an object a
 * million times smaller than the scene. */
#define RT_SURFACE_OFFSET (1.0 / 4294967296.0)

/* Performs one step. ops, contrib_count and created_count in *out are
 * reset first. The packet is updated in place when forwarded. */
rt_status rt_step(const rt_scene *scene, const rt_grid *grid, const int32_t *cell_owner, int32_t my_id,
                  const rt_step_params *params, rt_packet *packet, rt_step_result *out);

/* Linear index of the cell a packet is in. */
uint32_t rt_packet_cell(const rt_grid *grid, const rt_packet *packet);

#ifdef __cplusplus
}
#endif
#endif
