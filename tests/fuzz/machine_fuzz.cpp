// machine_fuzz.cpp - libFuzzer target: the machine-file reader (MachineFileReader, toml++ and
// the checks of keys, tables and values on a --config file) on arbitrary text; a ConfigError is a refusal, any other
// exception or crash a finding. Built by bench/fuzz.sh with libFuzzer and, beside
// replay_main.c, for the CTest replay of tests/fuzz/machine_corpus.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "machine_file_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size > 64 * 1024) return 0;
    std::istringstream text(std::string(reinterpret_cast<const char *>(data), size));
    // The keys of the seed files with their tables; a bare number for quantum would be seconds.
    static const std::vector<std::pair<std::string, std::string>> keys = {
        {"ips", "network"},    {"topology", "network"}, {"queue", "network"}, {"flow", "network"},
        {"cells", "network"},  {"link-us", "timing"},   {"style", "timing"},  {"timing", "timing"},
        {"quantum", "timing"}, {"cluster", "cluster"},  {"map", "mapping"},   {"timing-file", "timing"}};
    torusrt::MachineFileReader reader(keys, {"quantum"});
    try {
        reader.from_config(text);
    } catch (const CLI::ConfigError &) {
        // refused: a message, no crash
    }
    return 0;
}
