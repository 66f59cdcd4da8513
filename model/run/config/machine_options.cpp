// machine_options.cpp - the machine's option table. A value written back reads back as the same
// setting bit for bit: numbers are written with 17 significant digits, times in microseconds
// with their unit.
#include "machine_options.h"

#include <algorithm>
#include <climits>
#include <cstdio>
#include <cstring>
#include <unistd.h>

#include "bus_arbiter.h"
#include "cluster_dispatch.h"
#include "option_parsing.h"
#include "rt_grid.h"
#include "timing_choice.h"
#include "timing_limits.h"
#include "user_error.h"

namespace torusrt {

namespace {

std::string dims(const std::array<int, 3> &d)
{
    return std::to_string(d[0]) + "x" + std::to_string(d[1]) + "x" + std::to_string(d[2]);
}

double timing_value(const rt_timing &t, const char *key)
{
    for (size_t i = 0; i < rt_timing_key_count(); i++)
        if (std::strcmp(rt_timing_key_name(i), key) == 0) return rt_timing_get(&t, i);
    return 0;
}

void set_timing(const OptionSpec &spec, rt_timing &t, const char *key, double v)
{
    char msg[RT_MSG_LEN] = "";
    if (rt_timing_set(&t, key, v, msg, sizeof msg) != RT_OK) throw UserError(spec.long_name() + ": " + msg, 2);
}

// block, cyclic, block-cyclic:B, cost, cost:K, scatter.
rt_map_kind parse_mapping(const std::string &option, const std::string &text, int &block)
{
    size_t colon = text.find(':');
    std::string name = text.substr(0, colon);
    for (const auto &entry : kMappingNames) {
        if (name != entry.name || entry.value == RT_MAP_FILE) continue;
        bool parameter = entry.value == RT_MAP_BLOCK_CYCLIC || entry.value == RT_MAP_COST;
        if (colon == std::string::npos && entry.value != RT_MAP_BLOCK_CYCLIC) return entry.value;
        if (colon == std::string::npos || !parameter) break;
        const bool cost = entry.value == RT_MAP_COST;
        block = static_cast<int>(parse_integer(option + (cost ? " cost:K" : " block-cyclic:B"), text.substr(colon + 1),
                                               1, cost ? 64 : 1 << 20));
        return entry.value;
    }
    throw UserError(option + " '" + shown_text(text) + "': expected " + mapping_forms(), 2);
}

std::string map_text(const MachineConfig &m)
{
    std::string name = mapping_name(m.mapping);
    if (m.mapping == RT_MAP_BLOCK_CYCLIC || (m.mapping == RT_MAP_COST && m.block > 1))
        name += ":" + std::to_string(m.block);
    return name;
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

// --timing FILE: the table of the profile with the file's values on top.
void read_timing_file(const OptionSpec &, const std::string &t, MachineConfig &m)
{
    if (t.empty()) return;
    m.timing_profile = choose_timing(m.timing_base, t, &m.timing);
    m.timing_file = t;
    // The table as loaded is input: a value out of range is the file's fault, named at its line.
    std::string key, problem = timing_limit_problem(m.timing, &key);
    long line = problem.empty() ? 0 : timing_key_line(t, key);
    if (!problem.empty())
        throw UserError("--timing: " + shown_text(t) + (line > 0 ? ":" + std::to_string(line) : "") + ": " + problem);
}

// "KEY=VALUE,..." of every timing key, each key once; no empty item (a stray comma).
void read_timing_values(const OptionSpec &spec, const std::string &text, MachineConfig &m)
{
    std::vector<std::string> seen;
    size_t pos = 0;
    while (pos < text.size()) {
        size_t comma = text.find(',', pos);
        std::string item = text.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
        if (item.empty() || (comma + 1 == text.size()))
            throw UserError(spec.long_name() + " '" + shown_text(text) +
                                "': an empty item (a comma with no KEY=VALUE " + (item.empty() ? "before" : "after") +
                                " it)",
                            2);
        size_t eq = item.find('=');
        if (eq == std::string::npos)
            throw UserError(spec.long_name() + " '" + shown_text(item) + "': expected KEY=VALUE", 2);
        std::string key = item.substr(0, eq);
        if (std::find(seen.begin(), seen.end(), key) != seen.end())
            throw UserError(
                spec.long_name() + " '" + shown_text(item) + "': the key '" + shown_text(key) + "' is given twice", 2);
        seen.push_back(key);
        set_timing(spec, m.timing, key.c_str(),
                   parse_real(spec.long_name() + " " + key, item.substr(eq + 1), 0, kMaxTimingUs));
        if (comma == std::string::npos) break;
        pos = comma + 1;
    }
    m.timing_file.clear();
    m.timing_values = true;
    m.timing_profile = m.timing_base + " + values";
}

std::string timing_values_text(const MachineConfig &m)
{
    std::string s;
    for (size_t i = 0; i < rt_timing_key_count(); i++)
        s += std::string(i ? "," : "") + rt_timing_key_name(i) + "=" + number_text(rt_timing_get(&m.timing, i));
    return s;
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
        {{"--ips", "DIMS", K::text, "1", 1, kMaxNodes, "",
          "nodes: P, PXxPY or PXxPYxPZ, at most " + std::to_string(kMaxNodes), G::machine, "ips"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.ips = parse_dims_1_to_3(s.long_name(), t, 1, kMaxNodes);
         },
         [](const MachineConfig &m) { return dims(m.ips); }},
        {{"--topology", "KIND", K::text, "torus", 0, 0, "",
          "network: " + listed(topology_names()) + " (mesh: no wrap-around)", G::machine, "topology"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.topology = registered_name(s.long_name(), t, topology_names());
         },
         [](const MachineConfig &m) { return m.topology; }},
        {{"--route-ties", "RULE", K::text, route_ties_name(kDefaultRouteTies), 0, 0, "",
          choice_help("the way round an even ring when both are equally short", kRouteTiesNames) +
              " (split: + for a packet whose pixel x + y is even, - for odd, so a ring of two uses both its "
              "links; plus: always +, a ring of two then uses one link each way)",
          G::machine, "route-ties"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.route_ties = value_named(s.long_name(), t, kRouteTiesNames);
         },
         [](const MachineConfig &m) { return std::string(route_ties_name(m.route_ties)); },
         needs_even_ring},
        {common_option_spec("--cells"),
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.cells = parse_triple(s.long_name(), t, 1, static_cast<int>(s.max));
         },
         [](const MachineConfig &m) { return dims(m.cells); }},
        {common_option_spec("--preprocess-count"),
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.preprocess_count = value_named(s.long_name(), t, kPreprocessCountNames);
         },
         [](const MachineConfig &m) { return std::string(preprocess_count_name(m.preprocess_count)); }},
        {{"--queue", "N", K::integer, "0", 0, double(kMaxQueue), "packets",
          "capacity of every packet buffer (of each class), 0 = unbounded", G::machine, "queue"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.queue_capacity = static_cast<unsigned>(parse_integer(s.long_name(), t, 0, kMaxQueue));
         },
         [](const MachineConfig &m) { return std::to_string(m.queue_capacity); }},
        {{"--flow", "SCHEME", K::text, "classes", 0, 0, "",
          choice_help("flow control", kFlowNames) + " (none: one class, finite buffers may deadlock, exit 3)",
          G::machine, "flow"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.flow = value_named(s.long_name(), t, kFlowNames);
         },
         [](const MachineConfig &m) { return std::string(flow_name(m.flow)); }},
        {{"--queue-order", "ORDER", K::text, "primaries-first", 0, 0, "",
          choice_help("which waiting packet an IP takes up next", kQueueOrderNames) +
              " (primaries-first: the host's next primary, then the oldest packet; rays-first: the newest "
              "ray packet, then the next primary, then the newest shadow packet)",
          G::machine, "queue-order"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.queue_order = value_named(s.long_name(), t, kQueueOrderNames);
         },
         [](const MachineConfig &m) { return std::string(queue_order_name(m.queue_order)); }},
    };
}

// --link-us acts only while no bandwidth sets the link time.
const char *needs_no_bandwidth(const MachineConfig &m)
{
    return timing_value(m.timing, "link_bytes_per_us") > 0 ? "--link-bytes-per-us 0 (it sets the link time)" : nullptr;
}

// Machine options of the timing (profile, file, link, step limits, style), in dump order.
std::vector<MachineOption> timing_options()
{
    using G = OptionGroup;
    using K = ValueKind;
    const double max_time_s = kMaxSimTimeS;
    return {
        {common_option_spec("--timing-profile"),
         [](const OptionSpec &, const std::string &t, MachineConfig &m) {
             m.timing_profile = choose_timing(t, "", &m.timing);
             m.timing_base = t;
         },
         [](const MachineConfig &m) { return m.timing_base; }},
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
        {{"--link-us", "TIME", K::time, "50", 0, kMaxTimingUs, "us",
          "time per packet on a link; a bare number is microseconds", G::machine, "link-us"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             double us = parse_time(s.long_name(), t, -6, -6);
             if (us > s.max)
                 throw UserError(s.long_name() + " '" + shown_text(t) + "': must be at most " + number_text(s.max) +
                                     " us (1 s)",
                                 2);
             set_timing(s, m.timing, "link", us);
         },
         [](const MachineConfig &m) { return number_text(timing_value(m.timing, "link")); },
         needs_no_bandwidth},
        {{"--packet-bytes", "BYTES", K::real, "28", 0, kMaxTimingUs, "bytes", "packet size on the wire", G::machine,
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
        {{"--link-bytes-per-us", "RATE", K::real, "0", 0, HUGE_VAL, "bytes/us",
          "link bandwidth; when > 0 a packet takes packet-bytes / this (0: --link-us)", G::machine,
          "link-bytes-per-us"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             set_timing(s, m.timing, "link_bytes_per_us", parse_real(s.long_name(), t, s.min, s.max));
         },
         [](const MachineConfig &m) { return number_text(timing_value(m.timing, "link_bytes_per_us")); }},
        {common_option_spec("--max-depth"),
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.step.max_depth = static_cast<int>(parse_integer(s.long_name(), t, 0, static_cast<long long>(s.max)));
         },
         [](const MachineConfig &m) { return std::to_string(m.step.max_depth); }},
        {common_option_spec("--min-weight"),
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.step.min_weight = parse_fraction(s.long_name(), t);
         },
         [](const MachineConfig &m) { return number_text(m.step.min_weight); }},
        {{"--style", "at|lt", K::text, "at", 0, 0, "",
          choice_help("timing style", kStyleNames) + " (approximately or loosely timed; lt needs --quantum)",
          G::machine, "style"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.style = value_named(s.long_name(), t, kStyleNames);
         },
         [](const MachineConfig &m) { return std::string(style_name(m.style)); }},
        {{"--quantum", "TIME", K::time, "0", 0, max_time_s, "s", "loosely-timed global quantum, e.g. 500us, 10ms",
          G::machine, "quantum"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.quantum_us = parse_time(s.long_name(), t, 0, -6);
         },
         [](const MachineConfig &m) { return number_text(m.quantum_us) + "us"; }},
    };
}

// A memory-accounting option: bytes of one field of the memory layout, from `min` to
// kMaxRecordBytes.
template <uint32_t rt_memory_layout::*Field>
MachineOption layout_option(const char *name, const char *fallback, int min, const char *help)
{
    return {{name, "BYTES", ValueKind::integer, fallback, double(min), double(kMaxRecordBytes), "bytes", help,
             OptionGroup::machine, name + 2},
            [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
                m.memory_layout.*Field = static_cast<uint32_t>(
                    parse_integer(s.long_name(), t, static_cast<long long>(s.min), kMaxRecordBytes));
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
        {{"--cluster", "N", K::integer, "1", 1, kMaxCluster, "processors", "processors per torus node on a shared bus",
          G::machine, "cluster"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.cluster = static_cast<int>(parse_integer(s.long_name(), t, 1, kMaxCluster));
         },
         [](const MachineConfig &m) { return std::to_string(m.cluster); }},
        {{"--data", "KIND", K::text, "replicated", 0, 0, "", choice_help("object data in a cluster", kDataModeNames),
          G::machine, "data"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.data = value_named(s.long_name(), t, kDataModeNames);
         },
         [](const MachineConfig &m) { return std::string(data_mode_name(m.data)); },
         clustered_only},
        {{"--arbiter", "KIND", K::text, "round-robin", 0, 0, "",
          "cluster bus arbiter: " + listed(arbiter_policy_names()), G::machine, "arbiter"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.arbiter = registered_name(s.long_name(), t, arbiter_policy_names());
         },
         [](const MachineConfig &m) { return m.arbiter; },
         clustered_only},
        {{"--dispatch", "KIND", K::text, "round-robin", 0, 0, "",
          "cluster packet dispatch: " + listed(dispatch_policy_names()), G::machine, "dispatch"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.dispatch = registered_name(s.long_name(), t, dispatch_policy_names());
         },
         [](const MachineConfig &m) { return m.dispatch; },
         clustered_only},
        layout_option<&rt_memory_layout::cell_header_bytes>("--cell-header-bytes", "4", 0,
                                                            "memory accounting: bytes per cell list"),
        layout_option<&rt_memory_layout::list_entry_bytes>("--list-entry-bytes", "4", 1,
                                                           "memory accounting: bytes per object in a cell list"),
        layout_option<&rt_memory_layout::object_record_bytes>(
            "--object-record-bytes", "0", 0, "memory accounting: bytes per object record (0: each kind's own size)"),
    };
}

// Machine options of the mapping (its kind, an explicit map, the cost pilot, replicas), in dump order.
std::vector<MachineOption> mapping_options()
{
    using G = OptionGroup;
    using K = ValueKind;
    return {
        {{"--map", "KIND", K::text, "cyclic", 0, 0, "", "cell mapping: " + mapping_forms(), G::machine, "map"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.mapping = parse_mapping(s.long_name(), t, m.block);
         },
         map_text},
        {{"--map-file", "FILE", K::file, "", 0, 0, "", "explicit cell -> node table (torusrt-map 1 format)", G::machine,
          "map-file"},
         [](const OptionSpec &, const std::string &t, MachineConfig &m) {
             if (t.empty()) return;
             m.mapping = RT_MAP_FILE;
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
        {{"--replicate", "FRACTION", K::real, "0", 0, 64, "",
          "--map cost or scatter: extra memory per node for copies of hot cells, as a fraction of its data without "
          "them",
          G::machine, "replicate"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.replicate = parse_real(s.long_name(), t, 0, 64);
         },
         [](const MachineConfig &m) { return number_text(m.replicate); }},
        {{"--replica-choice", "RULE", K::text, "nearest", 0, 0, "",
          choice_help("owner of a replicated cell a packet goes to", kReplicaRuleNames) +
              " (nearest: fewest hops, then lowest node; hash: of pixel and depth)",
          G::machine, "replica-choice"},
         [](const OptionSpec &s, const std::string &t, MachineConfig &m) {
             m.replica_choice = value_named(s.long_name(), t, kReplicaRuleNames);
         },
         [](const MachineConfig &m) { return std::string(replica_rule_name(m.replica_choice)); },
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

std::vector<MachineOption> build_table()
{
    std::vector<MachineOption> table;
    for (const TablePart &part : kTableParts)
        for (MachineOption &o : part.options()) {
            o.table = part.name;
            table.push_back(std::move(o));
        }
    return table;
}

// A TOML basic string: quotes, backslashes and control bytes escaped; bytes that are not
// UTF-8 cannot be written at all (TOML files are UTF-8).
std::string toml_string(const std::string &key, const std::string &v)
{
    std::string out = "\"";
    for (size_t i = 0; i < v.size(); i++) {
        unsigned char c = static_cast<unsigned char>(v[i]);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += static_cast<char>(c);
        } else if (c < 0x20 || c == 0x7f) {
            char esc[8];
            std::snprintf(esc, sizeof esc, "\\u%04X", c);
            out += esc;
        } else if (c >= 0x80) {  // one UTF-8 sequence, checked
            size_t n = c >= 0xf0 && c < 0xf5 ? 4 : c >= 0xe0 ? 3 : c >= 0xc2 && c < 0xe0 ? 2 : 0;
            bool ok = n > 0 && i + n <= v.size();
            for (size_t k = 1; ok && k < n; k++) ok = (static_cast<unsigned char>(v[i + k]) & 0xc0) == 0x80;
            if (!ok)
                throw UserError("--" + key + " '" + shown_text(v) +
                                    "': a value that is not UTF-8 cannot be written to a machine file",
                                2);
            out.append(v, i, n);
            i += n - 1;
        } else {
            out += static_cast<char>(c);
        }
    }
    return out + "\"";
}

}  // namespace

std::string mapping_forms() { return "block, cyclic, block-cyclic:B, cost, cost:K or scatter"; }

const std::vector<MachineOption> &machine_option_table()
{
    static const std::vector<MachineOption> table = build_table();
    return table;
}

MachineConfig machine_from_texts(const std::map<std::string, std::string> &given)
{
    MachineConfig m;
    m.step = rt_step_params_default();
    m.timing_base = rt_timing_default_profile();
    m.timing_profile = choose_timing(m.timing_base, "", &m.timing);
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
        if (key == "map" && m.mapping == RT_MAP_FILE) continue;  // the map file holds the mapping
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

std::string machine_options_toml(const MachineConfig &m, bool with_timing)
{
    const nlohmann::json tables = machine_option_tables_json(m);
    std::string s, table;
    for (const auto &kv : machine_options(m, with_timing)) {
        const std::string &in = tables.at(kv.first).get_ref<const std::string &>();
        if (in != table) s += (table.empty() ? "[" : "\n[") + in + "]\n";
        table = in;
        s += kv.first + "=" + toml_string(kv.first, kv.second) + "\n";
    }
    return s;
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
        if (o.spec.key != "map" || m.mapping != RT_MAP_FILE) j[o.spec.key] = o.table;
    return j;
}

}  // namespace torusrt
