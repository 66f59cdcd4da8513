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
// A name is resolved before it is judged: a symbolic link (however many) stands for the file it
// names. A regular (or new) file is written to a temporary ".NAME.XXXXXX" (mkstemp) in its
// folder, made when staged() is first called, and renamed over it at commit (over the link's
// target, never over the link). The command's own standard output or error (/dev/stdout,
// /dev/fd/2, /proc/self/fd/1, or the file either is redirected to) is written in place through
// its descriptor; so is any other target that is not a regular file (/dev/null, a FIFO, a tty).
// Temporaries are removed when the set is destroyed uncommitted, and by a stopping signal
// (signal_cleanup.h).
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
    // Throws UserError (exit 2) if an output, or standard output or error redirected to a file,
    // is one of the inputs (also through another name, a link or a hard link), or if two outputs
    // are one file or one stream (standard output and error included; a null device is no
    // stream). One stat per file: O(outputs).
    void check() const;
    // The file to write for `id` now: its temporary (made on the first call) or, for a target
    // written in place, the name as given.
    std::string staged(Id id);
    const std::string &path(Id id) const { return m_entries[id].path; }
    bool special(Id id) const { return m_entries[id].special; }
    // Whether an output is the command's standard error (2) or output (1).
    bool writes_stream(int stream) const;
    // Renames every temporary onto its path. Throws UserError naming the target if one fails.
    void commit();
    // Renames only the temporaries registered for `option` (the others are removed with the
    // set): a run that fails after writing its report keeps the report alone.
    void commit(const std::string &option);

  private:
    struct Entry {
        std::string option, path, tmp;  // tmp empty: not staged yet, or written directly
        std::string target;             // the name renamed over: `path`, or what its links name
        bool special = false, exists = false;
        bool sink = false;  // a device that is no stream (/dev/null): any number may share it
        int stream = 0;     // 1 or 2: the command's standard output or error
        dev_t dev = 0;      // the existing file's identity
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
// A descriptor to write `write_path` through: a duplicate of standard output or error when it
// names either (the shell's redirection keeps its position), else a new open of it (created
// 0666 less the umask, truncated). -1 with errno set on failure.
int open_output_fd(const std::string &write_path);
// Points standard error at the terminal (/dev/tty) when the command has one, else at /dev/null:
// called when standard error is an input, so that no message is written into it.
void divert_stderr();
// Throws UserError (exit 2) if standard output or error is redirected to a regular file that a
// word of the command line names (the scene, --config FILE, --timing=FILE), other than the
// value of one of `output_options` (written through the stream in place) or a name under /dev or
// /proc: called before the parser, whose messages would be appended to that file. Standard
// error is diverted (divert_stderr) before the throw.
void check_streams_before_parsing(int argc, char **argv, const std::vector<std::string> &output_options);
// Throws UserError (exit 2) if the folder of `path` does not exist, naming `option`.
void check_output_folder(const std::string &option, const std::string &path);

}  // namespace torusrt
