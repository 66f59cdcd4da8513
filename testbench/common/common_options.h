// common_options.h - the options both executables have (scene, -o, --stats, --cells, --size,
// --max-depth, --min-weight, --memory-budget, --timing, --timing-profile, -q), declared once and
// parsed once. --version and the exit statuses are cli_main's; the frames are animation_options'.
#pragma once

#include <CLI/CLI.hpp>
#include <array>
#include <cstdint>
#include <string>

#include "preprocess_count.h"
#include "rt_step.h"
#include "rt_timing.h"

namespace torusrt {

// As typed.
struct CommonOptions {
    std::string scene, output, stats, cells = "24", size, min_weight = "1/512", memory_budget = "4G";
    std::string timing_file, timing_profile, preprocess_count = "sequential";
    int max_depth = 8;
    bool quiet = false;
};

// Registers the options; `output_help` describes -o. The scene, the outputs, the size, the
// memory budget and -q belong to a run, never to a machine file (configurable(false)).
void add_common_options(CLI::App &app, CommonOptions &options, const std::string &output_help);

// "scene is required" / "--output is required" (UserError, exit 2): checked after parsing, so
// that a command can go without them (torusrt-sim --dump-config).
void require_scene_and_output(const CommonOptions &options);

// What the options say. Syntax errors name the option (exit 2); an unknown profile exits 2, a
// bad timing file 1 (naming the file). Ranges are checked by the validators.
struct CommonSettings {
    std::array<int, 3> cells{};
    std::array<unsigned, 2> size{0, 0};      // 0x0: the scene's
    rt_step_params step{};
    uint64_t memory_bytes = 0;
    rt_timing timing{};
    std::string timing_label;                // the profile, with " + FILE" for a timing file
    std::string timing_base;                 // the profile
    rt_preprocess_count preprocess_count = RT_COUNT_SEQUENTIAL;
};
CommonSettings parse_common_options(const CommonOptions &options);

// Warnings about legal but surprising settings (stderr, unless quiet).
void warn_about_settings(const char *program, const rt_step_params &step, bool quiet);

}  // namespace torusrt
