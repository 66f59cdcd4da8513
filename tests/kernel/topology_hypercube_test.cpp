// topology_hypercube_test.cpp - the hypercube topology: e-cube routes by hand, hop distance =
// popcount, the Gray-code placement keeping neighbouring grid positions one hop apart (round the
// wrap too), Scotch's hypercube distances = the hops, the refused shapes, and a cost mapping on it.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include <scotch.h>

#include "rt_cost_map.h"
#include "rt_nff.h"
#include "rt_topology.h"
#include "test_support.h"
#include "topology_class.h"

namespace {

using torusrt_test::make_topology;

int popcount(int v) { return __builtin_popcount(static_cast<unsigned>(v)); }

}  // namespace

TEST(Hypercube, PortsFlipOneBitEach)
{
    const int dims[3] = {4, 2, 2};
    rt_topology t = make_topology("hypercube", dims);
    EXPECT_EQ(t.nodes, 16);
    EXPECT_EQ(t.ports, 4) << "the 4-cube";
    EXPECT_STREQ(rt_topology_port_name(&t, 0), "d0");
    EXPECT_STREQ(rt_topology_port_name(&t, 3), "d3");
    EXPECT_STREQ(rt_topology_port_name(&t, 4), "none");
    EXPECT_EQ(rt_topology_neighbour(&t, 0b0101, 1), 0b0111);
    EXPECT_EQ(rt_topology_neighbour(&t, 0b0101, 2), 0b0001);
    EXPECT_EQ(rt_topology_channels(&t), 1) << "e-cube needs no dateline";
    EXPECT_EQ(rt_topology_one_axis_name(&t), nullptr);
    EXPECT_FALSE(rt_topology_has_ties(&t));
    for (int n = 0; n < t.nodes; n++)
        for (int p = 0; p < t.ports; p++) EXPECT_FALSE(rt_topology_crosses_dateline(&t, n, p));
}

TEST(Hypercube, ECubeRoutesTheLowestDifferingBitFirst)
{
    const int dims[3] = {8, 4, 2};
    rt_topology t = make_topology("hypercube", dims);
    // 0b000000 -> 0b101100: bits 2, 3 and 5 differ, so d2, then d3, then d5.
    EXPECT_EQ(rt_topology_first_port(&t, 0b000000, 0b101100, RT_TIES_SPLIT, 0), 2);
    EXPECT_EQ(rt_topology_first_port(&t, 0b000100, 0b101100, RT_TIES_SPLIT, 1), 3);
    EXPECT_EQ(rt_topology_first_port(&t, 0b001100, 0b101100, RT_TIES_PLUS, 0), 5);
    EXPECT_EQ(rt_topology_first_port(&t, 0b101100, 0b101100, RT_TIES_SPLIT, 0), -1) << "no hop to itself";
    EXPECT_EQ(rt_topology_first_port(&t, 0b111111, 0b011110, RT_TIES_SPLIT, 7), 0);
    EXPECT_EQ(rt_topology_first_port(&t, 0b111110, 0b011110, RT_TIES_SPLIT, 7), 5);
}

TEST(Hypercube, HopsArePopcountAndTheRoutesLength)
{
    const int dims[3] = {4, 4, 2};
    rt_topology t = make_topology("hypercube", dims);
    for (int a = 0; a < t.nodes; a++)
        for (int b = 0; b < t.nodes; b++) {
            EXPECT_EQ(rt_topology_hops(&t, a, b), popcount(a ^ b));
            int h = 0, last = -1;
            for (int at = a; at != b && h <= t.ports; h++) {
                int port = rt_topology_first_port(&t, at, b, RT_TIES_SPLIT, 0);
                EXPECT_GT(port, last) << "each dimension once, in increasing order";
                last = port;
                at = rt_topology_neighbour(&t, at, port);
            }
            EXPECT_EQ(h, popcount(a ^ b)) << a << " -> " << b;
        }
}

TEST(Hypercube, GrayCodeKeepsNeighbouringPositionsOneHopApart)
{
    const int shapes[][3] = {{4, 4, 4}, {8, 2, 1}, {2, 8, 4}, {16, 1, 1}};
    for (const auto &dims : shapes) {
        rt_topology t = make_topology("hypercube", dims);
        std::set<int> seen;
        for (int id = 0; id < t.nodes; id++) {
            int c[3] = {id % dims[0], id / dims[0] % dims[1], id / (dims[0] * dims[1])};
            int n = rt_topology_node_at(&t, c);
            EXPECT_EQ(rt_topology_node_of_grid_id(&t, id), n);
            seen.insert(n);
            int back[3];
            rt_topology_position(&t, n, back);
            EXPECT_EQ(back[0], c[0]);
            EXPECT_EQ(back[1], c[1]);
            EXPECT_EQ(back[2], c[2]);
            for (int k = 0; k < 3; k++) {
                if (dims[k] < 2) continue;
                int next[3] = {c[0], c[1], c[2]};
                next[k] = (c[k] + 1) % dims[k];  // round the wrap too
                EXPECT_EQ(rt_topology_hops(&t, n, rt_topology_node_at(&t, next)), 1)
                    << "axis " << k << " from position id " << id;
            }
        }
        EXPECT_EQ(static_cast<int>(seen.size()), t.nodes) << "every node holds one position";
    }
}

TEST(Hypercube, SixCubeHopsAreThe4x4x4TorusHops)
{
    const int dims[3] = {4, 4, 4};
    rt_topology cube = make_topology("hypercube", dims), torus = make_topology("torus", dims);
    for (int a = 0; a < 64; a++)
        for (int b = 0; b < 64; b++)
            EXPECT_EQ(
                rt_topology_hops(&cube, rt_topology_node_of_grid_id(&cube, a), rt_topology_node_of_grid_id(&cube, b)),
                rt_topology_hops(&torus, a, b));
}

TEST(Hypercube, ScotchDistancesAreTheHops)
{
    const int dims[3] = {4, 2, 4};
    rt_topology t = make_topology("hypercube", dims);
    SCOTCH_Arch arch;
    ASSERT_EQ(SCOTCH_archInit(&arch), 0);
    const char *call = "";
    ASSERT_EQ(rt_topology_scotch_arch(&t, 1, &arch, &call), 0) << call;
    EXPECT_STREQ(call, "SCOTCH_archHcub");
    EXPECT_EQ(SCOTCH_archSize(&arch), t.nodes);
    SCOTCH_ArchDom da, db;
    for (int a = 0; a < t.nodes; a++) {
        ASSERT_EQ(SCOTCH_archDomTerm(&arch, &da, a), 0);
        EXPECT_EQ(SCOTCH_archDomNum(&arch, &da), a) << "terminal numbers are node ids";
        for (int b = 0; b < t.nodes; b++) {
            ASSERT_EQ(SCOTCH_archDomTerm(&arch, &db, b), 0);
            EXPECT_EQ(SCOTCH_archDomDist(&arch, &da, &db), rt_topology_hops(&t, a, b)) << a << ", " << b;
        }
    }
    SCOTCH_archExit(&arch);
    SCOTCH_archInit(&arch);
    ASSERT_EQ(rt_topology_scotch_arch(&t, 2, &arch, &call), 0) << call;
    EXPECT_EQ(SCOTCH_archSize(&arch), t.nodes * 8) << "cost:2 grows each of the three axes by a bit";
    SCOTCH_archExit(&arch);
    for (long term = 0; term < t.nodes * 8; term++)
        EXPECT_EQ(rt_topology_fold_terminal(&t, 2, term), term % t.nodes) << "the low bits are the node";
}

TEST(Hypercube, RefusesAxesThatAreNotPowersOfTwo)
{
    rt_topology t;
    char msg[256] = "";
    const int bad[3] = {6, 4, 4};
    EXPECT_EQ(rt_topology_make("hypercube", bad, &t, msg, sizeof msg), RT_ERR_INVALID);
    EXPECT_NE(std::string(msg).find("power of two"), std::string::npos) << msg;
    EXPECT_NE(std::string(msg).find("6x4x4"), std::string::npos) << msg;
    const int one[3] = {1, 1, 1};
    rt_topology single = make_topology("hypercube", one);
    EXPECT_EQ(single.ports, 0) << "one node, no link";
}

TEST(Hypercube, CostMappingUsesEveryNodeAndCountsCubeHops)
{
    rt_scene *scene = nullptr;
    char msg[RT_MSG_LEN] = "";
    std::string path = std::string(TORUSRT_SOURCE_DIR) + "/scenes/paper-image2.nff";
    ASSERT_EQ(rt_nff_load(path.c_str(), &scene, msg, sizeof msg, nullptr, nullptr), RT_OK) << msg;
    ASSERT_EQ(rt_scene_set_resolution(scene, 32, 32), RT_OK);
    rt_grid *grid = rt_grid_new(scene, 6, 5, 4, msg, sizeof msg);
    ASSERT_NE(grid, nullptr) << msg;
    rt_timing timing;
    rt_timing_defaults(&timing);
    rt_step_params prm = rt_step_params_default();
    rt_cost_pilot pilot;
    ASSERT_EQ(rt_cost_pilot_run(scene, grid, &prm, &timing, &pilot, msg, sizeof msg), RT_OK) << msg;
    const int dims[3] = {2, 2, 2};
    rt_topology t = make_topology("hypercube", dims);
    std::vector<int32_t> owner(pilot.cells, -1), again(pilot.cells, -2);
    rt_cost_map_facts f;
    ASSERT_EQ(rt_cost_map(&pilot, &t, rt_cost_edge_us(&timing), owner.data(), &f, msg, sizeof msg), RT_OK) << msg;
    std::set<int32_t> used(owner.begin(), owner.end());
    EXPECT_EQ(used.size(), 8u) << "every node of the 3-cube gets cells";
    EXPECT_GE(*used.begin(), 0);
    EXPECT_LE(*used.rbegin(), 7);
    // The facts' hops are the cube's: every cut face costs between 1 and 3 hops.
    EXPECT_GE(f.cut_hops, f.cut_packets);
    EXPECT_LE(f.cut_hops, 3 * f.cut_packets);
    ASSERT_EQ(rt_cost_map(&pilot, &t, rt_cost_edge_us(&timing), again.data(), nullptr, msg, sizeof msg), RT_OK);
    EXPECT_EQ(owner, again) << "reproducible";
    std::vector<int32_t> folded(pilot.cells, -1);
    ASSERT_EQ(rt_cost_map_folded(&pilot, &t, rt_cost_edge_us(&timing), 2, folded.data(), nullptr, msg, sizeof msg),
              RT_OK)
        << msg;
    std::set<int32_t> fused(folded.begin(), folded.end());
    EXPECT_EQ(fused.size(), 8u) << "cost:2 folds onto every node";
    rt_cost_pilot_release(&pilot);
    rt_grid_free(grid);
    rt_scene_free(scene);
}
