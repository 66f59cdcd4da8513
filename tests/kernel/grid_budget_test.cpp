// grid_budget_test.cpp - cell lists within the memory budget: they are counted before any is
// made, so lists that cannot fit are refused with the budget untouched by them, and lists that
// fit are the same as without a budget (coincident copies, whose counts are reused, included).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "rt_budget.h"
#include "rt_grid.h"
#include "test_support.h"

using namespace torusrt_test;

namespace {

// `copies` unit spheres at the origin, then a smaller one off centre, a triangle twice and a
// cone twice.
ScenePtr coincident(int copies)
{
    ScenePtr s(rt_scene_new());
    for (int i = 0; i < copies; i++) EXPECT_EQ(rt_scene_add_sphere(s.get(), rt_vec(0, 0, 0), 1.0), RT_OK);
    EXPECT_EQ(rt_scene_add_sphere(s.get(), rt_vec(0.3, 0.2, 0.1), 0.4), RT_OK);
    const rt_vec3 v[3] = {rt_vec(-1, -1, 0.2), rt_vec(1, -0.5, 0.3), rt_vec(0, 1, -0.4)};
    const rt_vec3 n[3] = {rt_vec(0, 0, 1), rt_vec(0, 0, 1), rt_vec(0, 0, 1)};
    for (int i = 0; i < 2; i++) {
        EXPECT_EQ(rt_scene_add_patch(s.get(), v, n, 3), RT_OK);
        EXPECT_EQ(rt_scene_add_cone(s.get(), rt_vec(0, -1, 0), 0.5, rt_vec(0, 1, 0), 0.1), RT_OK);
    }
    return s;
}

std::vector<uint32_t> lists(const rt_grid *g)
{
    std::vector<uint32_t> out;
    for (size_t c = 0; c < rt_grid_cell_count(g); c++) {
        size_t n;
        const uint32_t *l = rt_grid_cell_objects(g, c, &n);
        out.push_back(uint32_t(n));
        out.insert(out.end(), l, l + n);
    }
    return out;
}

}  // namespace

TEST(GridBudget, ListsThatFitAreTheSameAsWithoutABudget)
{
    ScenePtr s = coincident(50);
    GridPtr free_grid = make_grid(s.get(), 12, 12, 12);
    ASSERT_TRUE(free_grid);
    rt_budget b = rt_budget_make(64ull << 20);
    char msg[RT_MSG_LEN] = "";
    GridPtr g(rt_grid_new_budget(s.get(), 12, 12, 12, &b, msg, sizeof msg));
    ASSERT_TRUE(g) << msg;
    EXPECT_EQ(lists(g.get()), lists(free_grid.get()));
    EXPECT_EQ(rt_grid_units_serial(g.get()), rt_grid_units_serial(free_grid.get()));
}

TEST(GridBudget, ListsThatCannotFitAreRefusedBeforeTheyAreMade)
{
    ScenePtr s = coincident(20000);
    // 20000 spheres in most of 24^3 cells: about 150 million entries, 1.2 GB; 64 MiB allowed.
    rt_budget b = rt_budget_make(64ull << 20);
    char msg[RT_MSG_LEN] = "";
    GridPtr g(rt_grid_new_budget(s.get(), 24, 24, 24, &b, msg, sizeof msg));
    ASSERT_FALSE(g);
    std::string m = msg;
    EXPECT_EQ(m.rfind("memory budget exceeded: the cell lists", 0), 0u) << m;
    EXPECT_NE(m.find("counted before any is made"), std::string::npos) << m;
    // Only the grid's fixed tables were reserved; the lists took nothing.
    uint64_t cells = 24 * 24 * 24, objects = rt_scene_object_count(s.get());
    EXPECT_EQ(b.used, (cells + 1) * 4 + cells * 4 + (objects + 1) * 8 + objects * 8);
}
