/* rt_camera_path.h - camera paths: one camera pose per frame of an animation.
 *
 * Usage:
 *   rt_camera_pose start = rt_camera_pose_of(rt_scene_camera(scene));
 *   rt_camera_path *path = NULL;
 *   if (rt_camera_path_orbit(&start, 360.0, 32, &path, msg, sizeof msg) != RT_OK) ...
 *   // or: rt_camera_path_load("path.txt", &path, msg, sizeof msg)
 *   for (size_t k = 0; k < rt_camera_path_count(path); k++) {
 *       rt_scene_set_camera(scene, rt_camera_path_pose(path, k), msg, sizeof msg);
 *       ... render with the grid built once: the object space does not depend on the camera
 *   }
 *   rt_camera_path_free(path);
 *
 * Orbit: the eye turns about the `at` point around the `up` axis (right-handed) by `degrees`
 * in total; frame k is turned by k * degrees / frames, so frame 0 is the start pose unchanged
 * and a full 360-degree orbit ends one step before the start (frame `frames` would repeat
 * frame 0: the sequence loops without a doubled frame). `up` is the rotation axis and is kept
 * as it is, so the angle between the view direction and `up` never changes and the view never
 * flips. Turns that are whole multiples of 90 degrees use exact sines and cosines.
 *
 * Camera path file: one frame per line, ten numbers
 *   from_x from_y from_z at_x at_y at_z up_x up_y up_z angle
 * `#` starts a comment to the end of the line; blank lines are allowed; "\n", "\r\n" and a
 * lone "\r" end a line. Errors are
 * "FILE:LINE: message": wrong field count, a malformed or non-finite number, a magnitude above
 * 1e30, from == at, up zero or parallel to the view direction, angle outside (0, 180), a line
 * longer than RT_CAMERA_PATH_MAX_LINE bytes, more than RT_CAMERA_PATH_MAX_FRAMES frames, no
 * frame at all. The file is read as every input is (rt_file_read.h): a regular text file of
 * at most RT_CAMERA_PATH_MAX_BYTES.
 */
#ifndef RT_CAMERA_PATH_H
#define RT_CAMERA_PATH_H

#include <stddef.h>
#include <stdint.h>

#include "rt_scene.h"
#include "rt_status.h"
#include "rt_vec.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Documented limits: more frames or a longer line is rejected with RT_ERR_LIMIT. */
#define RT_CAMERA_PATH_MAX_FRAMES 100000u
#define RT_CAMERA_PATH_MAX_LINE 4096u
#define RT_CAMERA_PATH_MAX_BYTES (64u * 1024u * 1024u)

typedef struct rt_camera_pose {
    rt_vec3 from; /* eye position, scene units */
    rt_vec3 at;   /* point looked at */
    rt_vec3 up;   /* up hint (need not be unit or orthogonal) */
    double angle; /* degrees, as in the NFF `v` block */
} rt_camera_pose;

typedef struct rt_camera_path rt_camera_path;

/* The pose part of a scene's camera (the resolution is not part of a pose). */
rt_camera_pose rt_camera_pose_of(const rt_camera *camera);

/* RT_OK if the pose makes a camera: finite numbers, from != at, up not zero nor parallel to
 * the view direction, angle in (0, 180). Otherwise RT_ERR_INVALID and a message (no prefix). */
rt_status rt_camera_pose_check(const rt_camera_pose *pose, char *msg, size_t msg_len);

/* Frame k of an orbit of `degrees` over `frames` frames (see above); k < frames. */
rt_camera_pose rt_camera_orbit_pose(const rt_camera_pose *start, double degrees, uint32_t frames, uint32_t k);

/* An orbit path of `frames` poses. RT_ERR_INVALID for frames 0 or above the limit, a
 * non-finite `degrees` or a bad start pose; RT_ERR_NOMEM. */
rt_status rt_camera_path_orbit(const rt_camera_pose *start, double degrees, uint32_t frames, rt_camera_path **out,
                               char *msg, size_t msg_len);

/* Reads a camera path file (format above). RT_ERR_IO, RT_ERR_PARSE, RT_ERR_LIMIT or
 * RT_ERR_NOMEM with a message naming the file (and the line where one is at fault). */
rt_status rt_camera_path_load(const char *file, rt_camera_path **out, char *msg, size_t msg_len);

size_t rt_camera_path_count(const rt_camera_path *path);
const rt_camera_pose *rt_camera_path_pose(const rt_camera_path *path, size_t k);
void rt_camera_path_free(rt_camera_path *path);

/* Replaces the scene's camera pose, keeping its resolution. RT_ERR_INVALID (and a message) if
 * the pose fails rt_camera_pose_check; the scene is then unchanged. */
rt_status rt_scene_set_camera(rt_scene *scene, const rt_camera_pose *pose, char *msg, size_t msg_len);

#ifdef __cplusplus
}
#endif
#endif
