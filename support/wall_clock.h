// wall_clock.h - wall-clock seconds on a steady clock, for the wall times the reports give.
#pragma once

#include <chrono>

namespace torusrt {

inline double wall_clock_s()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace torusrt
