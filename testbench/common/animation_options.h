// animation_options.h - the frames of an animation on the command line: --frames, --orbit,
// --camera-path, shared by the executables, and the text of --motion (motion_options.h registers
// it).
#pragma once

#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "kernel_handles.h"  // CameraPathPtr
#include "rt_camera_path.h"
#include "option_spec.h"
#include "rt_scene.h"
#include "stats_json.h"  // camera_pose_json

namespace torusrt {

struct AnimationOptions {
    std::string frames_text;   // --frames as given; empty: not given
    long long frames = -1;     // set by check_animation_options: the number, -1 if not given
    std::string orbit;         // total degrees; empty: not given
    double orbit_degrees = 0;  // set by check_animation_options: --orbit's value
    std::string camera_path;   // file; empty: not given
    std::string motion;        // --motion file; empty: not given
    // Any of them given: the run is an animation and -o is a pattern.
    bool animated() const { return !frames_text.empty() || !orbit.empty() || !camera_path.empty() || !motion.empty(); }
    // --orbit or --camera-path given: the camera moves (else it stays where the scene puts it).
    bool camera_moves() const { return !orbit.empty() || !camera_path.empty(); }
};

// --frames, --orbit and --camera-path (the run's workload, never a machine file's).
std::vector<OptionSpec> animation_option_specs();
// Their texts from the options given (given_options()).
AnimationOptions animation_options_given(const std::map<std::string, std::string> &given);
// Checks the combination before any file is read; throws UserError (exit 2) naming the option.
// --frames N needs --orbit (and --orbit needs --frames); --camera-path gives the frame count
// itself, and --frames beside it must agree. Every frame's orbit angle must be finite. With
// --motion, --frames alone is allowed (motion_options.h checks it against the motion file).
void check_animation_options(AnimationOptions &opt);
// The --camera-path file's poses, read before the scene so that every frame's output can be
// checked first (nullptr for --orbit). A bad file is exit 2 with FILE:LINE, and so is --frames
// disagreeing with it.
CameraPathPtr read_camera_path_file(const AnimationOptions &opt);
// The number of frames: the file's poses, or --frames.
size_t animation_frame_count(const AnimationOptions &opt, const rt_camera_path *file);
// The frames' camera poses: the file's (read_camera_path_file), or the orbit from the scene's
// own camera; nullptr when neither is given (a --motion run: the scene's camera stays).
CameraPathPtr make_camera_path(const AnimationOptions &opt, const rt_scene *scene, CameraPathPtr file);

}  // namespace torusrt
