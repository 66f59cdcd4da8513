// replica_choice_test.cpp - which owner of a replicated cell a packet goes to, worked out by hand
// on a 2x2 torus and a ring of 4 (ReplicaChoice alone), and two 2x2 machines run end to end:
//   - every cell owned by all four nodes, --replica-choice hash: no packet is ever forwarded, and
//     each node steps exactly the packets the hash gives it (counted here on the renderer's steps);
//   - a cyclic table with every cell copied onto the diagonally opposite node, nearest, buffers
//     of capacity 1 under --flow classes: packets conserved and the renderer's image.
// Both machines are elaborated side by side and run in one simulation; none sees another.
#include <memory>
#include <string>
#include <vector>

#include "model_test.h"
#include "packet_ledger.h"
#include "replica_choice.h"
#include "rt_framebuffer.h"
#include "rt_grid.h"
#include "rt_mapping.h"
#include "rt_render.h"
#include "rt_scene.h"
#include "sim_config.h"
#include "torus_system.h"

using namespace torusrt;

namespace {

// A packet of pixel (x, y) at `depth`: a new one, or one a step handed over (forwarded).
rt_packet ray(uint32_t x, uint32_t y, uint16_t depth, bool handed_over = true)
{
    rt_packet p{};
    p.x = x;
    p.y = y;
    p.depth = depth;
    p.handed_over = handed_over;
    return p;
}

}  // namespace

// Nodes of the 2x2 torus: 0 (0,0), 1 (1,0), 2 (0,1), 3 (1,1). Hops: 0-1, 0-2, 1-3, 2-3 one;
// 0-3 and 1-2 two. Cell c's primary owner is node c; cell 3 has extra owners 1 and 2 (owners
// 1, 2, 3), cell 0 extra owner 3 (owners 0, 3), cells 1 and 2 none.
TEST(ReplicaChoice, NearestOnATwoByTwoTorus)
{
    Routing routing({2, 2, 1}, "torus");
    const int32_t owner[4] = {0, 1, 2, 3};
    const uint32_t first[5] = {0, 1, 1, 1, 3};
    const int32_t extra[3] = {3, 1, 2};
    rt_replicas table{first, extra};
    ReplicaChoice choice(owner, table, routing, ReplicaRule::nearest);
    rt_packet p = ray(0, 0, 0);
    EXPECT_EQ(choice.choose(0, 3, p), 1);  // 1 and 2 one hop, 3 two: the tie goes to node 1
    EXPECT_EQ(choice.choose(1, 3, p), 1);  // an owner keeps it
    EXPECT_EQ(choice.choose(2, 3, p), 2);
    EXPECT_EQ(choice.choose(3, 3, p), 3);
    EXPECT_EQ(choice.choose(1, 0, p), 0);  // 0 and 3 both one hop from 1: node 0
    EXPECT_EQ(choice.choose(2, 0, p), 0);  // likewise from 2
    EXPECT_EQ(choice.choose(0, 1, p), 1);  // not replicated: its owner
    EXPECT_EQ(choice.choose(3, 2, p), 2);
}

// rt_replica_hash by the documented formula, worked out separately: h(0,0,0) = 0,
// h(1,0,0) = 1834104592 (mod 3 = 1), h(0,1,0) = 3298878556 (mod 3 = 1), h(5,7,2) = 2306568458
// (mod 3 = 2), h(3,2,1) = 751259945 (mod 3 = 2). Owners of cell 3 in ascending order: 1, 2, 3.
TEST(ReplicaChoice, HashOnATwoByTwoTorus)
{
    EXPECT_EQ(rt_replica_hash(0, 0, 0), 0u);
    EXPECT_EQ(rt_replica_hash(1, 0, 0), 1834104592u);
    EXPECT_EQ(rt_replica_hash(0, 1, 0), 3298878556u);
    EXPECT_EQ(rt_replica_hash(5, 7, 2), 2306568458u);
    EXPECT_EQ(rt_replica_hash(3, 2, 1), 751259945u);
    Routing routing({2, 2, 1}, "torus");
    const int32_t owner[4] = {0, 1, 2, 3};
    const uint32_t first[5] = {0, 1, 1, 1, 3};
    const int32_t extra[3] = {3, 1, 2};
    rt_replicas table{first, extra};
    ReplicaChoice choice(owner, table, routing, ReplicaRule::hash);
    EXPECT_EQ(choice.choose(0, 3, ray(0, 0, 0)), 1);  // index 0
    EXPECT_EQ(choice.choose(0, 3, ray(1, 0, 0)), 2);  // index 1
    EXPECT_EQ(choice.choose(0, 3, ray(0, 1, 0)), 2);  // index 1
    EXPECT_EQ(choice.choose(0, 3, ray(5, 7, 2)), 3);  // index 2
    EXPECT_EQ(choice.choose(0, 3, ray(3, 2, 1)), 3);  // index 2
    EXPECT_EQ(choice.choose(2, 3, ray(5, 7, 2)), 2);  // an owner keeps a handed-over packet
    // A packet a step made in the cell goes where the hash says, even from an owner.
    EXPECT_EQ(choice.choose(2, 3, ray(5, 7, 2, false)), 3);
    EXPECT_EQ(choice.choose(3, 3, ray(0, 0, 0, false)), 1);
    // Cell 0 (owners 0, 3): h(1,0,0) mod 2 = 0 -> node 0; h(5,7,2) mod 2 = 0 -> 0; h(3,2,1) odd -> 3.
    EXPECT_EQ(choice.choose(1, 0, ray(1, 0, 0)), 0);
    EXPECT_EQ(choice.choose(1, 0, ray(5, 7, 2)), 0);
    EXPECT_EQ(choice.choose(1, 0, ray(3, 2, 1)), 3);
    // The host (-1) takes the hash rule under nearest too.
    ReplicaChoice nearest(owner, table, routing, ReplicaRule::nearest);
    EXPECT_EQ(nearest.choose(-1, 3, ray(5, 7, 2)), 3);
    EXPECT_EQ(nearest.choose(-1, 3, ray(0, 0, 0)), 1);
}

// A ring of 4: node 0 is one hop from 3 round the wrap-around link, three on a line.
TEST(ReplicaChoice, NearestFollowsTheTopology)
{
    const int32_t owner[1] = {2};
    const uint32_t first[2] = {0, 1};
    const int32_t extra[1] = {3};
    rt_replicas table{first, extra};
    Routing ring({4, 1, 1}, "torus"), line({4, 1, 1}, "mesh");
    EXPECT_EQ(ReplicaChoice(owner, table, ring, ReplicaRule::nearest).choose(0, 0, ray(0, 0, 0)), 3);
    EXPECT_EQ(ReplicaChoice(owner, table, line, ReplicaRule::nearest).choose(0, 0, ray(0, 0, 0)), 2);
    EXPECT_EQ(ReplicaChoice(owner, table, line, ReplicaRule::nearest).choose(1, 0, ray(0, 0, 0)), 2);
}

namespace {

rt_scene *glass_scene()
{
    rt_scene *s = rt_scene_new();
    rt_scene_set_view(s, rt_vec(0, 1, 9), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45.0, 16, 16);
    rt_material diffuse = rt_material_default();
    diffuse.color = rt_vec(0.8, 0.3, 0.2);
    rt_scene_set_material(s, &diffuse);
    rt_scene_add_sphere(s, rt_vec(-2, 0, 0), 1);
    rt_scene_add_sphere(s, rt_vec(2, -0.5, 1), 0.8);
    rt_material glass = rt_material_default();
    glass.ks = 0.3;
    glass.t = 0.6;
    glass.ior = 1.5;
    rt_scene_set_material(s, &glass);
    rt_scene_add_sphere(s, rt_vec(0, -0.3, -1), 1.3);
    rt_scene_add_light(s, rt_vec(3, 6, 8), nullptr);
    char msg[256];
    rt_scene_finish(s, msg, sizeof msg);
    return s;
}

struct Machine {
    bool conserved = false;
    uint64_t forwarded = 0;
    std::vector<uint64_t> packets_in;  // per node: packets it stepped
    std::vector<uint8_t> image;
};

struct Run {
    SimConfig config;
    std::vector<int32_t> owner;
    rt_replicas replicas{nullptr, nullptr};
    PacketLedger ledger;
    rt_framebuffer *fb = nullptr;
    std::unique_ptr<TorusSystem> top;
};

// A 2x2 machine on 4x4x4 cells: every cell on all four nodes (hash), or cyclic with each cell
// also on the node diagonally opposite its owner (nearest, capacity 1).
std::unique_ptr<Run> elaborate(const char *name, bool everywhere, const rt_scene *scene, const rt_grid *grid)
{
    auto r = std::make_unique<Run>();
    r->config.cells = {4, 4, 4};
    r->config.ips = {2, 2, 1};
    rt_timing_defaults(&r->config.timing);
    r->config.step = rt_step_params_default();
    r->config.replica_choice = everywhere ? ReplicaRule::hash : ReplicaRule::nearest;
    r->config.queue_capacity = everywhere ? 0 : 1;
    size_t cells = rt_grid_cell_count(grid);
    r->owner.resize(cells);
    int dims[3] = {4, 4, 4}, procs[3] = {2, 2, 1};
    char msg[256];
    if (rt_mapping_fill(dims, procs, RT_MAP_CYCLIC, 1, r->owner.data(), msg, sizeof msg) != RT_OK) return nullptr;
    for (size_t c = 0; c <= cells; c++)
        r->config.replica_first.push_back(static_cast<uint32_t>(c * (everywhere ? 3 : 1)));
    for (size_t c = 0; c < cells; c++) {
        for (int32_t n = 0; n < 4; n++)
            if (everywhere ? n != r->owner[c] : n == (r->owner[c] ^ 3)) r->config.replica_extra.push_back(n);
    }
    r->replicas = r->config.replica_table();
    const rt_camera *cam = rt_scene_camera(scene);
    r->fb = rt_framebuffer_new(cam->width, cam->height);
    r->top = std::make_unique<TorusSystem>(name, r->config, scene, grid, r->owner.data(), r->ledger, r->fb,
                                           HandOverTiming::at_once, &r->replicas);
    return r;
}

Machine record(Run &r, const rt_scene *scene)
{
    Machine m;
    m.conserved = r.ledger.conserved();
    m.forwarded = r.ledger.totals().forwarded;
    for (IntersectionProcessor *ip : r.top->processors()) m.packets_in.push_back(ip->packets_in());
    const rt_camera *cam = rt_scene_camera(scene);
    m.image.resize(size_t{cam->width} * cam->height * 3);
    rt_framebuffer_to_rgb8(r.fb, m.image.data());
    rt_framebuffer_free(r.fb);
    return m;
}

struct Outcome {
    Machine everywhere, diagonal;
    std::vector<uint8_t> reference;
    std::vector<uint64_t> hashed_steps;  // per node: the renderer's steps of the packets hashed to it
    bool built = false;
};

// Counts a renderer step at the node the hash rule sends its packet to.
void count_step(void *ctx, uint32_t, const rt_packet *p, const rt_step_result *)
{
    (*static_cast<std::vector<uint64_t> *>(ctx))[rt_replica_hash(p->x, p->y, p->depth) % 4]++;
}

// The renderer's image (every packet stepped once, the grid walked whole), and per node the
// steps of the packets the hash rule sends there.
void reference(const rt_scene *scene, const rt_grid *grid, Outcome &out)
{
    const rt_camera *cam = rt_scene_camera(scene);
    rt_framebuffer *fb = rt_framebuffer_new(cam->width, cam->height);
    rt_render_options o = rt_render_options_default();
    out.hashed_steps.assign(4, 0);
    o.on_step = count_step;
    o.on_step_ctx = &out.hashed_steps;
    rt_render_stats stats;
    char msg[256];
    if (rt_render(scene, grid, &o, fb, &stats, msg, sizeof msg) != RT_OK) return;
    out.reference.resize(size_t{cam->width} * cam->height * 3);
    rt_framebuffer_to_rgb8(fb, out.reference.data());
    rt_framebuffer_free(fb);
}

Outcome simulate()
{
    Outcome out;
    rt_scene *scene = glass_scene();
    char msg[256] = "";
    rt_grid *grid = rt_grid_new(scene, 4, 4, 4, msg, sizeof msg);
    if (!grid) return out;
    reference(scene, grid, out);
    auto everywhere = elaborate("everywhere", true, scene, grid);
    auto diagonal = elaborate("diagonal", false, scene, grid);
    if (!everywhere || !diagonal) return out;
    sc_core::sc_start();
    out.everywhere = record(*everywhere, scene);
    out.diagonal = record(*diagonal, scene);
    out.built = !out.reference.empty();
    rt_grid_free(grid);
    rt_scene_free(scene);
    return out;
}

const Outcome &run()
{
    static const Outcome r = simulate();
    return r;
}

}  // namespace

TEST(ReplicaChoice, MachinesBuilt) { ASSERT_TRUE(run().built); }

// Every node holds every cell: every packet, primary or made by a step, goes to the node the
// hash of its pixel and depth picks (owners 0..3 in order, so node h mod 4), and is walked
// there to its end: nothing is ever forwarded.
TEST(ReplicaChoice, EveryCellEverywhereKeepsEachRayAtItsHashedNode)
{
    const Outcome &o = run();
    ASSERT_TRUE(o.built);
    EXPECT_TRUE(o.everywhere.conserved);
    EXPECT_EQ(o.everywhere.forwarded, 0u);
    EXPECT_EQ(o.everywhere.image, o.reference);
    // Each node steps exactly the packets hashed to it, once each; the hash spreads them over
    // all four nodes.
    for (int n = 0; n < 4; n++) {
        EXPECT_EQ(o.everywhere.packets_in[n], o.hashed_steps[n]) << "node " << n;
        EXPECT_GT(o.hashed_steps[n], 0u) << "node " << n;
    }
}

TEST(ReplicaChoice, DiagonalCopiesAtCapacityOneConserveAndMatchTheRenderer)
{
    const Outcome &o = run();
    ASSERT_TRUE(o.built);
    EXPECT_TRUE(o.diagonal.conserved);
    EXPECT_GT(o.diagonal.forwarded, 0u);
    EXPECT_EQ(o.diagonal.image, o.reference);
}
