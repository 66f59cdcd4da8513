// cli_main.h - the common shape of an executable's main: parse with CLI11, run, and turn every
// error into a message on stderr and an exit status (0 ok, 1 input or run failure, 2 usage).
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace torusrt {

// Adds --version and the exit statuses (0, 1, 2, then `extra_exit_statuses` lines) to the help.
int run_cli(const char *program, CLI::App &app, int argc, char **argv, const std::function<int()> &body,
            const char *extra_exit_statuses = "");

}  // namespace torusrt
