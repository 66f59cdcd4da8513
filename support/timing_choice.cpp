// timing_choice.cpp - profile first, timing file second, so a file overrides single keys.
#include "timing_choice.h"

#include "rt_status.h"
#include "user_error.h"

namespace torusrt {

std::string choose_timing(const std::string &profile, const std::string &file, rt_timing *timing)
{
    std::string name = profile.empty() ? rt_timing_default_profile() : profile;
    char msg[RT_MSG_LEN] = "";
    if (rt_timing_profile(name.c_str(), timing, msg, sizeof msg) != RT_OK)
        throw UserError(std::string("--timing-profile: ") + msg, 2);
    if (file.empty()) return name;
    if (rt_timing_load(file.c_str(), timing, msg, sizeof msg) != RT_OK)
        throw UserError(std::string("--timing: ") + msg);
    return name + " + " + file;
}

}  // namespace torusrt
