/* rt_motion.h - scene motion: groups of objects moved per frame by keyframes (a motion file).
 *
 * Usage:
 *   rt_motion *m = NULL;
 *   if (rt_motion_load("balls.motion", &m, msg, sizeof msg) != RT_OK) ...   // "FILE:LINE: ..."
 *   rt_box space;
 *   if (rt_motion_space(m, scene, &space, msg, sizeof msg) != RT_OK) ...     // checks every frame
 *   rt_grid *g = rt_grid_new_in_space(frame_scene, nx, ny, nz, &space, rule, budget, msg, len);
 *   rt_scene *frame_scene = rt_scene_clone(scene);
 *   for (uint32_t k = 0; k < rt_motion_frame_count(m); k++) {
 *       rt_motion_apply(m, scene, frame_scene, k, moved);   // moved[o] = 1: o changed
 *       ... k == 0 ? build the grid : rt_grid_update(g, frame_scene, moved, ...); render
 *   }
 *   rt_motion_free(m);
 *
 * The format (docs/motion-files.md), one statement a line, `#` to the end of a line a comment:
 *   frames N                        frames of the animation (optional: else last key + 1)
 *   objects FIRST [LAST]            starts an entry: scene objects FIRST..LAST, 0-based, in the
 *                                   order the scene adds them (a `pp` of n vertices is n - 2)
 *   pivot X Y Z                     the entry's centre of rotation and scale (default 0 0 0)
 *   axis X Y Z                      the entry's rotation axis (needed by a non-zero turn)
 *   key FRAME [move X Y Z] [turn DEGREES] [scale S]
 *                                   a keyframe; parts not given are the identity
 * Frame k moves each point p of an entry's objects to pivot + S R(axis, DEGREES) (p - pivot) +
 * move, with move, DEGREES and S interpolated linearly between the keys around k (held before
 * the first key and after the last). The transform applies to the scene file's geometry, not
 * to the previous frame's. Every function returns RT_OK or an error status with a message
 * ("FILE:LINE: message" where a line is at fault).
 */
#ifndef RT_MOTION_H
#define RT_MOTION_H

#include <stddef.h>
#include <stdint.h>

#include "rt_scene.h"
#include "rt_status.h"
#include "rt_vec.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Documented limits: more is rejected with RT_ERR_LIMIT (sizes) or RT_ERR_PARSE (values). */
#define RT_MOTION_MAX_BYTES (16u * 1024u * 1024u) /* file size */
#define RT_MOTION_MAX_LINE 4096u                  /* bytes of one line */
#define RT_MOTION_MAX_FRAMES 100000u              /* the `frames` count */
#define RT_MOTION_MAX_KEY_FRAME 1000000u          /* a key's frame number */
#define RT_MOTION_MAX_ENTRIES 100000u             /* `objects` lines */
#define RT_MOTION_MAX_KEYS 1000000u               /* `key` lines in all */
#define RT_MOTION_MIN_SCALE 1e-6                  /* a key's scale: within [1e-6, 1e6] */
#define RT_MOTION_MAX_SCALE 1e6
#define RT_MOTION_MAX_TURN 1e6 /* |degrees| of a key's turn */

typedef struct rt_motion rt_motion;

/* One entry as the file gave it. */
typedef struct rt_motion_entry_info {
    size_t line;          /* the `objects` line, 1-based */
    uint32_t first, last; /* object indices, 0-based, inclusive */
    size_t keys;          /* its keyframes */
} rt_motion_entry_info;

/* Reads a motion file (rt_file_read.h: a regular text file of at most RT_MOTION_MAX_BYTES).
 * RT_ERR_IO, RT_ERR_PARSE, RT_ERR_LIMIT or RT_ERR_NOMEM with "FILE:LINE: message". */
rt_status rt_motion_load(const char *file, rt_motion **out, char *msg, size_t msg_len);
/* The same on text in memory (`name` is the file name messages show); a NUL or other control
 * byte than tab is refused as binary data. */
rt_status rt_motion_parse(const char *name, const char *text, size_t length, rt_motion **out, char *msg,
                          size_t msg_len);
void rt_motion_free(rt_motion *motion);

/* Frames of the animation: the `frames` line, or the last key's frame + 1. */
uint32_t rt_motion_frame_count(const rt_motion *motion);
size_t rt_motion_entry_count(const rt_motion *motion);
rt_motion_entry_info rt_motion_entry(const rt_motion *motion, size_t index);

/* Checks the motion against the scene it moves and gives the bounding box of every object
 * over every frame (0 .. frames - 1), unpadded: the object space of the animation (an empty
 * box, lo > hi, when no object has bounds). RT_ERR_PARSE with "FILE:LINE: ..." (the entry's
 * `objects` line) when an entry names objects the scene does not have, or when some frame
 * would move an object past 1e30 in magnitude or shrink a sphere to radius 0. */
rt_status rt_motion_space(const rt_motion *motion, const rt_scene *scene, rt_box *space, char *msg, size_t msg_len);

/* Gives the objects of `frame_scene` (an rt_scene_clone of `scene`, at any frame so far) their
 * geometry at `frame`, computed from `scene`'s. moved (NULL, or one byte per object) gets 1
 * for each object whose geometry changed, 0 for the others. RT_ERR_INVALID (a message) when
 * the scenes' object counts differ or an entry names objects past them; a motion that passed
 * rt_motion_space on `scene` never fails otherwise. */
rt_status rt_motion_apply(const rt_motion *motion, const rt_scene *scene, rt_scene *frame_scene, uint32_t frame,
                          uint8_t *moved, char *msg, size_t msg_len);

/* What entry `index` matched, for a message: "FILE:LINE: objects 0-3 (4 spheres), 3 keys". */
void rt_motion_describe(const rt_motion *motion, const rt_scene *scene, size_t index, char *buf, size_t buf_len);

#ifdef __cplusplus
}
#endif
#endif
