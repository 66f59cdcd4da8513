// common_options.cpp - the shared options of torusrt-render and torusrt-sim.
#include "common_options.h"

#include <algorithm>
#include <cstdio>

#include "option_parsing.h"
#include "option_registration.h"
#include "option_spec.h"
#include "timing_choice.h"
#include "timing_limits.h"
#include "user_error.h"

namespace torusrt {

void add_common_options(CLI::App &app, const std::string &output_help, const std::vector<std::string> &only)
{
    for (const OptionSpec &spec : common_option_specs(output_help))
        if (only.empty() || std::find(only.begin(), only.end(), spec.long_name()) != only.end())
            add_spec_option(app, spec);
}

CommonOptions common_options_given(const std::map<std::string, std::string> &given)
{
    CommonOptions o;
    auto take = [&given](const char *name, std::string &field) {
        auto it = given.find(name);
        if (it != given.end()) field = it->second;
    };
    take("scene", o.scene);
    take("--output", o.output);
    take("--stats", o.stats);
    take("--cells", o.cells);
    take("--size", o.size);
    take("--max-depth", o.max_depth);
    take("--min-weight", o.min_weight);
    take("--memory-budget", o.memory_budget);
    take("--timing", o.timing_file);
    take("--timing-profile", o.timing_profile);
    take("--preprocess-count", o.preprocess_count);
    o.quiet = given.count("--quiet") > 0;
    return o;
}

void require_scene_and_output(const CommonOptions &o)
{
    if (o.scene.empty()) throw UserError("scene is required: the NFF file to render (torusrt-sim SCENE -o FILE)", 2);
    if (o.output.empty()) throw UserError("--output is required: -o FILE, the image to write", 2);
}

CommonSettings parse_common_options(const CommonOptions &o)
{
    CommonSettings s;
    const OptionSpec &cells = common_option_spec("--cells"), &depth = common_option_spec("--max-depth");
    s.cells = parse_triple("--cells", o.cells, 1, static_cast<int>(cells.max));
    if (!o.size.empty()) s.size = parse_size("--size", o.size);
    s.step = rt_step_params_default();
    s.step.max_depth =
        static_cast<int>(parse_integer("--max-depth", o.max_depth, 0, static_cast<long long>(depth.max)));
    s.step.min_weight = parse_fraction("--min-weight", o.min_weight);
    s.preprocess_count = value_named("--preprocess-count", o.preprocess_count, kPreprocessCountNames);
    s.memory_bytes = parse_memory_size("--memory-budget", o.memory_budget);
    s.timing_label = choose_timing(o.timing_profile, o.timing_file, &s.timing);
    s.timing_base = o.timing_profile.empty() ? rt_timing_default_profile() : o.timing_profile;
    // The table as loaded is input: a value out of range is the file's (or profile's) fault.
    std::string key, problem = timing_limit_problem(s.timing, &key);
    long line = problem.empty() || o.timing_file.empty() ? 0 : timing_key_line(o.timing_file, key);
    if (!problem.empty())
        throw UserError((o.timing_file.empty() ? s.timing_label : shown_text(o.timing_file)) +
                        (line > 0 ? ":" + std::to_string(line) : "") + ": " + problem);
    return s;
}

void warn_about_settings(const char *program, const rt_step_params &step, bool quiet)
{
    if (step.min_weight > 1 && !quiet)
        std::fprintf(stderr, "%s: warning: --min-weight %g is above 1: every secondary ray is dropped\n", program,
                     step.min_weight);
}

}  // namespace torusrt
