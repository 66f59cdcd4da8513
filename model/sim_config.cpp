// sim_config.cpp - validation and names of the run settings.
#include "sim_config.h"

#include <cmath>

#include "user_error.h"

namespace torusrt {

void validate(const SimConfig &c)
{
    for (int a = 0; a < 3; a++)
        if (c.ips[a] < 1) throw UserError("--ips: every dimension needs at least 1 node", 2);
    if (c.node_count() > kMaxNodes) throw UserError("--ips: at most " + std::to_string(kMaxNodes) + " nodes", 2);
    if (c.block < 1) throw UserError("--map block-cyclic:B: B must be at least 1", 2);
    if (c.cluster < 1 || c.cluster > 256) throw UserError("--cluster: must be 1 to 256", 2);
    if (c.processor_count() > kMaxProcessors)
        throw UserError("--ips x --cluster: at most " + std::to_string(kMaxProcessors) +
                            " processors (each has its own SystemC threads; more do not fit in memory)", 2);
    if (c.step.max_depth < 0 || c.step.max_depth > 1000) throw UserError("--max-depth: must be 0 to 1000", 2);
    if (!(c.step.min_weight >= 0) || !std::isfinite(c.step.min_weight))
        throw UserError("--min-weight: must be a non-negative number", 2);
    if (!(c.quantum_us >= 0) || !std::isfinite(c.quantum_us)) throw UserError("--quantum: must not be negative", 2);
    if (c.style == TimingStyle::at && c.quantum_us > 0)
        throw UserError("--quantum: only meaningful with --style lt", 2);
    if (!(c.trace_from_us >= 0) || (c.trace_to_us >= 0 && c.trace_to_us < c.trace_from_us))
        throw UserError("--trace-from/--trace-to: the window must start at 0 or later and not end before it starts", 2);
    if ((c.trace_from_us > 0 || c.trace_to_us >= 0) && c.vcd_path.empty())
        throw UserError("--trace-from/--trace-to: only meaningful with --vcd", 2);
    if (c.quantum_us > kMaxSimTimeS * 1e6) throw UserError("--quantum: at most " + std::to_string(kMaxSimTimeS) + " s", 2);
    if (!(c.time_limit_s > 0) || c.time_limit_s > kMaxSimTimeS)
        throw UserError("--time-limit: must be above 0 and at most " + std::to_string(static_cast<long>(kMaxSimTimeS)) + " s", 2);
    for (int id : c.trace_ips)
        if (id < 0 || id >= c.node_count())
            throw UserError("--trace-ips: node " + std::to_string(id) + " does not exist (0.." +
                                std::to_string(c.node_count() - 1) + ")", 2);
}

const char *mapping_name(rt_map_kind k)
{
    switch (k) {
    case RT_MAP_BLOCK: return "block";
    case RT_MAP_CYCLIC: return "cyclic";
    case RT_MAP_BLOCK_CYCLIC: return "block-cyclic";
    case RT_MAP_FILE: return "file";
    case RT_MAP_COST: return "cost";
    }
    return "unknown";
}
const char *topology_name(Topology t) { return t == Topology::torus ? "torus" : "mesh"; }
const char *style_name(TimingStyle s) { return s == TimingStyle::at ? "at" : "lt"; }
const char *data_mode_name(DataMode d) { return d == DataMode::replicated ? "replicated" : "shared"; }
const char *arbiter_name(ArbiterPolicy a) { return a == ArbiterPolicy::round_robin ? "round-robin" : "fixed-priority"; }
const char *dispatch_name(DispatchPolicy d) { return d == DispatchPolicy::round_robin ? "round-robin" : "shortest-queue"; }
const char *flow_name(FlowControl f) { return f == FlowControl::none ? "none" : "classes"; }

}  // namespace torusrt
