// frame_pattern.cpp - output name patterns, expanded here rather than by printf so that no
// user text is ever a format string.
#include "frame_pattern.h"

#include <cctype>

#include "user_error.h"

namespace torusrt {

namespace {

// Length of the conversion starting at pattern[i] == '%' ("%d" 2, "%04d" 4), or 0 if it is
// not an integer conversion this accepts. Sets *width (0: none).
size_t conversion_length(const std::string &p, size_t i, int *width)
{
    size_t j = i + 1;
    *width = 0;
    if (j < p.size() && p[j] == 'd') return 2;
    if (j >= p.size() || p[j] != '0') return 0;
    j++;
    if (j < p.size() && p[j] == '0') return 0; /* "%00d", "%001d": one zero flag only */
    size_t digits = 0;
    while (j < p.size() && std::isdigit(static_cast<unsigned char>(p[j])) && digits < 3) {
        *width = *width * 10 + (p[j] - '0');
        j++;
        digits++;
    }
    if (digits == 0 || digits > 2 || *width == 0 || j >= p.size() || p[j] != 'd') return 0;
    return j + 1 - i;
}

// The text of a rejected conversion for messages: from '%' to its conversion letter.
std::string conversion_text(const std::string &p, size_t i)
{
    size_t j = i + 1;
    while (j < p.size() && j < i + 8 && !std::isalpha(static_cast<unsigned char>(p[j]))) j++;
    return p.substr(i, j < p.size() ? j + 1 - i : j - i);
}

}  // namespace

void check_frame_pattern(const std::string &option, const std::string &pattern)
{
    int conversions = 0, width;
    for (size_t i = 0; i < pattern.size(); i++) {
        if (pattern[i] != '%') continue;
        if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
            i++;
            continue;
        }
        size_t len = conversion_length(pattern, i, &width);
        if (len == 0)
            throw UserError(option + " '" + pattern + "': a frame pattern takes only %d or %0Nd " +
                                "(N 1 to 99) and %% for a percent sign; '" + conversion_text(pattern, i) +
                                "' is not one",
                            2);
        conversions++;
        i += len - 1;
    }
    if (conversions != 1)
        throw UserError(option + " '" + pattern + "': an animation's output is a pattern with " +
                            "exactly one %d or %0Nd for the frame number (found " + std::to_string(conversions) +
                            "), e.g. out_%04d.png",
                        2);
}

std::string frame_file_name(const std::string &pattern, uint64_t index)
{
    std::string out;
    int width;
    for (size_t i = 0; i < pattern.size(); i++) {
        size_t len = pattern[i] == '%' ? conversion_length(pattern, i, &width) : 0;
        if (pattern[i] != '%') {
            out += pattern[i];
        } else if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
            out += '%';
            i++;
        } else if (len) {
            std::string digits = std::to_string(index);
            if (digits.size() < static_cast<size_t>(width)) out += std::string(width - digits.size(), '0');
            out += digits;
            i += len - 1;
        }
    }
    return out;
}

}  // namespace torusrt
