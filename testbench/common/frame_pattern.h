// frame_pattern.h - the output name pattern of an animation: "out_%04d.png" -> out_0007.png.
#pragma once

#include <cstdint>
#include <string>

namespace torusrt {

// Checks a pattern: exactly one integer conversion, %d or %0Nd (N 1 to 2 digits), and no
// other '%' than "%%" (a literal percent sign). Throws UserError (exit 2) naming `option`.
void check_frame_pattern(const std::string &option, const std::string &pattern);
// The file name of frame `index` (the pattern must have passed check_frame_pattern).
std::string frame_file_name(const std::string &pattern, uint64_t index);

}  // namespace torusrt
