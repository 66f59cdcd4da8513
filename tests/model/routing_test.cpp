// routing_test.cpp - dimension-order routing on tori and meshes: neighbours, first hops, hop counts.
#include <systemc>

#include "harness.h"
#include "routing.h"

using harness::check;
using torusrt::Routing;
using torusrt::direction;

int sc_main(int, char **)
{
    Routing ring({8, 1, 1}, true);
    check(ring.neighbour(7, direction(0, true)) == 0, "torus: +x from the last node wraps to 0");
    check(ring.neighbour(0, direction(0, false)) == 7, "torus: -x from 0 wraps to the last node");
    check(ring.neighbour(0, direction(1, true)) == -1, "no link along an axis with one node");
    check(ring.next_direction(0, 3) == direction(0, true), "ring: 0 -> 3 goes +");
    check(ring.next_direction(0, 5) == direction(0, false), "ring: 0 -> 5 goes - (shorter)");
    check(ring.next_direction(0, 4) == direction(0, true), "ring: a tie goes +");
    check(ring.hops(0, 5) == 3, "ring: 0 -> 5 takes 3 hops");
    check(ring.next_direction(2, 2) == -1, "no hop to itself");

    Routing line({8, 1, 1}, false);
    check(line.neighbour(7, direction(0, true)) == -1, "mesh: no wrap-around link");
    check(line.next_direction(0, 5) == direction(0, true), "mesh: 0 -> 5 goes +");
    check(line.hops(0, 7) == 7, "mesh: 0 -> 7 takes 7 hops");

    Routing torus({4, 2, 2}, true);
    int from = torus.node({0, 0, 0}), to = torus.node({3, 1, 1});
    check(torus.next_direction(from, to) == direction(0, false), "3D: x first, the short way");
    check(torus.hops(from, to) == 3, "3D: (0,0,0) -> (3,1,1) takes 3 hops");
    bool all_reach = true;
    for (int a = 0; a < 16; a++)
        for (int b = 0; b < 16; b++) {
            int h = torus.hops(a, b);
            auto ca = torus.coords(a), cb = torus.coords(b);
            int expect = 0;
            const int dims[3] = {4, 2, 2};
            for (int k = 0; k < 3; k++) {
                int d = ((cb[k] - ca[k]) % dims[k] + dims[k]) % dims[k];
                expect += d < dims[k] - d ? d : dims[k] - d;
            }
            if (h != expect) all_reach = false;
        }
    check(all_reach, "3D torus: hops equal the sum of ring distances for every pair");
    for (int n = 0; n < 16; n++) check(torus.node(torus.coords(n)) == n, "coords round-trip");
    return harness::finish();
}
