// hand_over_timing_test.cpp - a flat machine that takes its processors' packets for other nodes
// on as they are handed over, tells a waiting processor of a packet in the delta it arrives and
// runs a processor right after its own node's deliveries (HandOverTiming::at_once, what every
// run uses), gives the same simulated times, counts and image as the same machine taking both
// packets one delta later and running its processors from the activation queue, after every
// delivery of the delta (next_delta). Two sizes, 2x2x2 and 4x4x4. All four machines are
// elaborated side by side and run in one simulation; none sees another.
//
// Scene: a mirror sphere among diffuse ones, so the runs have reflection and shadow packets,
// packets for the same node (created at a hit) and for other nodes (forwarded to the next cell).
#include <memory>
#include <string>
#include <vector>

#include "model_test.h"
#include "packet_ledger.h"
#include "rt_framebuffer.h"
#include "rt_grid.h"
#include "rt_mapping.h"
#include "rt_scene.h"
#include "sim_config.h"
#include "torus_system.h"

using namespace torusrt;

namespace {

rt_scene *mirror_scene()
{
    rt_scene *s = rt_scene_new();
    rt_scene_set_view(s, rt_vec(0, 1, 9), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45.0, 24, 24);
    rt_material diffuse = rt_material_default();
    diffuse.color = rt_vec(0.8, 0.3, 0.2);
    rt_scene_set_material(s, &diffuse);
    rt_scene_add_sphere(s, rt_vec(-2, 0, 0), 1);
    rt_scene_add_sphere(s, rt_vec(2, -0.5, 1), 0.8);
    rt_scene_add_sphere(s, rt_vec(0, 2, -1), 0.7);
    rt_material mirror = rt_material_default();
    mirror.ks = 0.6;
    rt_scene_set_material(s, &mirror);
    rt_scene_add_sphere(s, rt_vec(0, -0.3, -2), 1.3);
    rt_scene_add_light(s, rt_vec(3, 6, 8), nullptr);
    char msg[256];
    rt_scene_finish(s, msg, sizeof msg);
    return s;
}

// What one machine did.
struct Machine {
    double image_time_s = -1;
    bool conserved = false;
    std::vector<double> busy_s;
    std::vector<uint64_t> packets_in, packets_out, queue_high_water;
    std::vector<uint64_t> link_packets;
    std::vector<double> link_busy_s;
    std::vector<uint8_t> image;
};

struct Outcome {
    Machine small_once, small_delta, large_once, large_delta;
    bool built = false;
};

struct Run {
    SimConfig config;
    std::vector<int32_t> owner;
    PacketLedger ledger;
    rt_framebuffer *fb = nullptr;
    std::unique_ptr<TorusSystem> top;
};

std::unique_ptr<Run> elaborate(const char *name, int side, HandOverTiming timing, const rt_scene *scene,
                               const rt_grid *grid)
{
    auto r = std::make_unique<Run>();
    r->config.cells = {8, 8, 8};
    r->config.ips = {side, side, side};
    rt_timing_defaults(&r->config.timing);
    r->config.step = rt_step_params_default();
    r->owner.resize(rt_grid_cell_count(grid));
    int cells[3] = {8, 8, 8}, procs[3] = {side, side, side};
    char msg[256];
    if (rt_mapping_fill(cells, procs, RT_MAP_CYCLIC, 1, r->owner.data(), msg, sizeof msg) != RT_OK) return nullptr;
    const rt_camera *cam = rt_scene_camera(scene);
    r->fb = rt_framebuffer_new(cam->width, cam->height);
    r->top = std::make_unique<TorusSystem>(name, r->config, scene, grid, r->owner.data(), r->ledger, r->fb, timing);
    return r;
}

Machine record(Run &r, const rt_scene *scene)
{
    Machine m;
    m.image_time_s = r.ledger.image_time().to_seconds();
    m.conserved = r.ledger.conserved();
    for (IntersectionProcessor *ip : r.top->processors()) {
        m.busy_s.push_back(ip->busy_time().to_seconds());
        m.packets_in.push_back(ip->packets_in());
        m.packets_out.push_back(ip->packets_out());
        m.queue_high_water.push_back(ip->queue().high_water());
    }
    for (const auto &l : r.top->links()) {
        m.link_packets.push_back(l->packets());
        m.link_busy_s.push_back(l->busy_time().to_seconds());
    }
    const rt_camera *cam = rt_scene_camera(scene);
    m.image.resize(size_t{cam->width} * cam->height * 3);
    rt_framebuffer_to_rgb8(r.fb, m.image.data());
    rt_framebuffer_free(r.fb);
    return m;
}

Outcome simulate()
{
    Outcome out;
    rt_scene *scene = mirror_scene();
    char msg[256] = "";
    rt_grid *grid = rt_grid_new(scene, 8, 8, 8, msg, sizeof msg);
    if (!grid) return out;  // every check then fails on `built`
    auto small_once = elaborate("small_once", 2, HandOverTiming::at_once, scene, grid);
    auto small_delta = elaborate("small_delta", 2, HandOverTiming::next_delta, scene, grid);
    auto large_once = elaborate("large_once", 4, HandOverTiming::at_once, scene, grid);
    auto large_delta = elaborate("large_delta", 4, HandOverTiming::next_delta, scene, grid);
    if (!small_once || !small_delta || !large_once || !large_delta) return out;
    sc_core::sc_start();
    out.small_once = record(*small_once, scene);
    out.small_delta = record(*small_delta, scene);
    out.large_once = record(*large_once, scene);
    out.large_delta = record(*large_delta, scene);
    out.built = true;
    rt_grid_free(grid);
    rt_scene_free(scene);
    return out;
}

const Outcome &run()
{
    static const Outcome r = simulate();
    return r;
}

void expect_same(const Machine &once, const Machine &delta)
{
    EXPECT_TRUE(once.conserved);
    EXPECT_TRUE(delta.conserved);
    EXPECT_GT(once.image_time_s, 0);
    EXPECT_EQ(once.image_time_s, delta.image_time_s);
    EXPECT_EQ(once.busy_s, delta.busy_s);
    EXPECT_EQ(once.packets_in, delta.packets_in);
    EXPECT_EQ(once.packets_out, delta.packets_out);
    EXPECT_EQ(once.queue_high_water, delta.queue_high_water);
    EXPECT_EQ(once.link_packets, delta.link_packets);
    EXPECT_EQ(once.link_busy_s, delta.link_busy_s);
    EXPECT_EQ(once.image, delta.image);
}

}  // namespace

TEST(HandOverTiming, ScenarioBuilt)
{
    ASSERT_TRUE(run().built);
    // Packets cross links and some wait: the comparison below has something to compare.
    uint64_t crossings = 0, deepest = 0;
    for (uint64_t p : run().large_once.link_packets) crossings += p;
    for (uint64_t h : run().large_once.queue_high_water) deepest = h > deepest ? h : deepest;
    EXPECT_GT(crossings, 1000u);
    EXPECT_GT(deepest, 1u);
}

TEST(HandOverTiming, SameTimesWithOwnEvents)
{
    ASSERT_TRUE(run().built);
    expect_same(run().small_once, run().small_delta);
}

TEST(HandOverTiming, SameTimesWithTheWakeCalendar)
{
    ASSERT_TRUE(run().built);
    expect_same(run().large_once, run().large_delta);
}
