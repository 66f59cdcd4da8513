// output_files.h - the result files of a run, committed together or not at all.
//
// Usage:
//   OutputSet outs;
//   std::string png = outs.add("-o", path, scene_path);   // where to write it now
//   write_png_file(png, path, w, h, rgb);                   // throws UserError on any failure
//   outs.commit();                                         // every temporary onto its name
// A regular (or new) PATH is written as PATH.tmp.PID and renamed at commit; a device, FIFO or
// other non-regular PATH (/dev/null, /dev/stdout) is written directly and never replaced.
// Temporaries still present when the set is destroyed are removed.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace torusrt {

class OutputSet {
  public:
    OutputSet() = default;
    OutputSet(const OutputSet &) = delete;
    OutputSet &operator=(const OutputSet &) = delete;
    ~OutputSet();
    // Registers PATH for OPTION and returns the path to write. Throws UserError (exit 2) if its
    // folder is missing, or it is the input file `input` or another output of this set.
    std::string add(const std::string &option, const std::string &path, const std::string &input);
    // Throws UserError (exit 2) if an output of this set is the file `input` that `option` reads.
    void check_not_input(const std::string &option, const std::string &input) const;
    // Renames every temporary onto its path. Throws UserError if a rename fails.
    void commit();
    // Renames only the temporary registered for `option` (the others are removed with the set):
    // a run that fails after writing its report keeps the report alone.
    void commit(const std::string &option);

  private:
    struct Entry {
        std::string option, path, tmp;  // tmp empty: written directly
    };
    std::vector<Entry> m_entries;
};

// True if PATH exists and is not a regular file (a device, FIFO, socket...), so it must be
// written in place rather than replaced.
bool is_special_file(const std::string &path);
// Writes `text` to `write_path`, checking every write and the close; `shown` names it in errors.
void write_text_file(const std::string &write_path, const std::string &shown, const std::string &text);
// Writes an 8-bit RGB PNG to `write_path` the same way.
void write_png_file(const std::string &write_path, const std::string &shown, unsigned width, unsigned height,
                    const std::vector<uint8_t> &rgb8);
// Throws UserError (exit 2) if the folder of `path` does not exist, naming `option`.
void check_output_folder(const std::string &option, const std::string &path);

}  // namespace torusrt
