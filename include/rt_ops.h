/* rt_ops.h - operation counts: what an intersection processor did.
 *
 * Usage:
 *   rt_op_counts total = {0};
 *   rt_ops_add(&total, &step_result.ops);
 *
 * Each field counts one kind of operation of the paper's timing table; the
 * model multiplies them by rt_timing to get time. Cannot fail.
 */
#ifndef RT_OPS_H
#define RT_OPS_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rt_op_counts {
    uint64_t tests_missed;       /* ray-object tests that found no intersection */
    uint64_t tests_hit;          /* ray-object tests that found an intersection at t > 0 */
    uint64_t dda_steps;          /* next-cell determinations (moves, and start cells of new packets) */
    uint64_t shadings;           /* luminance computations, one per accepted ray hit */
    uint64_t reflection_vectors; /* reflection directions computed */
    uint64_t refraction_vectors; /* transmission directions computed */
    uint64_t packets_analysed;   /* new packets taken up: primaries and packets made at a hit */
    uint64_t packets_created;    /* new packets made at a hit */
    uint64_t fb_writes;          /* frame-buffer contributions */
    uint64_t handovers_sent;     /* packets handed on to the next cell's owner */
    uint64_t handovers_received; /* packets taken up after another IP handed them over */
    uint64_t cell_steps;         /* moves of a packet into its next cell inside the object space */
} rt_op_counts;

static inline void rt_ops_add(rt_op_counts *sum, const rt_op_counts *add)
{
    sum->tests_missed += add->tests_missed;
    sum->tests_hit += add->tests_hit;
    sum->dda_steps += add->dda_steps;
    sum->shadings += add->shadings;
    sum->reflection_vectors += add->reflection_vectors;
    sum->refraction_vectors += add->refraction_vectors;
    sum->packets_analysed += add->packets_analysed;
    sum->packets_created += add->packets_created;
    sum->fb_writes += add->fb_writes;
    sum->handovers_sent += add->handovers_sent;
    sum->handovers_received += add->handovers_received;
    sum->cell_steps += add->cell_steps;
}

#ifdef __cplusplus
}
#endif
#endif
