// machine_file_reader.h - reads a --config machine file: one `key = value` line per option, the
// value a TOML basic string ("...", with \" \\ \n \uXXXX escapes), a literal string ('...') or
// a bare word; '#' starts a comment outside quotes. A repeated key, a [section], a key that is
// no machine option (with the nearest one as a hint), a NUL byte, a line without a key and a
// bare number for a time in seconds are errors naming the line (MachineFileError, exit 2).
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <string>
#include <vector>

namespace torusrt {

class MachineFileError : public CLI::ConfigError {
  public:
    MachineFileError(int line, const std::string &what)
        : CLI::ConfigError(std::to_string(line) + ": " + what), m_line(line)
    {
    }
    int line() const { return m_line; }

  private:
    int m_line;
};

class MachineFileReader : public CLI::ConfigBase {
  public:
    // `keys`: every key a file may hold; `timed_keys`: those whose bare number would be seconds.
    MachineFileReader(std::vector<std::string> keys, std::vector<std::string> timed_keys);
    std::vector<CLI::ConfigItem> from_config(std::istream &input) const override;
    // The line that set `key` in the file read last (0: not there).
    int line_of(const std::string &key) const;

  private:
    std::vector<std::string> m_keys, m_timed_keys;
    mutable std::map<std::string, int> m_lines;
};

}  // namespace torusrt
