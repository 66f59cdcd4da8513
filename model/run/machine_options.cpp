// machine_options.cpp - the canonical text of each machine setting. A value read back by its
// option gives the same setting bit for bit: numbers are written with 17 significant digits.
#include "machine_options.h"

#include <cstdio>
#include <cstring>

namespace torusrt {

namespace {

std::string number(double v)
{
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

std::string dims(const std::array<int, 3> &d)
{
    return std::to_string(d[0]) + "x" + std::to_string(d[1]) + "x" + std::to_string(d[2]);
}

std::string size_text(const std::array<unsigned, 2> &s)
{
    return s[0] == 0 ? "" : std::to_string(s[0]) + "x" + std::to_string(s[1]);
}

std::string map_text(const MachineConfig &m)
{
    std::string name = mapping_name(m.mapping);
    if (m.mapping == RT_MAP_BLOCK_CYCLIC || (m.mapping == RT_MAP_COST && m.block > 1))
        name += ":" + std::to_string(m.block);
    return name;
}

double timing_value(const rt_timing &t, const char *key)
{
    for (size_t i = 0; i < rt_timing_key_count(); i++)
        if (std::strcmp(rt_timing_key_name(i), key) == 0) return rt_timing_get(&t, i);
    return 0;
}

}  // namespace

OptionList machine_options(const MachineConfig &m)
{
    OptionList o;
    o.emplace_back("ips", dims(m.ips));
    if (m.mapping != RT_MAP_FILE) o.emplace_back("map", map_text(m));
    o.emplace_back("topology", topology_name(m.topology));
    o.emplace_back("cells", dims(m.cells));
    o.emplace_back("preprocess-count", preprocess_count_name(m.preprocess_count));
    o.emplace_back("queue", std::to_string(m.queue_capacity));
    o.emplace_back("flow", flow_name(m.flow));
    o.emplace_back("timing", m.timing_file);
    o.emplace_back("link-us", number(timing_value(m.timing, "link")));
    o.emplace_back("packet-bytes", number(timing_value(m.timing, "packet_bytes")));
    o.emplace_back("link-bytes-per-us", number(timing_value(m.timing, "link_bytes_per_us")));
    o.emplace_back("max-depth", std::to_string(m.step.max_depth));
    o.emplace_back("min-weight", number(m.step.min_weight));
    o.emplace_back("style", style_name(m.style));
    o.emplace_back("quantum", number(m.quantum_us));
    o.emplace_back("cluster", std::to_string(m.cluster));
    o.emplace_back("data", data_mode_name(m.data));
    o.emplace_back("arbiter", arbiter_name(m.arbiter));
    o.emplace_back("dispatch", dispatch_name(m.dispatch));
    o.emplace_back("cell-header-bytes", std::to_string(m.memory_layout.cell_header_bytes));
    o.emplace_back("list-entry-bytes", std::to_string(m.memory_layout.list_entry_bytes));
    o.emplace_back("object-record-bytes", std::to_string(m.memory_layout.object_record_bytes));
    o.emplace_back("timing-profile", m.timing_base);
    o.emplace_back("map-file", m.map_file);
    o.emplace_back("pilot-size", size_text(m.pilot_size));
    return o;
}

std::string machine_options_toml(const MachineConfig &m)
{
    std::string s;
    for (const auto &kv : machine_options(m)) {
        // A literal string when the value holds a double quote (a path could).
        char quote = kv.second.find('"') == std::string::npos ? '"' : '\'';
        s += kv.first + "=" + quote + kv.second + quote + "\n";
    }
    return s;
}

nlohmann::json machine_options_json(const MachineConfig &m)
{
    nlohmann::json j = nlohmann::json::object();
    for (const auto &kv : machine_options(m)) j[kv.first] = kv.second;
    return j;
}

}  // namespace torusrt
