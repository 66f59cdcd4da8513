// queue_order_test.cpp - the order an IP's input queue offers its packets in (--queue-order):
// primaries-first offers the host's next primary when due, then the queued packets oldest
// first; rays-first offers the queued ray packets newest first, then the next primary when due,
// then the shadow packets newest first, then a primary not yet due. A reader that takes every
// packet in its pool slot (a flat processor) and one that is offered each in turn (a processor
// reserving buffer room) see the same order; a refused packet stays queued.
#include <cstdint>
#include <string>
#include <vector>

#include "model_test.h"
#include "packet_pool.h"
#include "packet_queue.h"
#include "primary_source.h"
#include "rt_grid.h"
#include "rt_scene.h"

using model_test::us;
using namespace torusrt;

namespace {

// Queued packets are named by their x: rays 10, 30, shadows 20, 40, in that arrival order; the
// host's primaries by "p" and their pixel.
struct Outcome {
    std::vector<std::string> fifo_taken, rays_taken, rays_offered, rays_late_primary;
    std::string refused_then_taken;
    size_t left_after_refusal = 0;
    std::vector<uint32_t> primary_pixels;  // the entering pixels, in order
    uint64_t inject_us = 0;
};

const uint32_t kW = 4, kH = 3;

TimedPacket queued(uint32_t x, rt_packet_kind kind, double stamp_us)
{
    TimedPacket p;
    p.packet.x = x;
    p.packet.kind = static_cast<uint8_t>(kind);
    p.stamp = us(stamp_us);
    return p;
}

std::string name_of(const TimedPacket &t)
{
    if (t.from_host) return "p" + std::to_string(t.packet.y * kW + t.packet.x);
    return std::to_string(t.packet.x);
}

// The setup of a queue of node 0 fed by `source`, in `pool`.
PacketQueueSetup setup(PacketPool &pool, PrimarySource &source, bool rays_first)
{
    PacketQueueSetup s;
    s.pool = &pool;
    s.primaries = &source;
    s.entry_node = 0;
    s.rays_first = rays_first;
    return s;
}

// The four packets pushed into `q` (the shadows stamped `shadow_stamp_us`).
void fill(PacketQueue &q, PacketPool &pool, double shadow_stamp_us = 0)
{
    q.push_pooled(pool, pool.add(queued(10, RT_PACKET_RAY, 0), -1));
    q.push_pooled(pool, pool.add(queued(20, RT_PACKET_SHADOW, shadow_stamp_us), -1));
    q.push_pooled(pool, pool.add(queued(30, RT_PACKET_RAY, 0), -1));
    q.push_pooled(pool, pool.add(queued(40, RT_PACKET_SHADOW, shadow_stamp_us), -1));
}

// Takes everything in pool slots, as a flat processor without reservations does.
std::vector<std::string> drain_pooled(PacketQueue &q, PacketPool &pool)
{
    std::vector<std::string> order;
    uint32_t h;
    while (q.try_take_first_pooled(h)) {
        order.push_back(name_of(pool.at(h)));
        pool.release(h);
    }
    return order;
}

Outcome simulate()
{
    Outcome r;
    char msg[256];
    rt_scene *scene = rt_scene_new();
    rt_scene_set_view(scene, rt_vec(0, 0, 5), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45.0, kW, kH);
    rt_scene_add_sphere(scene, rt_vec(0, 0, 0), 1.0);
    rt_scene_finish(scene, msg, sizeof msg);
    rt_grid *grid = rt_grid_new(scene, 1, 1, 1, msg, sizeof msg);
    int32_t owner[1] = {0};
    for (uint32_t p = 0; p < kW * kH; p++) {
        rt_packet pk;
        int enters = 0;
        rt_primary_packet(scene, grid, p % kW, p / kW, &pk, &enters);
        if (enters) r.primary_pixels.push_back(p);
    }
    {
        PacketPool pool;
        PrimarySource source(scene, grid, owner, 1, sc_core::SC_ZERO_TIME);
        PacketQueue q("fifo", 0, setup(pool, source, false));
        fill(q, pool);
        r.fifo_taken = drain_pooled(q, pool);
    }
    {
        PacketPool pool;
        PrimarySource source(scene, grid, owner, 1, sc_core::SC_ZERO_TIME);
        PacketQueue q("rays", 0, setup(pool, source, true));
        fill(q, pool);
        r.rays_taken = drain_pooled(q, pool);
    }
    {  // a reader that refuses all but shadow 20 is offered every packet in turn
        PacketPool pool;
        PrimarySource source(scene, grid, owner, 1, sc_core::SC_ZERO_TIME);
        PacketQueue q("offered", 0, setup(pool, source, true));
        fill(q, pool);
        TimedPacket got;
        bool taken = q.try_take(
            [&](const TimedPacket &c) {
                r.rays_offered.push_back(name_of(c));
                return c.packet.x == 20 && !c.from_host;
            },
            &got);
        r.refused_then_taken = taken ? name_of(got) : "none";
        r.left_after_refusal = q.size();
    }
    {  // primaries injected 1000 us apart: the first is due at 1000 us, after shadows of 500 us
        r.inject_us = 1000;
        PacketPool pool;
        PrimarySource source(scene, grid, owner, 1, us(1000));
        PacketQueue q("late", 0, setup(pool, source, true));
        fill(q, pool, 500);
        r.rays_late_primary = drain_pooled(q, pool);
    }
    rt_grid_free(grid);
    rt_scene_free(scene);
    return r;
}

const Outcome &run()
{
    static const Outcome r = simulate();
    return r;
}

std::vector<std::string> primaries()
{
    std::vector<std::string> v;
    for (uint32_t p : run().primary_pixels) v.push_back("p" + std::to_string(p));
    return v;
}

std::vector<std::string> joined(std::vector<std::string> a, const std::vector<std::string> &b)
{
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

}  // namespace

TEST(QueueOrder, ScenarioPremises)
{
    ASSERT_GE(run().primary_pixels.size(), 2u) << "some primaries enter the space";
    EXPECT_LT(run().primary_pixels.size(), size_t{kW * kH}) << "and some miss it";
}

TEST(QueueOrder, PrimariesFirstTakesThePrimariesThenTheOldest)
{
    EXPECT_EQ(run().fifo_taken, joined(primaries(), {"10", "20", "30", "40"}));
}

TEST(QueueOrder, RaysFirstTakesNewestRaysThenPrimariesThenNewestShadows)
{
    EXPECT_EQ(run().rays_taken, joined(joined({"30", "10"}, primaries()), {"40", "20"}));
}

TEST(QueueOrder, AnOfferedReaderSeesTheSameOrderAndARefusedPacketStays)
{
    // Offered 30, 10, then the first primary (refused: it is not consumed, the next is never
    // offered), then 40, then 20, which is taken.
    std::vector<std::string> want = {"30", "10", primaries().front(), "40", "20"};
    EXPECT_EQ(run().rays_offered, want);
    EXPECT_EQ(run().refused_then_taken, "20");
    EXPECT_EQ(run().left_after_refusal, 3u) << "the refused rays and shadow stay queued";
}

TEST(QueueOrder, RaysFirstTakesAPrimaryNotYetDueAfterTheShadows)
{
    // The first primary is due at (pixel + 1) x 1000 us >= 1000 us, later than the shadows'
    // stamps (500 us): the shadows come first.
    EXPECT_EQ(run().rays_late_primary, joined({"30", "10", "40", "20"}, primaries()));
}
