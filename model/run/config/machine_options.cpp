// machine_options.cpp - the machine's option table. A value written back reads back as the same
// setting bit for bit: numbers are written with 17 significant digits, times in microseconds
// with their unit.
#include "machine_options.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <unistd.h>

#include "bus_arbiter.h"
#include "cluster_dispatch.h"
#include "mapping.h"
#include "option_parsing.h"
#include "rt_grid.h"
#include "timing_choice.h"
#include "timing_limits.h"
#include "timing_option_texts.h"
#include "user_error.h"

namespace torusrt {

namespace {

std::string dims(const std::array<int, 3> &d)
{
    return std::to_string(d[0]) + "x" + std::to_string(d[1]) + "x" + std::to_string(d[2]);
}

// The help's forms of a default: --ips without its trailing dimensions of 1 ("4x2", "1"), --cells
// "N" for N x N x N, a weight 1/N as "1/N".
std::string short_ips(const std::array<int, 3> &d)
{
    int shown = d[2] != 1 ? 3 : d[1] != 1 ? 2 : 1;  // up to the last dimension above 1
    std::string s = std::to_string(d[0]);
    for (int axis = 1; axis < shown; axis++) s += "x" + std::to_string(d[axis]);
    return s;
}
std::string short_cells(const std::array<int, 3> &d)
{
    return d[0] == d[1] && d[1] == d[2] ? std::to_string(d[0]) : dims(d);
}
std::string short_fraction(double w)
{
    double n = 1 / w;
    return w > 0 && n == std::floor(n) && 1 / n == w ? "1/" + number_text(n) : number_text(w);
}

// NAME or NAME:N of a mapping --map chooses (the registry's forms); N into `block`.
void parse_mapping(const std::string &option, const std::string &text, MachineConfig &m)
{
    size_t colon = text.find(':');
    const Mapping *mapping = find_mapping(text.substr(0, colon));
    bool given = colon != std::string::npos;
    bool fits =
        mapping && !mapping->from_file &&
        (given ? mapping->parameter != MappingParameter::none : mapping->parameter != MappingParameter::required);
    if (!fits) throw UserError(option + " '" + shown_text(text) + "': expected " + mapping_forms(), 2);
    if (given)
        m.block = static_cast<int>(parse_integer(option + " " + mapping->name + ":" + mapping->parameter_name,
                                                 text.substr(colon + 1), 1, mapping->parameter_max));
    m.mapping = mapping->name;
}

// The mapping is a table read from --map-file.
bool from_file(const MachineConfig &m)
{
    const Mapping *mapping = find_mapping(m.mapping);
    return mapping && mapping->from_file;
}

// `path` as an absolute path (the working folder in front of a relative one; an absolute one as
// given): a machine file reads its relative paths from its own folder, so the path written back
// names the same file wherever the dump or a report's machine file is put.
std::string absolute_path(const std::string &path)
{
    if (path.empty() || path[0] == '/') return path;
    char cwd[PATH_MAX];
    if (getcwd(cwd, sizeof cwd) == nullptr) return path;  // a removed working folder: as given
    std::string rel = path;
    while (rel.rfind("./", 0) == 0) rel.erase(0, rel.find_first_not_of('/', 1));
    return (std::strcmp(cwd, "/") == 0 ? "" : std::string(cwd)) + "/" + rel;
}

template <typename E, size_t N> std::string choice_help(const char *what, const NamedValue<E> (&table)[N])
{
    return std::string(what) + ": " + names_of(table);
}

// "a, b or c": a policy registry's names for the help and messages.
std::string listed(const std::vector<std::string> &names)
{
    std::string s;
    for (size_t i = 0; i < names.size(); i++) s += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
    return s;
}

// `text` if a policy registry knows it; UserError (exit 2) naming `option` and the names.
std::string registered_name(const std::string &option, const std::string &text, const std::vector<std::string> &names)
{
    for (const std::string &n : names)
        if (n == text) return text;
    throw UserError(option + " '" + text + "': expected " + listed(names), 2);
}

// --route-ties acts only where a packet may go either way round: a ring of an even number of
// nodes, which a torus has in a dimension of --ips that is even (the topology says).
const char *needs_even_ring(const MachineConfig &m)
{
    rt_topology t;
    const int cube[3] = {2, 2, 2};  // a shape on which a topology with ways round has a tie
    if (rt_topology_make(m.topology.c_str(), cube, &t, nullptr, 0) == RT_OK && !rt_topology_has_ties(&t)) {
        static std::string text;
        text = "--topology torus (a " + m.topology + " has no way round)";
        return text.c_str();
    }
    if (rt_topology_make(m.topology.c_str(), m.ips.data(), &t, nullptr, 0) != RT_OK || rt_topology_has_ties(&t))
        return nullptr;
    return "an even ring (a dimension of --ips with an even number of nodes)";
}

// Machine options of the network (nodes, topology, grid, buffers, flow), in dump order.
std::vector<MachineOption> network_options()
{
    using G = OptionGroup;
    using K = ValueKind;
    return {
        {{"--ips", "DIMS", K::text, "", 1, kMaxNodes, "",
          "nodes: P, PXxPY or PXxPYxPZ, at most " + std::to_string(kMaxNodes), G::machine, "ips"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.ips = parse_dims_1_to_3(s.long_name(), t, static_cast<int>(s.min), static_cast<int>(s.max));
         },
         [](const MachineConfig &m) { return dims(m.ips); },
         [](const MachineConfig &m, nlohmann::json &j) {
             j["ips"] = m.ips;
             j["nodes"] = m.node_count();
         },
         nullptr,
         "1",
         [](const MachineConfig &m) { return short_ips(m.ips); }},
        {{"--topology", "KIND", K::text, "", 0, 0, "",
          "network: " + listed(topology_names()) + " (mesh: no wrap-around)", G::machine, "topology"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.topology = registered_name(s.long_name(), t, topology_names());
         },
         [](const MachineConfig &m) { return m.topology; },
         [](const MachineConfig &m, nlohmann::json &j) { j["topology"] = m.topology; }},
        {{"--route-ties", "RULE", K::text, "", 0, 0, "",
          choice_help("the way round an even ring when both are equally short", kRouteTiesNames) +
              " (split: + for a packet whose pixel x + y is even, - for odd, so a ring of two uses both its "
              "links; plus: always +, a ring of two then uses one link each way)",
          G::machine, "route-ties"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.route_ties = value_named(s.long_name(), t, kRouteTiesNames);
         },
         [](const MachineConfig &m) { return std::string(route_ties_name(m.route_ties)); },
         [](const MachineConfig &m, nlohmann::json &j) { j["route_ties"] = route_ties_name(m.route_ties); },
         needs_even_ring},
        {common_option_spec("--cells"),
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.cells = parse_triple(s.long_name(), t, static_cast<int>(s.min), static_cast<int>(s.max));
         },
         [](const MachineConfig &m) { return dims(m.cells); }, nullptr, nullptr, nullptr,
         [](const MachineConfig &m) { return short_cells(m.cells); }},
        {common_option_spec("--preprocess-count"),
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.preprocess_count = value_named(s.long_name(), t, kPreprocessCountNames);
         },
         [](const MachineConfig &m) { return std::string(preprocess_count_name(m.preprocess_count)); }},
        {{"--queue", "N", K::integer, "", 0, double(kMaxQueue), "packets",
          "capacity of every packet buffer (of each class), 0 = unbounded", G::machine, "queue"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.queue_capacity =
                 static_cast<unsigned>(parse_integer(s.long_name(), t, 0, static_cast<long long>(s.max)));
         },
         [](const MachineConfig &m) { return std::to_string(m.queue_capacity); },
         [](const MachineConfig &m, nlohmann::json &j) { j["queue"] = m.queue_capacity; },
         nullptr,
         "0"},  // T(1) is the unconstrained sequential time
        {{"--flow", "SCHEME", K::text, "", 0, 0, "",
          choice_help("flow control", kFlowNames) + " (none: one class, finite buffers may deadlock, exit 3)",
          G::machine, "flow"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.flow = value_named(s.long_name(), t, kFlowNames);
         },
         [](const MachineConfig &m) { return std::string(flow_name(m.flow)); }},
        {{"--queue-order", "ORDER", K::text, "", 0, 0, "",
          choice_help("which waiting packet an IP takes up next", kQueueOrderNames) +
              " (primaries-first: the host's next primary, then the oldest packet; rays-first: the newest "
              "ray packet, then the next primary, then the newest shadow packet)",
          G::machine, "queue-order"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.queue_order = value_named(s.long_name(), t, kQueueOrderNames);
         },
         [](const MachineConfig &m) { return std::string(queue_order_name(m.queue_order)); },
         [](const MachineConfig &m, nlohmann::json &j) { j["queue_order"] = queue_order_name(m.queue_order); }},
    };
}

// A link time: a bare number in microseconds (the unit is in the option's name), at most the
// spec's maximum.
double link_time_us(const OptionSpec &s, const std::string &text)
{
    double us = parse_time(s.long_name(), text, -6, -6);
    if (us > s.max)
        throw UserError(
            s.long_name() + " '" + shown_text(text) + "': must be at most " + number_text(s.max) + " us (1 s)", 2);
    return us;
}

// --link-us acts only while no bandwidth sets the link time.
const char *needs_no_bandwidth(const MachineConfig &m)
{
    return timing_value(m.timing, "link_bytes_per_us") > 0 ? "--link-bytes-per-us 0 (it sets the link time)" : nullptr;
}

// Machine options of the timing table (profile, file, values, link), in dump order.
std::vector<MachineOption> timing_table_options()
{
    using G = OptionGroup;
    using K = ValueKind;
    return {
        {common_option_spec("--timing-profile"),
         [](const OptionSpec &, const std::string &t, MachineConfig &m) {
             m.timing_profile = choose_timing(t, "", &m.timing);
             m.timing_base = t;
         },
         [](const MachineConfig &m) { return m.timing_base; },
         [](const MachineConfig &m, nlohmann::json &j) {
             j["timing_profile"] = m.timing_profile;  // the label: the profile with its file or values
             j["timing"] = timing_json(m.timing);
         }},
        {common_option_spec("--timing"), read_timing_file,
         [](const MachineConfig &m) { return absolute_path(m.timing_file); }},
        {{"--timing-values", "LIST", K::text, "", 0, 0, "",
          "KEY=VALUE,... for every key of the timing table, in place of a profile's and a file's "
          "(--dump-config --with-timing writes it)",
          G::machine, "timing-values"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             if (!t.empty()) read_timing_values(s, t, m);  // a machine file's "": not given
         },
         [](const MachineConfig &m) { return m.timing_values ? timing_values_text(m) : std::string(); }},
        {{"--link-us", "TIME", K::time, "", 0, kMaxTimingUs, "us",
          "time per packet on a link; a bare number is microseconds", G::machine, "link-us"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             set_timing(s, m.timing, "link", link_time_us(s, t));
         },
         [](const MachineConfig &m) { return number_text(timing_value(m.timing, "link")); },
         nullptr,
         needs_no_bandwidth},
        {{"--packet-bytes", "BYTES", K::real, "", 0, kMaxTimingUs, "bytes", "packet size on the wire", G::machine,
          "packet-bytes"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             // 0 passes the table's range but not the timing (no size): one range message for all.
             double bytes = parse_real(s.long_name(), t, -HUGE_VAL, HUGE_VAL);
             if (!(bytes > 0 && bytes <= s.max))
                 throw UserError(s.long_name() + " '" + shown_text(t) + "': must be more than 0 and at most " +
                                     number_text(s.max),
                                 2);
             set_timing(s, m.timing, "packet_bytes", bytes);
         },
         [](const MachineConfig &m) { return number_text(timing_value(m.timing, "packet_bytes")); }},
        {{"--link-bytes-per-us", "RATE", K::real, "", 0, HUGE_VAL, "bytes/us",
          "link bandwidth; when > 0 a packet takes packet-bytes / this (0: --link-us)", G::machine,
          "link-bytes-per-us"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             set_timing(s, m.timing, "link_bytes_per_us", parse_real(s.long_name(), t, s.min, s.max));
         },
         [](const MachineConfig &m) { return number_text(timing_value(m.timing, "link_bytes_per_us")); }},
        {{"--link-setup-us", "TIME", K::time, "", 0, kMaxTimingUs, "us",
          "fixed time per packet on a link before its transfer (--link-us or the bandwidth's); a bare number is "
          "microseconds",
          G::machine, "link-setup-us"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             set_timing(s, m.timing, "link_setup", link_time_us(s, t));
         },
         [](const MachineConfig &m) { return number_text(timing_value(m.timing, "link_setup")); }},
    };
}

// Machine options of the shade tree's limits and the timing style, in dump order (the timing table).
std::vector<MachineOption> step_and_style_options()
{
    using G = OptionGroup;
    using K = ValueKind;
    const double max_time_s = kMaxSimTimeS;
    return {
        {common_option_spec("--max-depth"),
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.step.max_depth = static_cast<int>(parse_integer(s.long_name(), t, 0, static_cast<long long>(s.max)));
         },
         [](const MachineConfig &m) { return std::to_string(m.step.max_depth); },
         [](const MachineConfig &m, nlohmann::json &j) { j["max_depth"] = m.step.max_depth; }},
        {common_option_spec("--min-weight"),
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.step.min_weight = parse_fraction(s.long_name(), t);
         },
         [](const MachineConfig &m) { return number_text(m.step.min_weight); },
         [](const MachineConfig &m, nlohmann::json &j) { j["min_weight"] = m.step.min_weight; }, nullptr, nullptr,
         [](const MachineConfig &m) { return short_fraction(m.step.min_weight); }},
        {{"--style", "at|lt", K::text, "", 0, 0, "",
          choice_help("timing style", kStyleNames) + " (approximately or loosely timed; lt needs --quantum)",
          G::machine, "style"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.style = value_named(s.long_name(), t, kStyleNames);
         },
         [](const MachineConfig &m) { return std::string(style_name(m.style)); },
         [](const MachineConfig &m, nlohmann::json &j) { j["style"] = style_name(m.style); },
         nullptr,
         "at"},
        {{"--quantum", "TIME", K::time, "", 0, max_time_s, "s", "loosely-timed global quantum, e.g. 500us, 10ms",
          G::machine, "quantum"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.quantum_us = parse_time(s.long_name(), t, 0, -6);
         },
         [](const MachineConfig &m) { return number_text(m.quantum_us) + "us"; },
         [](const MachineConfig &m, nlohmann::json &j) { j["quantum_us"] = m.quantum_us; },
         nullptr,
         "0",
         [](const MachineConfig &m) { return number_text(m.quantum_us / 1e6); }},  // a bare number: seconds
    };
}

// The machine file's [timing] table: the timing table's options, then the step limits and style.
std::vector<MachineOption> timing_options()
{
    std::vector<MachineOption> options = timing_table_options();
    for (MachineOption &o : step_and_style_options()) options.push_back(std::move(o));
    return options;
}

// A memory-accounting option: bytes of one field of the memory layout, from `min` to
// kMaxRecordBytes.
template <uint32_t rt_memory_layout::*Field> MachineOption layout_option(const char *name, int min, const char *help)
{
    return {{name, "BYTES", ValueKind::integer, "", double(min), double(kMaxRecordBytes), "bytes", help,
             OptionGroup::machine, name + 2},
            [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
                m.memory_layout.*Field = static_cast<uint32_t>(
                    parse_integer(s.long_name(), t, static_cast<long long>(s.min), static_cast<long long>(s.max)));
            },
            [](const MachineConfig &m) { return std::to_string(m.memory_layout.*Field); }};
}

// An option of the cluster bus and its memory: it acts only with processors sharing a node.
const char *clustered_only(const MachineConfig &m) { return m.cluster > 1 ? nullptr : "--cluster above 1"; }

// Machine options of clusters and the memory accounting, in dump order.
std::vector<MachineOption> cluster_options()
{
    using G = OptionGroup;
    using K = ValueKind;
    return {
        {{"--cluster", "N", K::integer, "", 1, kMaxCluster, "processors", "processors per torus node on a shared bus",
          G::machine, "cluster"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.cluster = static_cast<int>(
                 parse_integer(s.long_name(), t, static_cast<long long>(s.min), static_cast<long long>(s.max)));
         },
         [](const MachineConfig &m) { return std::to_string(m.cluster); },
         [](const MachineConfig &m, nlohmann::json &j) {
             j["cluster"] = m.cluster;
             j["processors"] = m.processor_count();
         },
         nullptr,
         "1"},
        {{"--data", "KIND", K::text, "", 0, 0, "", choice_help("object data in a cluster", kDataModeNames), G::machine,
          "data"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.data = value_named(s.long_name(), t, kDataModeNames);
         },
         [](const MachineConfig &m) { return std::string(data_mode_name(m.data)); },
         [](const MachineConfig &m, nlohmann::json &j) { j["data"] = data_mode_name(m.data); },
         clustered_only},
        {{"--arbiter", "KIND", K::text, "", 0, 0, "", "cluster bus arbiter: " + listed(arbiter_policy_names()),
          G::machine, "arbiter"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.arbiter = registered_name(s.long_name(), t, arbiter_policy_names());
         },
         [](const MachineConfig &m) { return m.arbiter; },
         [](const MachineConfig &m, nlohmann::json &j) { j["arbiter"] = m.arbiter; },
         clustered_only},
        {{"--dispatch", "KIND", K::text, "", 0, 0, "", "cluster packet dispatch: " + listed(dispatch_policy_names()),
          G::machine, "dispatch"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.dispatch = registered_name(s.long_name(), t, dispatch_policy_names());
         },
         [](const MachineConfig &m) { return m.dispatch; },
         [](const MachineConfig &m, nlohmann::json &j) { j["dispatch"] = m.dispatch; },
         clustered_only},
        layout_option<&rt_memory_layout::cell_header_bytes>("--cell-header-bytes", 0,
                                                            "memory accounting: bytes per cell list"),
        layout_option<&rt_memory_layout::list_entry_bytes>("--list-entry-bytes", 1,
                                                           "memory accounting: bytes per object in a cell list"),
        layout_option<&rt_memory_layout::object_record_bytes>(
            "--object-record-bytes", 0, "memory accounting: bytes per object record (0: each kind's own size)"),
    };
}

// Machine options of the mapping (its kind, an explicit map, the cost pilot, replicas), in dump order.
std::vector<MachineOption> mapping_options()
{
    using G = OptionGroup;
    using K = ValueKind;
    return {
        {{"--map", "KIND", K::text, "", 0, 0, "", "cell mapping: " + mapping_forms(), G::machine, "map"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) { parse_mapping(s.long_name(), t, m); },
         mapping_text,
         [](const MachineConfig &m, nlohmann::json &j) {
             j["mapping"] = m.mapping;
             j["block"] = m.block;
         },
         nullptr,
         "block"},  // one node owns every cell, whatever the mapping
        {{"--map-file", "FILE", K::file, "", 0, 0, "", "explicit cell -> node table (torusrt-map 1 format)", G::machine,
          "map-file"},
         [](const OptionSpec &, const std::string &t, MachineConfig &m) {
             if (t.empty()) return;
             m.mapping = file_mapping_name();
             m.map_file = t;
         },
         [](const MachineConfig &m) { return absolute_path(m.map_file); }},
        {{"--pilot-size", "WxH", K::text, "", 0, 0, "",
          "image size of the --map cost or scatter pilot run (default the image's)", G::machine, "pilot-size"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             if (!t.empty()) m.pilot_size = parse_size(s.long_name(), t);
         },
         [](const MachineConfig &m) {
             return m.pilot_size[0] == 0 ? std::string()
                                         : std::to_string(m.pilot_size[0]) + "x" + std::to_string(m.pilot_size[1]);
         }},
        {{"--replicate", "FRACTION", K::real, "", 0, 64, "",
          "--map cost or scatter: extra memory per node for copies of hot cells, as a fraction of its data without "
          "them",
          G::machine, "replicate"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.replicate = parse_real(s.long_name(), t, s.min, s.max);
         },
         [](const MachineConfig &m) { return number_text(m.replicate); },
         nullptr,
         nullptr,
         "0"},
        {{"--replica-choice", "RULE", K::text, "", 0, 0, "",
          choice_help("owner of a replicated cell a packet goes to", kReplicaRuleNames) +
              " (nearest: fewest hops, then lowest node; hash: of pixel and depth)",
          G::machine, "replica-choice"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.replica_choice = value_named(s.long_name(), t, kReplicaRuleNames);
         },
         [](const MachineConfig &m) { return std::string(replica_rule_name(m.replica_choice)); },
         nullptr,
         [](const MachineConfig &m) { return m.replicate > 0 ? nullptr : "--replicate above 0"; }},
    };
}

// The parts of the table, each a table of the machine file, in dump order.
struct TablePart {
    const char *name;
    std::vector<MachineOption> (*options)();
};
const TablePart kTableParts[] = {{"network", network_options},
                                 {"timing", timing_options},
                                 {"cluster", cluster_options},
                                 {"mapping", mapping_options}};

// The table with each entry's machine-file table and its default as a default machine has it.
std::vector<MachineOption> build_table()
{
    const MachineConfig defaults;
    std::vector<MachineOption> table;
    for (const TablePart &part : kTableParts)
        for (MachineOption &o : part.options()) {
            o.table = part.name;
            o.spec.default_text = o.default_text ? o.default_text(defaults) : o.write(defaults);
            table.push_back(std::move(o));
        }
    return table;
}

}  // namespace

const std::vector<MachineOption> &machine_option_table()
{
    static const std::vector<MachineOption> table = build_table();
    return table;
}

MachineConfig machine_from_texts(const std::map<std::string, std::string> &given)
{
    MachineConfig m;
    if (given.count("--map") && given.count("--map-file") && !given.at("--map-file").empty())
        throw UserError("--map-file: give either --map or --map-file, not both", 2);
    for (const MachineOption &o : machine_option_table()) {
        auto it = given.find(o.spec.long_name());
        if (it != given.end()) o.read(o.spec, it->second, m);
    }
    return m;
}

OptionList machine_options(const MachineConfig &m, bool with_timing)
{
    OptionList list;
    for (const MachineOption &o : machine_option_table()) {
        const std::string &key = o.spec.key;
        if (key == "map" && from_file(m)) continue;  // the map file holds the mapping
        if (with_timing && key == "timing-values") list.emplace_back(key, timing_values_text(m));
        else if (with_timing && key == "timing") list.emplace_back(key, std::string());
        else list.emplace_back(key, o.write(m));
    }
    return list;
}

std::vector<std::string> machine_file_tables()
{
    std::vector<std::string> names;
    for (const TablePart &part : kTableParts) names.push_back(part.name);
    return names;
}

MachineConfig one_processor_machine(const MachineConfig &machine)
{
    MachineConfig one = machine;
    for (const MachineOption &o : machine_option_table())
        if (o.one_processor) o.read(o.spec, o.one_processor, one);
    return one;
}

nlohmann::json machine_config_json(const MachineConfig &m)
{
    nlohmann::json j = nlohmann::json::object();
    for (const MachineOption &o : machine_option_table())
        if (o.json) o.json(m, j);
    return j;
}

nlohmann::json machine_options_json(const MachineConfig &m)
{
    nlohmann::json j = nlohmann::json::object();
    for (const auto &kv : machine_options(m)) j[kv.first] = kv.second;
    return j;
}

nlohmann::json machine_option_order_json(const MachineConfig &m)
{
    nlohmann::json j = nlohmann::json::array();
    for (const auto &kv : machine_options(m)) j.push_back(kv.first);
    return j;
}

nlohmann::json machine_option_tables_json(const MachineConfig &m)
{
    nlohmann::json j = nlohmann::json::object();
    for (const MachineOption &o : machine_option_table())
        if (o.spec.key != "map" || !from_file(m)) j[o.spec.key] = o.table;
    return j;
}

}  // namespace torusrt
