/* shade_tree.c - the worst-case size of one pixel's shade tree, from the materials. */
#include "rt_shade_tree.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "scene_internal.h"

#define SATURATED 1e300

/* Rays of a tree whose every node branches into weights x a and x b (b = 0: one branch),
 * from a root of weight 1, with depth <= max_depth and weight >= min_weight. */
static double tree_rays(double a, double b, int max_depth, double min_weight)
{
    /* A node of depth d with i factors a has weight a^i b^(d-i); rounding aside, the step
     * keeps it when that is >= min_weight, so a relative slack keeps the bound above it. */
    double floor_w = min_weight > 0.0 ? log(min_weight) - 1e-9 : -INFINITY;
    double la = log(a), lb = b > 0.0 ? log(b) : -INFINITY;
    double rays = 1.0;
    if (!(b > 0.0)) {
        for (int d = 1; d <= max_depth && d * la >= floor_w; d++) rays += 1.0;
        return rays;
    }
    /* C(d, i) nodes of depth d have i factors a: Pascal's triangle, row by row (exact while
     * below 2^53; C(1000, 500) is 2.7e299). */
    double *row = malloc(((size_t)max_depth + 2) * sizeof *row);
    if (!row) return SATURATED; /* no memory to count with: assume the worst */
    row[0] = 1.0;
    for (int d = 1; d <= max_depth && rays < SATURATED; d++) {
        row[d] = 1.0;
        for (int i = d - 1; i > 0; i--) row[i] = fmin(row[i] + row[i - 1], SATURATED);
        double level = 0.0;
        for (int i = 0; i <= d; i++)
            if (i * la + (d - i) * lb >= floor_w) level += row[i];
        if (level == 0.0) break;
        rays += level;
    }
    free(row);
    return fmin(rays, SATURATED);
}

double rt_shade_tree_packets(const rt_scene *s, int max_depth, double min_weight)
{
    double ks = 0.0, t = 0.0;
    int both = 0;
    for (size_t i = 0; i < s->object_count; i++) {
        const rt_material *m = &s->materials[s->objects[i].material];
        if (m->ks > 0.0) ks = fmax(ks, m->ks);
        if (m->t > 0.0) t = fmax(t, m->t);
        both |= m->ks > 0.0 && m->t > 0.0;
    }
    double rays = 1.0;
    if (max_depth > 0 && (ks > 0.0 || t > 0.0))
        rays = both ? tree_rays(ks, t, max_depth, min_weight)
                    : tree_rays(fmax(ks, t), 0.0, max_depth, min_weight);
    /* Every ray that hits sends one shadow packet per light at most. */
    return fmin(rays * (1.0 + (double)s->light_count), SATURATED);
}

rt_status rt_shade_tree_check(const rt_scene *s, const rt_step_params *params,
                              const rt_budget *budget, uint64_t packet_bytes, char *msg,
                              size_t msg_len)
{
    if (!budget || budget->limit == 0) return RT_OK;
    double packets = rt_shade_tree_packets(s, params->max_depth, params->min_weight);
    double need = packets * (double)packet_bytes;
    uint64_t left = rt_budget_left(budget);
    if (need <= (double)left) return RT_OK;
    char left_s[32], limit_s[32], count_s[40];
    snprintf(count_s, sizeof count_s, packets >= SATURATED ? "more than %.0e" : "%.3g", packets);
    if (msg && msg_len)
        snprintf(msg, msg_len,
                 "memory budget exceeded: one pixel's shade tree may hold %s packets of %llu "
                 "bytes with --max-depth %d and --min-weight %g on this scene's reflective and "
                 "transparent surfaces, more than the %s left of the %s budget; lower "
                 "--max-depth, raise --min-weight or raise --memory-budget",
                 count_s, (unsigned long long)packet_bytes, params->max_depth, params->min_weight,
                 rt_budget_format(left, left_s, sizeof left_s),
                 rt_budget_format(budget->limit, limit_s, sizeof limit_s));
    return RT_ERR_LIMIT;
}
