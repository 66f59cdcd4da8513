// tracing.cpp - sc_trace on the modules' plain state variables, named by hierarchy.
#include "tracing.h"

#include <cstdio>
#include <set>
#include <unistd.h>

#include "cluster_node.h"
#include "user_error.h"

namespace torusrt {

Tracer::Tracer(const std::string &path, const SimConfig &config, TorusSystem &top)
    : m_path(path), m_tmp_base(path + ".tmp." + std::to_string(getpid()))
{
    m_file = sc_core::sc_create_vcd_trace_file(m_tmp_base.c_str()); // SystemC appends ".vcd"
    if (!m_file) throw UserError("--vcd " + path + ": cannot create the trace file");
    // Bus transfers last fractions of a microsecond (0.25 us arbitration): clusters trace in ns.
    m_file->set_time_unit(1, config.cluster > 1 ? sc_core::SC_NS : sc_core::SC_US);
    std::set<int> nodes(config.trace_ips.begin(), config.trace_ips.end());
    auto traced = [&](int node) { return nodes.empty() || nodes.count(node) > 0; };
    auto procs = top.processors();
    for (size_t i = 0; i < procs.size(); i++) {
        int node = static_cast<int>(i) / config.cluster;
        if (!traced(node)) continue;
        std::string base = procs[i]->name();
        sc_core::sc_trace(m_file, procs[i]->busy_trace(), base + ".busy");
        sc_core::sc_trace(m_file, procs[i]->queue().depth_trace(), base + ".queue_depth");
    }
    for (const auto &l : top.links()) {
        if (!traced(l->from())) continue;
        std::string base = l->name();
        sc_core::sc_trace(m_file, l->busy_trace(), base + ".busy");
        sc_core::sc_trace(m_file, l->queue().depth_trace(), base + ".queue_depth");
    }
    for (size_t n = 0; n < top.clusters().size(); n++)
        if (traced(static_cast<int>(n))) trace_cluster(m_file, *top.clusters()[n]);
}

void Tracer::commit()
{
    if (m_file) sc_core::sc_close_vcd_trace_file(m_file);
    m_file = nullptr;
    std::string tmp = m_tmp_base + ".vcd";
    if (std::rename(tmp.c_str(), m_path.c_str()) != 0) {
        std::remove(tmp.c_str());
        throw UserError("--vcd " + m_path + ": cannot write the trace file");
    }
    m_committed = true;
}

Tracer::~Tracer()
{
    if (m_file) sc_core::sc_close_vcd_trace_file(m_file);
    if (!m_committed) std::remove((m_tmp_base + ".vcd").c_str());
}

}  // namespace torusrt
