// idle_options.cpp - options that change nothing, from the tables' `needs`.
#include "idle_options.h"

#include "machine_options.h"
#include "run_options.h"

namespace torusrt {

namespace {

std::string idle_line(const std::string &option, const char *needed)
{
    return option + " changes nothing here: it acts only with " + needed;
}

}  // namespace

std::vector<std::string> idle_option_warnings(const SimConfig &config,
                                              const std::function<bool(const std::string &)> &on_command_line)
{
    std::vector<std::string> lines;
    for (const MachineOption &o : machine_option_table()) {
        const char *needed = o.needs ? o.needs(config) : nullptr;
        if (needed && on_command_line(o.spec.long_name())) lines.push_back(idle_line(o.spec.long_name(), needed));
    }
    for (const RunOption &o : run_option_table()) {
        const char *needed = o.needs ? o.needs(config) : nullptr;
        if (needed && on_command_line(o.spec.long_name())) lines.push_back(idle_line(o.spec.long_name(), needed));
    }
    return lines;
}

}  // namespace torusrt
