// intersection_processor_test.cpp - an IP takes up each packet no earlier than its stamp, spends
// the operation counts of its packet step times the timing table (computed here from the counts
// of the same step run directly on a copy of the packet), then writes the step's contributions
// and emits the new packets followed by the forwarded one, all at the step's end.
#include <systemc>
#include <tlm>
#include <tlm_utils/simple_target_socket.h>
#include <vector>

#include "intersection_processor.h"
#include "model_test.h"
#include "packet_injector.h"
#include "rt_packet.h"

using model_test::Injector;
using model_test::us;
using sc_core::sc_time;
using namespace torusrt;

// Records (time, kind) of every packet the IP emits.
struct RecordingSink : PacketSinkIf {
    std::vector<sc_time> times;
    std::vector<int> kinds;
    void accept(const TimedPacket &p) override
    {
        times.push_back(sc_core::sc_time_stamp());
        kinds.push_back(p.packet.kind);
        if (p.stamp != sc_core::sc_time_stamp()) stamp_mismatch = true;
    }
    bool stamp_mismatch = false;
};

// Records (time, contribution count) of every frame-buffer write.
struct FrameBufferStub : sc_core::sc_module {
    tlm_utils::simple_target_socket<FrameBufferStub> socket;
    std::vector<sc_time> times;
    std::vector<size_t> counts;
    explicit FrameBufferStub(sc_core::sc_module_name n) : sc_module(n), socket("socket")
    {
        socket.register_b_transport(this, &FrameBufferStub::b_transport);
    }
    void b_transport(tlm::tlm_generic_payload &t, sc_time &delay)
    {
        times.push_back(sc_core::sc_time_stamp() + delay);
        counts.push_back(t.get_data_length() / sizeof(rt_contribution));
        t.set_response_status(tlm::TLM_OK_RESPONSE);
    }
};

// The step's cost written out field by field, independently of rt_timing_step_us.
static double step_us(const rt_timing &t, const rt_op_counts &o)
{
    return o.tests_missed * t.test_miss_us + o.tests_hit * t.test_hit_us + o.dda_steps * t.dda_step_us +
           o.shadings * t.shading_us + o.reflection_vectors * t.reflection_us + o.refraction_vectors * t.refraction_us +
           o.packets_analysed * t.packet_analysis_us + o.packets_created * t.packet_creation_us +
           o.fb_writes * t.fb_write_us + o.handovers_sent * t.handover_send_us +
           o.handovers_received * t.handover_receive_us + o.cell_steps * t.cell_step_packet_us;
}

struct Expected {
    double us;
    std::vector<int> kinds;
    size_t contribs;
};

static Expected expect(const rt_scene *s, const rt_grid *g, const int32_t *owner, const SimConfig &c, rt_packet p)
{
    rt_step_result r;
    rt_step_result_init(&r, s);
    rt_step(s, g, owner, 0, &c.step, &p, &r);
    Expected e{step_us(c.timing, r.ops), {}, r.contrib_count};
    for (size_t i = 0; i < r.created_count; i++) e.kinds.push_back(r.created[i].kind);
    if (r.fate == RT_FATE_FORWARDED) e.kinds.push_back(p.kind);
    rt_step_result_release(&r);
    return e;
}

// What the run recorded, and the step costs worked out apart from the model.
struct Outcome {
    bool both_enter = false;
    Expected ea, eb;  // A: hits the sphere; B: passes beside it and is forwarded
    std::vector<sc_time> times;
    std::vector<int> kinds;
    bool stamp_mismatch = false;
    std::vector<sc_time> fb_times;
    std::vector<size_t> fb_counts;
    sc_time busy;
    uint64_t packets_in = 0, packets_out = 0;
};

static Outcome simulate()
{
    Outcome run;
    char msg[256];
    rt_scene *scene = rt_scene_new();
    rt_scene_set_view(scene, rt_vec(0, 0, 5), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45.0, 16, 16);
    rt_scene_add_sphere(scene, rt_vec(0, 0, 0), 1.0);
    rt_scene_set_ambient(scene, rt_vec(0.2, 0.2, 0.2));  // a hit then writes a contribution
    rt_scene_add_light(scene, rt_vec(5, 5, 5), nullptr);
    rt_scene_finish(scene, msg, sizeof msg);
    rt_grid *grid = rt_grid_new(scene, 2, 2, 2, msg, sizeof msg);

    // A: hits the sphere; B: passes beside it into the far half of the grid. Both start in cells of owner 0;
    // every other cell belongs to owner 1, so B is forwarded.
    rt_packet a, b;
    int enters_a = 0, enters_b = 0;
    rt_primary_packet(scene, grid, 5, 5, &a, &enters_a);
    rt_primary_packet(scene, grid, 4, 4, &b, &enters_b);
    run.both_enter = enters_a && enters_b;
    std::vector<int32_t> owner(rt_grid_cell_count(grid), 1);
    owner[rt_packet_cell(grid, &a)] = 0;
    owner[rt_packet_cell(grid, &b)] = 0;

    SimConfig config;
    rt_timing_defaults(&config.timing);
    // Distinct whole microseconds per operation: a wrong multiplier changes the sum.
    config.timing.test_miss_us = 1300, config.timing.test_hit_us = 1750, config.timing.dda_step_us = 340;
    config.timing.shading_us = 4600, config.timing.reflection_us = 680, config.timing.refraction_us = 1100;
    config.timing.packet_analysis_us = 580, config.timing.packet_creation_us = 1600;
    config.timing.fb_write_us = 7, config.timing.handover_send_us = 11, config.timing.handover_receive_us = 13;
    config.step = rt_step_params_default();

    run.ea = expect(scene, grid, owner.data(), config, a);
    run.eb = expect(scene, grid, owner.data(), config, b);

    PacketLedger ledger;
    IntersectionProcessor ip("ip", config, scene, grid, owner.data(), 0, 0, ledger);
    RecordingSink sink;
    FrameBufferStub fb("fb");
    Injector inj("inj");
    ip.out.bind(sink);
    ip.fb_socket.bind(fb.socket);
    inj.out.bind(ip.in);
    // Both injected at 0; A is stamped 10 us (it arrives then), B at 0 waits behind A.
    inj.packets = {TimedPacket{a, us(10)}, TimedPacket{b, sc_core::SC_ZERO_TIME}};
    sc_core::sc_start();

    run.times = sink.times, run.kinds = sink.kinds, run.stamp_mismatch = sink.stamp_mismatch;
    run.fb_times = fb.times, run.fb_counts = fb.counts;
    run.busy = ip.busy_time(), run.packets_in = ip.packets_in(), run.packets_out = ip.packets_out();
    rt_grid_free(grid);
    rt_scene_free(scene);
    return run;
}

static const Outcome &run()
{
    static const Outcome r = simulate();
    return r;
}

// A's new packets, then B's forwarded ray.
static std::vector<int> want_kinds()
{
    std::vector<int> k = run().ea.kinds;
    k.insert(k.end(), run().eb.kinds.begin(), run().eb.kinds.end());
    return k;
}

TEST(IntersectionProcessor, ScenarioPremises)
{
    EXPECT_TRUE(run().both_enter) << "both test rays enter the grid";
    EXPECT_TRUE(!run().ea.kinds.empty() && run().ea.contribs > 0) << "A's step creates packets and contributions";
    EXPECT_TRUE(!run().eb.kinds.empty() && run().eb.kinds.back() == RT_PACKET_RAY) << "B's step forwards the ray";
}

TEST(IntersectionProcessor, EmitsNewPacketsThenTheForwardedRay)
{
    EXPECT_EQ(run().kinds, want_kinds()) << "emitted kinds: A's new packets, then B's forwarded ray";
}

TEST(IntersectionProcessor, EachPacketCostsItsStepAfterItsStamp)
{
    // A starts at its stamp, 10 us, and ends step(A) later; B waited behind A and ends step(B) after that.
    sc_time end_a = us(10) + us(run().ea.us), end_b = end_a + us(run().eb.us);
    std::vector<sc_time> want(run().ea.kinds.size(), end_a);
    want.insert(want.end(), run().eb.kinds.size(), end_b);
    EXPECT_EQ(run().times, want) << "emissions at 10 us + step(A), then + step(B)";
    EXPECT_FALSE(run().stamp_mismatch) << "every emitted packet is stamped with its emission time";
}

TEST(IntersectionProcessor, BusyTimeIsTheSumOfTheSteps)
{
    EXPECT_EQ(run().busy, us(run().ea.us + run().eb.us)) << "busy time is step(A) + step(B)";
}

TEST(IntersectionProcessor, CountsPacketsInAndOut)
{
    EXPECT_EQ(run().packets_in, 2u);
    EXPECT_EQ(run().packets_out, want_kinds().size());
}

TEST(IntersectionProcessor, WritesContributionsAtTheEndOfTheStep)
{
    const Outcome &r = run();
    ASSERT_FALSE(r.fb_times.empty());
    EXPECT_EQ(r.fb_times[0], us(10) + us(r.ea.us)) << "A's contributions written at the end of its step";
    EXPECT_EQ(r.fb_counts[0], r.ea.contribs);
    EXPECT_EQ(r.fb_times.size(), r.eb.contribs ? 2u : 1u) << "one frame-buffer write per step with contributions";
}
