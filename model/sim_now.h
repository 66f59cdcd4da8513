// sim_now.h - the simulation time, read inline: the current context's time_stamp() is an inline
// accessor of the kernel's public header, where sc_core::sc_time_stamp() (IEEE 1666) is an
// out-of-line library call, and the model reads the time many times a hop. Measured with
// callgrind inside sc_start (LTO, paper-image1-planar 64x64, --ips 8x8x8, --timing-profile
// calibrated): 251,076,186 instructions this way, 262,564,849 (+4.6 %) through sc_time_stamp().
#pragma once

#include <systemc>

namespace torusrt {

inline const sc_core::sc_time &sim_now() { return sc_core::sc_get_curr_simcontext()->time_stamp(); }

}  // namespace torusrt
