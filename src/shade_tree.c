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

/* Bins of weight per halving in the per-material count: a weight is rounded up to the next
 * 2^(-k/16), so the count stays an upper bound. */
#define BINS_PER_HALVING 16
#define MAX_PAIRS 16
#define MAX_WORK 2e8

/* The worst case over the materials, node by node: a node of weight bin k at depth d has
 * 1 + max over materials of its children's counts (rows from the deepest level up). Returns a
 * negative number when the work would be too large (the caller takes the coarser bound). */
static double per_material_rays(const double (*pair)[2], int pairs, int max_depth, double min_weight)
{
    int bins = (int)ceil(-log2(min_weight) * BINS_PER_HALVING) + 1;
    if (bins < 1 || (double)bins * max_depth * pairs > MAX_WORK) return -1.0;
    double *next = calloc((size_t)bins, sizeof *next), *cur = calloc((size_t)bins, sizeof *cur);
    int shift[MAX_PAIRS][2];
    for (int m = 0; m < pairs; m++)
        for (int c = 0; c < 2; c++) /* bins a child falls by (a factor of 0: no child) */
            shift[m][c] = pair[m][c] > 0.0 ? (int)floor(-log2(pair[m][c]) * BINS_PER_HALVING) : -1;
    if (!next || !cur) {
        free(next);
        free(cur);
        return -1.0;
    }
    /* next[] is the level below; at the deepest level every node is a leaf. */
    for (int d = max_depth; d >= 0; d--) {
        for (int k = 0; k < bins; k++) {
            double best = 0.0;
            for (int m = 0; d < max_depth && m < pairs; m++) {
                double sum = 0.0;
                for (int c = 0; c < 2; c++)
                    if (shift[m][c] >= 0 && k + shift[m][c] < bins) sum += next[k + shift[m][c]];
                best = fmax(best, sum);
            }
            cur[k] = fmin(1.0 + best, SATURATED);
        }
        double *t = next;
        next = cur;
        cur = t;
    }
    double rays = next[0];
    free(next);
    free(cur);
    return rays;
}

double rt_shade_tree_packets(const rt_scene *s, int max_depth, double min_weight)
{
    double ks = 0.0, t = 0.0;
    int both = 0, pairs = 0, all_below_one = 1;
    double pair[MAX_PAIRS][2];
    for (size_t i = 0; i < s->object_count; i++) {
        const rt_material *m = &s->materials[s->objects[i].material];
        double mk = m->ks > 0.0 ? m->ks : 0.0, mt = m->t > 0.0 ? m->t : 0.0;
        if (mk == 0.0 && mt == 0.0) continue;
        ks = fmax(ks, mk);
        t = fmax(t, mt);
        both |= mk > 0.0 && mt > 0.0;
        all_below_one &= mk < 1.0 && mt < 1.0;
        int seen = 0;
        for (int p = 0; p < pairs && !seen; p++) seen = pair[p][0] == mk && pair[p][1] == mt;
        if (!seen && pairs < MAX_PAIRS) {
            pair[pairs][0] = mk;
            pair[pairs][1] = mt;
        }
        if (!seen) pairs++;
    }
    double rays = 1.0;
    if (max_depth > 0 && (ks > 0.0 || t > 0.0)) {
        rays = -1.0;
        /* Weights that only fall, a cut by weight and few kinds of surface: node by node. */
        if (all_below_one && min_weight > 0.0 && pairs <= MAX_PAIRS)
            rays = per_material_rays((const double(*)[2])pair, pairs, max_depth, min_weight);
        if (rays < 0.0)
            rays = both ? tree_rays(ks, t, max_depth, min_weight) : tree_rays(fmax(ks, t), 0.0, max_depth, min_weight);
    }
    /* Every ray that hits sends one shadow packet per light at most. */
    return fmin(rays * (1.0 + (double)s->light_count), SATURATED);
}

rt_status rt_shade_tree_check(const rt_scene *s, const rt_step_params *params, const rt_budget *budget,
                              uint64_t packet_bytes, char *msg, size_t msg_len)
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
