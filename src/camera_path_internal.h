/* camera_path_internal.h - the camera path's storage, shared by its two sources (kernel internal). */
#ifndef RT_CAMERA_PATH_INTERNAL_H
#define RT_CAMERA_PATH_INTERNAL_H

#include <stddef.h>

#include "rt_camera_path.h"

struct rt_camera_path {
    rt_camera_pose *poses; /* count poses, frame 0 first */
    size_t count;
};

/* A path of `count` zeroed poses; RT_ERR_NOMEM. */
rt_status camera_path_new(size_t count, rt_camera_path **out);

#endif
