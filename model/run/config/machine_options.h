// machine_options.h - the machine's option table: every option a machine file may hold,
// declared once with its spec (name, kind, default, range, unit, help, group, key), how its text
// sets the machine and how the machine writes it back. The command line (torusrt-sim) registers
// these, --config files feed them, --dump-config and the JSON report's config.options write
// them, in the table's order; the JSON report's other config keys come from the entries' `json`,
// the one-processor run's machine (T(1)) from their `one_processor`. Adding a machine option is
// one entry here plus its field in MachineConfig (sim_config.h) and its use; the files it
// touches are listed in docs/options.md. No CLI11 here.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "option_spec.h"
#include "sim_config.h"

namespace torusrt {

struct MachineOption {
    // The entries leave spec.default_text empty: machine_option_table writes it from a
    // default-constructed MachineConfig (default_text below, else `write`), so that a default is
    // written once, as the field's initialiser (sim_config.h).
    OptionSpec spec;
    // Sets the machine from the option's text (UserError naming the option, exit 2).
    void (*read)(const OptionSpec &spec, const std::string &text, MachineConfig &machine);
    // The text that reads back to the same setting.
    std::string (*write)(const MachineConfig &machine);
    // Adds the option's keys of the JSON report's config block ("ips", "nodes", ...); nullptr:
    // the option is only in config.options.
    void (*json)(const MachineConfig &machine, nlohmann::json &config) = nullptr;
    // When the option changes nothing in `machine`: what it would need ("--cluster > 1"), else
    // nullptr; no function: it always acts. The validator warns of such an option given on the
    // command line (idle_option_warnings).
    const char *(*needs)(const MachineConfig &machine) = nullptr;
    // The text the one-processor run for T(1) reads for this option; nullptr: it keeps the
    // machine's (one_processor_machine).
    const char *one_processor = nullptr;
    // The help's text of the default machine's setting where it differs from the writer's ("1"
    // for --ips 1x1x1, "1/512" for --min-weight 0.001953125); it reads back to the same setting.
    // nullptr: the writer's.
    std::string (*default_text)(const MachineConfig &machine) = nullptr;
    // The machine file's table that groups it ("network", "timing", "cluster", "mapping"): the
    // part of the table that declares it.
    std::string table = "";
};

// Every machine option, in --dump-config's order.
const std::vector<MachineOption> &machine_option_table();

// The machine that the options given (long name -> text, from the command line or a machine
// file) describe on top of the defaults, read in the table's order (the timing profile before
// the timing file, the file before single timing keys). Ranges of single values are checked
// here; combinations are the validator's (validate_machine).
MachineConfig machine_from_texts(const std::map<std::string, std::string> &given);

using OptionList = std::vector<std::pair<std::string, std::string>>;

// Every machine option of the table as key and text, each written by its entry; with --map-file
// there is no "map" key. "timing-values" holds the timing table when --timing-values set it ("" =
// not given). With `with_timing`, "timing-values" holds every value of the timing table and
// "timing" is empty, so that the machine needs no timing file.
OptionList machine_options(const MachineConfig &machine, bool with_timing = false);

// The machine file's tables in --dump-config's order: "network", "timing", "cluster", "mapping".
std::vector<std::string> machine_file_tables();

// The machine file: a [table] per part of the option table, each holding its key = "value"
// lines, TOML basic strings with every byte a path may hold escaped.
std::string machine_options_toml(const MachineConfig &machine, bool with_timing = false);

// The one-processor machine of T(1): `machine` with every option's `one_processor` text read on
// top, in the table's order (one node, one processor, every cell on it, unbounded buffers,
// approximately timed); the rest, its timing included, as `machine` has it.
MachineConfig one_processor_machine(const MachineConfig &machine);

// The JSON report's config keys that the options' `json` write: {"ips": [4, 2, 2], "nodes": 16, ...}.
nlohmann::json machine_config_json(const MachineConfig &machine);

// {"key": "value", ...}.
nlohmann::json machine_options_json(const MachineConfig &machine);
// ["key", ...]: the keys of machine_options_json in --dump-config's order (a JSON object keeps none).
nlohmann::json machine_option_order_json(const MachineConfig &machine);
// {"key": "table", ...}: the machine file's table of each key of machine_options_json.
nlohmann::json machine_option_tables_json(const MachineConfig &machine);

}  // namespace torusrt
