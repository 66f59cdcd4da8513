// timing_limits.cpp - bounds on the timing table.
#include "timing_limits.h"

#include <fstream>

#include "option_parsing.h"

namespace torusrt {

std::string timing_limit_problem(const rt_timing &t, std::string *key)
{
    const std::string max = number_text(kMaxTimingUs);
    for (size_t i = 0; i < rt_timing_key_count(); i++) {
        double v = rt_timing_get(&t, i);
        if (v > kMaxTimingUs) {
            if (key) *key = rt_timing_key_name(i);
            return std::string("'") + rt_timing_key_name(i) + "' is " + number_text(v) +
                   "; every timing value must be at most " + max;
        }
    }
    // Rates and widths divide: bound the times they produce.
    double link = rt_timing_link_packet_us(&t), bus = rt_timing_bus_transfer_us(&t, 65536);
    if (link > kMaxTimingUs || bus > kMaxTimingUs) {
        if (key) *key = link > kMaxTimingUs ? "link transfer" : "bus transfer";
        return std::string("a ") + (link > kMaxTimingUs ? "packet's link" : "64 KiB bus") + " transfer takes " +
               number_text(link > kMaxTimingUs ? link : bus) + " us; it must take at most " + max + " us";
    }
    if (link > 0 && link < 1e-6) {  // SystemC counts whole picoseconds: it would round to 0
        if (key) *key = "link transfer";
        return "a packet's link transfer takes " + number_text(link) + " us, below SystemC's time resolution of 1 ps";
    }
    return "";
}

// The line of the timing file `path` that sets `key` (0 if none), so that a value out of range
// is named at its line. The file was read a moment ago (a regular file of at most 1 MiB).
long timing_key_line(const std::string &path, const std::string &key)
{
    std::ifstream in(path);
    std::string text;
    for (long number = 1; std::getline(in, text); number++) {
        size_t start = text.find_first_not_of(" \t\r");
        if (start == std::string::npos) continue;
        size_t end = text.find_first_of(" \t\r=", start);
        if (text.compare(start, end == std::string::npos ? std::string::npos : end - start, key) == 0) return number;
    }
    return 0;
}

}  // namespace torusrt
