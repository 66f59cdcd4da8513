// option_parsing.cpp - parsers for shared option values; every error names its option.
#include "option_parsing.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "rt_budget.h"
#include "user_error.h"

namespace torusrt {

namespace {
[[noreturn]] void bad(const std::string &option, const std::string &text, const std::string &why)
{
    throw UserError(option + " '" + text + "': " + why, 2);
}

bool parse_int(const std::string &s, long &out)
{
    if (s.empty() || s.size() > 9) return false;
    for (char c : s)
        if (c < '0' || c > '9') return false;
    out = std::strtol(s.c_str(), nullptr, 10);
    return true;
}

std::vector<std::string> split_x(const std::string &text)
{
    std::vector<std::string> parts;
    std::string cur;
    for (char c : text) {
        if (c == 'x' || c == 'X') {
            parts.push_back(cur);
            cur.clear();
        } else {
            cur += c;
        }
    }
    parts.push_back(cur);
    return parts;
}

bool parse_double(const std::string &s, double &out)
{
    if (s.empty()) return false;
    char *end = nullptr;
    errno = 0;
    out = std::strtod(s.c_str(), &end);
    return end && *end == '\0' && errno == 0 && std::isfinite(out) &&
           s.find_first_of("xXpPnN") == std::string::npos;
}
}  // namespace

std::array<int, 3> parse_dims_1_to_3(const std::string &option, const std::string &text,
                                     int min_value, int max_value)
{
    auto parts = split_x(text);
    if (parts.size() > 3) bad(option, text, "expected N, NXxNY or NXxNYxNZ");
    std::array<int, 3> out{1, 1, 1};
    for (size_t i = 0; i < parts.size(); i++) {
        long v;
        if (!parse_int(parts[i], v)) bad(option, text, "expected whole numbers like 4x2x2");
        if (v < min_value || v > max_value)
            bad(option, text, "each number must be " + std::to_string(min_value) + " to " + std::to_string(max_value));
        out[i] = static_cast<int>(v);
    }
    return out;
}

std::array<int, 3> parse_triple(const std::string &option, const std::string &text, int min_value,
                                int max_value)
{
    auto parts = split_x(text);
    if (parts.size() == 1) {
        auto one = parse_dims_1_to_3(option, text, min_value, max_value);
        return {one[0], one[0], one[0]};
    }
    if (parts.size() != 3) bad(option, text, "expected N or NXxNYxNZ");
    return parse_dims_1_to_3(option, text, min_value, max_value);
}

std::array<unsigned, 2> parse_size(const std::string &option, const std::string &text)
{
    auto parts = split_x(text);
    long w, h;
    if (parts.size() != 2 || !parse_int(parts[0], w) || !parse_int(parts[1], h))
        bad(option, text, "expected WIDTHxHEIGHT, e.g. 144x144");
    if (w < 1 || h < 1 || w > 16384 || h > 16384) bad(option, text, "each side must be 1 to 16384");
    return {static_cast<unsigned>(w), static_cast<unsigned>(h)};
}

double parse_non_negative(const std::string &option, const std::string &text)
{
    double v;
    if (!parse_double(text, v)) bad(option, text, "expected a number");
    if (v < 0) bad(option, text, "must not be negative");
    return v;
}

double parse_time_us(const std::string &option, const std::string &text)
{
    static const struct { const char *suffix; double us; } units[] = {
        {"ns", 1e-3}, {"us", 1.0}, {"ms", 1e3}, {"s", 1e6}};
    std::string num = text;
    double scale = 1.0;  // a bare number is microseconds
    for (const auto &u : units) {
        std::string suf = u.suffix;
        if (text.size() > suf.size() && text.compare(text.size() - suf.size(), suf.size(), suf) == 0) {
            num = text.substr(0, text.size() - suf.size());
            scale = u.us;
            break;
        }
    }
    double v;
    if (!parse_double(num, v)) bad(option, text, "expected a time: microseconds, or with a unit ns, us, ms or s (e.g. 500us)");
    if (v < 0) bad(option, text, "must not be negative");
    if (!std::isfinite(v * scale)) bad(option, text, "too large");
    return v * scale;
}

double parse_fraction(const std::string &option, const std::string &text)
{
    auto slash = text.find('/');
    double v;
    if (slash == std::string::npos) {
        if (!parse_double(text, v)) bad(option, text, "expected a number like 0.002 or 1/512");
    } else {
        double a, b;
        if (!parse_double(text.substr(0, slash), a) || !parse_double(text.substr(slash + 1), b) || b == 0)
            bad(option, text, "expected a number like 0.002 or 1/512");
        v = a / b;
    }
    if (v < 0) bad(option, text, "must not be negative");
    return v;
}

uint64_t parse_memory_size(const std::string &option, const std::string &text)
{
    uint64_t bytes = 0;
    char msg[RT_MSG_LEN] = "";
    if (rt_budget_parse(text.c_str(), &bytes, msg, sizeof msg) != RT_OK) bad(option, text, msg);
    return bytes;
}

}  // namespace torusrt
