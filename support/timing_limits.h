// timing_limits.h - the largest timing values a run accepts, so that no single delay and no
// image time can overflow (SystemC's time is a 64-bit count of picoseconds, about 1.8e7 s).
#pragma once

#include <string>

#include "rt_timing.h"

namespace torusrt {

// The most any one operation, link transfer or bus transfer may take, in microseconds (1 s).
constexpr double kMaxTimingUs = RT_TIMING_MAX_VALUE;

// "" if every value of `timing` is within the limits, else a message naming the first key
// that is not (the packet size is bounded by kMaxTimingUs bytes too). `key`, if given, is set
// to that key, or to "link transfer" / "bus transfer" for a time the rates and widths make.
std::string timing_limit_problem(const rt_timing &timing, std::string *key = nullptr);

// The line of the timing file `path` that sets `key` (0 if none): a value out of range is named
// at its line ("FILE:LINE: ...").
long timing_key_line(const std::string &path, const std::string &key);

}  // namespace torusrt
