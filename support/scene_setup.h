// scene_setup.h - loading a scene file and building its grid, with user-facing messages.
#pragma once

#include <array>
#include <string>

#include "kernel_handles.h"
#include "rt_budget.h"
#include "rt_step.h"
#include "rt_grid.h"

namespace torusrt {

struct LoadedScene {
    ScenePtr scene;
    GridPtr grid;
};

// Loads an NFF file (warnings go to stderr), applies an optional resolution
// override (width/height 0 = keep the file's), reserves the frame buffer in `budget`
// (may be null) and builds a grid with `cells` within what is left of it.
// Throws UserError with "FILE:LINE: message" style text on failure.
// A path as messages show it: control bytes escaped as \xNN.
std::string shown_path(const std::string &path);

LoadedScene load_scene(const std::string &path, unsigned width, unsigned height, const std::array<int, 3> &cells,
                       bool quiet, rt_budget *budget = nullptr, rt_preprocess_count count = RT_COUNT_SEQUENTIAL);

// Refuses (UserError, exit 1) a run whose one pixel's worst-case shade tree, at
// `packet_bytes` a packet, cannot fit in what is left of `budget` (rt_shade_tree.h).
void check_shade_tree(const std::string &path, const rt_scene *scene, const rt_step_params &step,
                      const rt_budget &budget, uint64_t packet_bytes);

}  // namespace torusrt
