// config_validation.cpp - the one validator of a run's settings: ranges and combinations,
// checked before the scene is loaded and the model elaborated. Values that do not parse are
// the option parsers' (option_parsing.h); files are checked where they are read.
#include <cmath>
#include <cstdlib>
#include <string>

#include "machine_options.h"
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
    if (m.processor_count() > kMaxProcessors)
        bad("--ips x --cluster: at most " + std::to_string(kMaxProcessors) +
            " processors (each has its own SystemC threads; more do not fit in memory)");
    check_cells(m.cells);
}

void validate_mapping(const MachineConfig &m)
{
    if (m.block < 1)
        bad(m.mapping == RT_MAP_COST ? "--map cost:K: K must be at least 1"
                                     : "--map block-cyclic:B: B must be at least 1");
    if ((m.mapping == RT_MAP_FILE) != !m.map_file.empty())
        bad("--map-file: a table file goes with the file mapping, and only with it");
    if (m.pilot_size[0] > 0 || m.pilot_size[1] > 0) {
        if (!m.measured_mapping()) bad("--pilot-size: only with --map cost or scatter");
        check_image_size("--pilot-size", m.pilot_size[0], m.pilot_size[1]);
    }
    if (m.replicate > 0 && !m.measured_mapping()) bad("--replicate: only with --map cost or scatter");
}

void validate_timing(const MachineConfig &m)
{
    std::string key;
    std::string why = timing_limit_problem(m.timing, &key);
    if (!why.empty()) bad(std::string(timing_option(m, key)) + ": " + why);
    check_step_limits(m.step);
    if (!(m.quantum_us >= 0) || !std::isfinite(m.quantum_us)) bad("--quantum: must not be negative");
    if (m.style == TimingStyle::at && m.quantum_us > 0) bad("--quantum: only meaningful with --style lt");
    if (m.quantum_us > 0 && m.quantum_us < 1e-6) bad("--quantum: 0 or at least 1 ps (SystemC's time resolution)");
    if (m.quantum_us > kMaxSimTimeS * 1e6) bad("--quantum: at most " + str(kMaxSimTimeS) + " s");
}

void validate_tracing(const RunOptions &r, const MachineConfig &m)
{
    if (!(r.trace_from_us >= 0) || (r.trace_to_us >= 0 && r.trace_to_us < r.trace_from_us))
        bad("--trace-from/--trace-to: the window must start at 0 or later and not end before it starts");
    if ((r.trace_from_us > 0 || r.trace_to_us >= 0) && r.vcd_path.empty())
        bad("--trace-from/--trace-to: only meaningful with --vcd");
    for (int id : r.trace_ips)
        if (id < 0 || id >= m.node_count())
            bad("--trace-ips: node " + std::to_string(id) + " does not exist (0.." +
                std::to_string(m.node_count() - 1) + ")");
}

void validate_memory_layout(const rt_memory_layout &l)
{
    if (l.cell_header_bytes > kMaxRecordBytes) bad("--cell-header-bytes: at most " + str(kMaxRecordBytes));
    if (l.list_entry_bytes < 1 || l.list_entry_bytes > kMaxRecordBytes)
        bad("--list-entry-bytes: 1 to " + str(kMaxRecordBytes));
    if (l.object_record_bytes > kMaxRecordBytes)
        bad("--object-record-bytes: 0 (each kind's own size) to " + str(kMaxRecordBytes));
}

}  // namespace

void validate_machine(const MachineConfig &m)
{
    validate_memory_layout(m.memory_layout);
    validate_table_ranges(m);
    validate_shape(m);
    validate_mapping(m);
    validate_timing(m);
}

void validate_run(const RunOptions &r, const MachineConfig &m)
{
    check_image_size("--size", r.width, r.height);
    validate_tracing(r, m);
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
