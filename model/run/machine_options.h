// machine_options.h - a machine written back as the options that rebuild it: the keys are the
// option names without dashes, the values as an option takes them. --dump-config prints them
// as a TOML file for --config; the JSON report carries them as config.options.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "sim_config.h"

namespace torusrt {

using OptionList = std::vector<std::pair<std::string, std::string>>;

// Every machine option, in the order of --help; with --map-file there is no "map" key.
OptionList machine_options(const MachineConfig &machine);

// key="value" lines (TOML, as CLI11 reads them back).
std::string machine_options_toml(const MachineConfig &machine);

// {"key": "value", ...}.
nlohmann::json machine_options_json(const MachineConfig &machine);

}  // namespace torusrt
