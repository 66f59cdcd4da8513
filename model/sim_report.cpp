// sim_report.cpp - statistics gathered from the modules after the run.
#include "sim_report.h"

#include <algorithm>
#include <sstream>
#include <vector>

#include "cluster_node.h"
#include "flow_report.h"
#include "rt_memory.h"
#include "stats_json.h"

namespace torusrt {

namespace {

nlohmann::json min_mean_max(const std::vector<double> &v)
{
    if (v.empty()) return {{"min", 0.0}, {"mean", 0.0}, {"max", 0.0}};
    double sum = 0;
    for (double x : v) sum += x;
    return {{"min", *std::min_element(v.begin(), v.end())},
            {"mean", sum / v.size()},
            {"max", *std::max_element(v.begin(), v.end())}};
}

nlohmann::json timing_json(const rt_timing &t)
{
    nlohmann::json j;
    for (size_t i = 0; i < rt_timing_key_count(); i++) j[rt_timing_key_name(i)] = rt_timing_get(&t, i);
    return j;
}

}  // namespace

nlohmann::json build_report(const SimConfig &config, TorusSystem &top, const PacketLedger &ledger,
                            const rt_scene *scene, const rt_grid *grid, const int32_t *cell_owner,
                            const RunFacts &facts)
{
    const rt_camera *cam = rt_scene_camera(scene);
    double T = ledger.image_time().to_seconds();
    int n = config.processor_count();
    int nodes = config.node_count();

    nlohmann::json per_ip = nlohmann::json::array();
    std::vector<double> busy;
    rt_op_counts total_ops{};
    double busy_sum = 0;
    uint64_t steps = 0;
    auto procs = top.processors();
    for (size_t i = 0; i < procs.size(); i++) {
        IntersectionProcessor *p = procs[i];
        double b = p->busy_time().to_seconds();
        busy.push_back(b);
        busy_sum += b;
        steps += p->packets_in();
        rt_ops_add(&total_ops, &p->ops());
        per_ip.push_back({{"id", i},
                          {"node", static_cast<int>(i) / config.cluster},
                          {"busy_s", b},
                          {"idle_s", std::max(0.0, T - b)},
                          {"utilisation", T > 0 ? b / T : 0.0},
                          {"packets_in", p->packets_in()},
                          {"packets_out", p->packets_out()},
                          {"tests", p->ops().tests_hit + p->ops().tests_missed},
                          {"queue_high_water", p->queue().high_water()},
                          {"ops", ops_json(p->ops())}});
    }

    nlohmann::json per_link = nlohmann::json::array();
    std::vector<double> link_util;
    uint64_t hops = 0;
    double link_bytes = 0;
    for (const auto &l : top.links()) {
        double u = T > 0 ? l->busy_time().to_seconds() / T : 0.0;
        link_util.push_back(u);
        hops += l->packets();
        link_bytes += l->bytes();
        per_link.push_back({{"from", l->from()},
                            {"to", l->to()},
                            {"dir", direction_name(l->dir())},
                            {"packets", l->packets()},
                            {"busy_s", l->busy_time().to_seconds()},
                            {"utilisation", u},
                            {"queue_high_water", l->queue().high_water()}});
    }

    // Data memory: what each node must hold for its cells, against every processor holding all.
    std::vector<rt_memory_use> use(nodes);
    rt_memory_per_owner(scene, grid, cell_owner, nodes, use.data());
    uint64_t max_node = 0;
    for (const auto &u : use) max_node = std::max(max_node, rt_memory_total(&u));
    rt_memory_use whole = rt_memory_whole_scene(scene, grid);
    uint64_t pixel_partitioned = rt_memory_total(&whole) * static_cast<uint64_t>(n);
    nlohmann::json memory;
    if (config.cluster == 1) {
        memory = {{"max_per_ip_bytes", max_node},
                  {"total_bytes", max_node * static_cast<uint64_t>(n)},
                  {"pixel_partitioned_bytes", pixel_partitioned},
                  {"whole_scene_bytes", rt_memory_total(&whole)}};
    } else {
        memory = cluster_memory_json(config, top, scene, grid, cell_owner, pixel_partitioned);
        memory["whole_scene_bytes"] = rt_memory_total(&whole);
    }
    memory["ratio_to_pixel_partitioned"] =
        pixel_partitioned ? memory["total_bytes"].get<double>() / static_cast<double>(pixel_partitioned) : 0.0;

    uint64_t events = steps + hops + top.host().injected();
    for (const auto &cl : top.clusters()) events += cl->bus().transfers();
    nlohmann::json report = {
        {"scene", config.scene_path},
        {"width", cam->width},
        {"height", cam->height},
        {"cells", config.cells},
        {"objects", rt_scene_object_count(scene)},
        {"lights", rt_scene_light_count(scene)},
        {"config",
         {{"ips", config.ips},
          {"nodes", nodes},
          {"processors", n},
          {"mapping", mapping_name(config.mapping)},
          {"block", config.block},
          {"topology", topology_name(config.topology)},
          {"queue", config.queue_capacity},
          {"style", style_name(config.style)},
          {"quantum_us", config.quantum_us},
          {"cluster", config.cluster},
          {"data", data_mode_name(config.data)},
          {"arbiter", arbiter_name(config.arbiter)},
          {"dispatch", dispatch_name(config.dispatch)},
          {"max_depth", config.step.max_depth},
          {"min_weight", config.step.min_weight},
          {"timing_profile", config.timing_profile},
          {"timing", timing_json(config.timing)}}},
        {"sim_time_s", T},
        {"t1_s", facts.t1_s},
        {"t1_source", facts.t1_source},
        {"ips", n},
        // The headline: ideal time over actual time, T(1) / (n T(n)). Busy time over n T(n)
        // only says how evenly the work was spread (hand-over costs count as busy).
        {"efficiency", T > 0 ? facts.t1_s / (n * T) : 0.0},
        {"efficiency_t1", T > 0 ? facts.t1_s / (n * T) : 0.0},
        {"load_balance", T > 0 ? busy_sum / (n * T) : 0.0},
        {"efficiency_busy", T > 0 ? busy_sum / (n * T) : 0.0},
        {"load", {{"busy_s", min_mean_max(busy)}}},
        {"packets", packets_json(ledger.totals())},
        {"links",
         {{"count", top.links().size()},
          {"packets", hops},
          {"bytes", link_bytes},
          {"utilisation", min_mean_max(link_util)},
          {"per_link", per_link}}},
        {"memory", memory},
        {"preprocess",
         {{"units_serial", rt_grid_units_serial(grid)},
          {"units_parallel", rt_grid_units_parallel(grid, n)},
          {"units_parallel_by_p", preprocess_json(grid, n)["units_parallel_by_p"]}}},
        {"ops", ops_json(total_ops)},
        {"per_ip", per_ip},
        {"packet_bytes_wire", config.timing.packet_bytes},
        {"packet_bytes_in_memory", sizeof(rt_packet)},
        {"wall_s", facts.wall_s},
        {"sim_wall_s", facts.sim_wall_s},
        {"events", events},
        {"events_per_s", facts.sim_wall_s > 0 ? events / facts.sim_wall_s : 0.0},
        {"packet_hops", hops},
        {"packet_hops_per_s", facts.sim_wall_s > 0 ? hops / facts.sim_wall_s : 0.0},
        {"delta_cycles", facts.delta_cycles}};
    report["packets"]["conserved"] = ledger.conserved();
    if (config.cluster > 1) add_cluster_report(report, config, top);
    report["flow"] = flow_report_json(config, top, scene);
    return report;
}

void print_summary(const nlohmann::json &r, std::FILE *out)
{
    const auto &c = r["config"];
    std::fprintf(out, "torusrt-sim: %s (%dx%d, %d objects, %d lights)\n", r["scene"].get<std::string>().c_str(),
                 r["width"].get<int>(), r["height"].get<int>(), r["objects"].get<int>(), r["lights"].get<int>());
    std::fprintf(out, "  system       %dx%dx%d %s, %s mapping, %d processor(s) per node, %s data, %s timing\n",
                 c["ips"][0].get<int>(), c["ips"][1].get<int>(), c["ips"][2].get<int>(),
                 c["topology"].get<std::string>().c_str(), c["mapping"].get<std::string>().c_str(),
                 c["cluster"].get<int>(), c["data"].get<std::string>().c_str(), c["style"].get<std::string>().c_str());
    std::fprintf(out, "  image time   %.6f s simulated   (T(1) %.3f s, %s)\n", r["sim_time_s"].get<double>(),
                 r["t1_s"].get<double>(), r["t1_source"].get<std::string>().c_str());
    std::fprintf(out, "  efficiency   %.1f %% = T(1)/(n T(n)), n = %d   (load balance %.1f %% = busy/(n T(n)))\n",
                 100 * r["efficiency"].get<double>(), r["ips"].get<int>(), 100 * r["load_balance"].get<double>());
    std::fprintf(out, "  timing       profile %s (hand-over send %g us, receive %g us)\n",
                 c["timing_profile"].get<std::string>().c_str(), c["timing"]["handover_send"].get<double>(),
                 c["timing"]["handover_receive"].get<double>());
    const auto &b = r["load"]["busy_s"];
    std::fprintf(out, "  load/IP      busy min %.4f  mean %.4f  max %.4f s\n", b["min"].get<double>(),
                 b["mean"].get<double>(), b["max"].get<double>());
    const auto &p = r["packets"];
    std::fprintf(out, "  packets      ray %llu  shadow %llu  created = consumed: %s  forwarded %llu  missed %llu\n",
                 p["created"]["ray"].get<unsigned long long>(), p["created"]["shadow"].get<unsigned long long>(),
                 p["conserved"].get<bool>() ? "yes" : "NO", p["forwarded"].get<unsigned long long>(),
                 p["primary_missed"].get<unsigned long long>());
    const auto &l = r["links"];
    std::fprintf(out, "  links        %d links, %llu packet hops, utilisation mean %.2f %% max %.2f %%\n",
                 l["count"].get<int>(), l["packets"].get<unsigned long long>(),
                 100 * l["utilisation"]["mean"].get<double>(), 100 * l["utilisation"]["max"].get<double>());
    if (r.contains("bus"))
        std::fprintf(out, "  bus          utilisation mean %.2f %% max %.2f %%, grant wait mean %.3f us max %.3f us\n",
                     100 * r["bus"]["utilisation"]["mean"].get<double>(), 100 * r["bus"]["utilisation"]["max"].get<double>(),
                     r["bus"]["grant_wait_us"]["mean"].get<double>(), r["bus"]["grant_wait_us"]["max"].get<double>());
    const auto &m = r["memory"];
    std::fprintf(out, "  memory       %llu bytes (max per processor x n) vs %llu pixel-partitioned (%.3f)\n",
                 m["total_bytes"].get<unsigned long long>(), m["pixel_partitioned_bytes"].get<unsigned long long>(),
                 m["ratio_to_pixel_partitioned"].get<double>());
    std::fprintf(out, "  preprocess   %llu units serial, %llu units on %d processors\n",
                 r["preprocess"]["units_serial"].get<unsigned long long>(),
                 r["preprocess"]["units_parallel"].get<unsigned long long>(), r["ips"].get<int>());
    if (r.contains("mapping") && r["mapping"].contains("pilot_wall_s")) {
        const auto &m = r["mapping"];
        std::fprintf(out, "  mapping      cost: pilot %.3f s modelled (%.3f s wall), Scotch %.3f s wall; not in the image time\n",
                     m["pilot_modelled_s"].get<double>(), m["pilot_wall_s"].get<double>(), m["mapper_wall_s"].get<double>());
    }
    std::fprintf(out, "  wall         %.3f s (%.3f s simulating), %.0f events/s, %.0f packet hops/s\n",
                 r["wall_s"].get<double>(), r["sim_wall_s"].get<double>(), r["events_per_s"].get<double>(),
                 r["packet_hops_per_s"].get<double>());
}

std::string deadlock_report(TorusSystem &top)
{
    std::ostringstream s;
    for (auto *p : top.processors())
        if (p->queue().full())
            s << "  full: " << p->name() << " input queue (" << p->queue().size() << "/" << p->queue().capacity()
              << "), " << p->queue().blocked_writers() << " writer(s) waiting\n";
    for (const auto &l : top.links())
        if (l->queue().full())
            s << "  full: " << l->name() << " output queue (" << l->queue().size() << "/" << l->queue().capacity()
              << "), " << l->queue().blocked_writers() << " writer(s) waiting\n";
    for (const auto &cl : top.clusters()) s << cluster_deadlock_lines(*cl);
    return s.str();
}

}  // namespace torusrt
