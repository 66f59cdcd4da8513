// motion_options.h - --motion FILE on the command line of both executables: the option, and the
// frame count it gives an animation (the moving scene itself is support/scene_motion.h).
#pragma once

#include "animation_options.h"
#include "option_spec.h"
#include "rt_camera_path.h"
#include "rt_motion.h"

namespace torusrt {

// The --motion option (group animation).
OptionSpec motion_option_spec();

// With --motion and --orbit but no --frames: the orbit's frame count is the motion file's (before
// check_animation_options, which needs one for --orbit).
void take_motion_frame_count(AnimationOptions &anim, const rt_motion *motion);
// With --motion, after check_animation_options and read_camera_path_file: the frame count is the
// motion file's `frames`; --frames, when given, and a --camera-path's poses must be as many
// (exit 2 otherwise). Sets anim.frames.
void check_motion_frames(AnimationOptions &anim, const rt_motion *motion, const rt_camera_path *file);

}  // namespace torusrt
