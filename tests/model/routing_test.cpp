// routing_test.cpp - dimension-order routing on tori and meshes: neighbours, first hops (ties on even
// rings split by the key, or all + under RouteTies::plus), hop counts.
#include "model_test.h"
#include "routing.h"

using torusrt::direction;
using torusrt::Routing;

TEST(Routing, TorusWrapsAround)
{
    Routing ring({8, 1, 1}, "torus");
    EXPECT_EQ(ring.neighbour(7, direction(0, true)), 0) << "+x from the last node wraps to 0";
    EXPECT_EQ(ring.neighbour(0, direction(0, false)), 7) << "-x from 0 wraps to the last node";
    EXPECT_EQ(ring.neighbour(0, direction(1, true)), -1) << "no link along an axis with one node";
}

TEST(Routing, RingTakesTheShorterWaySplittingTiesByTheKey)
{
    Routing ring({8, 1, 1}, "torus", torusrt::RouteTies::split);
    EXPECT_EQ(ring.next_direction(0, 3, 1), direction(0, true)) << "0 -> 3 goes + whatever the key";
    EXPECT_EQ(ring.next_direction(0, 5, 0), direction(0, false)) << "0 -> 5 goes - (shorter) whatever the key";
    EXPECT_EQ(ring.next_direction(0, 4, 6), direction(0, true)) << "a tie with an even key goes +";
    EXPECT_EQ(ring.next_direction(0, 4, 7), direction(0, false)) << "a tie with an odd key goes -";
    // After the first hop of a tie the rest of the way is shorter: no second tie, no turning back.
    EXPECT_EQ(ring.next_direction(7, 4, 6), direction(0, false)) << "7 -> 4 (after 0 -> 7) keeps going -";
    EXPECT_EQ(ring.next_direction(1, 4, 7), direction(0, true)) << "1 -> 4 (after 0 -> 1) keeps going +";
    EXPECT_EQ(ring.hops(0, 5), 3) << "0 -> 5 takes 3 hops";
    EXPECT_EQ(ring.hops(0, 4), 4) << "0 -> 4 takes 4 hops either way";
    EXPECT_EQ(ring.next_direction(2, 2, 0), -1) << "no hop to itself";
}

TEST(Routing, RingOfTwoUsesBothLinksUnderSplitAndOneUnderPlus)
{
    Routing split({2, 1, 1}, "torus", torusrt::RouteTies::split), plus({2, 1, 1}, "torus", torusrt::RouteTies::plus);
    EXPECT_EQ(split.next_direction(0, 1, 0), direction(0, true)) << "even key: 0 -> 1 on 0's + link";
    EXPECT_EQ(split.next_direction(0, 1, 1), direction(0, false)) << "odd key: 0 -> 1 on 0's - link";
    EXPECT_EQ(split.next_direction(1, 0, 3), direction(0, false)) << "odd key: 1 -> 0 on 1's - link";
    for (uint32_t key = 0; key < 4; key++) {
        EXPECT_EQ(plus.next_direction(0, 1, key), direction(0, true)) << "plus: always + (key " << key << ")";
        EXPECT_EQ(plus.next_direction(1, 0, key), direction(0, true)) << "plus: always + (key " << key << ")";
    }
    EXPECT_EQ(split.neighbour(0, direction(0, true)), 1);
    EXPECT_EQ(split.neighbour(0, direction(0, false)), 1) << "both of a ring of two's links reach the other node";
}

TEST(Routing, MeshHasNoWrapAround)
{
    Routing line({8, 1, 1}, "mesh");
    EXPECT_EQ(line.neighbour(7, direction(0, true)), -1) << "no wrap-around link";
    EXPECT_EQ(line.next_direction(0, 5, 1), direction(0, true)) << "0 -> 5 goes +";
    EXPECT_EQ(line.hops(0, 7), 7) << "0 -> 7 takes 7 hops";
}

TEST(Routing, Torus3dRoutesXFirstTheShortWay)
{
    Routing torus({4, 2, 2}, "torus");
    int from = torus.node({0, 0, 0}), to = torus.node({3, 1, 1});
    EXPECT_EQ(torus.next_direction(from, to, 0), direction(0, false)) << "x first, the short way";
    EXPECT_EQ(torus.hops(from, to), 3) << "(0,0,0) -> (3,1,1) takes 3 hops";
}

TEST(Routing, Torus3dHopsAreTheSumOfRingDistances)
{
    Routing torus({4, 2, 2}, "torus");
    for (int a = 0; a < 16; a++)
        for (int b = 0; b < 16; b++) {
            auto ca = torus.coords(a), cb = torus.coords(b);
            int expect = 0;
            const int dims[3] = {4, 2, 2};
            for (int k = 0; k < 3; k++) {
                int d = ((cb[k] - ca[k]) % dims[k] + dims[k]) % dims[k];
                expect += d < dims[k] - d ? d : dims[k] - d;
            }
            EXPECT_EQ(torus.hops(a, b), expect) << "from " << a << " to " << b;
        }
}

TEST(Routing, CoordsRoundTrip)
{
    Routing torus({4, 2, 2}, "torus");
    for (int n = 0; n < 16; n++) EXPECT_EQ(torus.node(torus.coords(n)), n);
}

// The face works the torus's and mesh's hops out itself: the same ports and datelines as the
// topology's own functions, on every pair of nodes, both tie rules and both key parities.
TEST(Routing, FaceAgreesWithTheTopologyOnEveryPair)
{
    const std::array<int, 3> shapes[] = {{4, 2, 2}, {3, 4, 1}, {2, 2, 2}, {6, 1, 1}};
    for (const char *name : {"torus", "mesh"})
        for (const auto &dims : shapes)
            for (auto ties : {torusrt::RouteTies::split, torusrt::RouteTies::plus}) {
                Routing r(dims, name, ties);
                const rt_topology &t = r.topology();
                rt_route_ties c_ties = ties == torusrt::RouteTies::plus ? RT_TIES_PLUS : RT_TIES_SPLIT;
                for (int a = 0; a < r.nodes(); a++) {
                    for (int b = 0; b < r.nodes(); b++)
                        for (uint32_t key = 0; key < 2; key++)
                            EXPECT_EQ(r.next_direction(a, b, key), rt_topology_first_port(&t, a, b, c_ties, key))
                                << name << " " << a << " -> " << b << " key " << key;
                    for (int p = 0; p < r.ports(); p++)
                        EXPECT_EQ(r.wraps(a, p), rt_topology_crosses_dateline(&t, a, p) != 0)
                            << name << " node " << a << " port " << p;
                }
            }
}
