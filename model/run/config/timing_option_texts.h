// timing_option_texts.h - the timing table as the machine options read and write it: a key's
// value, a key set under an option's name, a --timing file and a --timing-values list read into
// the machine, the list written back, and the table as the JSON report's config.timing.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "option_spec.h"
#include "sim_config.h"

namespace torusrt {

// The value of the timing key `key` (0 for an unknown key).
double timing_value(const rt_timing &t, const char *key);
// Sets the timing key `key`; UserError (exit 2) naming the option of `spec` when it is refused.
void set_timing(const OptionSpec &spec, rt_timing &t, const char *key, double v);
// --timing FILE: the table of the machine's profile with the file's values on top (UserError
// naming the file and line of a value out of range).
void read_timing_file(const OptionSpec &spec, const std::string &path, MachineConfig &m);
// --timing-values "KEY=VALUE,...": each key at most once, no empty item (UserError, exit 2).
void read_timing_values(const OptionSpec &spec, const std::string &text, MachineConfig &m);
// "KEY=VALUE,..." of every key of the machine's timing table.
std::string timing_values_text(const MachineConfig &m);
// {"test_miss": 1300, ...}: every key of the timing table.
nlohmann::json timing_json(const rt_timing &t);

}  // namespace torusrt
