// packet_ring_test.cpp - the packet queue's ring store (packet_ring.h): FIFO order through
// wrap-around and growth, and order kept by erase() on either side of the middle. No simulation.
#include <deque>
#include <random>

#include "model_test.h"
#include "packet_ring.h"

using torusrt::PacketRing;

namespace {

// The ring's contents, front to back.
std::deque<int> contents(const PacketRing<int> &r)
{
    std::deque<int> out;
    for (size_t i = 0; i < r.size(); i++) out.push_back(r[i]);
    return out;
}

}  // namespace

TEST(PacketRing, FifoThroughWrapAndGrowth)
{
    PacketRing<int> r;
    // Fill 6 of the first 8 slots, drain 5 so the head sits at slot 5, then push 10: the ring
    // wraps (slots 6, 7, 0, ...) and grows to 16 with the front at index 0 again.
    for (int i = 0; i < 6; i++) r.push_back(i);
    for (int i = 0; i < 5; i++) {
        EXPECT_EQ(r.front(), i);
        r.pop_front();
    }
    for (int i = 6; i < 16; i++) r.push_back(i);
    ASSERT_EQ(r.size(), 11u);
    for (int i = 5; i < 16; i++) {
        EXPECT_EQ(r.front(), i);
        r.pop_front();
    }
    EXPECT_TRUE(r.empty());
}

TEST(PacketRing, EraseKeepsOrderOnBothSides)
{
    PacketRing<int> r;
    for (int i = 0; i < 7; i++) r.push_back(i);
    r.erase(1); // near the front: the one before it moves back
    EXPECT_EQ(contents(r), (std::deque<int>{0, 2, 3, 4, 5, 6}));
    r.erase(4); // near the back: the one after it moves forward
    EXPECT_EQ(contents(r), (std::deque<int>{0, 2, 3, 4, 6}));
    r.erase(0);
    r.erase(r.size() - 1);
    EXPECT_EQ(contents(r), (std::deque<int>{2, 3, 4}));
    EXPECT_EQ(r.back(), 4);
}

TEST(PacketRing, SameAsDequeUnderMixedOperations)
{
    PacketRing<int> r;
    std::deque<int> d;
    std::mt19937 rng(7);
    int next = 0;
    for (int step = 0; step < 20000; step++) {
        unsigned op = rng() % 4;
        if (op < 2 || d.empty()) {
            r.push_back(next);
            d.push_back(next++);
        } else if (op == 2) {
            r.pop_front();
            d.pop_front();
        } else {
            size_t i = rng() % d.size();
            r.erase(i);
            d.erase(d.begin() + static_cast<std::ptrdiff_t>(i));
        }
        ASSERT_EQ(r.size(), d.size());
        if (!d.empty()) {
            ASSERT_EQ(r.front(), d.front());
        }
    }
    EXPECT_EQ(contents(r), d);
}
