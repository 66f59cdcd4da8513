// run_options.cpp - the run's option table and its readers.
#include "run_options.h"

#include "option_parsing.h"
#include "output_files.h"
#include "user_error.h"

namespace torusrt {

namespace {

[[noreturn]] void bad(const std::string &message);

using G = OptionGroup;
using K = ValueKind;

// A time in seconds (a bare number is seconds), at most the option's maximum (seconds).
double time_s(const OptionSpec &s, const std::string &text)
{
    double v = parse_time(s.long_name(), text, 0, 0);
    if (s.max > 0 && v > s.max)
        bad(s.long_name() + " '" + shown_text(text) + "': must be at most " + number_text(s.max) + " s");
    return v;
}
// The same in microseconds, read as such (a unit's power of ten applied once, exactly).
double time_us(const OptionSpec &s, const std::string &text)
{
    time_s(s, text);
    return parse_time(s.long_name(), text, 0, -6);
}
double real(const OptionSpec &s, const std::string &text) { return parse_real(s.long_name(), text, s.min, s.max); }

// --stats-interval: at least 1 ps, SystemC's resolution.
void read_stats_interval(const OptionSpec &s, const std::string &t, SimRequest &r)
{
    r.config.stats_interval_s = time_s(s, t);
    if (r.config.stats_interval_s < 1e-12) bad(s.long_name() + " '" + shown_text(t) + "': must be at least 1 ps");
}

void read_progress_every(const OptionSpec &s, const std::string &t, SimRequest &r)
{
    r.config.progress_every_s = time_s(s, t);
}

std::vector<RunOption> make_table()
{
    const double max_s = kMaxSimTimeS;
    return {
        {{"--write-map", "FILE", K::file, "", 0, 0, "", "write the cell -> node table this run used", G::outputs, ""},
         [](const OptionSpec &s, const std::string &t, SimRequest &r) {
             check_output_folder(s.long_name(), t);
             r.config.write_map = t;
         }},
        {{"--load-map", "FILE", K::file, "", 0, 0, "", "write the cells' work and owners as a PNG", G::outputs, ""},
         [](const OptionSpec &s, const std::string &t, SimRequest &r) {
             check_output_folder(s.long_name(), t);
             r.load_map = t;
         }},
        {{"--frames-csv", "FILE", K::file, "", 0, 0, "", "write one CSV row per frame of an animation", G::outputs, ""},
         [](const OptionSpec &, const std::string &t, SimRequest &r) { r.frames_csv = t; }},
        {{"--stats-interval", "TIME", K::time, "", 0, max_s, "s",
          "write statistics over time, one CSV row per interval of this simulated length, e.g. 10ms (to "
          "--stats-series, or X.series.csv beside --stats X.json)",
          G::outputs, ""},
         read_stats_interval},
        {{"--stats-series", "FILE", K::file, "", 0, 0, "",
          "with --stats-interval: the CSV file of the statistics over time", G::outputs, ""},
         [](const OptionSpec &, const std::string &t, SimRequest &r) { r.stats_series = t; }},
        {{"--t1", "TIME", K::time, "", 0, max_s, "s",
          "T(1) for the efficiency T(1)/(n T(n)) (default: run the model with one processor)", G::outputs, ""},
         [](const OptionSpec &s, const std::string &t, SimRequest &r) { r.config.t1_s = time_s(s, t); }},
        {{"--vcd", "FILE", K::file, "", 0, 0, "",
          "write a VCD trace (IP busy, queue depths, link use, bus activity) and a GTKWave save file beside "
          "it (X.gtkw for X.vcd)",
          G::tracing, ""},
         [](const OptionSpec &, const std::string &t, SimRequest &r) { r.config.vcd_path = t; }},
        {{"--trace-from", "TIME", K::time, "0", 0, max_s, "s", "trace only from this simulated time", G::tracing, ""},
         [](const OptionSpec &s, const std::string &t, SimRequest &r) { r.config.trace_from_us = time_us(s, t); }},
        {{"--trace-to", "TIME", K::time, "", 0, max_s, "s", "trace only up to this simulated time (default: the end)",
          G::tracing, ""},
         [](const OptionSpec &s, const std::string &t, SimRequest &r) { r.config.trace_to_us = time_us(s, t); }},
        {{"--trace-ips", "N,N,...", K::text, "", 0, kMaxNodes - 1, "",
          "trace only these nodes, e.g. 0,1,5 (default all)", G::tracing, ""},
         [](const OptionSpec &s, const std::string &t, SimRequest &r) {
             r.config.trace_ips = parse_integer_list(s.long_name(), t, 0, kMaxNodes - 1);
         },
         [](const SimConfig &c) { return c.vcd_path.empty() ? "--vcd" : nullptr; }},
        {{"--remap", "POLICY", K::text, "static", 0, 0, "",
          "mapping across the frames: static (the first frame's), every-frame, adaptive or oracle", G::animation, ""},
         [](const OptionSpec &, const std::string &t, SimRequest &r) { r.remap = parse_remap_policy(t); }},
        {{"--remap-pilot", "FRACTION", K::real, "0", 0, 1, "",
          "adaptive's host preview of each frame: this fraction of the pixels (0: no preview, guesses of the load "
          "from earlier frames)",
          G::animation, ""},
         [](const OptionSpec &s, const std::string &t, SimRequest &r) { r.adaptive.pilot_fraction = real(s, t); }},
        {{"--remap-window", "N", K::integer, std::to_string(default_remap_window), 1, double(max_remap_window), "",
          "adaptive without a preview: judge its guesses over this many past frames", G::animation, ""},
         [](const OptionSpec &s, const std::string &t, SimRequest &r) {
             r.adaptive.window = static_cast<size_t>(
                 parse_integer(s.long_name(), t, static_cast<long long>(s.min), static_cast<long long>(s.max)));
         }},
        {{"--remap-margin", "FRACTION", K::real, number_text(default_remap_margin), 0, 1, "",
          "adaptive without a preview: keep the previous frame's load as the guess unless another's back-test "
          "is better by more than this fraction",
          G::animation, ""},
         [](const OptionSpec &s, const std::string &t, SimRequest &r) { r.adaptive.margin = real(s, t); }},
        {{"--progress-every", "TIME", K::time, "10s", 0, 1e6, "s",
          "when standard error is no terminal (a batch log), a progress line this often in wall time: simulated "
          "time, packets done, time left (0: none)",
          G::run, ""},
         read_progress_every},
        {{"--time-limit", "TIME", K::time, "1e7s", 0, max_s, "s",
          "stop with an error (exit 1) when simulated time passes this (at most 1e7 s: SystemC's 64-bit "
          "picosecond time holds 1.8e7 s)",
          G::run, ""},
         [](const OptionSpec &s, const std::string &t, SimRequest &r) { r.config.time_limit_s = time_s(s, t); }},
    };
}

// Reads the options of the table that `take` selects, in the table's order.
template <class Take> void read_given(const std::map<std::string, std::string> &given, SimRequest &request, Take take)
{
    for (const RunOption &o : run_option_table()) {
        auto it = given.find(o.spec.long_name());
        if (it != given.end() && take(o.spec)) o.read(o.spec, it->second, request);
    }
}

[[noreturn]] void bad(const std::string &message) { throw UserError(message, 2); }

// Adaptive's guesses are judged by --remap-window and --remap-margin, which a preview replaces.
void check_guess_option(const std::string &name, const SimRequest &r)
{
    if (r.remap != RemapPolicy::adaptive) bad(name + ": only with --remap adaptive");
    if (r.adaptive.pilot_fraction > 0)
        bad(name + ": only without a preview (--remap-pilot 0); the preview judges the tables");
}

}  // namespace

const std::vector<RunOption> &run_option_table()
{
    static const std::vector<RunOption> table = make_table();
    return table;
}

void read_animation_run_options(const std::map<std::string, std::string> &given, bool animated, SimRequest &r)
{
    auto has = [&given](const char *name) { return given.count(name) > 0; };
    if (!animated) {
        for (const char *name : {"--remap-pilot", "--remap-window", "--remap-margin"})
            if (has(name)) bad(std::string(name) + ": only for an animation with --remap adaptive");
        for (const char *name : {"--remap", "--frames-csv"})
            if (has(name))
                bad(std::string(name) + ": only for an animation (--frames N with --orbit DEG, or --camera-path FILE)");
        return;
    }
    read_given(given, r, [](const OptionSpec &s) { return s.group == OptionGroup::animation; });
    if (has("--remap-pilot") && r.remap != RemapPolicy::adaptive) bad("--remap-pilot: only with --remap adaptive");
    for (const char *name : {"--remap-window", "--remap-margin"})
        if (has(name)) check_guess_option(name, r);
    if (has("--t1")) bad("--t1: not used by an animation (each frame's T(1) is its pilot's work)");
}

void read_run_options(const std::map<std::string, std::string> &given, SimRequest &request)
{
    read_given(given, request, [](const OptionSpec &s) { return s.group != OptionGroup::animation; });
}

}  // namespace torusrt
