// option_parsing.cpp - the one parser of option and machine-file values; every error names its
// option and quotes the value escaped.
#include "option_parsing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "rt_budget.h"
#include "rt_number.h"
#include "rt_text.h"
#include "user_error.h"

namespace torusrt {

namespace {

constexpr size_t kShownChars = 200;

[[noreturn]] void bad(const std::string &option, const std::string &text, const std::string &why)
{
    throw UserError(option + " '" + shown_text(text) + "': " + why, 2);
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Why `text` is not a decimal number ("" if it may be one): octal-looking and hex forms are
// named, as old scripts may hold them.
std::string not_decimal(const std::string &text)
{
    size_t i = text[0] == '-' ? 1 : 0;
    if (text.size() > i + 1 && text[i] == '0' && (text[i + 1] == 'x' || text[i + 1] == 'X'))
        return "decimal only (hexadecimal is not accepted)";
    if (text.size() > i + 1 && text[i] == '0' && is_digit(text[i + 1])) {
        size_t first = text.find_first_not_of('0', i);  // the value without its leading zeros
        // One zero kept before a point or an exponent, or where only zeros follow ("00": "0").
        if (first == std::string::npos || !is_digit(text[first]))
            first = (first == std::string::npos ? text.size() : first) - 1;
        std::string plain = text.substr(0, i) + text.substr(first);
        return "decimal only (a leading zero could be read as octal: write '" + shown_text(plain) + "')";
    }
    return "";
}

// The kernel's one decimal syntax (rt_number.h) decides; the messages name the option.
double read_real(const std::string &option, const std::string &text)
{
    double v = 0;
    switch (rt_number_real(text.data(), text.size(), &v)) {
    case RT_NUMBER_OK: return v == 0 ? 0.0 : v;  // -0 is 0 (and is written so in a dump)
    case RT_NUMBER_HEX:
    case RT_NUMBER_LEADING_ZERO: bad(option, text, not_decimal(text));
    case RT_NUMBER_TOO_LARGE: bad(option, text, "too large");
    case RT_NUMBER_UNDERFLOW: bad(option, text, "too close to 0 for a double (it would read as 0)");
    case RT_NUMBER_SYNTAX: break;
    }
    bad(option, text, "expected a decimal number such as 2, 0.5 or 1e-3");
}

// Whether `text` has the syntax of a real (its value aside).
bool real_syntax(const std::string &text)
{
    double v = 0;
    rt_number_fault f = rt_number_real(text.data(), text.size(), &v);
    return f != RT_NUMBER_SYNTAX && f != RT_NUMBER_HEX && f != RT_NUMBER_LEADING_ZERO;
}

std::vector<std::string> split(const std::string &text, char sep)
{
    std::vector<std::string> parts;
    size_t pos = 0;
    for (;;) {
        size_t next = text.find(sep, pos);
        parts.push_back(text.substr(pos, next == std::string::npos ? std::string::npos : next - pos));
        if (next == std::string::npos) return parts;
        pos = next + 1;
    }
}

std::string range_text(double lo, double hi) { return number_text(lo) + " to " + number_text(hi); }

}  // namespace

std::string shown_text(const std::string &bytes)
{
    // Each byte takes at most 4 characters escaped; the buffer ends the text with "..." at 200.
    std::string buf(kShownChars + 1, '\0');
    rt_escape_bytes(bytes.data(), bytes.size(), 0, &buf[0], buf.size());
    buf.resize(std::char_traits<char>::length(buf.c_str()));
    return buf;
}

std::string number_text(double v)
{
    char buf[40];
    for (int digits = 1; digits <= 17; digits++) {
        std::snprintf(buf, sizeof buf, "%.*g", digits, v);
        if (std::strtod(buf, nullptr) == v) break;
    }
    // Integral values below 2^53 are written whole: 1000000, not 1e+06.
    if (std::isfinite(v) && std::fabs(v) < 9007199254740992.0 && v == std::floor(v))
        std::snprintf(buf, sizeof buf, "%.0f", v);
    return buf;
}

long long parse_integer(const std::string &option, const std::string &text, long long min_value, long long max_value)
{
    const std::string range = "must be " + std::to_string(min_value) + " to " + std::to_string(max_value);
    if (text.empty()) bad(option, text, "expected a whole number");
    unsigned long long v = 0;
    switch (rt_number_whole(text.data(), text.size(), static_cast<unsigned long long>(std::max(max_value, 0LL)), &v)) {
    case RT_NUMBER_OK: break;
    case RT_NUMBER_HEX:
    case RT_NUMBER_LEADING_ZERO: bad(option, text, not_decimal(text));
    case RT_NUMBER_TOO_LARGE: bad(option, text, range);
    default:
        bad(option, text,
            not_decimal(text).empty() ? "expected a whole decimal number (digits only)" : not_decimal(text));
    }
    if (static_cast<long long>(v) < min_value) bad(option, text, range);
    return static_cast<long long>(v);
}

double parse_real(const std::string &option, const std::string &text, double min_value, double max_value)
{
    double v = read_real(option, text);
    if (v < min_value && min_value == 0) bad(option, text, "must not be negative");
    if (v < min_value || v > max_value) {
        if (!std::isfinite(max_value)) bad(option, text, "must be at least " + number_text(min_value));
        bad(option, text, "must be " + range_text(min_value, max_value));
    }
    return v;
}

namespace {

struct TimeUnitSuffix {
    const char *suffix;
    int exponent;  // power of ten of a second
};
constexpr TimeUnitSuffix kTimeUnits[] = {{"ns", -9}, {"us", -6}, {"ms", -3}, {"s", 0}};

const TimeUnitSuffix *time_unit_of(const std::string &text)
{
    for (const auto &u : kTimeUnits) {
        std::string suf = u.suffix;
        if (text.size() > suf.size() && text.compare(text.size() - suf.size(), suf.size(), suf) == 0) return &u;
    }
    return nullptr;
}

}  // namespace

bool has_time_unit(const std::string &text) { return time_unit_of(text) != nullptr; }

double parse_time(const std::string &option, const std::string &text, int bare_exponent, int result_exponent)
{
    const TimeUnitSuffix *unit = time_unit_of(text);
    std::string num = unit ? text.substr(0, text.size() - std::char_traits<char>::length(unit->suffix)) : text;
    int shift = (unit ? unit->exponent : bare_exponent) - result_exponent;
    const char *bare = bare_exponent == 0 ? "seconds" : "microseconds";
    if (num.empty() || (!real_syntax(num) && not_decimal(num).empty()))
        bad(option, text,
            std::string("expected a time: a decimal number of ") + bare +
                ", or with a unit ns, us, ms or s (e.g. 500us)");
    double v = read_real(option, num);
    if (v < 0) bad(option, text, "must not be negative");
    // Whole powers of ten multiply or divide exactly once: "10ms" is 10000 us, "500us" 0.0005 s.
    double scale = std::pow(10.0, std::abs(shift));
    double t = shift >= 0 ? v * scale : v / scale;
    if (!std::isfinite(t)) bad(option, text, "too large");
    return t;
}

std::array<int, 3> parse_dims_1_to_3(const std::string &option, const std::string &text, int min_value, int max_value)
{
    std::string lower = text;
    for (char &c : lower) c = c == 'X' ? 'x' : c;
    if (lower.rfind("0x", 0) == 0 && lower.size() > 2 && lower.find('x', 2) == std::string::npos)
        bad(option, text, "decimal only (hexadecimal is not accepted)");
    auto parts = split(lower, 'x');
    if (parts.size() > 3) bad(option, text, "expected N, NXxNY or NXxNYxNZ");
    std::array<int, 3> out{1, 1, 1};
    for (size_t i = 0; i < parts.size(); i++) {
        if (parts[i].empty()) bad(option, text, "expected whole numbers like 4x2x2");
        out[i] = static_cast<int>(parse_integer(option, parts[i], min_value, max_value));
    }
    return out;
}

std::array<int, 3> parse_triple(const std::string &option, const std::string &text, int min_value, int max_value)
{
    auto dims = parse_dims_1_to_3(option, text, min_value, max_value);
    size_t xs = 0;
    for (char c : text) xs += c == 'x' || c == 'X';
    if (xs == 0) return {dims[0], dims[0], dims[0]};
    if (xs != 2) bad(option, text, "expected N or NXxNYxNZ");
    return dims;
}

std::array<unsigned, 2> parse_size(const std::string &option, const std::string &text)
{
    std::string lower = text;
    for (char &c : lower) c = c == 'X' ? 'x' : c;
    auto parts = split(lower, 'x');
    if (parts.size() != 2 || parts[0].empty() || parts[1].empty())
        bad(option, text, "expected WIDTHxHEIGHT, e.g. 144x144");
    try {
        return {static_cast<unsigned>(parse_integer(option, parts[0], 1, 16384)),
                static_cast<unsigned>(parse_integer(option, parts[1], 1, 16384))};
    } catch (const UserError &) {
        std::string why = not_decimal(parts[0]).empty() ? not_decimal(parts[1]) : not_decimal(parts[0]);
        bad(option, text,
            "expected WIDTHxHEIGHT, each side a decimal number 1 to 16384 (e.g. 144x144)" +
                (why.empty() ? std::string() : ": " + why));
    }
}

std::vector<int> parse_integer_list(const std::string &option, const std::string &text, int min_value, int max_value)
{
    std::vector<int> out;
    for (const std::string &item : split(text, ',')) {
        if (item.empty()) bad(option, text, "expected decimal numbers separated by commas, e.g. 0,1,5");
        out.push_back(static_cast<int>(parse_integer(option, item, min_value, max_value)));
    }
    return out;
}

double parse_fraction(const std::string &option, const std::string &text)
{
    auto slash = text.find('/');
    if (slash == std::string::npos) return parse_real(option, text, 0, HUGE_VAL);
    double a = parse_real(option, text.substr(0, slash), 0, HUGE_VAL);
    double b = parse_real(option, text.substr(slash + 1), 0, HUGE_VAL);
    if (b == 0) bad(option, text, "the divisor must not be 0");
    return a / b;
}

uint64_t parse_memory_size(const std::string &option, const std::string &text)
{
    std::string why = text.empty() ? "" : not_decimal(text);
    if (!why.empty()) bad(option, text, why);
    uint64_t bytes = 0;
    char msg[RT_MSG_LEN] = "";
    if (rt_budget_parse(text.c_str(), &bytes, msg, sizeof msg) != RT_OK) bad(option, text, msg);
    return bytes;
}

}  // namespace torusrt
