// animation_run.h - an animation in one elaboration: the machine is built once (grid and cell
// lists too) and runs frame after frame. Frame k+1's primaries start once frame k is complete
// (every packet consumed) and its migration, if the mapping changes, has crossed the links; the
// camera and the owner table's contents change only between frames, with the network empty.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "frame_report.h"
#include "remap_policy.h"
#include "run_report.h"
#include "rt_camera_path.h"
#include "sim_config.h"

namespace torusrt {

struct AnimationOutcome {
    bool deadlock = false;
    std::string deadlock_details;
    double sim_time_s = 0;                       // when the network stalled (deadlock)
    std::vector<std::vector<uint8_t>> images;    // every frame's RGB
    std::vector<FrameRecord> frames;
    RunReport report;                            // the run's report, its frames included
};

// Runs every pose of `path` on `config`'s machine; `files` names each frame's PNG (for the
// report). `adaptive` holds adaptive's preview resolution (--remap-pilot), the frames its guesses
// are judged over (--remap-window) and the margin the plain guess keeps (--remap-margin). The
// scene's camera is left at the last frame's.
AnimationOutcome run_animation(const SimConfig &config, rt_scene *scene, const rt_grid *grid,
                               const rt_camera_path *path, const std::vector<std::string> &files,
                               RemapPolicy policy, const AdaptiveSettings &adaptive, double wall_start_s);

}  // namespace torusrt
