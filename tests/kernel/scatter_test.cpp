// scatter_test.cpp - the balanced scatter behind --map scatter (rt_cost_map_scatter): the deal
// worked out by hand, empty cells spread by count, the hottest cells cut into pieces on different
// nodes, a budget too small for a copy, and bad arguments.
#include <cstdlib>
#include <vector>

#include "rt_cost_map.h"
#include "test_support.h"

using namespace torusrt_test;

namespace {

// Two spheres in a row, cut into 4 x 1 x 1 cells (the cells' lists only count for the budget).
struct Row {
    ScenePtr scene;
    GridPtr grid;
};

Row row()
{
    Row t{ScenePtr(rt_scene_new()), nullptr};
    rt_scene_add_sphere(t.scene.get(), rt_vec(0, 0, 0), 1.0);
    rt_scene_add_sphere(t.scene.get(), rt_vec(6, 0, 0), 1.0);
    char msg[RT_MSG_LEN] = "";
    t.grid.reset(rt_grid_new(t.scene.get(), 4, 1, 1, msg, sizeof msg));
    return t;
}

struct Dealt {
    rt_status status;
    std::vector<int32_t> owner;
    std::vector<uint32_t> first;
    std::vector<int32_t> extra;
    rt_cost_map_facts facts;
};

Dealt scatter(const Row &t, std::vector<double> work, int nodes, double fraction)
{
    double total = 0;
    for (double w : work) total += w;
    std::vector<uint64_t> traffic(work.size() * RT_CELL_FACES, 0);
    rt_cost_pilot pilot{{4, 1, 1}, work.size(), work.data(), traffic.data(), total, {}, nullptr, 0};
    const int dims[3] = {nodes, 1, 1};
    rt_topology topo{};  // no machine of 0 nodes: the scatter is handed none
    if (nodes > 0) topo = torusrt_test::make_topology("torus", dims);
    Dealt d{RT_OK, std::vector<int32_t>(work.size(), -1), std::vector<uint32_t>(work.size() + 1), {}, {}};
    int32_t *extra = nullptr;
    size_t count = 0;
    char msg[RT_MSG_LEN] = "";
    d.status = rt_cost_map_scatter(&pilot, t.scene.get(), t.grid.get(), nodes > 0 ? &topo : nullptr, fraction, nullptr,
                                   d.owner.data(), d.first.data(), &extra, &count, &d.facts, msg, sizeof msg);
    if (extra) d.extra.assign(extra, extra + count);
    std::free(extra);
    return d;
}

}  // namespace

// Work {5, 1, 3, 3} on 2 nodes, hottest first: cell 0 (5) to node 0; cell 2 (3) to node 1, the
// lighter; cell 3 (3) to node 1 again (3 < 5); cell 1 (1) to node 0 (5 < 6). Both end at 6.
TEST(Scatter, DealByHand)
{
    Row t = row();
    ASSERT_TRUE(t.grid);
    Dealt d = scatter(t, {5, 1, 3, 3}, 2, 0);
    ASSERT_EQ(d.status, RT_OK);
    EXPECT_EQ(d.owner, (std::vector<int32_t>{0, 0, 1, 1}));
    EXPECT_TRUE(d.extra.empty());
    EXPECT_EQ(d.first, (std::vector<uint32_t>{0, 0, 0, 0, 0}));
    EXPECT_DOUBLE_EQ(d.facts.max_node_work_us, 6.0);
    EXPECT_DOUBLE_EQ(d.facts.mean_node_work_us, 6.0);
}

// Cells without work go to the node holding the fewest cells (ties: the lowest), not all to one.
TEST(Scatter, EmptyCellsSpreadByCount)
{
    Row t = row();
    ASSERT_TRUE(t.grid);
    Dealt d = scatter(t, {0, 0, 0, 0}, 2, 0);
    ASSERT_EQ(d.status, RT_OK);
    EXPECT_EQ(d.owner, (std::vector<int32_t>{0, 1, 0, 1}));
}

// Work {8, 1, 1, 1} on 2 nodes (mean 5.5): cell 0 is above half the mean, so it is cut into
// ceil(8 / 2.75) = 3 pieces, at most one per node: 2 of 4. Piece 0 to node 0, piece 1 to node 1;
// then cells 1, 2, 3 alternate (equal loads and counts: the lowest node first). Node 0 ends at 6.
TEST(Scatter, HotCellCutOverDifferentNodes)
{
    Row t = row();
    ASSERT_TRUE(t.grid);
    Dealt d = scatter(t, {8, 1, 1, 1}, 2, 64);
    ASSERT_EQ(d.status, RT_OK);
    EXPECT_EQ(d.owner, (std::vector<int32_t>{0, 0, 1, 0}));
    EXPECT_EQ(d.first, (std::vector<uint32_t>{0, 1, 1, 1, 1}));
    EXPECT_EQ(d.extra, (std::vector<int32_t>{1}));
    EXPECT_DOUBLE_EQ(d.facts.max_node_work_us, 6.0);
    // No budget for copies (fraction 0): the same work is dealt whole.
    Dealt whole = scatter(t, {8, 1, 1, 1}, 2, 0);
    ASSERT_EQ(whole.status, RT_OK);
    EXPECT_EQ(whole.owner, (std::vector<int32_t>{0, 1, 1, 1}));
    EXPECT_TRUE(whole.extra.empty());
    EXPECT_DOUBLE_EQ(whole.facts.max_node_work_us, 8.0);
}

// A copy always costs bytes (the cell's list header at least): a budget of a billionth of a
// node's data has no room for one, so the copy is dropped and the cell dealt whole again.
TEST(Scatter, CopyOverBudgetIsDropped)
{
    Row t = row();
    ASSERT_TRUE(t.grid);
    Dealt d = scatter(t, {8, 1, 1, 1}, 2, 1e-9);
    ASSERT_EQ(d.status, RT_OK);
    EXPECT_EQ(d.owner, (std::vector<int32_t>{0, 1, 1, 1}));
    EXPECT_TRUE(d.extra.empty());
    EXPECT_DOUBLE_EQ(d.facts.max_node_work_us, 8.0);
}

// A node never holds two pieces of one cell, even when the cut asks for more pieces than nodes.
TEST(Scatter, NoNodeHoldsACellTwice)
{
    Row t = row();
    ASSERT_TRUE(t.grid);
    Dealt d = scatter(t, {100, 1, 1, 1}, 3, 64);
    ASSERT_EQ(d.status, RT_OK);
    ASSERT_EQ(d.first[1], 2u);  // cut into 3: one per node
    std::vector<int32_t> cell0 = {d.owner[0], d.extra[0], d.extra[1]};
    EXPECT_NE(cell0[0], cell0[1]);
    EXPECT_NE(cell0[0], cell0[2]);
    EXPECT_LT(cell0[1], cell0[2]);  // extra owners ascending
}

TEST(Scatter, BadArgumentsAreRefused)
{
    Row t = row();
    ASSERT_TRUE(t.grid);
    EXPECT_EQ(scatter(t, {1, 1, 1, 1}, 0, 0).status, RT_ERR_INVALID);
    EXPECT_EQ(scatter(t, {1, 1, 1, 1}, 2, -1).status, RT_ERR_INVALID);
    EXPECT_EQ(scatter(t, {1, 1, 1}, 2, 0).status, RT_ERR_INVALID);  // not the grid's cells
}
