// timing_choice.cpp - profile first, timing file second, so a file overrides single keys.
#include "timing_choice.h"

#include "rt_status.h"
#include "user_error.h"

namespace torusrt {

namespace {

// The built-in profile whose table is `timing`, key for key; "" if none is.
std::string profile_equal_to(const rt_timing &timing)
{
    for (size_t p = 0; p < rt_timing_profile_count(); p++) {
        rt_timing named;
        if (rt_timing_profile(rt_timing_profile_name(p), &named, nullptr, 0) != RT_OK) continue;
        bool same = true;
        for (size_t k = 0; same && k < rt_timing_key_count(); k++)
            same = rt_timing_get(&named, k) == rt_timing_get(&timing, k);
        if (same) return rt_timing_profile_name(p);
    }
    return "";
}

}  // namespace

std::string choose_timing(const std::string &profile, const std::string &file, rt_timing *timing)
{
    std::string name = profile.empty() ? rt_timing_default_profile() : profile;
    char msg[RT_MSG_LEN] = "";
    if (rt_timing_profile(name.c_str(), timing, msg, sizeof msg) != RT_OK)
        throw UserError(std::string("--timing-profile: ") + msg, 2);
    if (file.empty()) return name;
    if (rt_timing_load(file.c_str(), timing, msg, sizeof msg) != RT_OK)
        throw UserError(std::string("--timing: ") + msg);
    // A file that sets the table of another profile names it, as the docs speak of that profile.
    std::string equal = profile_equal_to(*timing);
    return (equal.empty() || equal == name ? "" : equal + " = ") + name + " + " + file;
}

}  // namespace torusrt
