// machine_file_reader.h - reads a --config machine file with toml++: `key = value` lines, flat
// (at the top) or grouped in the table of their part of the machine ([network], [timing], ...).
// A value is a string, a boolean or a number; a number is taken as its source text, so that the
// project's one number parser (option_parsing.h) decides it as on the command line ("0x10",
// "1_000", "inf", "+5" are refused there). A TOML syntax error, a key that is no machine option
// (with the nearest one as a hint), a table that is none of the machine file's, a key in another
// table than its own, a key given twice (also once flat and once in its table), an array, an
// inline table, a date and a bare number for a time in seconds are errors naming the line and
// column (MachineFileError, exit 2).
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace torusrt {

class MachineFileError : public CLI::ConfigError {
  public:
    MachineFileError(long line, long column, const std::string &what)
        : CLI::ConfigError(std::to_string(line) + ":" + std::to_string(column) + ": " + what), m_line(line)
    {
    }
    long line() const { return m_line; }

  private:
    long m_line;
};

class MachineFileReader : public CLI::ConfigBase {
  public:
    // `keys`: every key a file may hold with its table; `timed_keys`: those whose bare number
    // would be seconds.
    MachineFileReader(std::vector<std::pair<std::string, std::string>> keys, std::vector<std::string> timed_keys);
    std::vector<CLI::ConfigItem> from_config(std::istream &input) const override;
    // "LINE:COLUMN" of the value that set `key` in the file read last ("": not there).
    std::string position_of(const std::string &key) const;

  private:
    std::vector<std::pair<std::string, std::string>> m_keys;
    std::vector<std::string> m_timed_keys;
    mutable std::map<std::string, std::string> m_positions;
};

}  // namespace torusrt
