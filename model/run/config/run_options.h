// run_options.h - the run's option table: every option of one invocation that is no part of the
// machine (outputs, tracing, T(1), the time limit, an animation's remapping), declared once with
// its spec and how its text sets the request. The command line registers these and reads them
// through here; none goes into a machine file. No CLI11 here.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "option_spec.h"
#include "simulation.h"

namespace torusrt {

struct RunOption {
    OptionSpec spec;
    // Sets the request from the option's text (UserError naming the option, exit 2).
    void (*read)(const OptionSpec &spec, const std::string &text, SimRequest &request);
    // When the option changes nothing in the run `config` asks for: what it would need ("--vcd"),
    // else nullptr; no function: it always acts (see MachineOption::needs).
    const char *(*needs)(const SimConfig &config) = nullptr;
};

// Every run option, in the help's order.
const std::vector<RunOption> &run_option_table();

// The options given (long name -> text) of the animation group: the remapping of the frames.
// Checked against `animated` (the run has frames) before anything else of the run is read, so
// that a remapping option on a single image is named as such; UserError (exit 2).
void read_animation_run_options(const std::map<std::string, std::string> &given, bool animated, SimRequest &request);

// The other run options given: outputs, tracing, T(1), the time limit (ranges checked here,
// combinations by validate_run).
void read_run_options(const std::map<std::string, std::string> &given, SimRequest &request);

}  // namespace torusrt
