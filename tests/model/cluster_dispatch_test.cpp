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
#include "grant_log.h"
#include "cluster_dispatch.h"
#include "model_test.h"
#include "packet_injector.h"
#include "rt_packet.h"

using model_test::Injector;
using model_test::us;
using sc_core::sc_time;
using namespace torusrt;

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

// What the policies chose on set loads (before the run) and what the run did.
struct Outcome {
    bool enters = false;
    std::vector<int> shortest_queue;  // choices at loads 0 0 0, 1 0 0, 1 2 0, 1 2 2, 3 2 2
    std::vector<int> round_robin;     // five choices at loads 3 2 2
    bool unknown_policy_threw = false;
    std::vector<ClusterBus::Grant> bus_log;
    std::vector<uint64_t> dispatched, consumed;
    std::vector<sc_time> last_arrival;
};

// Loads are packets waiting or in service: a queued packet counts 1, a busy line 1.
static void choose_on_set_loads(Processors &procs, const TimedPacket &p, Outcome &run)
{
    auto sq = make_dispatch_policy("shortest-queue");
    auto rr = make_dispatch_policy("round-robin");
    std::vector<IntersectionProcessor *> &v = procs.raw;
    run.shortest_queue.push_back(sq->choose(v));
    v[0]->busy_trace() = true;  // loads 1, 0, 0
    run.shortest_queue.push_back(sq->choose(v));
    v[1]->queue().push_blocking(p);
    v[1]->queue().push_blocking(p);  // loads 1, 2, 0
    run.shortest_queue.push_back(sq->choose(v));
    v[2]->queue().push_blocking(p);
    v[2]->busy_trace() = true;  // loads 1, 2, 2
    run.shortest_queue.push_back(sq->choose(v));
    v[0]->queue().push_blocking(p);
    v[0]->queue().push_blocking(p);  // loads 3, 2, 2
    run.shortest_queue.push_back(sq->choose(v));
    for (int i = 0; i < 5; i++) run.round_robin.push_back(rr->choose(v));
    for (auto *ip : v) ip->busy_trace() = false;
    try {
        make_dispatch_policy("longest-queue");
    } catch (const std::invalid_argument &) {
        run.unknown_policy_threw = true;
    }
}

// The bus figures: arbitration 1 us, 4-byte width, 2 us cycle, 30-byte packets.
static const double transfer_us = 1 + 8 * 2;  // ceil(30 / 4) = 8 cycles

static Outcome simulate()
{
    Outcome run;
    char msg[256];
    rt_scene *scene = rt_scene_new();
    rt_scene_set_view(scene, rt_vec(0, 0, 5), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45.0, 16, 16);
    rt_scene_add_sphere(scene, rt_vec(0, 0, 0), 1.0);  // no light: a hit creates nothing
    rt_scene_finish(scene, msg, sizeof msg);
    rt_grid *grid = rt_grid_new(scene, 2, 2, 2, msg, sizeof msg);
    TimedPacket p{};
    int enters = 0;
    rt_primary_packet(scene, grid, 8, 8, &p.packet, &enters);
    run.enters = enters;

    SimConfig config;
    rt_timing_defaults(&config.timing);
    rt_timing &t = config.timing;
    t.test_miss_us = t.test_hit_us = t.dda_step_us = t.shading_us = t.reflection_us = t.refraction_us = 0;
    t.packet_analysis_us = t.packet_creation_us = t.fb_write_us = t.handover_send_us = t.handover_receive_us = 0;
    t.bus_arbitration_us = 1, t.bus_width_bytes = 4, t.bus_cycle_us = 2, t.packet_bytes = 30;
    config.dispatch = "round-robin";

    Processors policy_ips("pol", 3, config, scene, grid);
    choose_on_set_loads(policy_ips, p, run);

    Processors procs("ip", 3, config, scene, grid);
    ClusterDispatcher dispatcher("dispatcher", config, procs.raw);
    auto arbiter = make_arbiter("round-robin", "arbiter", 1, -1);
    ClusterBus bus("bus", config.timing, false, 1);
    bus.arbiter.bind(*arbiter);
    dispatcher.bus_socket.bind(bus.target);
    GrantLog grants;
    bus.observe(&grants);
    Injector inj("inj");
    inj.out.bind(dispatcher.in);
    TimedPacket late = p;
    late.stamp = us(100);
    inj.packets = {p, p, p, p, late};
    sc_core::sc_start();

    run.bus_log = grants.grants;
    for (int k = 0; k < 3; k++) {
        run.dispatched.push_back(dispatcher.dispatched(k));
        run.consumed.push_back(procs.ledgers[k]->totals().consumed[RT_PACKET_RAY]);
        run.last_arrival.push_back(procs.ledgers[k]->image_time());
    }
    rt_grid_free(grid);
    rt_scene_free(scene);
    return run;
}

static const Outcome &run()
{
    static const Outcome r = simulate();
    return r;
}

TEST(ClusterDispatcher, TestRayEntersTheGrid) { EXPECT_TRUE(run().enters); }

TEST(ClusterDispatcher, ShortestQueuePicksTheFewestTiesToTheLowest)
{
    // Loads 0 0 0 -> 0; 1 0 0 -> 1 (tie with 2); 1 2 0 -> 2; 1 2 2 -> 0; 3 2 2 -> 1 (tie with 2).
    EXPECT_EQ(run().shortest_queue, (std::vector<int>{0, 1, 2, 0, 1}));
}

TEST(ClusterDispatcher, RoundRobinIgnoresTheLoads)
{
    EXPECT_EQ(run().round_robin, (std::vector<int>{0, 1, 2, 0, 1})) << "0, 1, 2, 0, 1 at loads 3 2 2";
}

TEST(ClusterDispatcher, UnknownPolicyThrows) { EXPECT_TRUE(run().unknown_policy_threw); }

TEST(ClusterDispatcher, EachPacketCrossesTheBusNoEarlierThanItsStamp)
{
    // Back to back from 0: ends 17, 34, 51, 68; the fifth waits for its stamp: 100 to 117.
    const std::vector<sc_time> want_start{us(0), us(17), us(34), us(51), us(100)};
    ASSERT_EQ(run().bus_log.size(), 5u);
    for (size_t i = 0; i < 5; i++) {
        EXPECT_EQ(run().bus_log[i].start, want_start[i]) << "transfer " << i;
        EXPECT_EQ(run().bus_log[i].end, want_start[i] + us(transfer_us)) << "transfer " << i << ": 1 + 8 x 2 = 17 us";
    }
}

TEST(ClusterDispatcher, RoundRobinDispatchReachesEachProcessor)
{
    EXPECT_EQ(run().dispatched, (std::vector<uint64_t>{2, 2, 1})) << "round-robin dispatch counts 2, 2, 1";
    EXPECT_EQ(run().consumed, (std::vector<uint64_t>{2, 2, 1})) << "each processor took up its packets";
    // Processor 0 got transfers 1 and 4 (ends 17, 68), 1 got 2 and 5 (34, 117), 2 got 3 (51).
    EXPECT_EQ(run().last_arrival, (std::vector<sc_time>{us(68), us(117), us(51)}));
}
