// dda_test.cpp - the 3D-DDA cell walk (rt_dda_start / rt_dda_advance) against an
// oracle written here.
//
// The oracle knows only the grid's public planes (rt_grid_cell_box) and the ray. It
// clips the ray to the object space, lists every crossing of an interior plane, and
// samples the ray at the midpoint between consecutive crossings: each sample's cell
// (located among the planes, with a tolerance at a plane) must be the visited cell
// whose [t_enter, t_exit] holds the sample, in walk order. Conversely, every visited
// cell's box (grown by a relative 1e-9) must hold the ray's points at its t_enter,
// t_exit and in between. Every walk must also end within the documented number of
// advances, move between face neighbours only, and keep t_enter non-decreasing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "rt_dda.h"
#include "rt_grid.h"
#include "rt_scene.h"
#include "test_support.h"

using namespace torusrt_test;

namespace {

double ax(rt_vec3 v, int a) { return a == 0 ? v.x : a == 1 ? v.y : v.z; }
void set_ax(rt_vec3 &v, int a, double x) { (a == 0 ? v.x : a == 1 ? v.y : v.z) = x; }

std::string vstr(rt_vec3 v)
{
    std::ostringstream s;
    s.precision(17);
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}

// Two spheres of radius r at lo and hi: the object space is known exactly.
ScenePtr two_spheres(rt_vec3 lo, rt_vec3 hi, double r) { return scene_with_spheres({{lo, r}, {hi, r}}); }

// What the test knows of a grid: its dimensions and planes, read through the public API.
struct Planes {
    int n[3];
    std::vector<double> p[3];  // p[a][k], k = 0..n[a]
    rt_box bounds;
    double scale;    // size of the numbers involved: max(diagonal, largest |coordinate|)
    double pos_tol;  // relative 1e-9 of the scale

    explicit Planes(const rt_grid *g)
    {
        rt_grid_dims(g, n);
        bounds = rt_grid_bounds(g);
        for (int a = 0; a < 3; a++) {
            for (int k = 0; k < n[a]; k++) {
                int c[3] = {0, 0, 0};
                c[a] = k;
                p[a].push_back(ax(rt_grid_cell_box(g, c[0], c[1], c[2]).lo, a));
            }
            int c[3] = {0, 0, 0};
            c[a] = n[a] - 1;
            p[a].push_back(ax(rt_grid_cell_box(g, c[0], c[1], c[2]).hi, a));
        }
        double diag = rt_vec_length(rt_vec_sub(bounds.hi, bounds.lo));
        scale = std::max({diag, rt_vec_max_abs(bounds.lo), rt_vec_max_abs(bounds.hi)});
        pos_tol = 1e-9 * scale;
    }
};

struct Visit {
    int32_t cell[3];
    double t_enter, t_exit;
};

struct Walk {
    bool started = false;
    bool ended = false;            // rt_dda_advance returned 0 within the limit
    bool unchanged_at_end = true;  // the failed advance left the state alone
    int advances = 0;
    std::vector<Visit> visits;
};

Walk walk(const rt_grid *g, rt_vec3 o, rt_vec3 d, double t_min)
{
    Walk w;
    rt_dda s;
    std::memset(&s, 0, sizeof s);
    if (!rt_dda_start(g, o, d, t_min, &s)) return w;
    w.started = true;
    int dims[3];
    rt_grid_dims(g, dims);
    int hard_limit = dims[0] + dims[1] + dims[2] + 8;
    for (;;) {
        w.visits.push_back({{s.cell[0], s.cell[1], s.cell[2]}, s.t_enter, rt_dda_t_exit(&s)});
        rt_dda before = s;
        if (!rt_dda_advance(g, &s, o, d)) {
            w.ended = true;
            w.unchanged_at_end = std::memcmp(&before, &s, sizeof s) == 0;
            return w;
        }
        if (++w.advances > hard_limit) return w;
    }
}

// The part [t0, t1] of the ray at t >= t_min inside box b (slab method); false if none.
bool clip_to_box(rt_vec3 o, rt_vec3 d, double t_min, const rt_box &b, double &t0, double &t1)
{
    t0 = t_min;
    t1 = INFINITY;
    for (int a = 0; a < 3; a++) {
        double oa = ax(o, a), da = ax(d, a), lo = ax(b.lo, a), hi = ax(b.hi, a);
        if (da == 0.0) {
            if (oa < lo || oa > hi) return false;
            continue;
        }
        double ta = (lo - oa) / da, tb = (hi - oa) / da;
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    return t0 <= t1;
}

rt_box grow(rt_box b, double e)
{
    b.lo = rt_vec_sub(b.lo, rt_vec(e, e, e));
    b.hi = rt_vec_add(b.hi, rt_vec(e, e, e));
    return b;
}

// The ray's point at t; an axis with no motion keeps the origin's coordinate exactly.
double coord(rt_vec3 o, rt_vec3 d, double t, int a) { return ax(d, a) == 0.0 ? ax(o, a) : ax(o, a) + t * ax(d, a); }

// Position tolerance on axis a at parameter t: relative 1e-9 of the scene plus the
// rounding of the point itself.
double pos_tol(const Planes &pl, rt_vec3 o, rt_vec3 d, double t, int a)
{
    double r = std::fabs(ax(o, a)) + std::fabs(t * ax(d, a));
    return pl.pos_tol + 8 * DBL_EPSILON * (std::isfinite(r) ? r : 0.0);
}

// t tolerance equivalent to the position tolerance.
double t_tol(const Planes &pl, rt_vec3 o, rt_vec3 d, double t)
{
    double dmax = rt_vec_max_abs(d);
    return (pl.pos_tol + 8 * DBL_EPSILON * (rt_vec_max_abs(o) + std::fabs(t) * dmax)) / dmax +
           8 * DBL_EPSILON * std::fabs(t);
}

// Checks every property of the walk of (o, d) from t_min. Returns a failure naming the ray.
::testing::AssertionResult check_walk(const rt_grid *g, rt_vec3 o, rt_vec3 d, double t_min = 0.0)
{
    Planes pl(g);
    std::ostringstream ray;
    ray.precision(17);
    ray << "ray o=" << vstr(o) << " d=" << vstr(d) << " t_min=" << t_min << " grid " << pl.n[0] << "x" << pl.n[1] << "x"
        << pl.n[2] << ": ";
    auto fail = [&]() { return ::testing::AssertionFailure() << ray.str(); };

    Walk w = walk(g, o, d, t_min);

    // Does the ray meet the object space? Decide only where the answer is clear.
    double t0, t1, g0, g1, s0, s1;
    bool meets = clip_to_box(o, d, t_min, pl.bounds, t0, t1);
    bool meets_grown = clip_to_box(o, d, t_min, grow(pl.bounds, pl.pos_tol), g0, g1);
    bool meets_shrunk = clip_to_box(o, d, t_min, grow(pl.bounds, -pl.pos_tol), s0, s1) && s1 - s0 > 0;
    if (!meets_grown && w.started) return fail() << "started although the ray misses the object space";
    if (meets_shrunk && !w.started) return fail() << "did not start although the ray crosses the object space";
    if (!w.started) return ::testing::AssertionSuccess();
    if (!meets) {  // grazing within tolerance: only the basic properties below apply
        t0 = g0;
        t1 = g1;
    }

    // (a) termination within the bound: each advance is monotone along its axis.
    int bound = (pl.n[0] - 1) + (pl.n[1] - 1) + (pl.n[2] - 1);
    if (!w.ended) return fail() << "did not end after " << w.advances << " advances";
    if (w.advances > bound) return fail() << w.advances << " advances, more than " << bound;
    if (w.advances > pl.n[0] + pl.n[1] + pl.n[2]) return fail() << w.advances << " advances, more than nx+ny+nz";
    if (!w.unchanged_at_end) return fail() << "the final failed advance changed the state";

    for (size_t i = 0; i < w.visits.size(); i++) {
        const Visit &v = w.visits[i];
        for (int a = 0; a < 3; a++)
            if (v.cell[a] < 0 || v.cell[a] >= pl.n[a])
                return fail() << "visit " << i << " cell index " << v.cell[a] << " out of range on axis " << a;
        // (c) t_enter never NaN, non-decreasing; t_exit not NaN and not before t_enter.
        if (std::isnan(v.t_enter) || std::isnan(v.t_exit)) return fail() << "NaN t at visit " << i;
        if (v.t_exit < v.t_enter - t_tol(pl, o, d, v.t_enter))
            return fail() << "visit " << i << " t_exit " << v.t_exit << " < t_enter " << v.t_enter;
        if (i > 0) {
            const Visit &u = w.visits[i - 1];
            if (v.t_enter < u.t_enter)
                return fail() << "t_enter decreases at visit " << i << ": " << u.t_enter << " -> " << v.t_enter;
            if (std::fabs(v.t_enter - u.t_exit) > t_tol(pl, o, d, v.t_enter))
                return fail() << "gap between visits " << i - 1 << " and " << i << ": t_exit " << u.t_exit
                              << ", next t_enter " << v.t_enter;
            // (b) a face neighbour, in the direction of the ray.
            int changed = 0;
            for (int a = 0; a < 3; a++) {
                int diff = v.cell[a] - u.cell[a];
                if (diff == 0) continue;
                changed++;
                int want = ax(d, a) > 0 ? 1 : ax(d, a) < 0 ? -1 : 0;
                if (diff != want)
                    return fail() << "visit " << i << " moves by " << diff << " on axis " << a
                                  << " (direction component " << ax(d, a) << ")";
            }
            if (changed != 1) return fail() << "visit " << i << " changes " << changed << " indices";
        }
        // (d, forward) the cell's box holds the ray over the cell's interval.
        rt_box box = rt_grid_cell_box(g, v.cell[0], v.cell[1], v.cell[2]);
        double ts[3] = {v.t_enter, v.t_exit, 0.5 * (v.t_enter + v.t_exit)};
        for (double t : ts)
            for (int a = 0; a < 3; a++) {
                double x = coord(o, d, t, a), e = pos_tol(pl, o, d, t, a);
                if (!(x >= ax(box.lo, a) - e && x <= ax(box.hi, a) + e))
                    return fail() << "visit " << i << " cell (" << v.cell[0] << "," << v.cell[1] << "," << v.cell[2]
                                  << ") [" << v.t_enter << ", " << v.t_exit << "]: point at t=" << t
                                  << " has coordinate " << x << " on axis " << a << " outside [" << ax(box.lo, a)
                                  << ", " << ax(box.hi, a) << "]";
            }
    }
    if (!meets) return ::testing::AssertionSuccess();

    // The walk covers exactly the ray's part inside the object space.
    const Visit &first = w.visits.front(), &last = w.visits.back();
    if (std::fabs(first.t_enter - t0) > t_tol(pl, o, d, t0))
        return fail() << "first t_enter " << first.t_enter << ", the ray enters the space at " << t0;
    if (std::fabs(last.t_exit - t1) > t_tol(pl, o, d, t1))
        return fail() << "last t_exit " << last.t_exit << ", the ray leaves the space at " << t1;

    // (d, converse) samples between consecutive plane crossings lie in visited cells, in order.
    std::vector<double> cross = {t0, t1};
    for (int a = 0; a < 3; a++) {
        double da = ax(d, a);
        if (da == 0.0) continue;
        for (int k = 1; k < pl.n[a]; k++) {
            double t = (pl.p[a][k] - ax(o, a)) / da;
            if (t > t0 && t < t1) cross.push_back(t);
        }
    }
    std::sort(cross.begin(), cross.end());
    cross.erase(std::unique(cross.begin(), cross.end()), cross.end());
    size_t j = 0;  // visits are matched in order
    for (size_t c = 0; c + 1 < cross.size(); c++) {
        double tm = 0.5 * (cross[c] + cross[c + 1]);
        if (!(tm > cross[c] && tm < cross[c + 1])) continue;  // adjacent doubles: no room for a sample
        while (j < w.visits.size() && !(w.visits[j].t_enter <= tm && tm <= w.visits[j].t_exit)) j++;
        if (j == w.visits.size())
            return fail() << "sample at t=" << tm << " (between crossings " << cross[c] << " and " << cross[c + 1]
                          << ") lies in no visited cell interval, in order";
        const Visit &v = w.visits[j];
        for (int a = 0; a < 3; a++) {
            double x = coord(o, d, tm, a), e = pos_tol(pl, o, d, tm, a);
            const std::vector<double> &p = pl.p[a];
            int k = v.cell[a];
            if (!(x >= p[k] - e && x <= p[k + 1] + e))
                return fail() << "sample at t=" << tm << " has coordinate " << x << " on axis " << a
                              << ", outside the visited cell's slab [" << p[k] << ", " << p[k + 1] << "] (index " << k
                              << ")";
        }
    }
    return ::testing::AssertionSuccess();
}

// Runs check_walk, stopping a loop's report after a few failures.
struct FailureBudget {
    int left = 10;
    bool check(const ::testing::AssertionResult &r)
    {
        if (r) return true;
        if (left-- > 0) ADD_FAILURE() << r.message();
        return false;
    }
};

struct TestSpace {
    std::string name;
    ScenePtr scene;
};

// The scenes the random tests walk: unit, tiny, huge, far from the origin, not a cube.
std::vector<TestSpace> test_spaces()
{
    std::vector<TestSpace> v;
    v.push_back({"unit cube", two_spheres(rt_vec(0, 0, 0), rt_vec(10, 10, 10), 1.0)});
    v.push_back({"tiny cube", two_spheres(rt_vec(0, 0, 0), rt_vec(10e-6, 10e-6, 10e-6), 1e-6)});
    v.push_back({"huge cube", two_spheres(rt_vec(0, 0, 0), rt_vec(10e6, 10e6, 10e6), 1e6)});
    v.push_back({"far box", two_spheres(rt_vec(1e6, 1e6 + 1, 1e6 - 2), rt_vec(1e6 + 3, 1e6 + 2, 1e6 + 5), 0.25)});
    v.push_back({"long flat box", two_spheres(rt_vec(-3, 0, 2), rt_vec(57, 1, 30), 0.5)});
    return v;
}

const int kGridDims[][3] = {{1, 1, 1}, {7, 7, 7}, {24, 24, 24}, {5, 9, 13}, {64, 1, 3}, {1, 24, 1}};

// A random point in the object space grown by `factor` around its centre.
rt_vec3 random_point(TestRng &rng, const rt_box &b, double factor)
{
    rt_vec3 c = rt_vec_scale(rt_vec_add(b.lo, b.hi), 0.5), h = rt_vec_scale(rt_vec_sub(b.hi, b.lo), 0.5 * factor);
    return rt_vec(c.x + rng.uniform(-h.x, h.x), c.y + rng.uniform(-h.y, h.y), c.z + rng.uniform(-h.z, h.z));
}

}  // namespace

TEST(DdaWalk, RandomRaysInsideAndOutside)
{
    TestRng rng(12345);
    for (auto &sp : test_spaces()) {
        for (auto &dm : kGridDims) {
            GridPtr g = make_grid(sp.scene.get(), dm[0], dm[1], dm[2]);
            ASSERT_TRUE(g);
            SCOPED_TRACE(sp.name);
            rt_box b = rt_grid_bounds(g.get());
            FailureBudget budget;
            int started = 0;
            for (int i = 0; i < 600; i++) {
                rt_vec3 o = random_point(rng, b, i % 2 ? 0.9 : 3.0);
                rt_vec3 d = rng.unit();
                // Some rays aim at a point of the space, so most outside rays meet it.
                if (i % 3 == 0) d = rt_vec_normalize(rt_vec_sub(random_point(rng, b, 1.0), o));
                // Non-unit directions: t is along origin + t * dir.
                if (i % 7 == 0) d = rt_vec_scale(d, rng.uniform(1e-3, 1e3));
                budget.check(check_walk(g.get(), o, d));
                rt_dda s;
                started += rt_dda_start(g.get(), o, d, 0.0, &s);
            }
            EXPECT_GT(started, 300) << "too few rays met the space for the test to mean much";
        }
    }
}

TEST(DdaWalk, RandomRaysWithZeroComponents)
{
    TestRng rng(777);
    for (auto &sp : test_spaces()) {
        for (auto &dm : kGridDims) {
            GridPtr g = make_grid(sp.scene.get(), dm[0], dm[1], dm[2]);
            ASSERT_TRUE(g);
            SCOPED_TRACE(sp.name);
            Planes pl(g.get());
            rt_box b = pl.bounds;
            FailureBudget budget;
            for (int i = 0; i < 300; i++) {
                rt_vec3 o = random_point(rng, b, i % 2 ? 0.9 : 2.0);
                rt_vec3 d = rng.unit();
                int zero_a = rng.below(3);
                set_ax(d, zero_a, 0.0);
                if (i % 2) set_ax(d, (zero_a + 1) % 3, 0.0);  // along an axis
                if (rt_vec_is_zero(d)) continue;
                // Put the origin exactly on a plane of each non-moving axis now and then:
                // the ray then runs along a cell face or edge.
                for (int a = 0; a < 3; a++)
                    if (ax(d, a) == 0.0 && rng.below(2)) set_ax(o, a, pl.p[a][rng.below(pl.n[a] + 1)]);
                budget.check(check_walk(g.get(), o, d));
                budget.check(check_walk(g.get(), o, rt_vec_scale(d, -1.0)));
            }
        }
    }
}

TEST(DdaWalk, RaysFromGridPlanePoints)
{
    // Origins exactly on grid planes (cell faces, edges and corners), random directions
    // and the diagonal directions through edges and corners.
    TestRng rng(4242);
    const rt_vec3 diag_dirs[] = {rt_vec(1, 1, 1),  rt_vec(-1, -1, -1), rt_vec(1, -1, 1), rt_vec(1, 1, 0),
                                 rt_vec(0, 1, -1), rt_vec(-1, 0, -1),  rt_vec(1, 0, 0),  rt_vec(0, 0, -1),
                                 rt_vec(2, 1, 0),  rt_vec(1, 2, 3)};
    for (auto &sp : test_spaces()) {
        for (auto &dm : kGridDims) {
            GridPtr g = make_grid(sp.scene.get(), dm[0], dm[1], dm[2]);
            ASSERT_TRUE(g);
            SCOPED_TRACE(sp.name);
            Planes pl(g.get());
            FailureBudget budget;
            for (int i = 0; i < 200; i++) {
                rt_vec3 o;
                for (int a = 0; a < 3; a++) set_ax(o, a, pl.p[a][rng.below(pl.n[a] + 1)]);
                for (const rt_vec3 &dd : diag_dirs) budget.check(check_walk(g.get(), o, dd));
                budget.check(check_walk(g.get(), o, rng.unit()));
            }
        }
    }
}

TEST(DdaWalk, DiagonalFromTheCornerBreaksTiesXThenYThenZ)
{
    // In a cube space with cube cells the planes are the same numbers on every axis, so
    // the ray (1,1,1) from the low corner crosses three planes at exactly the same t at
    // every lattice point: ties go x, then y, then z, with zero-length in-between cells.
    for (double scale : {1.0, 1e-6, 1e6}) {
        ScenePtr s = two_spheres(rt_vec(0, 0, 0), rt_vec(10 * scale, 10 * scale, 10 * scale), scale);
        for (int n : {1, 2, 7, 24}) {
            GridPtr g = make_grid(s.get(), n, n, n);
            ASSERT_TRUE(g);
            Planes pl(g.get());
            ASSERT_EQ(pl.p[0], pl.p[1]);
            ASSERT_EQ(pl.p[0], pl.p[2]);
            rt_vec3 o = pl.bounds.lo;
            Walk w = walk(g.get(), o, rt_vec(1, 1, 1), 0.0);
            ASSERT_TRUE(w.started);
            ASSERT_TRUE(w.ended);
            ASSERT_EQ(w.visits.size(), size_t(3 * (n - 1) + 1)) << "scale " << scale << " n " << n;
            for (int k = 0; k < n; k++) {
                const Visit *v = &w.visits[3 * k];
                EXPECT_EQ(v->cell[0], k);
                EXPECT_EQ(v->cell[1], k);
                EXPECT_EQ(v->cell[2], k);
                EXPECT_EQ(v->t_enter, pl.p[0][k] - o.x);
                EXPECT_EQ(v->t_exit, pl.p[0][k + 1] - o.x);
                if (k + 1 == n) break;
                // (k+1, k, k) and (k+1, k+1, k): zero length at the corner.
                const Visit &vx = w.visits[3 * k + 1], &vy = w.visits[3 * k + 2];
                EXPECT_EQ(vx.cell[0], k + 1);
                EXPECT_EQ(vx.cell[1], k);
                EXPECT_EQ(vx.cell[2], k);
                EXPECT_EQ(vy.cell[0], k + 1);
                EXPECT_EQ(vy.cell[1], k + 1);
                EXPECT_EQ(vy.cell[2], k);
                EXPECT_EQ(vx.t_enter, vx.t_exit);
                EXPECT_EQ(vy.t_enter, vy.t_exit);
            }
            EXPECT_TRUE(check_walk(g.get(), o, rt_vec(1, 1, 1)));
            // The same backwards from the high corner: ties still x, then y, then z.
            Walk b = walk(g.get(), pl.bounds.hi, rt_vec(-1, -1, -1), 0.0);
            ASSERT_TRUE(b.started);
            ASSERT_EQ(b.visits.size(), size_t(3 * (n - 1) + 1));
            if (n > 1) {
                EXPECT_EQ(b.visits[1].cell[0], n - 2);
                EXPECT_EQ(b.visits[1].cell[1], n - 1);
                EXPECT_EQ(b.visits[2].cell[1], n - 2);
                EXPECT_EQ(b.visits[2].cell[2], n - 1);
            }
            EXPECT_TRUE(check_walk(g.get(), pl.bounds.hi, rt_vec(-1, -1, -1)));
        }
    }
}

TEST(DdaWalk, EdgeDiagonalInAPlane)
{
    // (1,1,0) from the low x-y edge at a z inside one cell layer: x before y at every edge.
    ScenePtr s = two_spheres(rt_vec(0, 0, 0), rt_vec(10, 10, 10), 1.0);
    const int n = 6;
    GridPtr g = make_grid(s.get(), n, n, n);
    ASSERT_TRUE(g);
    Planes pl(g.get());
    rt_vec3 o = rt_vec(pl.bounds.lo.x, pl.bounds.lo.y, 0.5 * (pl.p[2][2] + pl.p[2][3]));
    Walk w = walk(g.get(), o, rt_vec(1, 1, 0), 0.0);
    ASSERT_TRUE(w.started);
    ASSERT_EQ(w.visits.size(), size_t(2 * (n - 1) + 1));
    for (size_t i = 0; i < w.visits.size(); i++) {
        EXPECT_EQ(w.visits[i].cell[0], int((i + 1) / 2));
        EXPECT_EQ(w.visits[i].cell[1], int(i / 2));
        EXPECT_EQ(w.visits[i].cell[2], 2);
    }
    EXPECT_TRUE(check_walk(g.get(), o, rt_vec(1, 1, 0)));
}

TEST(DdaWalk, AxisRaysVisitARowOfCells)
{
    ScenePtr s = two_spheres(rt_vec(-2, 1, 3), rt_vec(8, 4, 11), 1.0);
    GridPtr g = make_grid(s.get(), 5, 9, 13);
    ASSERT_TRUE(g);
    Planes pl(g.get());
    for (int a = 0; a < 3; a++) {
        for (int sign : {1, -1}) {
            // From well outside, through the middle of cell (1, 2, 3) on the other axes.
            rt_vec3 o;
            int idx[3] = {1, 2, 3};
            for (int b = 0; b < 3; b++) set_ax(o, b, 0.5 * (pl.p[b][idx[b]] + pl.p[b][idx[b] + 1]));
            set_ax(o, a, sign > 0 ? ax(pl.bounds.lo, a) - 5 : ax(pl.bounds.hi, a) + 5);
            rt_vec3 d = rt_vec(0, 0, 0);
            set_ax(d, a, sign);
            Walk w = walk(g.get(), o, d, 0.0);
            ASSERT_TRUE(w.started);
            ASSERT_EQ(w.visits.size(), size_t(pl.n[a])) << "axis " << a;
            for (int i = 0; i < pl.n[a]; i++) {
                const Visit &v = w.visits[i];
                for (int b = 0; b < 3; b++) EXPECT_EQ(v.cell[b], b == a ? (sign > 0 ? i : pl.n[a] - 1 - i) : idx[b]);
                int k = sign > 0 ? i : pl.n[a] - i;  // plane entered through
                EXPECT_EQ(v.t_enter, (pl.p[a][k] - ax(o, a)) / sign);
            }
            EXPECT_TRUE(check_walk(g.get(), o, d));
            // The same ray with its origin inside: starts at t = 0 in the origin's cell.
            rt_vec3 oi = o;
            set_ax(oi, a, 0.5 * (pl.p[a][2] + pl.p[a][3]));
            Walk wi = walk(g.get(), oi, d, 0.0);
            ASSERT_TRUE(wi.started);
            EXPECT_EQ(wi.visits[0].t_enter, 0.0);
            EXPECT_EQ(wi.visits[0].cell[a], 2);
            EXPECT_EQ(wi.visits.size(), size_t(sign > 0 ? pl.n[a] - 2 : 3));
            EXPECT_TRUE(check_walk(g.get(), oi, d));
        }
    }
}

TEST(DdaWalk, RayAlongAnEdgeOfTheObjectSpace)
{
    // Origin on the space's own boundary planes, moving along the boundary edge.
    ScenePtr s = two_spheres(rt_vec(0, 0, 0), rt_vec(10, 10, 10), 1.0);
    GridPtr g = make_grid(s.get(), 4, 4, 4);
    ASSERT_TRUE(g);
    rt_box b = rt_grid_bounds(g.get());
    rt_vec3 o = rt_vec(b.lo.x - 3, b.hi.y, b.lo.z);
    Walk w = walk(g.get(), o, rt_vec(1, 0, 0), 0.0);
    ASSERT_TRUE(w.started) << "a ray along the boundary edge touches the closed object space";
    EXPECT_EQ(w.visits.size(), 4u);
    for (const Visit &v : w.visits) {
        EXPECT_EQ(v.cell[1], 3);
        EXPECT_EQ(v.cell[2], 0);
    }
    EXPECT_TRUE(check_walk(g.get(), o, rt_vec(1, 0, 0)));
    // Just outside the boundary plane: no walk.
    rt_vec3 out = rt_vec(b.lo.x - 3, std::nextafter(b.hi.y, INFINITY), 5);
    rt_dda dd;
    EXPECT_EQ(rt_dda_start(g.get(), out, rt_vec(1, 0, 0), 0.0, &dd), 0);
}

TEST(DdaStart, RaysThatMissTheSpace)
{
    ScenePtr s = two_spheres(rt_vec(0, 0, 0), rt_vec(10, 10, 10), 1.0);
    GridPtr g = make_grid(s.get(), 24, 24, 24);
    ASSERT_TRUE(g);
    rt_dda d;
    // Pointing away.
    EXPECT_EQ(rt_dda_start(g.get(), rt_vec(20, 5, 5), rt_vec(1, 0, 0), 0.0, &d), 0);
    EXPECT_EQ(rt_dda_start(g.get(), rt_vec(-20, -20, -20), rt_vec_normalize(rt_vec(-1, -1, -1)), 0.0, &d), 0);
    // Passing beside it.
    EXPECT_EQ(rt_dda_start(g.get(), rt_vec(-20, 5, 12), rt_vec(1, 0, 0), 0.0, &d), 0);
    EXPECT_EQ(rt_dda_start(g.get(), rt_vec(-20, -20, 5), rt_vec_normalize(rt_vec(1, -0.1, 0)), 0.0, &d), 0);
    // Would meet it, but only before t_min.
    EXPECT_EQ(rt_dda_start(g.get(), rt_vec(-20, 5, 5), rt_vec(1, 0, 0), 40.0, &d), 0);
    // Degenerate directions.
    EXPECT_EQ(rt_dda_start(g.get(), rt_vec(5, 5, 5), rt_vec(0, 0, 0), 0.0, &d), 0);
    EXPECT_EQ(rt_dda_start(g.get(), rt_vec(5, 5, 5), rt_vec(NAN, 0, 1), 0.0, &d), 0);
    EXPECT_EQ(rt_dda_start(g.get(), rt_vec(5, 5, 5), rt_vec(INFINITY, 0, 0), 0.0, &d), 0);
    EXPECT_EQ(rt_dda_start(g.get(), rt_vec(NAN, 5, 5), rt_vec(1, 0, 0), 0.0, &d), 0);
    // Random misses: origins outside, aimed away from the space's bounding sphere.
    TestRng rng(99);
    rt_box b = rt_grid_bounds(g.get());
    rt_vec3 c = rt_vec_scale(rt_vec_add(b.lo, b.hi), 0.5);
    double r = 0.5 * rt_vec_length(rt_vec_sub(b.hi, b.lo));
    int tried = 0;
    for (int i = 0; i < 2000; i++) {
        rt_vec3 o = rt_vec_add(c, rt_vec_scale(rng.unit(), r * rng.uniform(1.1, 5)));
        rt_vec3 dir = rng.unit();
        rt_vec3 oc = rt_vec_sub(c, o);
        double tc = rt_vec_dot(oc, dir);
        double miss2 = rt_vec_dot(oc, oc) - (tc > 0 ? tc * tc : 0);
        if (miss2 <= r * r * 1.01) continue;
        tried++;
        EXPECT_EQ(rt_dda_start(g.get(), o, dir, 0.0, &d), 0) << "o=" << vstr(o) << " d=" << vstr(dir);
    }
    EXPECT_GT(tried, 500);
}

TEST(DdaStart, TMinLaterThanTheEntry)
{
    // The walk starts where the ray is at t_min, in that point's cell.
    TestRng rng(31337);
    ScenePtr s = two_spheres(rt_vec(0, 0, 0), rt_vec(10, 10, 10), 1.0);
    GridPtr g = make_grid(s.get(), 7, 7, 7);
    ASSERT_TRUE(g);
    rt_box b = rt_grid_bounds(g.get());
    FailureBudget budget;
    for (int i = 0; i < 1000; i++) {
        rt_vec3 o = random_point(rng, b, 3.0);
        rt_vec3 dir = rt_vec_normalize(rt_vec_sub(random_point(rng, b, 1.0), o));
        double t_min = rng.uniform(0, 30);
        budget.check(check_walk(g.get(), o, dir, t_min));
        rt_dda d;
        double t0, t1;
        if (rt_dda_start(g.get(), o, dir, t_min, &d) && clip_to_box(o, dir, 0.0, b, t0, t1) && t_min > t0 + 1e-9) {
            EXPECT_EQ(d.t_enter, t_min);
        }
    }
}

TEST(DdaStart, EmptyGridIsNeverEntered)
{
    ScenePtr s(rt_scene_new());
    GridPtr g = make_grid(s.get(), 24, 24, 24);
    ASSERT_TRUE(g);
    rt_dda d;
    EXPECT_EQ(rt_dda_start(g.get(), rt_vec(0, 0, 0), rt_vec(1, 0, 0), 0.0, &d), 0);
    EXPECT_EQ(rt_dda_start(g.get(), rt_vec(-1, -1, -1), rt_vec_normalize(rt_vec(1, 1, 1)), 0.0, &d), 0);
}

TEST(DdaStart, StateMatchesItsDocumentation)
{
    ScenePtr s = two_spheres(rt_vec(0, 0, 0), rt_vec(10, 10, 10), 1.0);
    GridPtr g = make_grid(s.get(), 6, 6, 6);
    ASSERT_TRUE(g);
    Planes pl(g.get());
    rt_vec3 o = rt_vec(-5, 5.1, 5.2);
    rt_vec3 dir = rt_vec_normalize(rt_vec(1, 0, -0.25));
    rt_dda d;
    ASSERT_EQ(rt_dda_start(g.get(), o, dir, 0.0, &d), 1);
    EXPECT_EQ(d.step[0], 1);
    EXPECT_EQ(d.step[1], 0);
    EXPECT_EQ(d.step[2], -1);
    EXPECT_EQ(d.t_next[1], INFINITY);
    EXPECT_EQ(d.t_delta[1], INFINITY);
    EXPECT_NEAR(d.t_delta[0], (pl.p[0][6] - pl.p[0][0]) / 6 / dir.x, 1e-12);
    EXPECT_NEAR(d.t_delta[2], (pl.p[2][6] - pl.p[2][0]) / 6 / -dir.z, 1e-12);
    EXPECT_EQ(d.cell[0], 0);
    EXPECT_DOUBLE_EQ(d.t_enter, (pl.bounds.lo.x - o.x) / dir.x);
    EXPECT_DOUBLE_EQ(d.t_next[0], (pl.p[0][1] - o.x) / dir.x);
    EXPECT_EQ(rt_dda_t_exit(&d), std::min(d.t_next[0], d.t_next[2]));
}

TEST(DdaWalk, HugeOriginDistanceAndExtremeDirections)
{
    // Origins far outside the space, direction components spanning many magnitudes.
    ScenePtr s = two_spheres(rt_vec(0, 0, 0), rt_vec(10, 10, 10), 1.0);
    GridPtr g = make_grid(s.get(), 24, 24, 24);
    ASSERT_TRUE(g);
    FailureBudget budget;
    TestRng rng(2024);
    for (int i = 0; i < 500; i++) {
        rt_box b = rt_grid_bounds(g.get());
        rt_vec3 target = random_point(rng, b, 0.95);
        rt_vec3 dir = rng.unit();
        double dist = std::pow(10.0, rng.uniform(0, 6));
        rt_vec3 o = rt_vec_sub(target, rt_vec_scale(dir, dist));
        budget.check(check_walk(g.get(), o, dir));
        // One component shrunk to almost nothing (but not zero).
        rt_vec3 d2 = dir;
        set_ax(d2, i % 3, ax(dir, i % 3) * std::pow(10.0, -rng.uniform(5, 200)));
        budget.check(check_walk(g.get(), target, d2));
        budget.check(check_walk(g.get(), target, rt_vec_scale(d2, -1.0)));
    }
}
