// combination_rules.h - the rules over combinations of settings, each declared once with the
// option it names and what it needs: the validator (config_validation.cpp, where the list is)
// stops a run that breaks one with "OPTION: RULE" (exit 2), and docs/cli.md's generated table
// lists them (option_docs.h).
#pragma once

#include <string>
#include <vector>

#include "sim_config.h"

namespace torusrt {

struct CombinationRule {
    std::string option;  // the option the message names: "--pilot-size"
    std::string rule;    // what it needs: "only with --map cost or scatter"
    // True when `run` on `machine` breaks the rule.
    bool (*broken)(const RunOptions &run, const MachineConfig &machine);
    bool of_machine;  // a rule of the machine alone (validate_machine), else of the run on it (validate_run)
};

// Every rule, in the order the validator checks them.
const std::vector<CombinationRule> &combination_rules();

}  // namespace torusrt
