// load_motion_test.cpp - the motion compensation of adaptive's prediction (load_motion.h) on a
// hand-made 4x4x4 load over the box [0,4]^3 (cell (x,y,z) centred at (x+.5, y+.5, z+.5)), the
// camera orbiting about up = +y through at = (2,2,2). No simulation: the functions are arithmetic.
#include <cmath>
#include <systemc>
#include <vector>

#include "load_motion.h"
#include "model_test.h"

using namespace torusrt;

namespace {

constexpr int side = 4;
constexpr size_t cells = side * side * side;

size_t cell(int x, int y, int z) { return static_cast<size_t>(x + side * (y + side * z)); }

// A load of the grid's size whose arrays the struct owns.
struct Load {
    std::vector<double> work = std::vector<double>(cells, 0.0);
    std::vector<uint64_t> traffic = std::vector<uint64_t>(cells * RT_CELL_FACES, 0);
    rt_cost_pilot pilot{};
    Load()
    {
        pilot.dims[0] = pilot.dims[1] = pilot.dims[2] = side;
        pilot.cells = cells;
        pilot.work_us = work.data();
        pilot.traffic = traffic.data();
    }
    double total() const
    {
        double t = 0;
        for (double w : work) t += w;
        return t;
    }
};

const rt_box box = {{0, 0, 0}, {4, 4, 4}};

rt_camera_pose start_pose()
{
    rt_camera_pose p;
    p.from = rt_vec(2, 2, 12);
    p.at = rt_vec(2, 2, 2);
    p.up = rt_vec(0, 1, 0);
    p.angle = 45;
    return p;
}

}  // namespace

// A right-handed quarter turn about +y through (2,2,2) takes (dx, dz) to (dz, -dx): the centre
// of cell (3,1,2), offset (1.5, -0.5, 0.5), goes to offset (0.5, -0.5, -1.5), the centre of
// cell (2,1,0); all of its work lands there, and its +x face's traffic leaves through -z.
TEST(LoadMotion, QuarterTurnMovesAHotCellToTheHandComputedCell)
{
    rt_camera_pose a = start_pose(), b = rt_camera_orbit_pose(&a, 360, 4, 1);
    Load in, out;
    in.work[cell(3, 1, 2)] = 7;
    in.traffic[cell(3, 1, 2) * RT_CELL_FACES + 1] = 5;  // +x
    in.pilot.total_us = 7;
    move_load(in.pilot, box, camera_motion(a, b), out.pilot);
    EXPECT_NEAR(out.work[cell(2, 1, 0)], 7, 1e-9);
    EXPECT_NEAR(out.total(), 7, 1e-9);
    EXPECT_EQ(out.traffic[cell(2, 1, 0) * RT_CELL_FACES + 4], 5u);  // -z
    EXPECT_DOUBLE_EQ(out.pilot.total_us, 7);
}

// No motion: every cell keeps its work and traffic.
TEST(LoadMotion, ZeroMotionIsTheIdentity)
{
    rt_camera_pose a = start_pose();
    Load in, out;
    for (size_t c = 0; c < cells; c++) {
        in.work[c] = static_cast<double>(c % 7) + 0.25;
        for (int f = 0; f < RT_CELL_FACES; f++) in.traffic[c * RT_CELL_FACES + f] = (c + 3 * f) % 5;
    }
    move_load(in.pilot, box, camera_motion(a, a), out.pilot);
    for (size_t c = 0; c < cells; c++) EXPECT_DOUBLE_EQ(out.work[c], in.work[c]) << "cell " << c;
    EXPECT_EQ(out.traffic, in.traffic);
}

// An orbit step of 11.25 degrees splits a cell's work over the cells around its moved centre
// (trilinear splat, clamped into the grid): the total is kept, and the work of a cell off the
// axis no longer sits in that cell alone.
TEST(LoadMotion, SmallStepConservesTheTotal)
{
    rt_camera_pose a = start_pose(), b = rt_camera_orbit_pose(&a, 360, 32, 1);
    Load in, out;
    for (size_t c = 0; c < cells; c++) in.work[c] = static_cast<double>((c * 37) % 11);
    in.work[cell(3, 0, 3)] = 100;  // a corner: its moved centre leaves the grid and is clamped
    move_load(in.pilot, box, camera_motion(a, b), out.pilot);
    EXPECT_NEAR(out.total(), in.total(), 1e-9 * in.total());
    Load hot, spread;
    hot.work[cell(3, 1, 2)] = 1;
    move_load(hot.pilot, box, camera_motion(a, b), spread.pilot);
    EXPECT_LT(spread.work[cell(3, 1, 2)], 1);
    EXPECT_NEAR(spread.total(), 1, 1e-12);
}

// The blur keeps `keep` of a cell's work and shares the rest among its face neighbours: an inner
// cell of 8 at keep 1/4 leaves 2 and gives 1 to each of its 6 neighbours; a corner cell (3
// neighbours) of 3 leaves 0.75 and gives 0.75 to each. Totals are kept.
TEST(LoadMotion, BlurSharesWithTheFaceNeighbours)
{
    Load in, out;
    in.work[cell(1, 1, 1)] = 8;
    in.work[cell(3, 3, 3)] = 3;
    blur_load(in.pilot, 0.25, out.pilot);
    EXPECT_DOUBLE_EQ(out.work[cell(1, 1, 1)], 2);
    EXPECT_DOUBLE_EQ(out.work[cell(0, 1, 1)], 1);
    EXPECT_DOUBLE_EQ(out.work[cell(1, 1, 2)], 1);
    EXPECT_DOUBLE_EQ(out.work[cell(3, 3, 3)], 0.75);
    EXPECT_DOUBLE_EQ(out.work[cell(2, 3, 3)], 0.75);
    EXPECT_NEAR(out.total(), 11, 1e-12);
}

// Moving the rays: with no motion and every cell visited, each cell's work per visit times its
// own visits is its work again; under a quarter turn the visits move and each landing cell's own
// work per visit prices them.
TEST(LoadMotion, MovedVisitsKeepEachCellsCostPerRay)
{
    rt_camera_pose a = start_pose(), b = rt_camera_orbit_pose(&a, 360, 4, 1);
    Load in, out;
    std::vector<char> occupied(cells, 1);
    for (size_t c = 0; c < cells; c++) {
        in.work[c] = 1;
        for (int f = 0; f < RT_CELL_FACES; f++) in.traffic[c * RT_CELL_FACES + f] = 1;
    }
    in.work[cell(2, 1, 0)] = 4;                          // 4 us per visit here ...
    in.traffic[cell(3, 1, 2) * RT_CELL_FACES + 1] = 31;  // ... and many rays through (3,1,2)
    in.pilot.total_us = in.total();
    move_visits(in.pilot, box, camera_motion(a, a), occupied, out.pilot);
    for (size_t c = 0; c < cells; c++) EXPECT_NEAR(out.work[c], in.work[c], 1e-9) << "cell " << c;
    move_visits(in.pilot, box, camera_motion(a, b), occupied, out.pilot);
    EXPECT_NEAR(out.total(), in.total(), 1e-9);
    size_t hottest = 0;
    for (size_t c = 0; c < cells; c++)
        if (out.work[c] > out.work[hottest]) hottest = c;
    EXPECT_EQ(hottest, cell(2, 1, 0));  // (3,1,2)'s rays land on the costly cell
}
