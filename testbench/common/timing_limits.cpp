// timing_limits.cpp - bounds on the timing table.
#include "timing_limits.h"

#include <cstdio>

namespace torusrt {

std::string timing_limit_problem(const rt_timing &t, std::string *key)
{
    char buf[200];
    for (size_t i = 0; i < rt_timing_key_count(); i++) {
        double v = rt_timing_get(&t, i);
        if (v > kMaxTimingUs) {
            std::snprintf(buf, sizeof buf, "'%s' is %g; every timing value must be at most %g", rt_timing_key_name(i),
                          v, kMaxTimingUs);
            if (key) *key = rt_timing_key_name(i);
            return buf;
        }
    }
    // Rates and widths divide: bound the times they produce.
    double link = rt_timing_link_packet_us(&t), bus = rt_timing_bus_transfer_us(&t, 65536);
    if (link > kMaxTimingUs || bus > kMaxTimingUs) {
        std::snprintf(buf, sizeof buf, "a %s transfer takes %g us; it must take at most %g us",
                      link > kMaxTimingUs ? "packet's link" : "64 KiB bus", link > kMaxTimingUs ? link : bus,
                      kMaxTimingUs);
        if (key) *key = link > kMaxTimingUs ? "link transfer" : "bus transfer";
        return buf;
    }
    if (link > 0 && link < 1e-6) {  // SystemC counts whole picoseconds: it would round to 0
        std::snprintf(buf, sizeof buf, "a packet's link transfer takes %g us, below SystemC's time resolution of 1 ps",
                      link);
        if (key) *key = "link transfer";
        return buf;
    }
    return "";
}

}  // namespace torusrt
