// run_frames.h - the one run path: a machine elaborated once runs its frames one after
// another. A single image is one frame under the scene's own camera; an animation is N frames
// under a camera path's poses (or the scene's camera), each frame starting once the one before
// is complete (every packet consumed) and its migration, if the mapping changes, and a moving
// scene's cell-list update (motion_update.h) are done. The camera, the objects, the cell lists
// and the owner table's contents change only between frames, with the network empty.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "frame_report.h"
#include "remap_policy.h"
#include "run_report.h"
#include "rt_camera_path.h"
#include "scene_motion.h"
#include "sim_config.h"

namespace torusrt {

// What the frames are and how the mapping follows them.
struct FramePlan {
    size_t frames = 0;                     // an animation's frames; 0: a single image
    const rt_camera_path *path = nullptr;  // the frames' poses; null: the scene's camera in every frame
    std::vector<std::string> files;        // each frame's PNG, for the report (an animation)
    RemapPolicy policy = RemapPolicy::static_map;
    AdaptiveSettings adaptive;  // --remap-pilot, --remap-window, --remap-margin
    // A single image's T(1): < 0, this run is T(1) (one processor); else the value and where
    // it came from. An animation's T(1) is the sum of its frames' pilots.
    double t1_s = -1;
    std::string t1_source;

    // A moving scene: frame k > 0 moves its objects and updates `moving_grid`'s lists in place
    // (the grid the run renders, frame 0's already built); null: the objects stay.
    SceneMotion *motion = nullptr;
    rt_grid *moving_grid = nullptr;

    // Takes each frame's 8-bit RGB as the frame completes (an animation writes it to its staged
    // file), so that no frame is kept; null: the images are kept in RunOutcome::images.
    std::function<void(size_t frame, const std::vector<uint8_t> &rgb8)> frame_done;

    // --stats or --frames-csv: every frame's record is written out when the run ends (its JSON
    // or CSV built in memory then), so the budget holds room for that too.
    bool report_frames = false;

    bool animated() const { return frames > 0; }
};

struct RunOutcome {
    bool deadlock = false;                     // the network stalled with packets outstanding
    std::string deadlock_details;              // which queues were full (deadlock_text)
    double sim_time_s = 0;                     // the image time (a deadlock: the time of the stall)
    std::vector<std::vector<uint8_t>> images;  // every completed frame's RGB (none with frame_done)
    std::vector<FrameRecord> frames;           // an animation's frame records
    RunReport report;                          // the statistics, also after a deadlock
    std::string series_csv;                    // --stats-interval's rows ("" without)
};

// Runs `plan`'s frames on `config`'s machine and the loaded scene (an animation leaves the
// scene's camera at its last frame's). A VCD trace, if asked for, is moved to its final name
// only when the run succeeds.
RunOutcome run_frames(const SimConfig &config, rt_scene *scene, const rt_grid *grid, const FramePlan &plan,
                      double wall_start_s);

}  // namespace torusrt
