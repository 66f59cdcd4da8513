// motion_update_test.cpp - a moving scene's cell-list update charged on a 2x1 machine, counted by
// hand: two spheres in a 2x1x1 grid (cell 0 = node 0, cell 1 = node 1), moved by a motion file
// over three frames. The units are the kernel's half-space tests, the bytes 4 per list entry
// changed at another node plus a 20-byte sphere record for a node that did not hold it, the time
// the slowest processor's units x preprocess_unit and the busiest link's bytes at the link
// timing. No simulation: motion_update_cost is arithmetic on the grid before and after.
#include <cstring>
#include <systemc>
#include <vector>

#include "model_test.h"
#include "motion_update.h"
#include "rt_motion.h"
#include "scene_motion.h"

using namespace torusrt;

namespace {

// Sphere 0 at (-3, 0, 0) and sphere 1 at (3, 0, 0), radius 1. Frame 1: sphere 0 moves by 3.5 in
// x to (0.5, 0, 0), across the plane x = 0 between the cells; sphere 1 moves by 0.5 in z, staying
// in cell 1. Frame 2: sphere 0 is back at (-3, 0, 0), sphere 1 stays where frame 1 put it (held
// after its last key: not moved).
// Object space over the frames: x [-4, 4], y [-1, 1], z [-1, 1.5]; padded alike on both sides
// of x, so the one cutting plane of the 2x1x1 grid (one factor 2 on x, none on y and z) is x = 0.
const char *const kMotion = "frames 3\n"
                            "objects 0\n"
                            "key 0\n"
                            "key 1 move 3.5 0 0\n"
                            "key 2 move 0 0 0\n"
                            "objects 1\n"
                            "key 0\n"
                            "key 1 move 0 0 0.5\n";

// Frame k's update under two link timings: 50 us per 28-byte piece, and 2 bytes per us.
struct Outcome {
    bool built = false;
    MotionUpdate per_piece[3], per_byte[3];
    std::vector<uint8_t> moved[3];
};

rt_timing link_timing(double bytes_per_us)
{
    rt_timing t;
    rt_timing_defaults(&t);
    t.preprocess_unit_us = 340;
    t.link_us = 50;
    t.packet_bytes = 28;
    t.link_bytes_per_us = bytes_per_us;
    return t;
}

Outcome simulate()
{
    Outcome out;
    char msg[RT_MSG_LEN] = "";
    rt_scene *scene = rt_scene_new();
    rt_scene_set_view(scene, rt_vec(0, 0, 20), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45.0, 8, 8);
    rt_scene_add_sphere(scene, rt_vec(-3, 0, 0), 1.0);
    rt_scene_add_sphere(scene, rt_vec(3, 0, 0), 1.0);
    if (rt_scene_finish(scene, msg, sizeof msg) != RT_OK) return out;
    rt_motion *raw = nullptr;
    if (rt_motion_parse("two.motion", kMotion, std::strlen(kMotion), &raw, msg, sizeof msg) != RT_OK) return out;
    SceneMotion motion(MotionPtr(raw), ScenePtr(scene), "two.motion", true);
    GridPtr grid;
    const int cells[3] = {2, 1, 1};
    motion.move_to(0, grid, cells, RT_COUNT_SEQUENTIAL, nullptr);
    const Routing ring2({2, 1, 1}, "torus");
    const std::vector<int32_t> owner = {0, 1};
    const rt_timing per_piece = link_timing(0), per_byte = link_timing(2);
    for (uint32_t k = 1; k < 3; k++) {
        motion.move_objects(k);
        std::vector<ObjectCell> before = moved_entries(grid.get(), motion.moved());
        motion.update_lists(k, grid.get(), nullptr);
        out.moved[k] = motion.moved();
        out.per_piece[k] = motion_update_cost(motion.frame_scene(), grid.get(), motion.moved(), before,
                                              MotionMachine{ring2, 2, 1, per_piece, owner.data()});
        out.per_byte[k] = motion_update_cost(motion.frame_scene(), grid.get(), motion.moved(), before,
                                             MotionMachine{ring2, 2, 1, per_byte, owner.data()});
    }
    out.built = true;
    return out;
}

const Outcome &run()
{
    static const Outcome r = simulate();
    return r;
}

}  // namespace

TEST(MotionUpdate, PremiseTheMotionMovesWhatTheCommentsSay)
{
    const Outcome &o = run();
    ASSERT_TRUE(o.built);
    EXPECT_EQ(o.moved[1], (std::vector<uint8_t>{1, 1}));
    EXPECT_EQ(o.moved[2], (std::vector<uint8_t>{1, 0}));
}

// Frame 1. Units (the sequential rule, one plane x = 0, tests on x only):
//   sphere 0, x [-0.5, 1.5]: "-0.5 <= 0?" yes (first slab 0), "1.5 >= 0?" yes (last slab 1): 2;
//   sphere 1, x [2, 4]: "2 <= 0?" no (first = last = slab 1): 1.
// Update 2 + 1 = 3 units; a rebuild lists both: 3 as well. Processor 0 (object 0) has 2, processor
// 1 (object 1) has 1: the slowest has 2, 2 x 340 us = 680 us. A rebuild dealt out alike: 2.
TEST(MotionUpdate, FrameOneUnitsAndUpdateTime)
{
    const MotionUpdate &u = run().per_piece[1];
    EXPECT_EQ(u.objects_moved, 2u);
    EXPECT_EQ(u.units, 3u);
    EXPECT_EQ(u.slowest_units, 2u);
    EXPECT_EQ(u.rebuild_units, 3u);
    EXPECT_EQ(u.rebuild_slowest_units, 2u);
    EXPECT_DOUBLE_EQ(u.update_s, 680e-6);
}

// Frame 1's transfers. Sphere 0 (handled by processor 0, node 0) keeps cell 0 and gains cell 1,
// node 1's, whose cells did not list it: node 0 -> node 1 carries 4 (the entry) + 20 (the sphere
// record: centre and radius as 4 floats, material 4) = 24 bytes, one hop. Sphere 1 (node 1) stays
// in cell 1 of its own node: nothing. The busiest link carries 24 bytes: one 28-byte piece,
// 50 us; at 2 bytes/us, 12 us. The frame waits 680 + 50 = 730 us.
TEST(MotionUpdate, FrameOneSendsTheRecordAndTheEntryToTheNewOwner)
{
    const MotionUpdate &u = run().per_piece[1];
    EXPECT_EQ(u.entries_sent, 1u);
    EXPECT_EQ(u.transfer.objects, 1u);
    EXPECT_EQ(u.transfer.list_bytes, 4u);
    EXPECT_EQ(u.transfer.object_bytes, 20u);
    EXPECT_EQ(u.transfer.bytes(), 24u);
    EXPECT_EQ(u.transfer.byte_hops, 24u);
    EXPECT_EQ(u.transfer.max_hops, 1);
    EXPECT_EQ(u.transfer.busiest_link_bytes, 24u);
    EXPECT_DOUBLE_EQ(u.transfer.time_s, 50e-6);
    EXPECT_DOUBLE_EQ(u.time_s(), 730e-6);
    EXPECT_DOUBLE_EQ(run().per_byte[1].transfer.time_s, 12e-6);
}

// Frame 2: sphere 0 back in cell 0 alone: "-4 <= 0?" yes, "-2 >= 0?" no: 2 units, processor 0,
// 680 us. Sphere 1 did not move. A rebuild: 2 + 1 = 3 units. Node 1's cell 1 loses sphere 0's
// entry: 4 bytes from node 0, no record (removed, not gained); one piece, 50 us; at 2 bytes/us,
// 2 us.
TEST(MotionUpdate, FrameTwoRemovesTheEntryWithoutARecord)
{
    const MotionUpdate &u = run().per_piece[2];
    EXPECT_EQ(u.objects_moved, 1u);
    EXPECT_EQ(u.units, 2u);
    EXPECT_EQ(u.slowest_units, 2u);
    EXPECT_EQ(u.rebuild_units, 3u);
    EXPECT_DOUBLE_EQ(u.update_s, 680e-6);
    EXPECT_EQ(u.entries_sent, 1u);
    EXPECT_EQ(u.transfer.objects, 0u);
    EXPECT_EQ(u.transfer.bytes(), 4u);
    EXPECT_EQ(u.transfer.busiest_link_bytes, 4u);
    EXPECT_DOUBLE_EQ(u.transfer.time_s, 50e-6);
    EXPECT_DOUBLE_EQ(run().per_byte[2].transfer.time_s, 2e-6);
    EXPECT_DOUBLE_EQ(u.time_s(), 730e-6);
}
