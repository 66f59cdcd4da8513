// option_spec.h - an option declared once: its name, value kind, default, range, unit, help,
// help group and machine-file key. The executables register their command lines from these
// (option_registration.h) and the machine's table (machine_option_table.h) parses, checks and
// writes back its values by them. No CLI11 here.
#pragma once

#include <string>
#include <vector>

namespace torusrt {

enum class OptionGroup { machine, workload, outputs, tracing, animation, run };
// "Machine", "Workload", ... (torusrt-sim heads its machine group with machine_file_group_title)
const char *group_title(OptionGroup group);

enum class ValueKind {
    integer,  // decimal whole number in [min, max]
    real,     // decimal number in [min, max]
    time,     // a time (option_parsing.h's parse_time); min and max in `unit`
    text,     // anything else with its own grammar (dimensions, names, lists, fractions)
    file,     // a path
    flag      // no value
};

struct OptionSpec {
    std::string name;        // CLI11 form: "--queue", "-o,--output", "scene"
    std::string value_name;  // "N", "TIME", "FILE"; "" for a flag
    ValueKind kind = ValueKind::text;
    std::string default_text;  // shown in the help; "" = none
    double min = 0, max = 0;   // integer, real and time ranges
    std::string unit;          // the bare number's unit: "s", "us", "bytes", "packets"
    std::string help;          // one sentence; the default is added from default_text
    OptionGroup group = OptionGroup::run;
    std::string key;  // machine-file and --dump-config key; "" = command line only

    // The long name ("--queue"; "scene" for the positional).
    std::string long_name() const;
    // The help with its default: "capacity of ... (default 0)".
    std::string full_help() const;
};

// The options both executables have: scene, -o, --stats, --cells, --size, --max-depth,
// --min-weight, --memory-budget, --timing, --timing-profile, -q. `output_help` describes -o.
std::vector<OptionSpec> common_option_specs(const std::string &output_help);
// One of them by long name (std::logic_error if there is none).
const OptionSpec &common_option_spec(const std::string &long_name);

// The closest of `names` to `typed` ("" if none is close): a different spelling of '_' and
// '-' or at most two letters off.
std::string closest_name(const std::string &typed, const std::vector<std::string> &names);

}  // namespace torusrt
