// input_file_check.h - a CLI11 check that an option's file can be read as every input is read
// (rt_file_read.h): a regular text file within a size bound. CLI11 reads a --config file itself,
// with a blocking open; this check runs first, so a FIFO, a device or a folder is refused with
// a message saying what it is instead of hanging or being read without end.
//
// Usage:
//   app.set_config("--config", ...)->check(input_file_check(kMachineFileMaxBytes));
#pragma once

#include <CLI/CLI.hpp>
#include <cstddef>

namespace torusrt {

// The largest machine file read (a --dump-config file is about 1 KB).
constexpr size_t kMachineFileMaxBytes = 1024 * 1024;

CLI::Validator input_file_check(size_t max_bytes);

}  // namespace torusrt
