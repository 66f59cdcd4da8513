// link_bookings_test.cpp - a loosely-timed link's bookings (link_bookings.h): a crossing takes the
// earliest gap at or after its ready time that fits one packet time, whatever order the crossings
// are booked in; crossings handed over in time order start as the busy-until rule starts them.
#include <cstdint>
#include <vector>

#include "link_bookings.h"
#include "model_test.h"

using torusrt::LinkBookings;

namespace {
constexpr uint64_t kLength = 10;  // one packet time, in ticks
}

TEST(LinkBookings, InTimeOrderTheyStartAsBusyUntil)
{
    LinkBookings b;
    uint64_t free_at = 0;
    const uint64_t ready[] = {0, 3, 5, 40, 41, 80};
    for (uint64_t r : ready) {
        uint64_t expected = r > free_at ? r : free_at;
        EXPECT_EQ(b.book(r, r, kLength), expected) << "ready at " << r;
        free_at = expected + kLength;
    }
}

TEST(LinkBookings, ALateCrossingTakesTheGapAtItsTime)
{
    LinkBookings b;
    EXPECT_EQ(b.book(100, 0, kLength), 100u);  // booked ahead first
    EXPECT_EQ(b.book(20, 0, kLength), 20u) << "the link is free at 20: not behind the crossing at 100";
    EXPECT_EQ(b.book(95, 0, kLength), 110u) << "[95, 105) overlaps [100, 110): it starts at 110";
    EXPECT_EQ(b.book(85, 0, kLength), 85u) << "[85, 95) fits before 100";
    EXPECT_EQ(b.book(86, 0, kLength), 120u) << "every gap from 86 on is too short until 120";
    EXPECT_EQ(b.book(25, 0, kLength), 30u) << "behind [20, 30)";
}

TEST(LinkBookings, NoTwoCrossingsOverlap)
{
    LinkBookings b;
    std::vector<uint64_t> starts;
    // Ready times out of order, several in one place, as senders a quantum apart hand them over.
    const uint64_t ready[] = {500, 10, 505, 12, 300, 300, 300, 15, 499, 0, 510, 290};
    for (uint64_t r : ready) {
        uint64_t s = b.book(r, 0, kLength);
        EXPECT_GE(s, r) << "never before it is ready";
        starts.push_back(s);
    }
    for (size_t i = 0; i < starts.size(); i++)
        for (size_t j = i + 1; j < starts.size(); j++)
            EXPECT_TRUE(starts[i] + kLength <= starts[j] || starts[j] + kLength <= starts[i])
                << "crossings " << i << " at " << starts[i] << " and " << j << " at " << starts[j] << " overlap";
}

TEST(LinkBookings, CrossingsOverByNowAreForgotten)
{
    LinkBookings b;
    for (uint64_t t = 0; t < 1000; t += kLength) b.book(t, t, kLength);
    EXPECT_EQ(b.book(2000, 2000, kLength), 2000u);
    EXPECT_EQ(b.booked(), 1u) << "only the crossing not over at 2000 is kept";
}
