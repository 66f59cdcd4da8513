// animation_options.cpp - parsing and checking --frames, --orbit and --camera-path.
#include "animation_options.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "user_error.h"

namespace torusrt {

namespace {

double parse_degrees(const std::string &text)
{
    const char *s = text.c_str();
    char *end = nullptr;
    errno = 0;
    double v = std::strtod(s, &end);
    bool plain = text.find_first_not_of("0123456789+-.eE") == std::string::npos;
    if (!plain || end == s || *end != '\0' || !std::isfinite(v))
        throw UserError("--orbit '" + text + "': expected a finite number of degrees", 2);
    return v;
}

}  // namespace

void add_animation_options(CLI::App &app, AnimationOptions &opt)
{
    app.add_option("--frames", opt.frames_text, "frames of an animation (needs --orbit; 1 to " +
                                               std::to_string(RT_CAMERA_PATH_MAX_FRAMES) + ")")
        ->type_name("N")
        ->configurable(false);  // the frames are the run's workload, never a machine file's
    app.add_option("--orbit", opt.orbit,
                   "turn the eye about 'at' around 'up' by DEG degrees over the frames")
        ->type_name("DEG")
        ->configurable(false);
    app.add_option("--camera-path", opt.camera_path,
                   "camera path file: one 'from at up angle' line (10 numbers) per frame")
        ->type_name("FILE")
        ->configurable(false);
}

void check_animation_options(AnimationOptions &opt)
{
    const long long max = RT_CAMERA_PATH_MAX_FRAMES;
    opt.frames = -1;
    if (!opt.frames_text.empty()) {
        const std::string &t = opt.frames_text;
        bool digits = t.size() <= 7 && t.find_first_not_of("0123456789") == std::string::npos;
        long long n = digits ? std::stoll(t) : 0;
        if (!digits || n < 1 || n > max)
            throw UserError("--frames " + t + ": must be a whole number from 1 to " + std::to_string(max), 2);
        opt.frames = n;
    }
    if (!opt.orbit.empty() && !opt.camera_path.empty())
        throw UserError("--orbit and --camera-path: give one of them, not both", 2);
    if (!opt.orbit.empty()) {
        parse_degrees(opt.orbit);
        if (opt.frames < 0) throw UserError("--orbit " + opt.orbit + ": needs --frames N", 2);
    }
    if (opt.frames >= 0 && opt.orbit.empty() && opt.camera_path.empty())
        throw UserError("--frames " + std::to_string(opt.frames) +
                            ": needs --orbit DEG or --camera-path FILE for the frames' cameras",
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
        throw UserError("--frames " + std::to_string(opt.frames) + ": " + opt.camera_path +
                            " holds " + std::to_string(count) + " camera lines (one per frame)",
                        2);
    return path;
}

size_t animation_frame_count(const AnimationOptions &opt, const rt_camera_path *file)
{
    return file ? rt_camera_path_count(file) : static_cast<size_t>(opt.frames);
}

CameraPathPtr make_camera_path(const AnimationOptions &opt, const rt_scene *scene, CameraPathPtr file)
{
    if (file) return file;
    char msg[RT_MSG_LEN] = "";
    rt_camera_path *raw = nullptr;
    rt_camera_pose start = rt_camera_pose_of(rt_scene_camera(scene));
    if (rt_camera_path_orbit(&start, parse_degrees(opt.orbit), static_cast<uint32_t>(opt.frames), &raw, msg,
                             sizeof msg) != RT_OK)
        throw UserError(std::string("--orbit: ") + msg);
    return CameraPathPtr(raw);
}

}  // namespace torusrt
