// output_files.h - writing result files whole or not at all.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace torusrt {

// Writes `text` to PATH.tmp.PID and renames it to PATH. Throws UserError on failure.
void write_text_file(const std::string &path, const std::string &text);
// Writes an 8-bit RGB PNG (atomically). Throws UserError on failure.
void write_png_file(const std::string &path, unsigned width, unsigned height,
                    const std::vector<uint8_t> &rgb8);
// Removes a file if present (used to undo the first of several outputs).
void remove_file(const std::string &path);
// Throws UserError (exit 2) if the folder of `path` does not exist, naming `option`.
void check_output_folder(const std::string &option, const std::string &path);

}  // namespace torusrt
