// stamp_order_queue_test.cpp - an input queue in stamp order (PacketQueueSetup::stamp_order, the
// loosely-timed path with a quantum): the reader takes the earliest stamp first, whatever order
// the packets arrived in, and packets of one stamp in their arrival order; in arrival order (the
// default) a packet stamped earlier that arrives later waits behind the others.
#include <cstdint>
#include <vector>

#include "model_test.h"
#include "packet_pool.h"
#include "packet_queue.h"

using namespace torusrt;

namespace {

struct Outcome {
    std::vector<uint32_t> by_stamp, by_arrival;  // packet x, in the order each reader took them
    size_t high_water = 0;
};

Outcome simulate()
{
    Outcome r;
    PacketPool pool;
    PacketQueueSetup setup;
    setup.pool = &pool;
    PacketQueue arrival("arrival", 0, setup);
    setup.stamp_order = true;
    PacketQueue stamped("stamped", 0, setup);
    // (x, stamp in us): arrival order differs from stamp order; x 4 and 5 share a stamp.
    const uint32_t xs[] = {1, 2, 3, 4, 5, 6};
    const double stamps[] = {30, 10, 20, 15, 15, 5};
    for (int i = 0; i < 6; i++) {
        TimedPacket p;
        p.packet.x = xs[i];
        p.stamp = model_test::us(stamps[i]);
        arrival.push_pooled(pool, pool.add(p, -1));
        stamped.push_pooled(pool, pool.add(p, -1));
    }
    r.high_water = stamped.high_water();
    uint32_t h;
    while (stamped.try_take_first_pooled(h)) {
        r.by_stamp.push_back(pool.at(h).packet.x);
        pool.release(h);
    }
    while (arrival.try_take_first_pooled(h)) {
        r.by_arrival.push_back(pool.at(h).packet.x);
        pool.release(h);
    }
    return r;
}

const Outcome &run()
{
    static const Outcome r = simulate();
    return r;
}

}  // namespace

TEST(StampOrderQueue, EarliestStampFirstTiesInArrivalOrder)
{
    // Stamps 5 (x 6), 10 (x 2), 15 (x 4, then x 5: arrival order), 20 (x 3), 30 (x 1).
    EXPECT_EQ(run().by_stamp, (std::vector<uint32_t>{6, 2, 4, 5, 3, 1}));
    EXPECT_EQ(run().high_water, 6u);
}

TEST(StampOrderQueue, ArrivalOrderIsTheDefault)
{
    EXPECT_EQ(run().by_arrival, (std::vector<uint32_t>{1, 2, 3, 4, 5, 6}));
}
