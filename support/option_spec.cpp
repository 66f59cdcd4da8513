// option_spec.cpp - help text, the shared options, and the nearest name for "did you mean".
#include "option_spec.h"

#include <algorithm>
#include <stdexcept>

#include "rt_grid.h"
#include "rt_timing.h"

namespace torusrt {

const char *group_title(OptionGroup group)
{
    switch (group) {
    case OptionGroup::machine: return "Machine";
    case OptionGroup::workload: return "Workload";
    case OptionGroup::outputs: return "Outputs";
    case OptionGroup::tracing: return "Tracing";
    case OptionGroup::animation: return "Animation";
    case OptionGroup::run: return "Run";
    }
    return "Run";
}

std::string OptionSpec::long_name() const
{
    size_t comma = name.rfind(',');
    return comma == std::string::npos ? name : name.substr(comma + 1);
}

std::string OptionSpec::full_help() const
{
    return default_text.empty() ? help : help + " (default " + default_text + ")";
}

std::vector<OptionSpec> common_option_specs(const std::string &output_help)
{
    const double cells_max = RT_GRID_MAX_CELLS_PER_AXIS;
    using G = OptionGroup;
    using K = ValueKind;
    return {
        {"scene", "SCENE", K::file, "", 0, 0, "", "the scene file (NFF), required", G::workload, ""},
        {"--size", "WxH", K::text, "", 1, 16384, "", "image size, overriding the scene's resolution", G::workload, ""},
        {"-o,--output", "FILE", K::file, "", 0, 0, "", output_help, G::outputs, ""},
        {"--stats", "FILE", K::file, "", 0, 0, "", "write the statistics as JSON to this file", G::outputs, ""},
        {"--cells", "DIMS", K::text, "24", 1, cells_max, "", "grid cells: N or NXxNYxNZ", G::machine, "cells"},
        {"--max-depth", "N", K::integer, "8", 0, 1000, "", "deepest shade-tree depth of a ray", G::machine,
         "max-depth"},
        {"--min-weight", "W", K::text, "1/512", 0, 0, "", "smallest ray weight, e.g. 0.002 or 1/512", G::machine,
         "min-weight"},
        {"--timing-profile", "NAME", K::text, rt_timing_default_profile(), 0, 0, "",
         "timing profile: calibrated, literal, fitted or round-one; --timing FILE overrides single keys on top",
         G::machine, "timing-profile"},
        {"--timing", "FILE", K::file, "", 0, 0, "", "timing file overriding single keys of the profile", G::machine,
         "timing"},
        {"--preprocess-count", "RULE", K::text, "sequential", 0, 0, "",
         "how preprocessing units are counted: sequential, per-plane or bounding-sphere", G::machine,
         "preprocess-count"},
        {"--memory-budget", "SIZE", K::text, "4G", 0, 0, "",
         "memory for cell lists, frame buffer and packets, e.g. 512M; 0 = no limit", G::run, ""},
        {"-q,--quiet", "", K::flag, "", 0, 0, "", "print nothing but errors; no progress", G::run, ""},
    };
}

const OptionSpec &common_option_spec(const std::string &long_name)
{
    static const std::vector<OptionSpec> specs = common_option_specs("");
    for (const OptionSpec &s : specs)
        if (s.long_name() == long_name) return s;
    throw std::logic_error("no shared option " + long_name);
}

namespace {

size_t edit_distance(const std::string &a, const std::string &b)
{
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); j++) row[j] = j;
    for (size_t i = 1; i <= a.size(); i++) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); j++) {
            size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = up;
        }
    }
    return row[b.size()];
}

}  // namespace

std::string closest_name(const std::string &typed, const std::vector<std::string> &names)
{
    std::string dashed = typed;
    std::replace(dashed.begin(), dashed.end(), '_', '-');
    std::string best;
    size_t best_distance = 3;
    for (const std::string &name : names) {
        size_t d = edit_distance(dashed, name);
        if (d < best_distance) best = name, best_distance = d;
    }
    return best;
}

}  // namespace torusrt
