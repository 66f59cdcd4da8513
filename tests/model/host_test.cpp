// host_test.cpp - the host and its primary source: every pixel whose primary ray enters the object
// space is handed out by the node owning its entry cell, in pixel order, stamped (pixel + 1) x
// host_inject; the rays that miss get the background written at the start and count as missed;
// every entering primary counts as created at once.
#include <systemc>
#include <tlm>
#include <tlm_utils/simple_target_socket.h>
#include <vector>

#include "host.h"
#include "model_test.h"
#include "rt_packet.h"

using model_test::us;
using sc_core::sc_time;
using namespace torusrt;

struct FrameBufferStub : sc_core::sc_module {
    tlm_utils::simple_target_socket<FrameBufferStub> socket;
    std::vector<uint32_t> pixels;  // y * width + x
    std::vector<sc_time> times;
    bool colour_ok = true;
    rt_vec3 want{};
    uint32_t width = 0;
    explicit FrameBufferStub(sc_core::sc_module_name n) : sc_module(n), socket("socket")
    {
        socket.register_b_transport(this, &FrameBufferStub::b_transport);
    }
    void b_transport(tlm::tlm_generic_payload &t, sc_time &delay)
    {
        auto *c = reinterpret_cast<const rt_contribution *>(t.get_data_ptr());
        for (size_t i = 0; i < t.get_data_length() / sizeof *c; i++) {
            pixels.push_back(c[i].y * width + c[i].x);
            colour_ok = colour_ok && c[i].rgb.x == want.x && c[i].rgb.y == want.y && c[i].rgb.z == want.z;
        }
        times.push_back(sc_core::sc_time_stamp() + delay);
        t.set_response_status(tlm::TLM_OK_RESPONSE);
    }
};

// What one node's primary source handed out.
struct NodePrimaries {
    std::vector<uint32_t> pixels;
    bool stamps = true, entry = true, flags = true;
};

// The expected pixels (computed from the kernel's primary rays, apart from the host) and what the
// host did with them.
struct Outcome {
    std::vector<std::vector<uint32_t>> want_pixels;  // per entry node, the entering pixels in order
    std::vector<uint32_t> want_missed;
    size_t entering = 0;
    uint64_t created_before_start = 0, missed_before_start = 0;
    sc_time image_time_before_start;
    bool done_injecting = false, colour_ok = false;
    std::vector<uint32_t> background_pixels;
    std::vector<sc_time> background_times;
    uint64_t injected = 0;
    std::vector<NodePrimaries> nodes;
};

static const uint32_t w = 16, h = 12;

// Takes every primary of each node from the source, checking stamps, entry cells and flags.
static void take_primaries(PrimarySource &src, const rt_grid *grid, const std::vector<int32_t> &owner, Outcome &run)
{
    for (int node = 0; node < 3; node++) {
        NodePrimaries got;
        while (src.pending(node)) {
            sc_time next = src.next_time(node);
            TimedPacket t = src.take(node);
            uint32_t p = t.packet.y * w + t.packet.x;
            got.pixels.push_back(p);
            got.stamps = got.stamps && t.stamp == us(3.0 * (p + 1)) && next == t.stamp;
            got.entry = got.entry && owner[rt_packet_cell(grid, &t.packet)] == node;
            got.flags = got.flags && t.from_host && t.packet.kind == RT_PACKET_RAY && t.packet.depth == 0;
        }
        run.nodes.push_back(got);
    }
}

static Outcome simulate()
{
    Outcome run;
    char msg[256];
    rt_scene *scene = rt_scene_new();
    rt_scene_set_view(scene, rt_vec(0, 0, 5), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45.0, w, h);
    rt_scene_set_background(scene, rt_vec(0.25, 0.5, 0.75));
    rt_scene_add_sphere(scene, rt_vec(0, 0, 0), 1.0);
    rt_scene_finish(scene, msg, sizeof msg);
    rt_grid *grid = rt_grid_new(scene, 2, 2, 2, msg, sizeof msg);
    std::vector<int32_t> owner(rt_grid_cell_count(grid));
    for (size_t c = 0; c < owner.size(); c++) owner[c] = static_cast<int32_t>(c % 3);  // 3 nodes

    run.want_pixels.resize(3);
    for (uint32_t p = 0; p < w * h; p++) {
        rt_packet pk;
        int enters = 0;
        rt_primary_packet(scene, grid, p % w, p / w, &pk, &enters);
        if (enters) run.want_pixels[owner[rt_packet_cell(grid, &pk)]].push_back(p);
        else run.want_missed.push_back(p);
    }
    run.entering = run.want_pixels[0].size() + run.want_pixels[1].size() + run.want_pixels[2].size();

    SimConfig config;
    rt_timing_defaults(&config.timing);
    config.timing.host_inject_us = 3;
    config.ips = {3, 1, 1};
    PacketLedger ledger;
    Host host("host", config, scene, grid, owner.data(), ledger);
    FrameBufferStub fb("fb");
    fb.want = rt_vec(0.25, 0.5, 0.75);
    fb.width = w;
    host.fb_socket.bind(fb.socket);

    run.created_before_start = ledger.totals().created[RT_PACKET_RAY];
    run.missed_before_start = ledger.totals().primary_missed;
    run.image_time_before_start = ledger.image_time();
    sc_core::sc_start();

    run.done_injecting = host.done_injecting();
    run.background_pixels = fb.pixels, run.background_times = fb.times, run.colour_ok = fb.colour_ok;
    run.injected = host.injected();
    take_primaries(host.primaries(), grid, owner, run);
    rt_grid_free(grid);
    rt_scene_free(scene);
    return run;
}

static const Outcome &run()
{
    static const Outcome r = simulate();
    return r;
}

TEST(Host, ScenarioPremises)
{
    EXPECT_TRUE(!run().want_missed.empty() && run().entering > 0) << "the scene has missed and entering primaries";
    for (int node = 0; node < 3; node++)
        EXPECT_FALSE(run().want_pixels[node].empty()) << "node " << node << " is the entry node of some primary";
}

TEST(Host, CountsPrimariesAtOnce)
{
    EXPECT_EQ(run().created_before_start, run().entering) << "every entering primary counts as created at once";
    EXPECT_EQ(run().missed_before_start, run().want_missed.size()) << "every missing primary counts as missed";
    // The last missed pixel p is injected at (p + 1) x 3 us.
    EXPECT_EQ(run().image_time_before_start, us(3.0 * (run().want_missed.back() + 1)))
        << "image time starts at the last missed pixel's injection";
}

TEST(Host, WritesTheBackgroundOfMissedPixelsAtTimeZero)
{
    EXPECT_TRUE(run().done_injecting) << "background written";
    EXPECT_EQ(run().background_pixels, run().want_missed) << "exactly the missed pixels, in pixel order";
    EXPECT_TRUE(run().colour_ok) << "background colour is the scene's";
    for (const sc_time &t : run().background_times) EXPECT_EQ(t, sc_core::SC_ZERO_TIME) << "written at time 0";
}

TEST(Host, InjectsTheEnteringPrimaries) { EXPECT_EQ(run().injected, run().entering); }

TEST(Host, HandsOutPrimariesInPixelOrderAtTheirEntryNode)
{
    ASSERT_EQ(run().nodes.size(), 3u);
    for (int node = 0; node < 3; node++) {
        const NodePrimaries &got = run().nodes[node];
        EXPECT_EQ(got.pixels, run().want_pixels[node]) << "primaries in pixel order at their entry node " << node;
        EXPECT_TRUE(got.stamps) << "primary stamped (pixel + 1) x 3 us (node " << node << ")";
        EXPECT_TRUE(got.entry) << "primary packet starts in a cell of its node (node " << node << ")";
        EXPECT_TRUE(got.flags) << "primary is a depth-0 ray from the host (node " << node << ")";
    }
}
