// simulation.h - one invocation of the simulator, from a checked request to the files written:
// every output is staged and checked against the inputs before the scene is read, the scene is
// loaded and mapped, the frames run (run_frames.h), and the image or frames, the statistics and
// the other outputs commit together. The command line only builds the request.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "kernel_handles.h"
#include "remap_policy.h"
#include "scene_motion.h"
#include "sim_config.h"

namespace torusrt {

struct SimRequest {
    SimConfig config;
    // The frames: a single image (frame_count 0), an orbit of frame_count frames turning by
    // orbit_degrees in all about the scene's camera, or camera_file's poses.
    size_t frame_count = 0;
    double orbit_degrees = 0;
    CameraPathPtr camera_file;
    std::string camera_source;  // "orbit", "camera-path" or "scene" (the camera stays), for the report
    // A moving scene (--motion, read and checked against the frame count): the objects move
    // from frame to frame (null: they stay).
    MotionPtr motion;
    std::string motion_path;
    RemapPolicy remap = RemapPolicy::static_map;
    AdaptiveSettings adaptive;
    // The outputs ("" = not written): -o is the image, or an animation's pattern whose frames
    // are frame_files.
    std::string image;
    std::vector<std::string> frame_files;
    std::string stats, load_map, frames_csv;
    std::string stats_series;  // --stats-series, or (with --stats-interval) a name from --stats  // the trace and
                               // --write-map are config.vcd_path, config.write_map
    // Input files (option, path) that no output may replace.
    std::vector<std::pair<std::string, std::string>> inputs;

    bool animated() const { return frame_count > 0; }
};

// Runs the request; returns the exit status: 0, or 3 after a deadlock (the statistics alone
// are written). Throws UserError for bad input or a failed write, leaving no output behind.
int simulate(SimRequest &request, double wall_start_s);

// X.vcd -> X.gtkw; any other name gets ".gtkw" appended.
std::string save_file_path(const std::string &vcd);

}  // namespace torusrt
