// tracing.cpp - sc_trace on the modules' plain state variables, named by hierarchy, and the
// GTKWave save file listing the same names, each with a short alias, zoomed to the traced span.
#include "tracing.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <set>

#include "cluster_node.h"
#include "output_files.h"
#include "user_error.h"

namespace torusrt {

namespace {

uint64_t us_to_ps(double us) { return us < 0 ? UINT64_MAX : static_cast<uint64_t>(std::llround(us * 1e6)); }

// The file name without its folder: the save file lies beside the VCD, and GTKWave finds the
// dump relative to the save file's folder when both names are given that way.
std::string base_name(const std::string &path)
{
    size_t slash = path.rfind('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

// "xp" -> "+x", "zm" -> "-z": a link's direction as the row's name shows it.
std::string direction(const std::string &dir)
{
    if (dir.size() != 2 || (dir[1] != 'p' && dir[1] != 'm')) return dir;
    return std::string(1, dir[1] == 'p' ? '+' : '-') + dir[0];
}

// A row's name in GTKWave from its hierarchical signal name:
// top.ip_3.busy -> "ip 3 busy", top.link_3_to_7_zp.queue_depth -> "link 3->7 +z queue",
// top.cluster_2.bus.request_cu -> "bus 2 request cu", top.cluster_2.ip_9.busy -> "ip 9 busy".
std::string alias_of(const std::string &signal)
{
    std::string rest = signal.rfind("top.", 0) == 0 ? signal.substr(4) : signal;
    size_t dot = rest.rfind('.');
    if (dot == std::string::npos) return rest;
    std::string owner = rest.substr(0, dot), what = rest.substr(dot + 1);
    if (what == "queue_depth") what = "queue";
    for (char &c : what)
        if (c == '_') c = ' ';
    std::string cluster;
    if (owner.rfind("cluster_", 0) == 0 && owner.find('.') != std::string::npos) {
        cluster = owner.substr(8, owner.find('.') - 8);
        owner = owner.substr(owner.find('.') + 1);
    }
    int a = 0, b = 0;
    char dir[3] = {0};
    if (std::sscanf(owner.c_str(), "link_%d_to_%d_%2s", &a, &b, dir) == 3)
        return "link " + std::to_string(a) + "->" + std::to_string(b) + " " + direction(dir) + " " + what;
    if (owner.rfind("ip_", 0) == 0) return "ip " + owner.substr(3) + " " + what;
    if (!cluster.empty()) return owner + " " + cluster + " " + what;  // the bus, the dispatcher
    return owner + " " + what;
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
    // First every traced processor's busy row, one under the other, then a group per node.
    Group busy{"processors busy", {}};
    for (int node = 0; node < config.node_count(); node++) {
        if (!nodes.empty() && nodes.count(node) == 0) continue;
        for (int k = 0; k < config.cluster; k++) {
            IntersectionProcessor *p = procs[static_cast<size_t>(node * config.cluster + k)];
            add(busy, p->busy_trace(), std::string(p->name()) + ".busy");
        }
    }
    m_groups.push_back(busy);
    for (int node = 0; node < config.node_count(); node++) {
        if (!nodes.empty() && nodes.count(node) == 0) continue;
        Group g{"node " + std::to_string(node), {}};
        for (const auto &l : top.links())
            if (l->from() == node) {
                add(g, l->use_trace(), std::string(l->name()) + ".use", Shown::level);
                g.signals.back().link = l.get();
            }
        if (static_cast<size_t>(node) < top.clusters().size()) trace_cluster(g, *top.clusters()[node]);
        for (const QueueRef &q : top.queues().all())  // every buffer held in this node
            if (q.node == node) add(g, *q.depth, q.trace);
        m_groups.push_back(g);
    }
}

void Tracer::add(Group &g, bool &value, const std::string &name)
{
    sc_core::sc_trace(m_file, value, name);
    g.signals.push_back({"SystemC." + name, alias_of(name), Shown::flag});  // SystemC's VCD scope is SystemC
}

void Tracer::add(Group &g, int &value, const std::string &name, Shown shown)
{
    sc_core::sc_trace(m_file, value, name);
    g.signals.push_back({"SystemC." + name + "[31:0]", alias_of(name), shown});
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

std::string Tracer::save_file_text(uint64_t end_ps) const
{
    // The window opens on the traced span: from --trace-from (or 0) to --trace-to or the end of
    // the run. GTKWave shows 2^-zoom time units per 200 pixels; the window's size and signal pane
    // are fixed so that the span takes about kSpanPixels of the wave pane.
    constexpr double kSpanPixels = 1000;
    uint64_t from = m_config.trace_from_us > 0 ? us_to_ps(m_config.trace_from_us) : 0;
    uint64_t to = std::min(end_ps, us_to_ps(m_config.trace_to_us));
    double span = to > from ? static_cast<double>(to - from) : 1.0;
    char zoom[64];
    std::snprintf(zoom, sizeof zoom, "*%.6f -1\n", -std::log2(span * 200.0 / kSpanPixels));
    // GTKWave flags: 0x200 blank (a label line), 0x800000/0x1000000 group begin/end,
    // 0x28 binary, 0x24 decimal (right-justified), 0x88024 decimal drawn as an analog step
    // (0x8000) scaled to the row's range over the whole trace (0x80000): a link's use in percent,
    // its peak in the row's name, so that a link used 1 % of the time reads low, not solid;
    // "+{NAME} SIGNAL" shows SIGNAL as NAME.
    std::string s = "[*] torusrt trace: open with  gtkwave FILE.gtkw\n";
    s += "[dumpfile] \"" + base_name(m_config.vcd_path) + "\"\n";
    s += "[savefile] \"" + base_name(m_config.gtkw_path) + "\"\n";
    s += "[timestart] " + std::to_string(from) + "\n";
    s += "[size] 1400 900\n[signals_width] 220\n[sst_expanded] 0\n";
    s += zoom;
    for (const auto &g : m_groups) {
        s += "@800200\n-" + g.name + "\n";
        for (const auto &sig : g.signals) {
            std::string alias = sig.alias;
            if (sig.link) alias += " % (peak " + std::to_string(sig.link->use_peak()) + ")";
            s += std::string(sig.shown == Shown::flag ? "@28\n" : sig.shown == Shown::count ? "@24\n" : "@88024\n");
            s += "+{" + alias + "} " + sig.name + "\n";
        }
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
    if (m_file && sc_core::sc_time_stamp() == sc_core::SC_ZERO_TIME &&
        sc_core::sc_get_status() != sc_core::SC_STOPPED) {
        static sc_core::sc_event kick("torusrt_empty_trace_kick");
        kick.notify(sc_core::sc_time(1, sc_core::SC_PS));
        sc_core::sc_start(sc_core::sc_time(1, sc_core::SC_PS));
    }
    if (m_file) sc_core::sc_close_vcd_trace_file(m_file);
    m_file = nullptr;
    m_stream->finish();
    if (!m_config.gtkw_write_path.empty())
        write_text_file(m_config.gtkw_write_path, m_config.gtkw_path, save_file_text(sc_core::sc_time_stamp().value()));
}

Tracer::~Tracer()
{
    if (m_file) sc_core::sc_close_vcd_trace_file(m_file);
}

}  // namespace torusrt
