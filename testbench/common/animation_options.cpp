// animation_options.cpp - parsing and checking --frames, --orbit and --camera-path.
#include "animation_options.h"

#include <cmath>

#include "option_parsing.h"
#include "user_error.h"

namespace torusrt {

namespace {

double parse_degrees(const std::string &text) { return parse_real("--orbit", text, -HUGE_VAL, HUGE_VAL); }

}  // namespace

std::vector<OptionSpec> animation_option_specs()
{
    using G = OptionGroup;
    using K = ValueKind;
    return {
        {"--frames", "N", K::integer, "", 1, RT_CAMERA_PATH_MAX_FRAMES, "",
         "frames of an animation (with --orbit; 1 to " + std::to_string(RT_CAMERA_PATH_MAX_FRAMES) + ")", G::animation,
         ""},
        {"--orbit", "DEG", K::real, "", 0, 0, "", "turn the eye about 'at' around 'up' by DEG degrees over the frames",
         G::animation, ""},
        {"--camera-path", "FILE", K::file, "", 0, 0, "",
         "camera path file: one 'from at up angle' line (10 numbers) per frame", G::animation, ""},
    };
}

AnimationOptions animation_options_given(const std::map<std::string, std::string> &given)
{
    AnimationOptions opt;
    auto take = [&given](const char *name, std::string &field) {
        auto it = given.find(name);
        if (it != given.end()) field = it->second;
    };
    take("--frames", opt.frames_text);
    take("--orbit", opt.orbit);
    take("--camera-path", opt.camera_path);
    take("--motion", opt.motion);
    return opt;
}

void check_animation_options(AnimationOptions &opt)
{
    const long long max = RT_CAMERA_PATH_MAX_FRAMES;
    opt.frames = -1;
    if (!opt.frames_text.empty()) {
        try {
            opt.frames = parse_integer("--frames", opt.frames_text, 1, max);
        } catch (const UserError &e) {  // "--frames 0: ..." as the option was typed
            throw UserError("--frames " + shown_text(opt.frames_text) + ": must be a whole decimal number from 1 to " +
                                std::to_string(max) + " (" + e.what() + ")",
                            2);
        }
    }
    if (!opt.orbit.empty() && !opt.camera_path.empty())
        throw UserError("--orbit and --camera-path: give one of them, not both", 2);
    if (!opt.orbit.empty()) {
        double degrees = parse_degrees(opt.orbit);
        opt.orbit_degrees = degrees;
        if (opt.frames < 0) throw UserError("--orbit " + shown_text(opt.orbit) + ": needs --frames N", 2);
        // Frame k turns by k x DEG / N degrees: the product must stay finite for the last frame.
        if (!std::isfinite(static_cast<double>(opt.frames - 1) * degrees))
            throw UserError("--orbit " + shown_text(opt.orbit) + ": the last frame's angle (" +
                                std::to_string(opt.frames - 1) + " x DEG / " + std::to_string(opt.frames) +
                                ") would not be a finite number",
                            2);
    }
    if (opt.frames >= 0 && opt.orbit.empty() && opt.camera_path.empty() && opt.motion.empty())
        throw UserError("--frames " + std::to_string(opt.frames) +
                            ": needs --orbit DEG or --camera-path FILE for the frames' cameras (or --motion FILE)",
                        2);
}

CameraPathPtr read_camera_path_file(const AnimationOptions &opt)
{
    if (opt.camera_path.empty()) return nullptr;
    char msg[RT_MSG_LEN] = "";
    rt_camera_path *raw = nullptr;
    // A camera path, like a --map-file, is part of the command line: a bad one is exit 2.
    if (rt_camera_path_load(opt.camera_path.c_str(), &raw, msg, sizeof msg) != RT_OK)
        throw UserError(std::string("--camera-path: ") + msg, 2);
    CameraPathPtr path(raw);
    size_t count = rt_camera_path_count(raw);
    if (opt.frames >= 0 && static_cast<size_t>(opt.frames) != count)
        throw UserError("--frames " + std::to_string(opt.frames) + ": " + shown_text(opt.camera_path) + " holds " +
                            std::to_string(count) + " camera lines (one per frame)",
                        2);
    return path;
}

size_t animation_frame_count(const AnimationOptions &opt, const rt_camera_path *file)
{
    return file ? rt_camera_path_count(file) : static_cast<size_t>(opt.frames);
}

CameraPathPtr make_camera_path(const AnimationOptions &opt, const rt_scene *scene, CameraPathPtr file)
{
    if (file || opt.orbit.empty()) return file;
    char msg[RT_MSG_LEN] = "";
    rt_camera_path *raw = nullptr;
    rt_camera_pose start = rt_camera_pose_of(rt_scene_camera(scene));
    if (rt_camera_path_orbit(&start, parse_degrees(opt.orbit), static_cast<uint32_t>(opt.frames), &raw, msg,
                             sizeof msg) != RT_OK)
        throw UserError(std::string("--orbit: ") + msg);
    return CameraPathPtr(raw);
}

}  // namespace torusrt
