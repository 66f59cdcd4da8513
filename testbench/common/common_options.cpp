// common_options.cpp - the shared options of torusrt-render and torusrt-sim.
#include "common_options.h"

#include <cstdio>

#include "option_parsing.h"
#include "rt_grid.h"
#include "timing_choice.h"
#include "timing_limits.h"
#include "user_error.h"

namespace torusrt {

void add_common_options(CLI::App &app, CommonOptions &o, const std::string &output_help)
{
    app.add_option("scene", o.scene, "scene file (NFF)")->type_name("FILE")->configurable(false);
    app.add_option("-o,--output", o.output, output_help)->type_name("FILE")->configurable(false);
    app.add_option("--stats", o.stats, "write the statistics as JSON to this file")->type_name("FILE")
        ->configurable(false);
    app.add_option("--cells", o.cells, "grid cells: N or NXxNYxNZ (default 24)")->type_name("DIMS");
    app.add_option("--size", o.size, "image size WxH, overriding the scene's resolution")->type_name("WxH")
        ->configurable(false);
    app.add_option("--max-depth", o.max_depth, "deepest shade-tree depth of a ray (default 8)")->type_name("N");
    app.add_option("--min-weight", o.min_weight, "smallest ray weight, e.g. 1/512 (default)")->type_name("W");
    app.add_option("--memory-budget", o.memory_budget, "memory the run may use for cell lists, frame buffer and\n"
                   "packets, e.g. 512M or 4G; 0 = no limit (default 4G)")->type_name("SIZE")->configurable(false);
    app.add_option("--timing", o.timing_file, "timing file overriding single keys of the profile")->type_name("FILE");
    app.add_option("--timing-profile", o.timing_profile,
                   std::string("timing profile: calibrated or literal (default ") + rt_timing_default_profile() +
                       "); --timing FILE overrides single keys on top")
        ->type_name("NAME");
    app.add_option("--preprocess-count", o.preprocess_count,
                   "how preprocessing units are counted: sequential (default), per-plane or bounding-sphere")
        ->type_name("RULE");
    app.add_flag("-q,--quiet", o.quiet, "print nothing but errors; no progress")->configurable(false);
}

void require_scene_and_output(const CommonOptions &o)
{
    if (o.scene.empty()) throw UserError("scene is required", 2);
    if (o.output.empty()) throw UserError("--output is required", 2);
}

CommonSettings parse_common_options(const CommonOptions &o)
{
    CommonSettings s;
    s.cells = parse_triple("--cells", o.cells, 1, RT_GRID_MAX_CELLS_PER_AXIS);
    if (!o.size.empty()) s.size = parse_size("--size", o.size);
    s.step = rt_step_params_default();
    s.step.max_depth = o.max_depth;
    s.step.min_weight = parse_fraction("--min-weight", o.min_weight);
    s.preprocess_count = value_named("--preprocess-count", o.preprocess_count, kPreprocessCountNames);
    s.memory_bytes = parse_memory_size("--memory-budget", o.memory_budget);
    s.timing_label = choose_timing(o.timing_profile, o.timing_file, &s.timing);
    s.timing_base = o.timing_profile.empty() ? rt_timing_default_profile() : o.timing_profile;
    // The table as loaded is input: a value out of range is the file's (or profile's) fault.
    std::string problem = timing_limit_problem(s.timing);
    if (!problem.empty()) throw UserError((o.timing_file.empty() ? s.timing_label : o.timing_file) + ": " + problem);
    return s;
}

void warn_about_settings(const char *program, const rt_step_params &step, bool quiet)
{
    if (step.min_weight > 1 && !quiet)
        std::fprintf(stderr, "%s: warning: --min-weight %g is above 1: every secondary ray is dropped\n", program,
                     step.min_weight);
}

}  // namespace torusrt
