/* rt_shade_tree.h - the most packets one primary ray's shade tree can make, from the scene's
 * materials alone, and the memory-budget check built on it (run before any rendering).
 *
 * Usage:
 *   double n = rt_shade_tree_packets(scene, params.max_depth, params.min_weight);
 *   if (rt_shade_tree_check(scene, &params, &budget, sizeof(rt_packet), msg, sizeof msg)) ...;
 *
 * Only reflective (Ks > 0) and transparent (T > 0) surfaces make ray packets, so a scene
 * without either makes one ray and one shadow packet per light, at any depth. The bound is the
 * worst case: every ray hits whichever surface makes the most rays below it (weights rounded up
 * to steps of 2^(1/16); without a cut by weight, the largest Ks and T on every hit), and no ray
 * leaves the scene.
 */
#ifndef RT_SHADE_TREE_H
#define RT_SHADE_TREE_H

#include <stddef.h>
#include <stdint.h>

#include "rt_budget.h"
#include "rt_scene.h"
#include "rt_status.h"
#include "rt_step.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Upper bound on the ray and shadow packets one primary ray makes with these pruning limits
 * (rt_step_params); saturates at 1e300. Never fails. */
double rt_shade_tree_packets(const rt_scene *scene, int max_depth, double min_weight);

/* RT_ERR_LIMIT with a message naming --max-depth and --min-weight when the bound, at
 * `packet_bytes` a packet, exceeds what is left of the budget; RT_OK otherwise (always
 * without a limit). */
rt_status rt_shade_tree_check(const rt_scene *scene, const rt_step_params *params, const rt_budget *budget,
                              uint64_t packet_bytes, char *msg, size_t msg_len);

#ifdef __cplusplus
}
#endif
#endif
