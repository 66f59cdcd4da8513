// option_parsing.h - the one parser of the values that options and machine files hold.
// Numbers are decimal only: an integer is digits without a leading zero ("0" itself is one), a
// real is [-]DIGITS[.DIGITS][e[+-]DIGITS]. Octal-looking ("010"), hex ("0x10", "0x1p3"), signs
// on integers, "inf" and "nan" are refused with a message that says "decimal only". Every error
// is a UserError (exit 2) naming the option and quoting the value as shown_text() shows it.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace torusrt {

// User bytes as messages show them: control bytes and backslashes escaped (rt_escape_bytes),
// cut to at most 200 characters with "...".
std::string shown_text(const std::string &bytes);

// A number as messages and machine files write it: the shortest decimal text that reads back
// as the same double ("1000000", "0.0005", "1.0000000000000002").
std::string number_text(double value);

// A decimal integer in [min_value, max_value].
long long parse_integer(const std::string &option, const std::string &text, long long min_value, long long max_value);
// A decimal real in [min_value, max_value] (finite).
double parse_real(const std::string &option, const std::string &text, double min_value, double max_value);

// A time: a decimal real with an optional unit ns, us, ms or s. A bare number is seconds, or,
// for an option whose name carries its unit (--link-us), that unit: `bare_exponent` is the
// bare number's power of ten of a second (0 for s, -6 for us) and `result_exponent` the
// result's. Not negative.
double parse_time(const std::string &option, const std::string &text, int bare_exponent, int result_exponent);
// Whether `text` carries one of the time units.
bool has_time_unit(const std::string &text);

// "P", "PXxPY" or "PXxPYxPZ" (missing dimensions are 1), each in [min_value, max_value].
std::array<int, 3> parse_dims_1_to_3(const std::string &option, const std::string &text, int min_value, int max_value);
// "N" (N x N x N) or "NXxNYxNZ".
std::array<int, 3> parse_triple(const std::string &option, const std::string &text, int min_value, int max_value);
// "WxH", each side 1 to 16384.
std::array<unsigned, 2> parse_size(const std::string &option, const std::string &text);
// A comma-separated list of decimal integers, each in [min_value, max_value]: "0,1,5".
std::vector<int> parse_integer_list(const std::string &option, const std::string &text, int min_value, int max_value);
// A weight: "0.002" or "A/B", not negative.
double parse_fraction(const std::string &option, const std::string &text);
// A memory size: "512M", "4G", "1000000" (bytes); "0" = no limit.
uint64_t parse_memory_size(const std::string &option, const std::string &text);

}  // namespace torusrt
