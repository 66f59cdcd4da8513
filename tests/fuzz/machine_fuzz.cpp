// machine_fuzz.cpp - libFuzzer target: the machine-file reader (MachineFileReader, the lines
// CLI11 gets from a --config file) on arbitrary text; a ConfigError is a refusal, any other
// exception or crash a finding. Built by bench/fuzz.sh with libFuzzer and, beside
// replay_main.c, for the CTest replay of tests/fuzz/machine_corpus.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "machine_file_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size > 64 * 1024) return 0;
    std::istringstream text(std::string(reinterpret_cast<const char *>(data), size));
    // The keys of the seed files; a bare number for quantum would be seconds.
    static const std::vector<std::string> keys = {"ips",   "map",    "topology", "queue",   "flow",    "link-us",
                                                  "style", "timing", "cells",    "quantum", "cluster", "timing-file"};
    torusrt::MachineFileReader reader(keys, {"quantum"});
    try {
        reader.from_config(text);
    } catch (const CLI::ConfigError &) {
        // refused: a message, no crash
    }
    return 0;
}
