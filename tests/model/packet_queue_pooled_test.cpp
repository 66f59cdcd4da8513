// packet_queue_pooled_test.cpp - a reader that takes packets up in their pool slots
// (try_take_first_pooled, what a flat processor without reservations does) sees the same packets
// in the same order as one that copies them out (try_take_first); the take frees the packet's
// buffer slot at once but leaves its pool slot with the reader until the reader releases it,
// and a handle handed back to the queue by push_pooled is the same slot, not a copy.
#include <cstdint>
#include <vector>

#include "model_test.h"
#include "packet_pool.h"
#include "packet_queue.h"

using namespace torusrt;

namespace {

struct Outcome {
    std::vector<uint32_t> copied_x, pooled_x;  // packet x, in the order each reader took them
    std::vector<uint32_t> handles;             // the handles the pooled reader was given
    std::vector<uint32_t> pushed;              // the handles pushed into the pooled queue
    size_t pool_in_use_after_takes = 0, pool_in_use_after_release = 0;
    size_t occupancy_after_takes = 1;
    bool empty_after = false;
    uint32_t handed_back = 0, retaken = 0, retaken_x = 0;
};

TimedPacket packet(uint32_t x, uint32_t cls)
{
    TimedPacket p;
    p.packet.x = x;
    p.cls = cls;
    return p;
}

Outcome simulate()
{
    Outcome r;
    PacketPool pool;
    PacketQueueSetup in_pool;
    in_pool.pool = &pool;
    PacketQueue copied("copied", 0, in_pool), pooled("pooled", 0, in_pool);
    const uint32_t xs[] = {7, 3, 11, 5};
    for (uint32_t i = 0; i < 4; i++) {
        copied.push_pooled(pool, pool.add(packet(xs[i], i % 2), -1));
        uint32_t h = pool.add(packet(xs[i], i % 2), -1);
        r.pushed.push_back(h);
        pooled.push_pooled(pool, h);
    }
    TimedPacket t;
    while (copied.try_take_first(t)) r.copied_x.push_back(t.packet.x);
    uint32_t h;
    while (pooled.try_take_first_pooled(h)) {
        r.handles.push_back(h);
        r.pooled_x.push_back(pool.at(h).packet.x);
    }
    r.pool_in_use_after_takes = pool.in_use();
    r.occupancy_after_takes = pooled.size();
    // The reader hands one packet back by its handle (as a processor forwards to itself) ...
    r.handed_back = r.handles[1];
    pooled.push_pooled(pool, r.handed_back);
    pooled.try_take_first_pooled(r.retaken);
    r.retaken_x = pool.at(r.retaken).packet.x;
    r.empty_after = pooled.empty();
    // ... and releases every slot it holds.
    for (uint32_t k : r.handles) pool.release(k);
    r.pool_in_use_after_release = pool.in_use();
    return r;
}

const Outcome &run()
{
    static const Outcome r = simulate();
    return r;
}

}  // namespace

TEST(PacketQueuePooled, SameOrderAsTakingByCopy)
{
    std::vector<uint32_t> expected = {7, 3, 11, 5};  // arrival order, whatever the class
    EXPECT_EQ(run().copied_x, expected);
    EXPECT_EQ(run().pooled_x, expected);
}

TEST(PacketQueuePooled, TheReaderKeepsThePacketsSlot)
{
    EXPECT_EQ(run().handles, run().pushed) << "each packet is taken up where it was pushed";
    EXPECT_EQ(run().occupancy_after_takes, 0u) << "its buffer slot is free once taken";
    // The copying reader's four slots were freed as it took them; the pooled reader holds four.
    EXPECT_EQ(run().pool_in_use_after_takes, 4u);
    EXPECT_EQ(run().pool_in_use_after_release, 0u) << "until it releases them";
}

TEST(PacketQueuePooled, AHandleHandedBackIsTheSameSlot)
{
    EXPECT_EQ(run().retaken, run().handed_back);
    EXPECT_EQ(run().retaken_x, 3u);
    EXPECT_TRUE(run().empty_after);
}
