// migration_test.cpp - the migration between two frames' mappings counted by hand on a scene of
// two spheres in a 2x1x1 grid (one sphere per cell): bytes (cell list 4 + 4 per entry, plus each
// object record the new owner lacks), hops by dimension-order routing, and the time of the
// busiest link at link_us per packet_bytes piece. No simulation: migration_cost is arithmetic.
#include <cmath>
#include <systemc>
#include <vector>

#include "migration.h"
#include "model_test.h"
#include "rt_grid.h"
#include "rt_scene.h"

using namespace torusrt;

namespace {

// A scene in a 2x1x1 grid and the link timing of the hand counts (50 us per 28-byte piece).
struct TwoCells {
    rt_scene *scene = nullptr;
    rt_grid *grid = nullptr;
    rt_timing timing{};
    TwoCells(rt_vec3 c0, double r0, rt_vec3 c1, double r1)
    {
        char msg[256];
        scene = rt_scene_new();
        rt_scene_set_view(scene, rt_vec(0, 0, 20), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45.0, 8, 8);
        rt_scene_add_sphere(scene, c0, r0);
        rt_scene_add_sphere(scene, c1, r1);
        rt_scene_finish(scene, msg, sizeof msg);
        grid = rt_grid_new(scene, 2, 1, 1, msg, sizeof msg);
        rt_timing_defaults(&timing);
        timing.link_us = 50;
        timing.packet_bytes = 28;
        timing.link_bytes_per_us = 0;
    }
    ~TwoCells()
    {
        rt_grid_free(grid);
        rt_scene_free(scene);
    }
    size_t listed(uint32_t cell) const
    {
        size_t n = 0;
        rt_grid_cell_objects(grid, cell, &n);
        return n;
    }
};

// Sphere 0 in cell 0 (x in [-4, 0]), sphere 1 in cell 1 (x in [0, 4]).
struct OnePerCell : TwoCells {
    OnePerCell() : TwoCells(rt_vec(-3, 0, 0), 1.0, rt_vec(3, 0, 0), 1.0) {}
};

const Routing ring2({2, 1, 1}, "torus");
const Routing ring4({4, 1, 1}, "torus");

}  // namespace

TEST(Migration, PremiseOneSpherePerCellOfEqualRecords)
{
    OnePerCell s;
    ASSERT_NE(s.grid, nullptr);
    size_t n0 = 0, n1 = 0;
    const uint32_t *l0 = rt_grid_cell_objects(s.grid, 0, &n0);
    const uint32_t *l1 = rt_grid_cell_objects(s.grid, 1, &n1);
    ASSERT_EQ(n0, 1u);
    ASSERT_EQ(n1, 1u);
    EXPECT_EQ(l0[0], 0u);
    EXPECT_EQ(l1[0], 1u);
    EXPECT_GT(rt_scene_object_bytes(s.scene, 0), 0u);
    EXPECT_EQ(rt_scene_object_bytes(s.scene, 0), rt_scene_object_bytes(s.scene, 1));
}

TEST(Migration, UnchangedMappingMovesNothing)
{
    OnePerCell s;
    MigrationCost none = migration_cost(s.scene, s.grid, ring2, 2, s.timing, {0, 1}, {0, 1});
    EXPECT_EQ(none.bytes(), 0u);
    EXPECT_EQ(none.cells, 0u);
    EXPECT_EQ(none.time_s, 0.0);
}

TEST(Migration, OneCellOneHop)
{
    // Cell 1 moves from node 1 to node 0, one hop: 8 list bytes + sphere 1's record.
    OnePerCell s;
    const uint64_t record = rt_scene_object_bytes(s.scene, 1), want = 8 + record;
    MigrationCost one = migration_cost(s.scene, s.grid, ring2, 2, s.timing, {0, 1}, {0, 0});
    EXPECT_EQ(one.cells, 1u);
    EXPECT_EQ(one.objects, 1u);
    EXPECT_EQ(one.list_bytes, 8u) << "4 + 4 x 1 entry";
    EXPECT_EQ(one.object_bytes, record);
    EXPECT_EQ(one.bytes(), want);
    EXPECT_EQ(one.max_hops, 1);
    EXPECT_EQ(one.byte_hops, want);
    EXPECT_NEAR(one.time_s, std::ceil(static_cast<double>(want) / 28.0) * 50e-6, 1e-12)
        << "time = ceil(bytes / 28) x 50 us";
}

TEST(Migration, TwoCellsShareTheBusiestLink)
{
    // On a ring of 4 with every tie the + way (--route-ties plus): cell 0 goes 0 -> 2
    // (0 -> 1 -> 2), cell 1 goes 1 -> 3 (1 -> 2 -> 3). Both cross link 1 -> 2, which sends the
    // two back to back.
    OnePerCell s;
    const Routing ring4_plus({4, 1, 1}, "torus", torusrt::RouteTies::plus);
    const uint64_t each = 8 + rt_scene_object_bytes(s.scene, 0);
    MigrationCost two = migration_cost(s.scene, s.grid, ring4_plus, 4, s.timing, {0, 1}, {2, 3});
    EXPECT_EQ(two.cells, 2u);
    EXPECT_EQ(two.bytes(), 2 * each) << "two cells, each 8 + a record";
    EXPECT_EQ(two.max_hops, 2);
    EXPECT_EQ(two.byte_hops, 4 * each) << "two hops each";
    EXPECT_EQ(two.busiest_link_bytes, 2 * each) << "link 1 -> 2 carries both";
    EXPECT_NEAR(two.time_s, std::ceil(2.0 * each / 28.0) * 50e-6, 1e-12) << "time of the shared link";
}

TEST(Migration, SplitTiesSendTwoCellsOppositeWays)
{
    // The same moves with ties split by the cell's index (the default): cell 0 (even) goes the +
    // way, 0 -> 1 -> 2; cell 1 (odd) the - way, 1 -> 0 -> 3. No link carries both, so the
    // busiest carries one cell and the move takes one cell's time.
    OnePerCell s;
    const uint64_t each = 8 + rt_scene_object_bytes(s.scene, 0);
    MigrationCost two = migration_cost(s.scene, s.grid, ring4, 4, s.timing, {0, 1}, {2, 3});
    EXPECT_EQ(two.byte_hops, 4 * each) << "two hops each";
    EXPECT_EQ(two.busiest_link_bytes, each) << "no link carries both";
    EXPECT_NEAR(two.time_s, std::ceil(static_cast<double>(each) / 28.0) * 50e-6, 1e-12);
}

TEST(Migration, HeldObjectsAreNotSentAgain)
{
    // Both cells list both spheres: node 0 already holds every object cell 1 lists.
    TwoCells s(rt_vec(0, 0, 0), 2.0, rt_vec(0, 3, 0), 0.5);
    ASSERT_EQ(s.listed(0), 2u);
    ASSERT_EQ(s.listed(1), 2u);
    MigrationCost held = migration_cost(s.scene, s.grid, ring2, 2, s.timing, {0, 1}, {0, 0});
    EXPECT_EQ(held.bytes(), 4u + 4 * 2) << "only the cell list: 12 bytes";
    EXPECT_EQ(held.objects, 0u);
    EXPECT_NEAR(held.time_s, 50e-6, 1e-12) << "12 bytes: one piece, 50 us";
}

TEST(Migration, BandwidthTimesBytes)
{
    OnePerCell s;
    s.timing.link_bytes_per_us = 4;
    const uint64_t want = 8 + rt_scene_object_bytes(s.scene, 1);
    MigrationCost rate = migration_cost(s.scene, s.grid, ring2, 2, s.timing, {0, 1}, {0, 0});
    EXPECT_NEAR(rate.time_s, static_cast<double>(want) / 4 * 1e-6, 1e-12) << "bandwidth: bytes / 4 us";
}
