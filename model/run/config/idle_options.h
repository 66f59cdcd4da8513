// idle_options.h - the options given on the command line that change nothing in the machine and
// run asked for (--data without --cluster above 1, --trace-ips without --vcd, ...), found from
// the option tables' `needs`. Warned about, not refused: a --dump-config file holds every key.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "sim_config.h"

namespace torusrt {

// One line per option of the machine and run tables for which `on_command_line(long name)` holds
// and whose `needs` says it changes nothing in `config`: "--data changes nothing here: it acts
// only with --cluster above 1".
std::vector<std::string> idle_option_warnings(const SimConfig &config,
                                              const std::function<bool(const std::string &)> &on_command_line);

}  // namespace torusrt
