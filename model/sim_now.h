// sim_now.h - the simulation time, read inline: sc_core::sc_time_stamp() is an out-of-line
// library call, while the current context and its time are inline accessors of the kernel's
// public header, and the model reads the time many times a hop.
#pragma once

#include <systemc>

namespace torusrt {

inline const sc_core::sc_time &sim_now() { return sc_core::sc_get_curr_simcontext()->time_stamp(); }

}  // namespace torusrt
