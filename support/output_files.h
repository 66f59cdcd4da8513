// output_files.h - the result files of a run, checked together before it starts and committed
// together or not at all.
//
// Usage:
//   OutputSet outs;
//   auto png = outs.add("-o", path);                     // every output, every frame included
//   outs.add_input("--timing", timing_file);             // every input the run reads
//   outs.check();                                        // before anything runs (exit 2)
//   write_png_file(outs.staged(png), path, w, h, rgb);   // throws UserError on any failure
//   outs.commit();                                       // every temporary onto its name
// A regular (or new) PATH is written to a temporary ".PATH.XXXXXX" (mkstemp) in its folder,
// made when staged() is first called, and renamed at commit; a device, FIFO or other
// non-regular PATH (/dev/null, /dev/stdout) is written directly and never replaced.
// Temporaries are removed when the set is destroyed uncommitted, and by SIGINT, SIGTERM or
// SIGHUP (signal_cleanup.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <sys/types.h>
#include <vector>

#include "rt_status.h"

namespace torusrt {

class OutputSet {
  public:
    using Id = size_t;
    OutputSet() = default;
    OutputSet(const OutputSet &) = delete;
    OutputSet &operator=(const OutputSet &) = delete;
    ~OutputSet();
    // Registers PATH for OPTION. Throws UserError (exit 2) if its folder is missing or PATH is
    // a folder; the other clashes are check()'s.
    Id add(const std::string &option, const std::string &path);
    // Registers a file the run reads for OPTION ("scene", "--timing", ...): no output may be it.
    void add_input(const std::string &option, const std::string &path);
    // Throws UserError (exit 2) if an output is one of the inputs (also through another name or
    // a hard link) or two outputs are one file. One stat per file: O(outputs).
    void check() const;
    // The file to write for `id` now: its temporary (made on the first call) or, for a device,
    // the target itself.
    std::string staged(Id id);
    const std::string &path(Id id) const { return m_entries[id].path; }
    bool special(Id id) const { return m_entries[id].special; }
    // Renames every temporary onto its path. Throws UserError naming the target if one fails.
    void commit();
    // Renames only the temporaries registered for `option` (the others are removed with the
    // set): a run that fails after writing its report keeps the report alone.
    void commit(const std::string &option);

  private:
    struct Entry {
        std::string option, path, tmp;  // tmp empty: not staged yet, or written directly
        bool special = false, exists = false;
        dev_t dev = 0;  // the existing file's identity
        ino_t ino = 0;
        size_t slot = 0;  // its signal_cleanup registration, when tmp is set
    };
    struct Input {
        std::string option, path;
    };
    std::vector<Entry> m_entries;
    std::vector<Input> m_inputs;
};

// Writes `text` to `write_path`, checking every write and the close; `shown` names it in errors.
void write_text_file(const std::string &write_path, const std::string &shown, const std::string &text);
// Writes an 8-bit RGB PNG to `write_path` the same way.
void write_png_file(const std::string &write_path, const std::string &shown, unsigned width, unsigned height,
                    const std::vector<uint8_t> &rgb8);
// Opens `write_path` and lets `write` (a kernel writer: map file, load map, cost image) fill
// the stream; its message or a failed close is thrown as UserError with `option` in front.
using StreamWriter = std::function<rt_status(FILE *fp, char *msg, size_t msg_len)>;
void write_stream_file(const std::string &write_path, const std::string &shown, const std::string &option,
                       const StreamWriter &write);
// Throws UserError (exit 2) if the folder of `path` does not exist, naming `option`.
void check_output_folder(const std::string &option, const std::string &path);

}  // namespace torusrt
