// stats_json.cpp - JSON forms of the kernel's counters.
#include "stats_json.h"

#include <string>

namespace torusrt {

nlohmann::json ops_json(const rt_op_counts &o)
{
    return {{"tests_missed", o.tests_missed},
            {"tests_hit", o.tests_hit},
            {"dda_steps", o.dda_steps},
            {"shadings", o.shadings},
            {"reflection_vectors", o.reflection_vectors},
            {"refraction_vectors", o.refraction_vectors},
            {"packets_analysed", o.packets_analysed},
            {"packets_created", o.packets_created},
            {"fb_writes", o.fb_writes},
            {"handovers_sent", o.handovers_sent},
            {"handovers_received", o.handovers_received},
            {"cell_steps", o.cell_steps}};
}

nlohmann::json packets_json(const rt_packet_totals &t)
{
    auto by_kind = [](const uint64_t *v) {
        return nlohmann::json{{"ray", v[RT_PACKET_RAY]},
                              {"shadow", v[RT_PACKET_SHADOW]},
                              {"total", v[RT_PACKET_RAY] + v[RT_PACKET_SHADOW]}};
    };
    return {{"created", by_kind(t.created)},
            {"consumed", by_kind(t.consumed)},
            {"forwarded", t.forwarded},
            {"primary_missed", t.primary_missed}};
}

nlohmann::json preprocess_json(const rt_grid *grid, int extra_processors)
{
    nlohmann::json parallel = nlohmann::json::object();
    for (int p = 1; p <= 64; p *= 2) parallel[std::to_string(p)] = rt_grid_units_parallel(grid, p);
    if (extra_processors > 0)
        parallel[std::to_string(extra_processors)] = rt_grid_units_parallel(grid, extra_processors);
    return {{"units_serial", rt_grid_units_serial(grid)}, {"units_parallel_by_p", parallel}};
}

nlohmann::json camera_pose_json(const rt_camera_pose &p)
{
    auto vec = [](rt_vec3 v) { return nlohmann::json::array({v.x, v.y, v.z}); };
    return {{"from", vec(p.from)}, {"at", vec(p.at)}, {"up", vec(p.up)}, {"angle", p.angle}};
}

}  // namespace torusrt
