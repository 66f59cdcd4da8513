// cluster_dispatch_test.cpp - the cluster dispatcher: round-robin hands packets to processors
// 0, 1, 2, 0, ... whatever their load; shortest-queue picks the fewest waiting-or-in-service,
// ties to the lowest index; each packet crosses the bus no earlier than its stamp, occupying it
// for arbitration + ceil(packet_bytes / width) x cycle, and reaches its processor at the end.
#include <memory>
#include <stdexcept>
#include <systemc>
#include <tlm>
#include <string>
#include <tlm_utils/simple_target_socket.h>
#include <vector>

#include "bus_arbiter.h"
#include "cluster_bus.h"
#include "cluster_dispatch.h"
#include "harness.h"
#include "packet_injector.h"
#include "rt_packet.h"

using harness::check;
using harness::Injector;
using sc_core::sc_time;
using namespace torusrt;

static sc_time us(double v) { return sc_time(v, sc_core::SC_US); }

struct NullSink : PacketSinkIf {
    size_t count = 0;
    void accept(const TimedPacket &) override { count++; }
};

struct FrameBufferStub : sc_core::sc_module {
    tlm_utils::simple_target_socket<FrameBufferStub> socket;
    explicit FrameBufferStub(sc_core::sc_module_name n) : sc_module(n), socket("socket")
    {
        socket.register_b_transport(this, &FrameBufferStub::b_transport);
    }
    void b_transport(tlm::tlm_generic_payload &t, sc_time &) { t.set_response_status(tlm::TLM_OK_RESPONSE); }
};

// m processors, each with its own ledger (its last consumption time = its last packet's arrival,
// since every operation costs 0 here).
struct Processors {
    std::vector<std::unique_ptr<PacketLedger>> ledgers;
    std::vector<std::unique_ptr<IntersectionProcessor>> ips;
    std::vector<IntersectionProcessor *> raw;
    std::vector<std::unique_ptr<FrameBufferStub>> fbs;
    NullSink sink;
    Processors(const char *name, int m, const SimConfig &c, const rt_scene *s, const rt_grid *g)
    {
        for (int k = 0; k < m; k++) {
            ledgers.push_back(std::make_unique<PacketLedger>());
            std::string n = std::string(name) + std::to_string(k);
            ips.push_back(std::make_unique<IntersectionProcessor>(n.c_str(), c, s, g, nullptr, 0, k, *ledgers[k]));
            ips[k]->out.bind(sink);
            fbs.push_back(std::make_unique<FrameBufferStub>((n + "_fb").c_str()));
            ips[k]->fb_socket.bind(fbs[k]->socket);
            raw.push_back(ips[k].get());
        }
    }
};

static void policy_checks(Processors &procs, const TimedPacket &p)
{
    auto sq = make_dispatch_policy("shortest-queue");
    auto rr = make_dispatch_policy("round-robin");
    std::vector<IntersectionProcessor *> &v = procs.raw;
    check(sq->choose(v) == 0, "shortest-queue: all idle, ties to processor 0");
    v[0]->busy_trace() = true; // loads 1, 0, 0
    check(sq->choose(v) == 1, "shortest-queue: 0 in service, ties between 1 and 2 go to 1");
    v[1]->queue().push_blocking(p);
    v[1]->queue().push_blocking(p); // loads 1, 2, 0
    check(sq->choose(v) == 2, "shortest-queue: loads 1, 2, 0 give 2");
    v[2]->queue().push_blocking(p);
    v[2]->busy_trace() = true; // loads 1, 2, 2
    check(sq->choose(v) == 0, "shortest-queue: loads 1, 2, 2 give 0");
    v[0]->queue().push_blocking(p);
    v[0]->queue().push_blocking(p); // loads 3, 2, 2
    check(sq->choose(v) == 1, "shortest-queue: loads 3, 2, 2 give 1 (lowest of the tie)");
    std::vector<int> seq;
    for (int i = 0; i < 5; i++) seq.push_back(rr->choose(v));
    check((seq == std::vector<int>{0, 1, 2, 0, 1}), "round-robin: 0, 1, 2, 0, 1 whatever the loads");
    for (auto *ip : v) ip->busy_trace() = false;
    bool threw = false;
    try {
        make_dispatch_policy("longest-queue");
    } catch (const std::invalid_argument &) {
        threw = true;
    }
    check(threw, "an unknown policy name throws invalid_argument");
}

int sc_main(int, char *[])
{
    char msg[256];
    rt_scene *scene = rt_scene_new();
    rt_scene_set_view(scene, rt_vec(0, 0, 5), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45.0, 16, 16);
    rt_scene_add_sphere(scene, rt_vec(0, 0, 0), 1.0); // no light: a hit creates nothing
    rt_scene_finish(scene, msg, sizeof msg);
    rt_grid *grid = rt_grid_new(scene, 2, 2, 2, msg, sizeof msg);
    TimedPacket p{};
    int enters = 0;
    rt_primary_packet(scene, grid, 8, 8, &p.packet, &enters);
    check(enters, "the test ray enters the grid");

    SimConfig config;
    rt_timing_defaults(&config.timing);
    rt_timing &t = config.timing;
    t.test_miss_us = t.test_hit_us = t.dda_step_us = t.shading_us = t.reflection_us = t.refraction_us = 0;
    t.packet_analysis_us = t.packet_creation_us = t.fb_write_us = t.handover_send_us = t.handover_receive_us = 0;
    t.bus_arbitration_us = 1, t.bus_width_bytes = 4, t.bus_cycle_us = 2, t.packet_bytes = 30;
    const double transfer_us = 1 + 8 * 2; // ceil(30 / 4) = 8 cycles
    config.dispatch = DispatchPolicy::round_robin;

    Processors policy_ips("pol", 3, config, scene, grid);
    policy_checks(policy_ips, p);

    Processors procs("ip", 3, config, scene, grid);
    ClusterDispatcher dispatcher("dispatcher", config, procs.raw);
    auto arbiter = make_arbiter("round-robin", "arbiter", 1, -1);
    ClusterBus bus("bus", config.timing, false, 1);
    bus.arbiter.bind(*arbiter);
    dispatcher.bus_socket.bind(bus.target);
    bus.keep_log(true);
    Injector inj("inj");
    inj.out.bind(dispatcher.in);
    TimedPacket late = p;
    late.stamp = us(100);
    inj.packets = {p, p, p, p, late};
    sc_core::sc_start();

    // Back to back from 0: ends 17, 34, 51, 68; the fifth waits for its stamp: 100 to 117.
    std::vector<sc_time> want_start{us(0), us(17), us(34), us(51), us(100)};
    bool log_ok = bus.log().size() == 5;
    for (size_t i = 0; log_ok && i < 5; i++)
        log_ok = bus.log()[i].start == want_start[i] && bus.log()[i].end == want_start[i] + us(transfer_us);
    check(log_ok, "bus transfers at 0, 17, 34, 51 and 100 us, each 1 + 8 x 2 = 17 us");
    check(dispatcher.dispatched(0) == 2 && dispatcher.dispatched(1) == 2 && dispatcher.dispatched(2) == 1,
          "round-robin dispatch counts 2, 2, 1");
    check(procs.ledgers[0]->totals().consumed[RT_PACKET_RAY] == 2 &&
              procs.ledgers[1]->totals().consumed[RT_PACKET_RAY] == 2 &&
              procs.ledgers[2]->totals().consumed[RT_PACKET_RAY] == 1,
          "each processor took up the packets dispatched to it");
    check(procs.ledgers[0]->image_time() == us(68), "processor 0's last packet arrived at 68 us (4th transfer)");
    check(procs.ledgers[1]->image_time() == us(117), "processor 1's last packet arrived at 117 us (5th transfer)");
    check(procs.ledgers[2]->image_time() == us(51), "processor 2's packet arrived at 51 us (3rd transfer)");
    int rc = harness::finish();
    rt_grid_free(grid);
    rt_scene_free(scene);
    return rc;
}
