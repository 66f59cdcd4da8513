// option_docs.h - docs/cli.md's generated option tables, written from the option tables
// (machine_options.h, run_options.h): the machine file's tables and keys, and a reference row
// per option with its key, value, default, range, unit, JSON config keys and one-processor
// value, and the combination rules. `torusrt-sim --option-tables` prints them; scripts/write_option_docs.py puts them
// into docs/cli.md between their markers, and tests/cli/option_tables_documented.sh fails when the two differ.
#pragma once

#include <string>

namespace torusrt {

// Every generated block, each between its "<!-- BEGIN generated: NAME -->" and
// "<!-- END generated: NAME -->" lines, in docs/cli.md's order.
std::string option_tables_markdown();

}  // namespace torusrt
