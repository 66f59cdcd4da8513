// topology_test.cpp - the topology interface (rt_topology.h) on the torus and the mesh: the
// registry, neighbours, hops against the routes, positions, and Scotch's distances against the hops.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include <scotch.h>

#include "rt_topology.h"
#include "test_support.h"
#include "topology_class.h"

namespace {

using torusrt_test::make_topology;

// Hops along the routes rt_topology_first_port gives, with `key` for the ties.
int walked_hops(const rt_topology &t, int from, int to, uint32_t key)
{
    int h = 0;
    for (int at = from; at != to; h++) {
        int port = rt_topology_first_port(&t, at, to, RT_TIES_SPLIT, key);
        EXPECT_GE(port, 0);
        at = rt_topology_neighbour(&t, at, port);
        EXPECT_GE(at, 0);
        if (h > t.nodes) return -1;  // a route that does not arrive
    }
    return h;
}

// Scotch's distance between the terminals of nodes a and b of the topology's architecture.
void expect_scotch_distances_are_hops(const rt_topology &t)
{
    SCOTCH_Arch arch;
    ASSERT_EQ(SCOTCH_archInit(&arch), 0);
    const char *call = "";
    ASSERT_EQ(rt_topology_scotch_arch(&t, 1, &arch, &call), 0) << call;
    EXPECT_EQ(SCOTCH_archSize(&arch), t.nodes);
    SCOTCH_ArchDom da, db;
    for (int a = 0; a < t.nodes; a++) {
        ASSERT_EQ(SCOTCH_archDomTerm(&arch, &da, a), 0);
        for (int b = 0; b < t.nodes; b++) {
            ASSERT_EQ(SCOTCH_archDomTerm(&arch, &db, b), 0);
            EXPECT_EQ(SCOTCH_archDomDist(&arch, &da, &db), rt_topology_hops(&t, a, b))
                << rt_topology_name(&t) << " terminals " << a << ", " << b;
            EXPECT_EQ(rt_topology_fold_terminal(&t, 1, a), a) << "fold 1: a terminal is its node";
        }
    }
    SCOTCH_archExit(&arch);
}

}  // namespace

TEST(Topology, RegistryNamesTorusAndMeshAndRefusesOthers)
{
    EXPECT_STREQ(rt_topology_name_at(0), "torus");
    EXPECT_STREQ(rt_topology_name_at(1), "mesh");
    EXPECT_EQ(rt_topology_name_at(-1), nullptr);
    const int dims[3] = {2, 2, 2};
    rt_topology t;
    char msg[128] = "";
    EXPECT_EQ(rt_topology_make("ring", dims, &t, msg, sizeof msg), RT_ERR_INVALID);
    EXPECT_NE(std::string(msg).find("ring"), std::string::npos) << msg;
    const int none[3] = {4, 0, 1};
    EXPECT_EQ(rt_topology_make("torus", none, &t, msg, sizeof msg), RT_ERR_INVALID);
}

TEST(Topology, TorusAndMeshHaveSixNamedPorts)
{
    const int dims[3] = {4, 2, 1};
    rt_topology torus = make_topology("torus", dims), mesh = make_topology("mesh", dims);
    EXPECT_EQ(torus.ports, 6);
    EXPECT_EQ(torus.nodes, 8);
    EXPECT_STREQ(rt_topology_port_name(&torus, 0), "xp");
    EXPECT_STREQ(rt_topology_port_name(&mesh, 5), "zm");
    EXPECT_STREQ(rt_topology_port_name(&torus, 6), "none");
    EXPECT_EQ(rt_topology_neighbour(&torus, 3, 0), 0) << "+x from the last node wraps round";
    EXPECT_EQ(rt_topology_neighbour(&mesh, 3, 0), -1) << "a mesh has no wrap-around";
    EXPECT_EQ(rt_topology_neighbour(&torus, 0, 4), -1) << "no link along an axis of one node";
    EXPECT_EQ(rt_topology_channels(&torus), 2);
    EXPECT_EQ(rt_topology_channels(&mesh), 1);
    EXPECT_TRUE(rt_topology_crosses_dateline(&torus, 3, 0));
    EXPECT_FALSE(rt_topology_crosses_dateline(&torus, 2, 0));
    EXPECT_TRUE(rt_topology_crosses_dateline(&torus, 0, 1));
    EXPECT_FALSE(rt_topology_crosses_dateline(&mesh, 0, 1));
    EXPECT_EQ(rt_topology_port_dimension(&torus, 3), 1);
    EXPECT_STREQ(rt_topology_one_axis_name(&torus), "ring");
    EXPECT_STREQ(rt_topology_one_axis_name(&mesh), "line");
}

TEST(Topology, TiesOnlyOnATorusWithAnEvenRing)
{
    const int odd[3] = {3, 3, 1}, even[3] = {3, 2, 1};
    rt_topology t_odd = make_topology("torus", odd);
    EXPECT_FALSE(rt_topology_has_ties(&t_odd));
    rt_topology t_even = make_topology("torus", even), m_even = make_topology("mesh", even);
    EXPECT_TRUE(rt_topology_has_ties(&t_even));
    EXPECT_FALSE(rt_topology_has_ties(&m_even));
    const int ring[3] = {8, 1, 1};
    rt_topology r = make_topology("torus", ring);
    EXPECT_EQ(rt_topology_first_port(&r, 0, 4, RT_TIES_SPLIT, 6), 0) << "a tie with an even key goes +";
    EXPECT_EQ(rt_topology_first_port(&r, 0, 4, RT_TIES_SPLIT, 7), 1) << "a tie with an odd key goes -";
    EXPECT_EQ(rt_topology_first_port(&r, 0, 4, RT_TIES_PLUS, 7), 0) << "plus: always +";
    EXPECT_EQ(rt_topology_first_port(&r, 2, 2, RT_TIES_SPLIT, 0), -1) << "no hop to itself";
}

TEST(Topology, HopsAreTheRoutesLengthAndPositionsRoundTrip)
{
    const int shapes[][3] = {{8, 1, 1}, {4, 2, 2}, {3, 4, 2}, {5, 3, 1}};
    for (const char *name : {"torus", "mesh"})
        for (const auto &dims : shapes) {
            rt_topology t = make_topology(name, dims);
            for (int a = 0; a < t.nodes; a++) {
                int c[3];
                rt_topology_position(&t, a, c);
                EXPECT_EQ(rt_topology_node_at(&t, c), a);
                EXPECT_EQ(rt_topology_node_of_grid_id(&t, a), a) << "grid ids are node ids";
                for (int b = 0; b < t.nodes; b++)
                    for (uint32_t key = 0; key < 2; key++)
                        EXPECT_EQ(walked_hops(t, a, b, key), rt_topology_hops(&t, a, b))
                            << name << " " << a << " -> " << b << " key " << key;
            }
        }
}

TEST(Topology, ScotchDistancesAreTheHops)
{
    const int shapes[][3] = {{4, 2, 2}, {3, 4, 2}, {8, 1, 1}};
    for (const char *name : {"torus", "mesh"})
        for (const auto &dims : shapes) expect_scotch_distances_are_hops(make_topology(name, dims));
}
