// machine_file_reader.h - reads a --config machine file: CLI11's TOML reader, with '#' a comment
// only outside quotes and a repeated key or a [section] an error naming the line.
#pragma once

#include <CLI/CLI.hpp>

namespace torusrt {

class MachineFileReader : public CLI::ConfigBase {
  public:
    MachineFileReader();
    std::vector<CLI::ConfigItem> from_config(std::istream &input) const override;
};

}  // namespace torusrt
