// option_parsing.h - parsers for the option values the executables share.
#pragma once

#include <array>
#include <cstdint>
#include <string>

namespace torusrt {

// "24" -> 24x24x24, "16x8x4" -> 16x8x4. Throws UserError (exit 2) naming `option`.
std::array<int, 3> parse_triple(const std::string &option, const std::string &text, int min_value,
                                int max_value);
// "P", "PXxPY" or "PXxPYxPZ" (missing dimensions are 1).
std::array<int, 3> parse_dims_1_to_3(const std::string &option, const std::string &text,
                                     int min_value, int max_value);
// "WxH".
std::array<unsigned, 2> parse_size(const std::string &option, const std::string &text);
// A non-negative finite number.
double parse_non_negative(const std::string &option, const std::string &text);
// A time in microseconds: "500" (a bare number is microseconds), "500us", "10ms", "1s", "250ns".
double parse_time_us(const std::string &option, const std::string &text);
// A weight: "0.002", "1/512".
double parse_fraction(const std::string &option, const std::string &text);
// A memory size: "512M", "4G", "1000000" (bytes); "0" = no limit.
uint64_t parse_memory_size(const std::string &option, const std::string &text);

}  // namespace torusrt
