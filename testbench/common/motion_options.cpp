// motion_options.cpp - the --motion option and the frame count it gives an animation.
#include "motion_options.h"

#include "option_parsing.h"
#include "user_error.h"

namespace torusrt {

OptionSpec motion_option_spec()
{
    return {"--motion",
            "FILE",
            ValueKind::file,
            "",
            0,
            0,
            "",
            "motion file: moves groups of objects per frame by keyframes (docs/motion-files.md); the "
            "frame count is the file's unless --frames is given",
            OptionGroup::animation,
            ""};
}

void take_motion_frame_count(AnimationOptions &anim, const rt_motion *motion)
{
    if (motion && !anim.orbit.empty() && anim.frames_text.empty())
        anim.frames_text = std::to_string(rt_motion_frame_count(motion));
}

void check_motion_frames(AnimationOptions &anim, const rt_motion *motion, const rt_camera_path *file)
{
    uint32_t n = rt_motion_frame_count(motion);
    if (anim.frames >= 0 && static_cast<uint64_t>(anim.frames) != n)
        throw UserError("--frames " + std::to_string(anim.frames) + ": " + shown_text(anim.motion) + " has " +
                            std::to_string(n) + " frames (leave --frames out to take them)",
                        2);
    if (file && rt_camera_path_count(file) != n)
        throw UserError("--camera-path: " + shown_text(anim.camera_path) + " holds " +
                            std::to_string(rt_camera_path_count(file)) + " camera lines, " + shown_text(anim.motion) +
                            " has " + std::to_string(n) + " frames",
                        2);
    anim.frames = n;
}

}  // namespace torusrt
