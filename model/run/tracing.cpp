// tracing.cpp - sc_trace on the modules' plain state variables, named by hierarchy, and the
// GTKWave save file listing the same names.
#include "tracing.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits.h>
#include <set>
#include <unistd.h>

#include "cluster_node.h"
#include "output_files.h"
#include "user_error.h"

namespace torusrt {

namespace {

uint64_t us_to_ps(double us) { return us < 0 ? UINT64_MAX : static_cast<uint64_t>(std::llround(us * 1e6)); }

// The VCD's absolute path, so the save file opens it from any folder.
std::string absolute(const std::string &path)
{
    if (!path.empty() && path[0] == '/') return path;
    char cwd[PATH_MAX];
    return getcwd(cwd, sizeof cwd) ? std::string(cwd) + "/" + path : path;
}

}  // namespace

Tracer::Tracer(const SimConfig &config, TorusSystem &top) : m_config(config)
{
    m_stream = std::make_unique<VcdStream>(config.vcd_write_path, config.vcd_path, us_to_ps(config.trace_from_us),
                                           us_to_ps(config.trace_to_us));
    m_file = sc_core::sc_create_vcd_trace_file(m_stream->systemc_name().c_str());  // appends ".vcd"
    if (!m_file) throw UserError("--vcd " + config.vcd_path + ": cannot create the trace file");
    // The trace's unit is SystemC's default resolution (1 ps, never changed here), so every
    // time a run can produce (fractional link times, bus cycles) is exact: no rounding warnings.
    // SystemC's note about it (I703) would name the FIFO, not the user's file: not shown.
    sc_core::sc_report_handler::set_actions("tracing timescale unit set", sc_core::SC_DO_NOTHING);
    // Nor its note that a file closed before any cycle was not written (W715): finish() always
    // traces one, and a failed run discards its trace anyway.
    sc_core::sc_report_handler::set_actions("trace file closed before any cycles were traced, file not written",
                                            sc_core::SC_DO_NOTHING);
    m_file->set_time_unit(1, sc_core::SC_PS);
    std::set<int> nodes(config.trace_ips.begin(), config.trace_ips.end());
    auto procs = top.processors();
    for (int node = 0; node < config.node_count(); node++) {
        if (!nodes.empty() && nodes.count(node) == 0) continue;
        Group g{"node " + std::to_string(node), {}};
        for (int k = 0; k < config.cluster; k++) {
            IntersectionProcessor *p = procs[static_cast<size_t>(node * config.cluster + k)];
            add(g, p->busy_trace(), std::string(p->name()) + ".busy");
        }
        for (const auto &l : top.links())
            if (l->from() == node) add(g, l->busy_trace(), std::string(l->name()) + ".busy");
        if (static_cast<size_t>(node) < top.clusters().size()) trace_cluster(g, *top.clusters()[node]);
        for (const QueueRef &q : top.queues().all())  // every buffer held in this node
            if (q.node == node) add(g, *q.depth, q.trace);
        m_groups.push_back(g);
    }
}

void Tracer::add(Group &g, bool &value, const std::string &name)
{
    sc_core::sc_trace(m_file, value, name);
    g.signals.push_back({"SystemC." + name, false});  // SystemC's VCD puts everything in scope SystemC
}

void Tracer::add(Group &g, int &value, const std::string &name)
{
    sc_core::sc_trace(m_file, value, name);
    g.signals.push_back({"SystemC." + name + "[31:0]", true});
}

void Tracer::trace_cluster(Group &g, ClusterNode &cluster)
{
    ClusterBus &bus = cluster.bus();
    std::string base = bus.name();
    add(g, bus.owner_trace(), base + ".owner");
    for (int r = 0; r < bus.requesters(); r++)
        add(g, bus.request_trace(r), base + ".request_" + (r < cluster.size() ? std::to_string(r) : std::string("cu")));
    add(g, cluster.dispatcher().busy_trace(), std::string(cluster.dispatcher().name()) + ".busy");
}

std::string Tracer::save_file_text() const
{
    // GTKWave flags: 0x200 blank (a label line), 0x800000/0x1000000 group begin/end,
    // 0x28 binary, 0x24 decimal (right-justified).
    std::string s = "[*] torusrt trace: open with  gtkwave FILE.gtkw\n";
    s += "[dumpfile] \"" + absolute(m_config.vcd_path) + "\"\n";
    s += "[timestart] " + std::to_string(m_config.trace_from_us > 0 ? us_to_ps(m_config.trace_from_us) : 0) + "\n";
    for (const auto &g : m_groups) {
        s += "@800200\n-" + g.name + "\n";
        for (const auto &sig : g.signals) s += std::string(sig.second ? "@24\n" : "@28\n") + sig.first + "\n";
        s += "@1000200\n-" + g.name + "\n";
    }
    return s;
}

void Tracer::finish()
{
    // A run in which nothing happened (no packets: simulated time never left 0) traced no
    // cycle, and SystemC would write no VCD at all (its warning W715, naming the FIFO): one
    // picosecond more, on an event no process waits for, writes the header and the signals'
    // values. The run's figures are taken already.
    if (m_file && sc_core::sc_time_stamp() == sc_core::SC_ZERO_TIME && sc_core::sc_get_status() != sc_core::SC_STOPPED) {
        static sc_core::sc_event kick("torusrt_empty_trace_kick");
        kick.notify(sc_core::sc_time(1, sc_core::SC_PS));
        sc_core::sc_start(sc_core::sc_time(1, sc_core::SC_PS));
    }
    if (m_file) sc_core::sc_close_vcd_trace_file(m_file);
    m_file = nullptr;
    m_stream->finish();
    if (!m_config.gtkw_write_path.empty())
        write_text_file(m_config.gtkw_write_path, m_config.gtkw_path, save_file_text());
}

Tracer::~Tracer()
{
    if (m_file) sc_core::sc_close_vcd_trace_file(m_file);
}

}  // namespace torusrt
