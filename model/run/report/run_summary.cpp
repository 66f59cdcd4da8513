// run_summary.cpp - the human summary and the deadlock description, printed from a RunReport.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <sstream>
#include <string>

#include "run_report.h"
#include "significant.h"

namespace torusrt {

namespace {

struct Spread {
    double min = 0, mean = 0, max = 0;
};

template <typename T, typename F> Spread spread(const std::vector<T> &items, F value)
{
    if (items.empty()) return {};
    Spread s{value(items[0]), 0, value(items[0])};
    double sum = 0;
    for (const T &x : items) {
        double v = value(x);
        s.min = std::min(s.min, v);
        s.max = std::max(s.max, v);
        sum += v;
    }
    s.mean = sum / items.size();
    return s;
}

// The network as the summary's system line names it: its shape, a ring or line when only one
// dimension has more than one node ("16x1x1 torus: a ring of 16"), and for a torus with an even
// ring how it breaks ties.
std::string network_text(const SimConfig &c)
{
    int long_dims = 0;
    for (int p : c.ips) long_dims += p > 1;
    const rt_topology topo = c.network();
    const char *one_axis = rt_topology_one_axis_name(&topo);
    std::string name =
        std::to_string(c.ips[0]) + "x" + std::to_string(c.ips[1]) + "x" + std::to_string(c.ips[2]) + " " + c.topology;
    if (long_dims == 1 && one_axis) name += ": a " + std::string(one_axis) + " of " + std::to_string(c.node_count());
    if (!rt_topology_has_ties(&topo)) return name;
    return name + " (ties " + route_ties_name(c.route_ties) + ")";
}

// The processors of a node as the system line gives them: one, or a cluster and its data.
std::string node_text(const SimConfig &c)
{
    if (c.cluster == 1) return "1 processor per node";
    return std::to_string(c.cluster) + " processors per node, " + data_mode_name(c.data) + " data";
}

// The machine as the summary's system line gives it: timing style, buffers and flow control.
std::string machine_text(const SimConfig &c)
{
    std::string style = c.style == TimingStyle::lt ? "loosely timed (LT, quantum " + sig4(c.quantum_us) + " us)"
                                                   : std::string("approximately timed (AT)");
    std::string queue = c.queue_capacity ? std::to_string(c.queue_capacity) + " packets per buffer" +
                                               (c.flow == FlowControl::classes ? " and class" : "")
                                         : std::string("unbounded buffers");
    std::string flow = c.flow == FlowControl::classes ? "flow control classes (deadlock-free)"
                                                      : "flow control none (finite buffers may deadlock)";
    return style + ", " + queue + ", " + flow + ", queue order " + queue_order_name(c.queue_order);
}

void print_queues(const RunReport &r, std::FILE *out)
{
    if (r.queues.empty()) return;
    auto hw = std::max_element(r.queues.begin(), r.queues.end(),
                               [](const QueueStats &a, const QueueStats &b) { return a.high_water < b.high_water; });
    auto st = std::max_element(r.queues.begin(), r.queues.end(),
                               [](const QueueStats &a, const QueueStats &b) { return a.stalled_s < b.stalled_s; });
    std::string cap = hw->capacity ? std::to_string(hw->capacity) : std::string("unbounded");
    std::fprintf(out, "  queues       %zu, largest high water %llu (%s, capacity %s)", r.queues.size(),
                 static_cast<unsigned long long>(hw->high_water), hw->name.c_str(), cap.c_str());
    if (st->stalled_s > 0) {
        double T = r.sim_time_s;
        std::fprintf(out,
                     "\n               writers waited for room: %s, the longest-stalled queue, %s s;"
                     " some writer waited %s %% of the image time",
                     st->name.c_str(), sig4(st->stalled_s).c_str(),
                     T > 0 ? sig4(100 * r.any_stalled_s / T).c_str() : "-");
    } else {
        std::fprintf(out, ", no writer waited for room");
    }
    std::fprintf(out, "\n");
}

void print_bus(const RunReport &r, std::FILE *out)
{
    if (!r.clusters.empty()) {
        double T = r.sim_time_s;
        auto util = [T](const ClusterNodeReport &c) { return T > 0 ? std::min(1.0, c.bus.busy_s / T) : 0.0; };
        Spread u = spread(r.clusters, util);
        uint64_t grants = 0, sum = 0, max = 0;
        for (const auto &c : r.clusters) {
            grants += c.bus.all.grants;
            sum += c.bus.all.wait_sum;
            max = std::max(max, c.bus.all.wait_max);
        }
        auto us = [](uint64_t ticks) { return sc_core::sc_time::from_value(ticks).to_seconds() * 1e6; };
        std::fprintf(out, "  bus          utilisation mean %.2f %% max %.2f %%, grant wait mean %.3f us max %.3f us\n",
                     100 * u.mean, 100 * u.max, grants ? us(sum) / static_cast<double>(grants) : 0.0, us(max));
    }
}

void print_mapping(const RunReport &r, std::FILE *out)
{
    if (r.mapping.is_object() && r.mapping.contains("pilot_wall_s")) {
        const auto &m = r.mapping;
        bool scatter = m.value("mapper", "") == "scatter";
        std::fprintf(out,
                     "  mapping      %s: pilot %.3f s modelled (%.3f s wall), %s %.3f s wall; not in the image time\n",
                     scatter ? "scatter" : "cost", m["pilot_modelled_s"].get<double>(), m["pilot_wall_s"].get<double>(),
                     scatter ? "deal" : "Scotch", m["mapper_wall_s"].get<double>());
    }
}

}  // namespace

void print_summary(const RunReport &r, std::FILE *out)
{
    const SimConfig &c = r.config;
    const RunFacts &f = r.facts;
    double T = r.sim_time_s;
    int n = c.processor_count();
    std::fprintf(out, "torusrt-sim: %s (%ux%u, %llu object%s, %llu light%s)\n", c.scene_path.c_str(), r.width, r.height,
                 static_cast<unsigned long long>(r.objects), r.objects == 1 ? "" : "s",
                 static_cast<unsigned long long>(r.lights), r.lights == 1 ? "" : "s");
    std::fprintf(out,
                 "  system       %s, %s mapping, %s,\n"
                 "               %s\n",
                 network_text(c).c_str(), c.mapping.c_str(), node_text(c).c_str(), machine_text(c).c_str());
    if (r.frames.empty())
        std::fprintf(out, "  image time   %s s simulated   (T(1) %s s, %s)\n", sig4(T).c_str(), sig4(f.t1_s).c_str(),
                     f.t1_source.c_str());
    else
        std::fprintf(out,
                     "  time         %s s simulated over %zu frames, first frame's start to last's end"
                     " (frames: below)\n",
                     sig4(T).c_str(), r.frames.size());
    std::fprintf(out, "  efficiency   %.1f %% = T(1)/(n T(n)), n = %d   (load balance %.1f %% = busy/(n T(n)))\n",
                 T > 0 ? 100 * (f.t1_s / (n * T)) : 0.0, n, T > 0 ? 100 * (r.totals.busy_s / (n * T)) : 0.0);
    print_efficiency_factors(r, out);
    std::fprintf(out,
                 "  timing       profile %s (hand-over send %g us, receive %g us; cell step %g us; bus cycle %g us, "
                 "memory %g us)\n",
                 c.timing_profile.c_str(), c.timing.handover_send_us, c.timing.handover_receive_us,
                 c.timing.cell_step_packet_us, c.timing.bus_cycle_us, c.timing.memory_access_us);
    Spread b = spread(r.ips, [](const IpStats &p) { return p.busy_s; });
    std::fprintf(out, "  busy per IP  min %s  mean %s  max %s s\n", sig4(b.min).c_str(), sig4(b.mean).c_str(),
                 sig4(b.max).c_str());
    print_time_split(r, out);
    const rt_packet_totals &p = r.packets;
    std::fprintf(out,
                 "  packets      ray %llu  shadow %llu  created = consumed: %s  handed between nodes %llu\n"
                 "               primary rays that missed the scene %llu\n",
                 static_cast<unsigned long long>(p.created[RT_PACKET_RAY]),
                 static_cast<unsigned long long>(p.created[RT_PACKET_SHADOW]), r.conserved ? "yes" : "NO",
                 static_cast<unsigned long long>(p.forwarded), static_cast<unsigned long long>(p.primary_missed));
    Spread l = spread(r.links, [T](const LinkStats &k) { return T > 0 ? k.busy_s / T : 0.0; });
    std::fprintf(out, "  links        %zu links, %llu packet hops, utilisation mean %s %% max %s %%\n", r.links.size(),
                 static_cast<unsigned long long>(r.totals.hops), sig4(100 * l.mean).c_str(), sig4(100 * l.max).c_str());
    print_busiest_links(r, out);
    print_latency(r, out);
    print_bus(r, out);
    print_queues(r, out);
    const MemoryReport &m = r.memory;
    std::fprintf(
        out, "  memory       %llu bytes (max per processor x n) vs %llu pixel-partitioned (%s)\n",
        static_cast<unsigned long long>(m.total_bytes), static_cast<unsigned long long>(m.pixel_partitioned_bytes),
        sig4(m.pixel_partitioned_bytes ? static_cast<double>(m.total_bytes) / m.pixel_partitioned_bytes : 0.0).c_str());
    if (m.replication.cells)
        std::fprintf(out, "  replication  %zu cells, %zu extra copies, %llu bytes; rays to the %s owner\n",
                     m.replication.cells, m.replication.copies, static_cast<unsigned long long>(m.replication.bytes),
                     r.config.replica_choice == ReplicaRule::nearest ? "nearest" : "hashed");
    std::fprintf(out, "  preprocess   %llu units serial, %llu units on %d processors\n",
                 static_cast<unsigned long long>(r.units_serial), static_cast<unsigned long long>(r.units_parallel), n);
    print_mapping(r, out);
    double w = f.sim_wall_s;
    std::fprintf(out, "  wall         %.3f s (%.3f s elaborating, %.3f s simulating), %s events/s, %s packet hops/s\n",
                 f.wall_s, f.elaboration_wall_s, w, sig4(w > 0 ? r.totals.events / w : 0.0).c_str(),
                 sig4(w > 0 ? r.totals.hops / w : 0.0).c_str());
    print_frame_table(r.frames, r.remap, out);
}

std::string deadlock_text(const RunReport &r)
{
    std::ostringstream s;
    for (const QueueStats &q : r.deadlock.full)
        s << "  full: " << q.name << " (" << q.occupancy << "/" << q.capacity << "), " << q.waiting_writers
          << " writer(s) waiting\n";
    for (const auto &b : r.deadlock.bus_waits) s << "  waiting: " << b.second << " requester(s) on " << b.first << "\n";
    if (r.deadlock.held) s << "  held: " << r.deadlock.held << " packet(s) in communication units waiting for room\n";
    return s.str();
}

}  // namespace torusrt
