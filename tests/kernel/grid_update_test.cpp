// grid_update_test.cpp - the grid over a given object space and the incremental update of the
// cell lists: units counted by hand on two spheres, and the update equal to a from-scratch build
// (the same lists and units) on the shipped moving scenes, frame after frame.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "rt_grid.h"
#include "rt_motion.h"
#include "rt_nff.h"
#include "rt_scene.h"
#include "test_support.h"

namespace {

using torusrt_test::GridPtr;
using torusrt_test::ScenePtr;

struct MotionDeleter {
    void operator()(rt_motion *m) const { rt_motion_free(m); }
};
using MotionPtr = std::unique_ptr<rt_motion, MotionDeleter>;

MotionPtr parse(const std::string &text)
{
    char msg[256] = "";
    rt_motion *m = nullptr;
    EXPECT_EQ(rt_motion_parse("t.motion", text.data(), text.size(), &m, msg, sizeof msg), RT_OK) << msg;
    return MotionPtr(m);
}

// Every cell's list of a grid, in cell order.
std::vector<std::vector<uint32_t>> lists_of(const rt_grid *g)
{
    std::vector<std::vector<uint32_t>> out(rt_grid_cell_count(g));
    for (size_t c = 0; c < out.size(); c++) {
        size_t n = 0;
        const uint32_t *objs = rt_grid_cell_objects(g, c, &n);
        out[c].assign(objs, objs + n);
    }
    return out;
}

// The two grids have the same space, lists and per-object units.
void expect_same_grid(const rt_grid *a, const rt_grid *b, size_t objects, const std::string &where)
{
    rt_box ba = rt_grid_bounds(a), bb = rt_grid_bounds(b);
    EXPECT_EQ(std::memcmp(&ba, &bb, sizeof ba), 0) << where;
    EXPECT_TRUE(lists_of(a) == lists_of(b)) << where << ": cell lists differ";
    EXPECT_EQ(rt_grid_list_entries(a), rt_grid_list_entries(b)) << where;
    EXPECT_EQ(rt_grid_units_serial(a), rt_grid_units_serial(b)) << where;
    for (size_t o = 0; o < objects; o++)
        EXPECT_EQ(rt_grid_units_of_object(a, o), rt_grid_units_of_object(b, o)) << where << " object " << o;
}

// Two spheres of radius 0.5 at x = -2 and x = +2 on the x axis.
ScenePtr two_spheres()
{
    ScenePtr s(rt_scene_new());
    rt_scene_set_view(s.get(), rt_vec(0, 0, 10), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45, 8, 8);
    rt_scene_add_sphere(s.get(), rt_vec(-2, 0, 0), 0.5);
    rt_scene_add_sphere(s.get(), rt_vec(2, 0, 0), 0.5);
    rt_scene_finish(s.get(), nullptr, 0);
    return s;
}

// Runs a motion frame by frame on an nx x ny x nz grid: the update (checked against a
// from-scratch build of every frame) and its stats per frame.
std::vector<rt_grid_update_stats> run_motion(const rt_scene *scene, const rt_motion *m, int nx, int ny, int nz,
                                             rt_preprocess_count rule, const std::string &name)
{
    char msg[256] = "";
    rt_box space;
    EXPECT_EQ(rt_motion_space(m, scene, &space, msg, sizeof msg), RT_OK) << msg;
    ScenePtr frame(rt_scene_clone(scene));
    size_t n = rt_scene_object_count(scene);
    std::vector<uint8_t> moved(n);
    std::vector<rt_grid_update_stats> out;
    GridPtr g;
    for (uint32_t k = 0; k < rt_motion_frame_count(m); k++) {
        EXPECT_EQ(rt_motion_apply(m, scene, frame.get(), k, moved.data(), msg, sizeof msg), RT_OK) << msg;
        rt_grid_update_stats st{};
        if (!g) {
            g.reset(rt_grid_new_in_space(frame.get(), nx, ny, nz, &space, rule, nullptr, msg, sizeof msg));
            EXPECT_NE(g, nullptr) << msg;
            if (!g) return out;
            st.units = st.rebuild_units = rt_grid_units_serial(g.get());
        } else {
            EXPECT_EQ(rt_grid_update(g.get(), frame.get(), moved.data(), nullptr, &st, msg, sizeof msg), RT_OK) << msg;
        }
        GridPtr fresh(rt_grid_new_in_space(frame.get(), nx, ny, nz, &space, rule, nullptr, msg, sizeof msg));
        EXPECT_NE(fresh, nullptr) << msg;
        if (!fresh) return out;
        expect_same_grid(g.get(), fresh.get(), n, name + " frame " + std::to_string(k));
        EXPECT_EQ(st.rebuild_units, rt_grid_units_serial(fresh.get()));
        EXPECT_LE(st.units, st.rebuild_units);
        out.push_back(st);
    }
    return out;
}

TEST(GridInSpace, NullSpaceIsTheScenesOwnGrid)
{
    ScenePtr s = two_spheres();
    char msg[256] = "";
    GridPtr own(rt_grid_new(s.get(), 4, 2, 3, msg, sizeof msg));
    GridPtr in(rt_grid_new_in_space(s.get(), 4, 2, 3, nullptr, RT_COUNT_SEQUENTIAL, nullptr, msg, sizeof msg));
    ASSERT_NE(own, nullptr);
    ASSERT_NE(in, nullptr);
    expect_same_grid(own.get(), in.get(), 2, "no space given");
}

TEST(GridInSpace, AGivenBoxIsPaddedAndAnObjectOutsideIsRefused)
{
    ScenePtr s = two_spheres();
    char msg[256] = "";
    rt_box space = {rt_vec(-10, -1, -1), rt_vec(10, 1, 1)};
    GridPtr g(rt_grid_new_in_space(s.get(), 2, 1, 1, &space, RT_COUNT_SEQUENTIAL, nullptr, msg, sizeof msg));
    ASSERT_NE(g, nullptr) << msg;
    rt_box b = rt_grid_bounds(g.get());
    EXPECT_LT(b.lo.x, -10.0);
    EXPECT_GT(b.lo.x, -10.0 - 1e-4);
    EXPECT_GT(b.hi.x, 10.0);
    rt_box small = {rt_vec(-2.5, -0.5, -0.5), rt_vec(2.4, 0.5, 0.5)};
    GridPtr none(rt_grid_new_in_space(s.get(), 2, 1, 1, &small, RT_COUNT_SEQUENTIAL, nullptr, msg, sizeof msg));
    EXPECT_EQ(none, nullptr);
    EXPECT_STREQ(msg, "object 1 lies outside the given object space");
}

// Two spheres on a 2 x 1 x 1 grid; sphere 1 moves from x = +2 to x = -2 over frames 0..2. The
// grid splits x once (factor 2: one plane, at x = 0 up to the padding's rounding), so an object
// costs, by the sequential rule, 1 unit ("lo <= plane?" no: it lies in slab 1) or 2 units
// ("lo <= plane?" yes, then "hi >= plane?"), and nothing on y and z (factor 1).
TEST(GridUpdate, TwoSphereUnitsByHand)
{
    ScenePtr s = two_spheres();
    MotionPtr m = parse("frames 3\nobjects 1\nkey 0\nkey 2 move -4 0 0\n");
    ASSERT_NE(m, nullptr);
    std::vector<rt_grid_update_stats> st = run_motion(s.get(), m.get(), 2, 1, 1, RT_COUNT_SEQUENTIAL, "two spheres");
    ASSERT_EQ(st.size(), 3u);
    /* Frame 0, the first build: sphere 0 (left) 2 units, sphere 1 (right) 1 unit. */
    EXPECT_EQ(st[0].units, 3u);
    /* Frame 1: sphere 1 at x = 0 spans the plane: "lo <= plane" yes, "hi >= plane" yes: 2. */
    EXPECT_EQ(st[1].objects_moved, 1u);
    EXPECT_EQ(st[1].units, 2u);
    EXPECT_EQ(st[1].rebuild_units, 4u);
    EXPECT_EQ(st[1].entries, 3u); /* cell 0: {0, 1}, cell 1: {1} */
    /* Frame 2: sphere 1 at x = -2, left of the plane: 2 units; cell 1 is empty. */
    EXPECT_EQ(st[2].objects_moved, 1u);
    EXPECT_EQ(st[2].units, 2u);
    EXPECT_EQ(st[2].rebuild_units, 4u);
    EXPECT_EQ(st[2].entries, 2u);
}

// The same motion by the per-plane rule: one unit a plane, so 1 unit an object on this grid.
TEST(GridUpdate, TwoSphereUnitsByThePerPlaneRule)
{
    ScenePtr s = two_spheres();
    MotionPtr m = parse("frames 3\nobjects 1\nkey 0\nkey 2 move -4 0 0\n");
    ASSERT_NE(m, nullptr);
    std::vector<rt_grid_update_stats> st = run_motion(s.get(), m.get(), 2, 1, 1, RT_COUNT_PER_PLANE, "per plane");
    ASSERT_EQ(st.size(), 3u);
    EXPECT_EQ(st[0].units, 2u);
    EXPECT_EQ(st[1].units, 1u);
    EXPECT_EQ(st[2].rebuild_units, 2u);
}

// A still frame moves nothing and costs nothing; the lists stay.
TEST(GridUpdate, AStillFrameCostsNothing)
{
    ScenePtr s = two_spheres();
    MotionPtr m = parse("frames 4\nobjects 1\nkey 1\nkey 2 move 0 1 0\n");
    ASSERT_NE(m, nullptr);
    std::vector<rt_grid_update_stats> st = run_motion(s.get(), m.get(), 4, 4, 4, RT_COUNT_SEQUENTIAL, "still");
    ASSERT_EQ(st.size(), 4u);
    EXPECT_EQ(st[1].objects_moved, 0u); /* frame 1 = frame 0 (held before the first key) */
    EXPECT_EQ(st[1].units, 0u);
    EXPECT_EQ(st[2].objects_moved, 1u);
    EXPECT_GT(st[2].units, 0u);
    EXPECT_EQ(st[3].objects_moved, 0u);
    EXPECT_EQ(st[3].units, 0u);
}

// A sphere moved exactly onto a cell boundary and back onto the object space's face. The space
// is symmetric about x = 0 (x from -2.5 to 2.5 before padding, padded the same on both sides), so
// the 2 x 1 x 1 grid's plane is x = 0 exactly; at frame 1 sphere 1's left side is on it.
TEST(GridUpdate, OntoACellBoundaryAndTheSpaceFace)
{
    ScenePtr s = two_spheres();
    MotionPtr m = parse("frames 3\nobjects 1\nkey 0\nkey 1 move -1.5 0 0\nkey 2 move 0 0 0\n");
    ASSERT_NE(m, nullptr);
    std::vector<rt_grid_update_stats> st = run_motion(s.get(), m.get(), 2, 1, 1, RT_COUNT_SEQUENTIAL, "boundary");
    ASSERT_EQ(st.size(), 3u);
    /* Touching the plane it is listed on both sides (the tolerance): 2 units, 3 entries. */
    EXPECT_EQ(st[1].units, 2u);
    EXPECT_EQ(st[1].entries, 3u);
    /* Back at x = 2, its right side on the space's face (x = 2.5 before padding): 1 unit. */
    EXPECT_EQ(st[2].units, 1u);
    EXPECT_EQ(st[2].entries, 2u);
    run_motion(s.get(), m.get(), 2, 2, 2, RT_COUNT_SEQUENTIAL, "boundary 2x2x2");
    run_motion(s.get(), m.get(), 24, 24, 24, RT_COUNT_SEQUENTIAL, "boundary 24");
}

// A turn and a scale of every kind of object: the update still equals a fresh build.
TEST(GridUpdate, TurnsAndScalesEqualAFreshBuild)
{
    ScenePtr five(rt_scene_new());
    rt_scene_set_view(five.get(), rt_vec(0, 0, 10), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45, 8, 8);
    rt_scene_add_sphere(five.get(), rt_vec(-2, 0, 0), 1);
    const rt_vec3 tri[3] = {rt_vec(0, 0, 0), rt_vec(1, 0, 0), rt_vec(0, 1, 0)};
    const rt_vec3 nrm[3] = {rt_vec(0, 0, 1), rt_vec(0, 0, 1), rt_vec(0, 0, 1)};
    rt_scene_add_patch(five.get(), tri, nrm, 3);
    const rt_vec3 quad[4] = {rt_vec(0, 0, -1), rt_vec(1, 0, -1), rt_vec(1, 1, -1), rt_vec(0, 1, -1)};
    rt_scene_add_polygon(five.get(), quad, 4);
    rt_scene_add_cone(five.get(), rt_vec(2, 0, 0), 1, rt_vec(2, 2, 0), 0.5);
    rt_scene_finish(five.get(), nullptr, 0);
    MotionPtr spin = parse("frames 9\nobjects 0 3\npivot 0.5 0.5 0\naxis 1 1 0.3\nkey 0\n"
                           "key 8 turn 300 scale 1.7 move 0 3 0\n");
    ASSERT_NE(spin, nullptr);
    for (rt_preprocess_count rule : {RT_COUNT_SEQUENTIAL, RT_COUNT_PER_PLANE, RT_COUNT_BOUNDING_SPHERE})
        run_motion(five.get(), spin.get(), 12, 6, 5, rule, "spin rule " + std::to_string(rule));
}

TEST(GridUpdate, RefusesAnObjectOutsideTheSpaceAndLeavesTheGrid)
{
    ScenePtr s = two_spheres();
    char msg[256] = "";
    GridPtr g(rt_grid_new(s.get(), 2, 1, 1, msg, sizeof msg));
    ASSERT_NE(g, nullptr);
    auto before = lists_of(g.get());
    ScenePtr f(rt_scene_clone(s.get()));
    MotionPtr m = parse("objects 1\nkey 0 move 5 0 0\n");
    ASSERT_NE(m, nullptr);
    std::vector<uint8_t> moved(2);
    ASSERT_EQ(rt_motion_apply(m.get(), s.get(), f.get(), 0, moved.data(), msg, sizeof msg), RT_OK);
    EXPECT_EQ(rt_grid_update(g.get(), f.get(), moved.data(), nullptr, nullptr, msg, sizeof msg), RT_ERR_INVALID);
    EXPECT_STREQ(msg, "object 1 moved out of the object space");
    EXPECT_TRUE(lists_of(g.get()) == before);
    ScenePtr other(rt_scene_new());
    EXPECT_EQ(rt_grid_update(g.get(), other.get(), moved.data(), nullptr, nullptr, msg, sizeof msg), RT_ERR_INVALID);
    EXPECT_STREQ(msg, "the scene holds 0 objects, the grid was built for 2");
}

// A scene without objects has no moved flags to give (an empty vector's data may be null): the
// update is a no-op, not an error.
TEST(GridUpdate, AnEmptySceneNeedsNoFlags)
{
    ScenePtr s(rt_scene_new());
    rt_scene_set_view(s.get(), rt_vec(0, 0, 10), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45, 8, 8);
    rt_scene_finish(s.get(), nullptr, 0);
    char msg[256] = "";
    GridPtr g(rt_grid_new(s.get(), 2, 2, 2, msg, sizeof msg));
    ASSERT_NE(g, nullptr) << msg;
    rt_grid_update_stats st;
    std::memset(&st, 0xff, sizeof st);
    EXPECT_EQ(rt_grid_update(g.get(), s.get(), nullptr, nullptr, &st, msg, sizeof msg), RT_OK) << msg;
    EXPECT_EQ(st.units, 0u);
    EXPECT_EQ(st.objects_moved, 0u);
}

TEST(GridUpdate, GrowthIsChargedToTheBudget)
{
    ScenePtr s = two_spheres();
    MotionPtr m = parse("frames 2\nobjects 1\nkey 0\nkey 1 scale 8\n");
    ASSERT_NE(m, nullptr);
    char msg[256] = "";
    rt_box space;
    ASSERT_EQ(rt_motion_space(m.get(), s.get(), &space, msg, sizeof msg), RT_OK);
    rt_budget budget = rt_budget_make(0);
    GridPtr g(rt_grid_new_in_space(s.get(), 8, 8, 8, &space, RT_COUNT_SEQUENTIAL, &budget, msg, sizeof msg));
    ASSERT_NE(g, nullptr);
    budget.limit = budget.used + 8; /* room for one more entry only: the grown sphere needs many */
    ScenePtr f(rt_scene_clone(s.get()));
    std::vector<uint8_t> moved(2);
    ASSERT_EQ(rt_motion_apply(m.get(), s.get(), f.get(), 1, moved.data(), msg, sizeof msg), RT_OK);
    auto before = lists_of(g.get());
    EXPECT_EQ(rt_grid_update(g.get(), f.get(), moved.data(), &budget, nullptr, msg, sizeof msg), RT_ERR_LIMIT);
    EXPECT_EQ(std::string(msg).rfind("memory budget exceeded", 0), 0u) << msg;
    EXPECT_TRUE(lists_of(g.get()) == before);
}

// The shipped moving scenes: the update equals a fresh build on frames spread over the run.
void check_shipped(const std::string &name)
{
    std::string base = std::string(TORUSRT_SOURCE_DIR) + "/scenes/" + name;
    char msg[512] = "";
    rt_scene *raw = nullptr;
    ASSERT_EQ(rt_nff_load((base + ".nff").c_str(), &raw, msg, sizeof msg, nullptr, nullptr), RT_OK) << msg;
    ScenePtr s(raw);
    rt_motion *mraw = nullptr;
    ASSERT_EQ(rt_motion_load((base + ".motion").c_str(), &mraw, msg, sizeof msg), RT_OK) << msg;
    MotionPtr m(mraw);
    EXPECT_EQ(rt_motion_frame_count(m.get()), 64u);
    std::vector<rt_grid_update_stats> st = run_motion(s.get(), m.get(), 24, 24, 24, RT_COUNT_SEQUENTIAL, name);
    ASSERT_EQ(st.size(), 64u);
    uint64_t moved = 0;
    for (size_t k = 1; k < st.size(); k++) {
        moved += st[k].objects_moved;
        EXPECT_LT(st[k].units, st[k].rebuild_units) << name << " frame " << k << ": the update should cost less";
    }
    EXPECT_GT(moved, 0u);
}

TEST(GridUpdate, BouncingBallsEqualsAFreshBuildEveryFrame) { check_shipped("bouncing-balls"); }
TEST(GridUpdate, OrbitingMirrorEqualsAFreshBuildEveryFrame) { check_shipped("orbiting-mirror"); }

}  // namespace
