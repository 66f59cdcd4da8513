// object_work_carry_test.cpp - adaptive's `objects` guess on the two-sphere motion of
// motion_update_test.cpp: sphere 0 at (-3, 0, 0) and sphere 1 at (3, 0, 0), radius 1, in a
// 2x1x1 grid cut at x = 0. Frame 1 moves sphere 0 by 3.5 in x (it then spans both cells) and
// sphere 1 by 0.5 in z (it stays in cell 1). The pilot of frame 0 counts each object's work;
// carried into frame 1's lists, sphere 0's work in cell 0 goes with it: cell 0's centre
// (-2, 0, 0.25) moved by 3.5 in x lies in cell 1, which lists sphere 0 in frame 1. Sphere 1's
// work in cell 1 moves to cell 1 again. So frame 1's guess is cell 0 less sphere 0's work there
// and cell 1 plus it, the total unchanged, the faces' traffic untouched.
#include <cstring>
#include <vector>

#include "model_test.h"
#include "object_work_carry.h"
#include "rt_cost_map.h"
#include "rt_motion.h"
#include "scene_motion.h"

using namespace torusrt;

namespace {

const char *const kMotion = "frames 2\n"
                            "objects 0\n"
                            "key 0\n"
                            "key 1 move 3.5 0 0\n"
                            "objects 1\n"
                            "key 0\n"
                            "key 1 move 0 0 0.5\n";

struct Outcome {
    bool built = false;
    std::vector<double> before, after;  // per cell: frame 0's work and the guess of frame 1's
    std::vector<uint64_t> traffic, carried_traffic;
    double total_before = 0, total_after = 0;
    double sphere0_in_cell0 = 0, sphere1_in_cell1 = 0;  // the pilot's per-object work
    std::vector<uint8_t> moved;
};

double object_work(const rt_cost_pilot &p, uint32_t object, uint32_t cell)
{
    for (size_t i = 0; i < p.object_us_count; i++)
        if (p.object_us[i].object == object && p.object_us[i].cell == cell) return p.object_us[i].us;
    return 0;
}

Outcome simulate()
{
    Outcome out;
    char msg[RT_MSG_LEN] = "";
    rt_scene *scene = rt_scene_new();
    rt_scene_set_view(scene, rt_vec(0, 0, 20), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45.0, 16, 16);
    rt_scene_add_light(scene, rt_vec(0, 10, 10), nullptr);
    rt_scene_add_sphere(scene, rt_vec(-3, 0, 0), 1.0);
    rt_scene_add_sphere(scene, rt_vec(3, 0, 0), 1.0);
    if (rt_scene_finish(scene, msg, sizeof msg) != RT_OK) return out;
    rt_motion *raw = nullptr;
    if (rt_motion_parse("two.motion", kMotion, std::strlen(kMotion), &raw, msg, sizeof msg) != RT_OK) return out;
    SceneMotion motion(MotionPtr(raw), ScenePtr(scene), "two.motion", true);
    GridPtr grid;
    const int cells[3] = {2, 1, 1};
    motion.move_to(0, grid, cells, RT_COUNT_SEQUENTIAL, nullptr);
    rt_timing timing;
    rt_timing_defaults(&timing);
    rt_step_params params = rt_step_params_default();
    rt_cost_pilot pilot;
    if (rt_cost_pilot_run_by_object(motion.frame_scene(), grid.get(), &params, &timing, &pilot, msg, sizeof msg) !=
        RT_OK)
        return out;
    out.sphere0_in_cell0 = object_work(pilot, 0, 0);
    out.sphere1_in_cell1 = object_work(pilot, 1, 1);
    ObjectShifts shifts;
    motion.move_objects(1);
    motion.update_lists(1, grid.get(), nullptr);
    shifts.moved = motion.moved();
    shifts.shift = {rt_vec(3.5, 0, 0), rt_vec(0, 0, 0.5)};
    rt_cost_pilot guess = pilot;  // same sizes; its own arrays below
    std::vector<double> work(pilot.cells);
    std::vector<uint64_t> traffic(pilot.cells * RT_CELL_FACES);
    guess.work_us = work.data();
    guess.traffic = traffic.data();
    guess.object_us = nullptr;
    guess.object_us_count = 0;
    carry_object_work(pilot, grid.get(), shifts, guess);
    out.before.assign(pilot.work_us, pilot.work_us + pilot.cells);
    out.after = work;
    out.traffic.assign(pilot.traffic, pilot.traffic + pilot.cells * RT_CELL_FACES);
    out.carried_traffic = traffic;
    out.total_before = pilot.total_us;
    out.total_after = guess.total_us;
    out.moved = shifts.moved;
    rt_cost_pilot_release(&pilot);
    out.built = true;
    return out;
}

const Outcome &run()
{
    static const Outcome r = simulate();
    return r;
}

}  // namespace

TEST(ObjectWorkCarry, PremiseBothSpheresMovedAndWereSeen)
{
    const Outcome &o = run();
    ASSERT_TRUE(o.built);
    EXPECT_EQ(o.moved, (std::vector<uint8_t>{1, 1}));
    EXPECT_GT(o.sphere0_in_cell0, 0);
    EXPECT_GT(o.sphere1_in_cell1, 0);
    EXPECT_LE(o.sphere0_in_cell0, o.before[0]);
}

TEST(ObjectWorkCarry, SphereZerosWorkLeavesCellZeroForCellOne)
{
    const Outcome &o = run();
    ASSERT_TRUE(o.built);
    EXPECT_NEAR(o.after[0], o.before[0] - o.sphere0_in_cell0, 1e-9 * o.total_before);
    EXPECT_NEAR(o.after[1], o.before[1] + o.sphere0_in_cell0, 1e-9 * o.total_before);
}

TEST(ObjectWorkCarry, TotalAndTrafficUnchanged)
{
    const Outcome &o = run();
    ASSERT_TRUE(o.built);
    EXPECT_NEAR(o.total_after, o.total_before, 1e-9 * o.total_before);
    EXPECT_EQ(o.carried_traffic, o.traffic);
}
