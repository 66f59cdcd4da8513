// time_report.cpp - where the time goes: each processor's image time split into busy time by
// operation (and the bus and memory waits inside its steps) and idle time (starved, blocked,
// drained); the efficiency as work x balance x finish spread; packet and pixel latencies; the
// busiest links.
#include <algorithm>
#include <cstdio>
#include <numeric>
#include <string>

#include "routing.h"
#include "run_report.h"
#include "significant.h"

namespace torusrt {

namespace {

// The timing table's operations, as the JSON names them, with their counts and costs.
struct OpCost {
    const char *name;
    uint64_t rt_op_counts::*count;
    double rt_timing::*cost;
};
const OpCost kOpCosts[] = {
    {"test_miss", &rt_op_counts::tests_missed, &rt_timing::test_miss_us},
    {"test_hit", &rt_op_counts::tests_hit, &rt_timing::test_hit_us},
    {"dda_step", &rt_op_counts::dda_steps, &rt_timing::dda_step_us},
    {"shading", &rt_op_counts::shadings, &rt_timing::shading_us},
    {"reflection", &rt_op_counts::reflection_vectors, &rt_timing::reflection_us},
    {"refraction", &rt_op_counts::refraction_vectors, &rt_timing::refraction_us},
    {"packet_analysis", &rt_op_counts::packets_analysed, &rt_timing::packet_analysis_us},
    {"packet_creation", &rt_op_counts::packets_created, &rt_timing::packet_creation_us},
    {"handover_send", &rt_op_counts::handovers_sent, &rt_timing::handover_send_us},
    {"handover_receive", &rt_op_counts::handovers_received, &rt_timing::handover_receive_us},
    {"cell_step_packet", &rt_op_counts::cell_steps, &rt_timing::cell_step_packet_us},
    {"fb_write", &rt_op_counts::fb_writes, &rt_timing::fb_write_us},
};

// One processor's (or the machine's summed) time, in seconds.
struct Breakdown {
    double ops[sizeof kOpCosts / sizeof kOpCosts[0]] = {};
    double bus_memory_wait = 0, starved = 0, blocked = 0, drained = 0;
    double busy() const { return std::accumulate(std::begin(ops), std::end(ops), 0.0) + bus_memory_wait; }
    double idle() const { return starved + blocked + drained; }
    void add(const Breakdown &b)
    {
        for (size_t i = 0; i < std::size(ops); i++) ops[i] += b.ops[i];
        bus_memory_wait += b.bus_memory_wait;
        starved += b.starved;
        blocked += b.blocked;
        drained += b.drained;
    }
};

Breakdown breakdown_of(const IpStats &p, const rt_timing &t, double T)
{
    Breakdown b;
    double ops = 0;
    for (size_t i = 0; i < std::size(kOpCosts); i++) {
        b.ops[i] = static_cast<double>(p.ops.*kOpCosts[i].count) * (t.*kOpCosts[i].cost) * 1e-6;
        ops += b.ops[i];
    }
    // A step's time beyond its operations is the shared-data fetches' bus and memory waits; a
    // remainder within SystemC's resolution (1 ps) per step is the sum's rounding.
    double wait = p.busy_s - ops;
    b.bus_memory_wait = wait > 1e-12 * static_cast<double>(p.packets_in + 1) ? wait : 0.0;
    b.starved = p.starved_s;
    b.blocked = p.blocked_s;
    b.drained = T - p.last_done_s;
    return b;
}

nlohmann::json breakdown_json(const Breakdown &b)
{
    nlohmann::json busy;
    for (size_t i = 0; i < std::size(kOpCosts); i++) busy[kOpCosts[i].name] = b.ops[i];
    busy["bus_memory_wait"] = b.bus_memory_wait;
    return {{"busy", busy},           {"busy_s", b.busy()},     {"starved_s", b.starved},
            {"blocked_s", b.blocked}, {"drained_s", b.drained}, {"idle_s", b.idle()}};
}

nlohmann::json histogram_json(const LogHistogram &h)
{
    nlohmann::json buckets = nlohmann::json::array();
    for (int k = -1; k < LogHistogram::kOctaves; k++)
        if (uint64_t n = h.octave_count(k))
            buckets.push_back(
                {{"from_us", k < 0 ? 0.0 : std::ldexp(1.0, k)}, {"to_us", std::ldexp(1.0, k + 1)}, {"count", n}});
    return {{"count", h.count()},         {"mean_us", h.mean()},        {"p50_us", h.percentile(50)},
            {"p95_us", h.percentile(95)}, {"p99_us", h.percentile(99)}, {"max_us", h.max()},
            {"histogram", buckets}};
}

std::string percent(double part, double whole) { return whole > 0 ? sig4(100 * part / whole) + " %" : "-"; }

}  // namespace

nlohmann::json time_breakdown_json(const RunReport &r)
{
    Breakdown machine;
    nlohmann::json per_ip = nlohmann::json::array();
    for (const IpStats &p : r.ips) {
        Breakdown b = breakdown_of(p, r.config.timing, r.sim_time_s);
        machine.add(b);
        per_ip.push_back(breakdown_json(b));
    }
    nlohmann::json j = breakdown_json(machine);
    j["processor_s"] = r.sim_time_s * static_cast<double>(r.ips.size());
    j["per_ip"] = std::move(per_ip);
    return j;
}

nlohmann::json latency_json(const PacketLatency &lat)
{
    nlohmann::json packets;
    for (int k = 0; k < PacketLatency::kKinds; k++) {
        const KindLatency &l = lat.kind(k);
        double n = l.total.count() ? static_cast<double>(l.total.count()) : 1.0;
        nlohmann::json j = histogram_json(l.total);
        j["queued_us"] = {{"mean", l.queued_us / n}, {"max", l.queued_max_us}};
        j["links_us"] = {{"mean", l.links_us / n}, {"max", l.links_max_us}};
        j["processing_us"] = {{"mean", l.processing_us / n}, {"max", l.processing_max_us}};
        j["hops"] = {{"mean", static_cast<double>(l.hops) / n}, {"max", l.hops_max}};
        packets[PacketLatency::kind_name(k)] = std::move(j);
    }
    return {{"packets", packets}, {"pixels", histogram_json(lat.pixels())}};
}

void print_efficiency_factors(const RunReport &r, std::FILE *out)
{
    if (r.ips.empty() || r.sim_time_s <= 0) return;
    double max_busy = 0;
    for (const IpStats &p : r.ips) max_busy = std::max(max_busy, p.busy_s);
    double n = static_cast<double>(r.ips.size()), mean_busy = r.totals.busy_s / n;
    double work = mean_busy > 0 ? r.facts.t1_s / (n * mean_busy) : 0.0;
    double balance = max_busy > 0 ? mean_busy / max_busy : 0.0;
    std::fprintf(out,
                 "               = work %.1f %% x balance %.1f %% x finish spread %.1f %%"
                 "   (T(1)/(n mean busy), mean/max busy, max busy/T(n))\n",
                 100 * work, 100 * balance, 100 * max_busy / r.sim_time_s);
}

void print_time_split(const RunReport &r, std::FILE *out)
{
    if (r.ips.empty() || r.sim_time_s <= 0) return;
    Breakdown m;
    for (const IpStats &p : r.ips) m.add(breakdown_of(p, r.config.timing, r.sim_time_s));
    double nT = static_cast<double>(r.ips.size()) * r.sim_time_s;
    // The busy time's parts, largest first; those under 0.5 % of n T(n) are summed as "other".
    std::vector<std::pair<double, std::string>> parts;
    for (size_t i = 0; i < std::size(kOpCosts); i++) parts.push_back({m.ops[i], kOpCosts[i].name});
    parts.push_back({m.bus_memory_wait, "bus_memory_wait"});
    std::stable_sort(parts.begin(), parts.end(), [](const auto &a, const auto &b) { return a.first > b.first; });
    std::string busy;
    double other = 0;
    for (const auto &p : parts) {
        if (p.first < 0.005 * nT) {
            other += p.first;
            continue;
        }
        busy += (busy.empty() ? "" : ", ") + p.second + " " + percent(p.first, nT);
    }
    if (other > 0) busy += (busy.empty() ? "" : ", ") + std::string("other ") + percent(other, nT);
    std::fprintf(out,
                 "  time split   of n T(n) = %s processor-s: busy %s, idle %s = starved %s + blocked %s"
                 " + drained %s\n"
                 "               busy: %s\n",
                 sig4(nT).c_str(), percent(m.busy(), nT).c_str(), percent(m.idle(), nT).c_str(),
                 percent(m.starved, nT).c_str(), percent(m.blocked, nT).c_str(), percent(m.drained, nT).c_str(),
                 busy.c_str());
}

void print_latency(const RunReport &r, std::FILE *out)
{
    if (!r.latency.is_object()) return;
    std::string line;
    for (int k = 0; k < PacketLatency::kKinds; k++) {
        const auto &j = r.latency["packets"][PacketLatency::kind_name(k)];
        if (j["count"].get<uint64_t>() == 0) continue;
        line +=
            std::string(line.empty() ? "" : "\n               ") + PacketLatency::kind_name(k) + " mean " +
            sig4(j["mean_us"].get<double>() / 1e3) + " p95 " + sig4(j["p95_us"].get<double>() / 1e3) + " max " +
            sig4(j["max_us"].get<double>() / 1e3) + " ms (queued " + sig4(j["queued_us"]["mean"].get<double>() / 1e3) +
            ", links " + sig4(j["links_us"]["mean"].get<double>() / 1e3) + ", processing " +
            sig4(j["processing_us"]["mean"].get<double>() / 1e3) + "), hops " + sig4(j["hops"]["mean"].get<double>());
    }
    const auto &px = r.latency["pixels"];
    if (px["count"].get<uint64_t>())
        line += "\n               pixel mean " + sig4(px["mean_us"].get<double>() / 1e3) + " p50 " +
                sig4(px["p50_us"].get<double>() / 1e3) + " p95 " + sig4(px["p95_us"].get<double>() / 1e3) + " max " +
                sig4(px["max_us"].get<double>() / 1e3) + " ms, primary taken up to last contribution";
    if (!line.empty()) std::fprintf(out, "  latency      %s\n", line.c_str());
}

void print_busiest_links(const RunReport &r, std::FILE *out)
{
    if (r.links.empty() || r.sim_time_s <= 0) return;
    std::vector<const LinkStats *> order;
    for (const LinkStats &l : r.links) order.push_back(&l);
    std::stable_sort(order.begin(), order.end(),
                     [](const LinkStats *a, const LinkStats *b) { return a->busy_s > b->busy_s; });
    std::string text;
    const rt_topology topo = r.config.network();
    for (size_t i = 0; i < order.size() && i < 3 && order[i]->busy_s > 0; i++)
        text += std::string(i ? ", " : "") + std::to_string(order[i]->from) + "->" + std::to_string(order[i]->to) +
                " " + rt_topology_port_name(&topo, order[i]->dir) + " " + sig4(100 * order[i]->busy_s / r.sim_time_s) +
                " %";
    if (!text.empty()) std::fprintf(out, "               busiest links (from->to direction use): %s\n", text.c_str());
}

}  // namespace torusrt
