/* motion_internal.h - a motion's storage, shared by motion_file.c (reading) and motion.c
 * (applying). Kernel-internal. */
#ifndef RT_MOTION_INTERNAL_H
#define RT_MOTION_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "rt_motion.h"

typedef struct rt_motion_key {
    uint32_t frame; /* frame number */
    rt_vec3 move;   /* translation, scene units */
    double turn;    /* rotation about the entry's axis through its pivot, degrees */
    double scale;   /* uniform scale about the pivot, > 0 */
} rt_motion_key;

typedef struct motion_entry {
    size_t line;                  /* the `objects` line */
    uint32_t first, last;         /* objects, inclusive */
    rt_vec3 pivot;                /* centre of rotation and scale */
    rt_vec3 axis;                 /* unit rotation axis (0 0 0: none given) */
    size_t pivot_line, axis_line; /* 0: not given */
    rt_motion_key *keys;          /* frames strictly increasing */
    size_t key_count, key_capacity;
} motion_entry;

struct rt_motion {
    char *file; /* the name messages show */
    uint32_t frames;
    motion_entry *entries;
    size_t entry_count, entry_capacity;
};

#endif
