// kernel_handles.h - owning C++ handles for the kernel's C objects.
#pragma once

#include <memory>

#include "rt_camera_path.h"
#include "rt_framebuffer.h"
#include "rt_grid.h"
#include "rt_scene.h"

namespace torusrt {

struct SceneDeleter {
    void operator()(rt_scene *s) const { rt_scene_free(s); }
};
struct GridDeleter {
    void operator()(rt_grid *g) const { rt_grid_free(g); }
};
struct CameraPathDeleter {
    void operator()(rt_camera_path *p) const { rt_camera_path_free(p); }
};
struct FramebufferDeleter {
    void operator()(rt_framebuffer *f) const { rt_framebuffer_free(f); }
};

using ScenePtr = std::unique_ptr<rt_scene, SceneDeleter>;
using GridPtr = std::unique_ptr<rt_grid, GridDeleter>;
using CameraPathPtr = std::unique_ptr<rt_camera_path, CameraPathDeleter>;
using FramebufferPtr = std::unique_ptr<rt_framebuffer, FramebufferDeleter>;

}  // namespace torusrt
