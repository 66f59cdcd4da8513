// common_options.h - the options both executables have (scene, -o, --stats, --cells, --size,
// --max-depth, --min-weight, --memory-budget, --timing, --timing-profile, -q), declared once
// (common_option_specs, option_spec.h) and parsed once. --version and the exit statuses are
// cli_main's; the frames are animation_options'.
#pragma once

#include <CLI/CLI.hpp>
#include <array>
#include <cstdint>
#include <map>
#include <string>

#include "preprocess_count.h"
#include "rt_step.h"
#include "rt_timing.h"

namespace torusrt {

// As typed (the defaults as the help states them).
struct CommonOptions {
    std::string scene, output, stats, cells = "24", size, max_depth = "8", min_weight = "1/512", memory_budget = "4G";
    std::string timing_file, timing_profile, preprocess_count = "sequential";
    bool quiet = false;
};

// Registers the shared options whose long names `only` lists (all when empty), from their
// specs; `output_help` describes -o.
void add_common_options(CLI::App &app, const std::string &output_help, const std::vector<std::string> &only = {});

// The shared options' texts from the options given (given_options()).
CommonOptions common_options_given(const std::map<std::string, std::string> &given);

// "SCENE is required" / "-o FILE is required" (UserError, exit 2): checked after parsing, so
// that a command can go without them (torusrt-sim --dump-config).
void require_scene_and_output(const CommonOptions &options);

// What the options say. Syntax errors name the option (exit 2); an unknown profile exits 2, a
// bad timing file 1 (naming the file). Ranges are checked by the validators.
struct CommonSettings {
    std::array<int, 3> cells{};
    std::array<unsigned, 2> size{0, 0};  // 0x0: the scene's
    rt_step_params step{};
    uint64_t memory_bytes = 0;
    rt_timing timing{};
    std::string timing_label;  // the profile, with " + FILE" for a timing file
    std::string timing_base;   // the profile
    rt_preprocess_count preprocess_count = RT_COUNT_SEQUENTIAL;
};
CommonSettings parse_common_options(const CommonOptions &options);

// Warnings about legal but surprising settings (stderr, unless quiet).
void warn_about_settings(const char *program, const rt_step_params &step, bool quiet);

}  // namespace torusrt
