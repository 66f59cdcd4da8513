// option_registration.h - CLI11 options registered from their specs (option_spec.h), the values
// given read back by long name, and the help's layout: at most 100 columns, the usage line
// showing what is required, examples at the end.
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <string>
#include <vector>

#include "option_spec.h"

namespace torusrt {

// The help fits this many columns.
constexpr size_t kHelpColumns = 100;

// Registers one option: its help wrapped to fit, its group, configurable (a --config file may
// set it) exactly when it has a machine-file key.
CLI::Option *add_spec_option(CLI::App &app, const OptionSpec &spec);

// Every option of `app` in the help group `from` moved to the group `to` (a heading of its own).
void retitle_group(CLI::App &app, const std::string &from, const std::string &to);

// `text` wrapped at spaces into lines of at most `width` characters, joined by '\n'.
std::string wrapped(const std::string &text, size_t width);

// Every option given on the command line or by a --config file, by long name ("scene" for the
// positional), as typed; a flag given reads "true".
std::map<std::string, std::string> given_options(const CLI::App &app);

// Sets the help's layout: `usage` lines replace CLI11's usage line, `rules` follow the program's
// description, `examples` close the help before the exit statuses.
void set_help_layout(CLI::App &app, const std::string &usage, const std::string &rules, const std::string &examples);

// "did you mean --link-us?" for a misspelt option name, or "" (names: the app's long names).
std::string option_suggestion(const CLI::App &app, const std::string &typed);

}  // namespace torusrt
