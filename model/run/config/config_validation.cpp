// config_validation.cpp - the one validator of a run's settings: ranges and combinations (the
// list of combination rules, combination_rules.h, is here), checked before the scene is loaded
// and the model elaborated. Values that do not parse are the option parsers' (option_parsing.h);
// files are checked where they are read.
#include <cmath>
#include <cstdlib>
#include <string>

#include "combination_rules.h"
#include "machine_options.h"
#include "mapping.h"
#include "option_parsing.h"
#include "setting_checks.h"
#include "sim_config.h"
#include "timing_limits.h"
#include "user_error.h"

namespace torusrt {

namespace {

[[noreturn]] void bad(const std::string &message) { throw UserError(message, 2); }

std::string str(double v) { return std::to_string(static_cast<long long>(v)); }

// The option that sets a timing key (the table from the profile and the file is checked when
// it is loaded, so what is out of range here came from one of these).
const char *timing_option(const MachineConfig &m, const std::string &key)
{
    if (key == "link" || (key == "link transfer" && !(m.timing.link_bytes_per_us > 0))) return "--link-us";
    if (key == "packet_bytes") return "--packet-bytes";
    if (key == "link_bytes_per_us" || key == "link transfer") return "--link-bytes-per-us";
    return "--timing";
}

std::string range_text(double v) { return std::isinf(v) ? std::string("any") : number_text(v); }

// A machine filled in by a program rather than by options: each numeric option of the table
// within the range the table declares for it (the one place a range is written).
void validate_table_ranges(const MachineConfig &m)
{
    for (const MachineOption &option : machine_option_table()) {
        const OptionSpec &spec = option.spec;
        if (spec.kind != ValueKind::integer && spec.kind != ValueKind::real) continue;
        std::string text = option.write(m);
        if (text.empty()) continue;
        double v = std::strtod(text.c_str(), nullptr);
        if (!(v >= spec.min && v <= spec.max))
            bad(spec.long_name() + ": must be " + range_text(spec.min) + " to " + range_text(spec.max));
    }
}

void validate_shape(const MachineConfig &m)
{
    for (int a = 0; a < 3; a++)
        if (m.ips[a] < 1) bad("--ips: every dimension needs at least 1 node");
    if (m.node_count() > kMaxNodes) bad("--ips: at most " + std::to_string(kMaxNodes) + " nodes");
    char msg[256] = "";
    rt_topology t;
    if (rt_topology_make(m.topology.c_str(), m.ips.data(), &t, msg, sizeof msg) != RT_OK)
        bad("--ips " + std::to_string(m.ips[0]) + "x" + std::to_string(m.ips[1]) + "x" + std::to_string(m.ips[2]) +
            " with --topology " + m.topology + ": " + msg);
    check_cells(m.cells);
}

void validate_mapping(const MachineConfig &m)
{
    const Mapping &mapping = mapping_of(m);
    if (m.block < 1) {
        const bool named = mapping.parameter != MappingParameter::none;
        const std::string form = named ? std::string(mapping.name) + ":" + mapping.parameter_name : "block-cyclic:B";
        bad("--map " + form + ": " + form.substr(form.find(':') + 1) + " must be at least 1");
    }
    if (m.pilot_size[0] > 0 || m.pilot_size[1] > 0) check_image_size("--pilot-size", m.pilot_size[0], m.pilot_size[1]);
}

void validate_timing(const MachineConfig &m)
{
    std::string key;
    std::string why = timing_limit_problem(m.timing, &key);
    if (!why.empty()) bad(std::string(timing_option(m, key)) + ": " + why);
    check_step_limits(m.step);
    if (!(m.quantum_us >= 0) || !std::isfinite(m.quantum_us)) bad("--quantum: must not be negative");
    if (m.quantum_us > 0 && m.quantum_us < 1e-6) bad("--quantum: 0 or at least 1 ps (SystemC's time resolution)");
    if (m.quantum_us > kMaxSimTimeS * 1e6) bad("--quantum: at most " + str(kMaxSimTimeS) + " s");
}

// The rules of the machine alone (`of_machine`) or of the run on it, in their order.
void check_rules(const RunOptions &r, const MachineConfig &m, bool of_machine)
{
    for (const CombinationRule &rule : combination_rules())
        if (rule.of_machine == of_machine && rule.broken(r, m)) bad(rule.option + ": " + rule.rule);
}

void validate_tracing(const RunOptions &r, const MachineConfig &m)
{
    if (!(r.trace_from_us >= 0) || (r.trace_to_us >= 0 && r.trace_to_us < r.trace_from_us))
        bad("--trace-from/--trace-to: the window must start at 0 or later and not end before it starts");
    for (int id : r.trace_ips)
        if (id < 0 || id >= m.node_count())
            bad("--trace-ips: node " + std::to_string(id) + " does not exist (0.." +
                std::to_string(m.node_count() - 1) + ")");
}

}  // namespace

const std::vector<CombinationRule> &combination_rules()
{
    using R = const RunOptions &;
    using M = const MachineConfig &;
    static const std::vector<CombinationRule> rules = {
        {"--ips x --cluster",
         "at most " + std::to_string(kMaxProcessors) +
             " processors (each has its own SystemC threads; more do not fit in memory)",
         [](R, M m) { return m.processor_count() > kMaxProcessors; }, true},
        {"--map-file", "a table file goes with the file mapping, and only with it",
         [](R, M m) { return mapping_of(m).from_file != !m.map_file.empty(); }, true},
        {"--pilot-size", "only with --map cost or scatter",
         [](R, M m) { return (m.pilot_size[0] > 0 || m.pilot_size[1] > 0) && !mapping_of(m).measured; }, true},
        {"--replicate", "only with --map cost or scatter",
         [](R, M m) { return m.replicate > 0 && !mapping_of(m).measured; }, true},
        {"--quantum", "only meaningful with --style lt",
         [](R, M m) { return m.style == TimingStyle::at && m.quantum_us > 0; }, true},
        {"--trace-from/--trace-to", "only meaningful with --vcd",
         [](R r, M) { return (r.trace_from_us > 0 || r.trace_to_us >= 0) && r.vcd_path.empty(); }, false},
    };
    return rules;
}

void validate_machine(const MachineConfig &m)
{
    validate_table_ranges(m);
    validate_shape(m);
    check_rules(RunOptions{}, m, true);
    validate_mapping(m);
    validate_timing(m);
}

void validate_run(const RunOptions &r, const MachineConfig &m)
{
    check_image_size("--size", r.width, r.height);
    validate_tracing(r, m);
    check_rules(r, m, false);
    if (r.t1_s >= 0 && !(r.t1_s > 0 && r.t1_s <= kMaxSimTimeS))
        bad("--t1: must be a positive number of seconds, at most " + str(kMaxSimTimeS));
    if (!(r.time_limit_s > 0) || r.time_limit_s > kMaxSimTimeS)
        bad("--time-limit: must be above 0 and at most " + str(kMaxSimTimeS) + " s");
}

void validate(const SimConfig &config)
{
    validate_machine(config);
    validate_run(config, config);
}

}  // namespace torusrt
