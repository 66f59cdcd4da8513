// timing_choice.h - the timing table a run uses: a built-in profile, then a timing file on top.
#pragma once

#include <string>

#include "rt_timing.h"

namespace torusrt {

// Fills *timing from `profile` ("" = the default profile), then applies `file` ("" = none).
// Returns the label reports carry: the profile name, with " + FILE" when a file was loaded, and
// "OTHER = " before them when the table loaded is the built-in profile OTHER's
// ("fitted = calibrated + machines/timing/fitted.timing").
// Throws UserError: exit 2 for an unknown profile, 1 for a bad file (message names file and line).
std::string choose_timing(const std::string &profile, const std::string &file, rt_timing *timing);

}  // namespace torusrt
