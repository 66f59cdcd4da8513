// pilot_by_object_test.cpp - the pilot's per-object work (rt_cost_pilot_run_by_object): the same
// per-cell work as the plain pilot, and each object's share lying in a cell that lists it, no
// cell's shares exceeding its work, sorted by object then cell.
#include <gtest/gtest.h>

#include <vector>

#include "rt_cost_map.h"
#include "test_support.h"

namespace {

struct ThreeSpheres {
    rt_scene *scene = nullptr;
    rt_grid *grid = nullptr;
    ThreeSpheres()
    {
        char msg[RT_MSG_LEN] = "";
        scene = rt_scene_new();
        rt_scene_set_view(scene, rt_vec(0, 0, 20), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45.0, 16, 16);
        rt_scene_add_light(scene, rt_vec(0, 10, 10), nullptr);
        rt_scene_add_sphere(scene, rt_vec(-3, 0, 0), 1.0);
        rt_scene_add_sphere(scene, rt_vec(0, 0, 0), 1.0);  // across the cut x = 0
        rt_scene_add_sphere(scene, rt_vec(3, 0, 0), 1.0);
        if (rt_scene_finish(scene, msg, sizeof msg) == RT_OK) grid = rt_grid_new(scene, 2, 1, 1, msg, sizeof msg);
    }
    ~ThreeSpheres()
    {
        rt_grid_free(grid);
        rt_scene_free(scene);
    }
};

bool listed(const rt_grid *grid, uint32_t cell, uint32_t object)
{
    size_t n = 0;
    const uint32_t *list = rt_grid_cell_objects(grid, cell, &n);
    for (size_t i = 0; i < n; i++)
        if (list[i] == object) return true;
    return false;
}

}  // namespace

TEST(PilotByObject, SameCellWorkAsThePlainPilot)
{
    ThreeSpheres s;
    ASSERT_TRUE(s.grid);
    rt_timing t;
    rt_timing_defaults(&t);
    rt_step_params prm = rt_step_params_default();
    rt_cost_pilot plain, counted;
    char msg[RT_MSG_LEN] = "";
    ASSERT_EQ(rt_cost_pilot_run(s.scene, s.grid, &prm, &t, &plain, msg, sizeof msg), RT_OK) << msg;
    ASSERT_EQ(rt_cost_pilot_run_by_object(s.scene, s.grid, &prm, &t, &counted, msg, sizeof msg), RT_OK) << msg;
    EXPECT_EQ(plain.object_us, nullptr);
    for (size_t c = 0; c < plain.cells; c++) EXPECT_DOUBLE_EQ(plain.work_us[c], counted.work_us[c]);
    EXPECT_DOUBLE_EQ(plain.total_us, counted.total_us);
    rt_cost_pilot_release(&plain);
    rt_cost_pilot_release(&counted);
}

TEST(PilotByObject, SharesLieInListedCellsAndFitTheirCells)
{
    ThreeSpheres s;
    ASSERT_TRUE(s.grid);
    rt_timing t;
    rt_timing_defaults(&t);
    rt_step_params prm = rt_step_params_default();
    rt_cost_pilot p;
    char msg[RT_MSG_LEN] = "";
    ASSERT_EQ(rt_cost_pilot_run_by_object(s.scene, s.grid, &prm, &t, &p, msg, sizeof msg), RT_OK) << msg;
    // Sphere 0 lies in cell 0, sphere 1 in both, sphere 2 in cell 1: four pairs, each met by some ray.
    ASSERT_EQ(p.object_us_count, 4u);
    std::vector<double> sum(p.cells, 0.0);
    for (size_t i = 0; i < p.object_us_count; i++) {
        const rt_object_cell_us &e = p.object_us[i];
        EXPECT_TRUE(listed(s.grid, e.cell, e.object)) << "object " << e.object << " cell " << e.cell;
        EXPECT_GT(e.us, 0);
        if (i > 0) {
            const rt_object_cell_us &b = p.object_us[i - 1];
            EXPECT_TRUE(b.object < e.object || (b.object == e.object && b.cell < e.cell));
        }
        sum[e.cell] += e.us;
    }
    for (size_t c = 0; c < p.cells; c++) EXPECT_LE(sum[c], p.work_us[c] * (1 + 1e-12));
    rt_cost_pilot_release(&p);
}
