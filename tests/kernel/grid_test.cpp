// grid_test.cpp - the grid's object space, cell lists and preprocessing units.
//
// Cell lists are checked against an oracle written here independently of
// src/grid.c: spheres by the sphere-box distance, polygons and triangles by
// intersecting the box with the polygon's plane (a convex cross-section,
// computed by clipping a large square in the plane) and testing that
// cross-section against the polygon in 2D (even-odd vertex test plus
// Cyrus-Beck edge clipping). Both sides grow every cell by
// rt_grid_overlap_tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "rt_grid.h"
#include "rt_scene.h"
#include "test_support.h"

using namespace torusrt_test;

namespace {

// What the test knows of each object, kept apart from the scene's internals.
struct TestObject {
    rt_object_kind kind;
    rt_vec3 center;
    double radius;
    std::vector<rt_vec3> verts;
};

struct TestScene {
    ScenePtr scene{rt_scene_new()};
    std::vector<TestObject> objects;

    void sphere(rt_vec3 c, double r)
    {
        ASSERT_EQ(rt_scene_add_sphere(scene.get(), c, r), RT_OK);
        objects.push_back({RT_OBJ_SPHERE, c, r, {}});
    }
    void polygon(const std::vector<rt_vec3> &v)
    {
        ASSERT_EQ(rt_scene_add_polygon(scene.get(), v.data(), v.size()), RT_OK);
        objects.push_back({RT_OBJ_POLYGON, rt_vec(0, 0, 0), 0, v});
    }
    void patch(const std::vector<rt_vec3> &v)
    {
        std::vector<rt_vec3> normals(v.size(), rt_vec(0, 0, 1));
        ASSERT_EQ(rt_scene_add_patch(scene.get(), v.data(), normals.data(), v.size()), RT_OK);
        for (size_t i = 1; i + 1 < v.size(); i++)
            objects.push_back({RT_OBJ_TRIANGLE, rt_vec(0, 0, 0), 0, {v[0], v[i], v[i + 1]}});
    }
};

double axis(rt_vec3 v, int a) { return a == 0 ? v.x : a == 1 ? v.y : v.z; }

rt_box grown_cell(const rt_grid *g, int ix, int iy, int iz)
{
    double t = rt_grid_overlap_tolerance(g);
    rt_box b = rt_grid_cell_box(g, ix, iy, iz);
    b.lo = rt_vec_sub(b.lo, rt_vec(t, t, t));
    b.hi = rt_vec_add(b.hi, rt_vec(t, t, t));
    return b;
}

// --- the oracle ---------------------------------------------------------

bool sphere_meets_box(rt_vec3 c, double r, const rt_box &b)
{
    double d2 = 0;
    for (int a = 0; a < 3; a++) {
        double x = axis(c, a), lo = axis(b.lo, a), hi = axis(b.hi, a);
        double d = x < lo ? lo - x : x > hi ? x - hi : 0.0;
        d2 += d * d;
    }
    return d2 <= r * r;
}

// Keeps the part of a convex polygon with sign * (p[a] - bound) >= 0.
std::vector<rt_vec3> clip_convex(const std::vector<rt_vec3> &poly, int a, double bound, double sign)
{
    std::vector<rt_vec3> out;
    for (size_t i = 0; i < poly.size(); i++) {
        const rt_vec3 &p = poly[i], &q = poly[(i + 1) % poly.size()];
        double dp = sign * (axis(p, a) - bound), dq = sign * (axis(q, a) - bound);
        if (dp >= 0) out.push_back(p);
        if ((dp >= 0) != (dq >= 0)) {
            double t = dp / (dp - dq);
            out.push_back(rt_vec_add(p, rt_vec_scale(rt_vec_sub(q, p), t)));
        }
    }
    return out;
}

struct P2 {
    double x, y;
};

bool inside_even_odd(const std::vector<P2> &poly, P2 p)
{
    bool in = false;
    for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        const P2 &a = poly[i], &b = poly[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x)) in = !in;
    }
    return in;
}

// Cyrus-Beck: does segment a-b meet the convex counter-clockwise polygon q?
bool segment_meets_convex(P2 a, P2 b, const std::vector<P2> &q)
{
    double t0 = 0, t1 = 1;
    for (size_t i = 0; i < q.size(); i++) {
        P2 e = {q[(i + 1) % q.size()].x - q[i].x, q[(i + 1) % q.size()].y - q[i].y};
        P2 n = {-e.y, e.x};  // inward for counter-clockwise
        double num = (a.x - q[i].x) * n.x + (a.y - q[i].y) * n.y;
        double den = (b.x - a.x) * n.x + (b.y - a.y) * n.y;
        if (den == 0) {
            if (num < 0) return false;
            continue;
        }
        double t = -num / den;
        if (den > 0) t0 = std::max(t0, t);
        else t1 = std::min(t1, t);
        if (t0 > t1) return false;
    }
    return true;
}

bool flat_meets_box(const std::vector<rt_vec3> &v, const rt_box &b)
{
    // Cheap rejection by the vertices' bounding box.
    for (int a = 0; a < 3; a++) {
        double lo = INFINITY, hi = -INFINITY;
        for (const rt_vec3 &p : v) lo = std::min(lo, axis(p, a)), hi = std::max(hi, axis(p, a));
        if (hi < axis(b.lo, a) || lo > axis(b.hi, a)) return false;
    }
    // Plane: Newell normal through the centroid; an in-plane basis e1, e2.
    rt_vec3 n = rt_vec(0, 0, 0), c = rt_vec(0, 0, 0);
    for (size_t i = 0; i < v.size(); i++) {
        const rt_vec3 &p = v[i], &q = v[(i + 1) % v.size()];
        n = rt_vec_add(n, rt_vec((p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y)));
        c = rt_vec_add(c, rt_vec_scale(p, 1.0 / double(v.size())));
    }
    n = rt_vec_normalize(n);
    rt_vec3 e1 = rt_vec_normalize(rt_vec_cross(n, std::fabs(n.x) < 0.6 ? rt_vec(1, 0, 0) : rt_vec(0, 1, 0)));
    rt_vec3 e2 = rt_vec_cross(n, e1);

    // The box's cross-section: a square in the plane, larger than the box,
    // clipped by the six faces (exact for a convex polygon).
    rt_vec3 bc = rt_vec_scale(rt_vec_add(b.lo, b.hi), 0.5);
    rt_vec3 centre = rt_vec_sub(bc, rt_vec_scale(n, rt_vec_dot(rt_vec_sub(bc, c), n)));
    double h = rt_vec_length(rt_vec_sub(b.hi, b.lo));
    std::vector<rt_vec3> q = {
        rt_vec_add(centre, rt_vec_add(rt_vec_scale(e1, -h), rt_vec_scale(e2, -h))),
        rt_vec_add(centre, rt_vec_add(rt_vec_scale(e1, h), rt_vec_scale(e2, -h))),
        rt_vec_add(centre, rt_vec_add(rt_vec_scale(e1, h), rt_vec_scale(e2, h))),
        rt_vec_add(centre, rt_vec_add(rt_vec_scale(e1, -h), rt_vec_scale(e2, h))),
    };
    for (int a = 0; a < 3 && q.size() >= 3; a++) {
        q = clip_convex(q, a, axis(b.lo, a), 1.0);
        if (q.size() >= 3) q = clip_convex(q, a, axis(b.hi, a), -1.0);
    }
    if (q.size() < 3) return false;  // no cross-section (touching at an edge has measure zero here)

    auto to2d = [&](rt_vec3 p) {
        rt_vec3 d = rt_vec_sub(p, c);
        return P2{rt_vec_dot(d, e1), rt_vec_dot(d, e2)};
    };
    std::vector<P2> q2, p2;
    for (const rt_vec3 &p : q) q2.push_back(to2d(p));
    for (const rt_vec3 &p : v) p2.push_back(to2d(p));
    for (const P2 &p : q2)
        if (inside_even_odd(p2, p)) return true;  // the cross-section lies (partly) inside
    for (size_t i = 0; i < p2.size(); i++)
        if (segment_meets_convex(p2[i], p2[(i + 1) % p2.size()], q2)) return true;  // an edge crosses it
    return false;
}

bool oracle_meets(const TestObject &o, const rt_box &b)
{
    if (o.kind == RT_OBJ_SPHERE) return sphere_meets_box(o.center, o.radius, b);
    return flat_meets_box(o.verts, b);
}

std::vector<uint32_t> cell_list(const rt_grid *g, size_t cell)
{
    size_t n = 0;
    const uint32_t *objs = rt_grid_cell_objects(g, cell, &n);
    return std::vector<uint32_t>(objs, objs + n);
}

// Every cell's list must equal the oracle's, in ascending order.
void expect_lists_match_oracle(const TestScene &ts, const rt_grid *g)
{
    int d[3];
    rt_grid_dims(g, d);
    size_t mismatches = 0;
    uint64_t entries = 0;
    for (int iz = 0; iz < d[2]; iz++)
        for (int iy = 0; iy < d[1]; iy++)
            for (int ix = 0; ix < d[0]; ix++) {
                rt_box b = grown_cell(g, ix, iy, iz);
                std::vector<uint32_t> want;
                for (size_t o = 0; o < ts.objects.size(); o++)
                    if (oracle_meets(ts.objects[o], b)) want.push_back(uint32_t(o));
                const int32_t cell[3] = {ix, iy, iz};
                std::vector<uint32_t> got = cell_list(g, rt_grid_index(d, cell));
                entries += got.size();
                EXPECT_TRUE(std::is_sorted(got.begin(), got.end()));
                if (got != want && ++mismatches <= 5) {
                    std::string w, h;
                    for (uint32_t o : want) w += " " + std::to_string(o);
                    for (uint32_t o : got) h += " " + std::to_string(o);
                    ADD_FAILURE() << "cell (" << ix << "," << iy << "," << iz << "): oracle {" << w << " } grid {" << h
                                  << " }";
                }
            }
    EXPECT_EQ(mismatches, 0u);
    EXPECT_EQ(entries, rt_grid_list_entries(g));
}

std::vector<rt_vec3> star(rt_vec3 c, rt_vec3 n, double r_out, double r_in, int points, double phase)
{
    rt_vec3 u = rt_vec_normalize(rt_vec_cross(n, std::fabs(n.x) < 0.6 ? rt_vec(1, 0, 0) : rt_vec(0, 1, 0)));
    rt_vec3 w = rt_vec_cross(n, u);
    std::vector<rt_vec3> v;
    for (int i = 0; i < 2 * points; i++) {
        double a = phase + M_PI * i / points, r = i % 2 ? r_in : r_out;
        v.push_back(rt_vec_add(c, rt_vec_add(rt_vec_scale(u, r * std::cos(a)), rt_vec_scale(w, r * std::sin(a)))));
    }
    return v;
}

// Self-crossing pentagram {5/2}: even-odd leaves its central pentagon out.
std::vector<rt_vec3> pentagram(rt_vec3 c, rt_vec3 n, double r, double phase)
{
    rt_vec3 u = rt_vec_normalize(rt_vec_cross(n, std::fabs(n.x) < 0.6 ? rt_vec(1, 0, 0) : rt_vec(0, 1, 0)));
    rt_vec3 w = rt_vec_cross(n, u);
    std::vector<rt_vec3> v;
    for (int i = 0; i < 5; i++) {
        double a = phase + 4 * M_PI * i / 5;
        v.push_back(rt_vec_add(c, rt_vec_add(rt_vec_scale(u, r * std::cos(a)), rt_vec_scale(w, r * std::sin(a)))));
    }
    return v;
}

void random_scene(TestScene &ts, uint64_t seed, int spheres, int triangles, int stars, int pentagrams)
{
    TestRng rng(seed);
    for (int i = 0; i < spheres; i++) ts.sphere(rng.point(0, 10), rng.uniform(0.05, 1.5));
    for (int i = 0; i < triangles; i++) {
        rt_vec3 c = rng.point(0, 10);
        int n = i % 4 == 0 ? 5 : 3;  // some fans of three triangles
        std::vector<rt_vec3> v;
        for (int k = 0; k < n; k++) v.push_back(rt_vec_add(c, rng.point(-2, 2)));
        ts.patch(v);
    }
    for (int i = 0; i < stars; i++) {
        double r = rng.uniform(0.5, 3.0);
        ts.polygon(star(rng.point(0, 10), rng.unit(), r, r * rng.uniform(0.2, 0.5), 5 + i % 3, rng.uniform(0, 6.3)));
    }
    for (int i = 0; i < pentagrams; i++)
        ts.polygon(pentagram(rng.point(0, 10), rng.unit(), rng.uniform(0.5, 3.0), rng.uniform(0, 6.3)));
}

const int kDims[][3] = {{1, 1, 1}, {7, 7, 7}, {24, 24, 24}, {5, 9, 13}};

// expect_lists_match_oracle on a grid of every size in kDims.
void expect_lists_match_oracle_on_every_grid(const TestScene &ts)
{
    for (const auto &d : kDims) {
        SCOPED_TRACE(std::to_string(d[0]) + "x" + std::to_string(d[1]) + "x" + std::to_string(d[2]));
        GridPtr g = make_grid(ts.scene.get(), d[0], d[1], d[2]);
        ASSERT_TRUE(g);
        expect_lists_match_oracle(ts, g.get());
    }
}

}  // namespace

TEST(GridLists, SpheresMatchOracle)
{
    TestScene ts;
    random_scene(ts, 1, 150, 0, 0, 0);
    expect_lists_match_oracle_on_every_grid(ts);
}

TEST(GridLists, TrianglesMatchOracle)
{
    TestScene ts;
    random_scene(ts, 2, 0, 80, 0, 0);
    expect_lists_match_oracle_on_every_grid(ts);
}

TEST(GridLists, ConcaveAndSelfCrossingPolygonsMatchOracle)
{
    TestScene ts;
    random_scene(ts, 3, 0, 0, 50, 25);
    expect_lists_match_oracle_on_every_grid(ts);
}

TEST(GridLists, MixedSceneMatchesOracle)
{
    TestScene ts;
    random_scene(ts, 4, 40, 30, 20, 10);
    expect_lists_match_oracle_on_every_grid(ts);
}

// Objects a million times smaller than the scene, far from the origin.
TEST(GridLists, TinyObjectsInHugeSceneMatchOracle)
{
    TestScene ts;
    TestRng rng(5);
    rt_vec3 off = rt_vec(1e6, -2e6, 3e6);
    ts.sphere(rt_vec_add(off, rt_vec(0, 0, 0)), 1.0);
    ts.sphere(rt_vec_add(off, rt_vec(10, 10, 10)), 1.0);
    for (int i = 0; i < 60; i++) ts.sphere(rt_vec_add(off, rng.point(0, 10)), 1e-5 * rng.uniform(0.5, 2));
    for (int i = 0; i < 30; i++) {
        rt_vec3 c = rt_vec_add(off, rng.point(0, 10));
        ts.patch({c, rt_vec_add(c, rng.point(-1e-5, 1e-5)), rt_vec_add(c, rng.point(-1e-5, 1e-5))});
    }
    GridPtr g = make_grid(ts.scene.get(), 24, 24, 24);
    ASSERT_TRUE(g);
    expect_lists_match_oracle(ts, g.get());
}

// Sutherland-Hodgman non-emptiness would keep a cell in the notch of a U
// (a zero-width bridge along a clip plane); the grid must not list it.
TEST(GridLists, CellInTheNotchOfAUIsNotListed)
{
    for (int opening = 0; opening < 2; opening++) {
        SCOPED_TRACE(opening ? "U opening towards +x" : "U opening towards +y");
        TestScene ts;
        // Corner spheres fix the object space to x, y in [0, 5], z in [-0.05, 1.05].
        ts.sphere(rt_vec(0.05, 0.05, 0), 0.05);
        ts.sphere(rt_vec(4.95, 4.95, 1), 0.05);
        // Outer 5 x 5, notch x in [1.5, 3.5], y in [1.5, 5] at z = 0.5.
        std::vector<rt_vec3> u = {rt_vec(0, 0, .5),     rt_vec(5, 0, .5),     rt_vec(5, 5, .5),   rt_vec(3.5, 5, .5),
                                  rt_vec(3.5, 1.5, .5), rt_vec(1.5, 1.5, .5), rt_vec(1.5, 5, .5), rt_vec(0, 5, .5)};
        if (opening)
            for (rt_vec3 &p : u) p = rt_vec(p.y, p.x, p.z);
        if (opening) std::reverse(u.begin(), u.end());
        ts.polygon(u);
        GridPtr g = make_grid(ts.scene.get(), 5, 5, 1);
        ASSERT_TRUE(g);
        expect_lists_match_oracle(ts, g.get());
        int d[3];
        rt_grid_dims(g.get(), d);
        for (int k = 2; k <= 4; k++) {
            const int32_t notch[3] = {opening ? k : 2, opening ? 2 : k, 0};
            std::vector<uint32_t> l = cell_list(g.get(), rt_grid_index(d, notch));
            EXPECT_EQ(std::count(l.begin(), l.end(), 2u), 0) << "notch cell " << notch[0] << "," << notch[1];
        }
        const int32_t arm[3] = {0, 4, 0};
        std::vector<uint32_t> l = cell_list(g.get(), rt_grid_index(d, arm));
        EXPECT_EQ(std::count(l.begin(), l.end(), 2u), 1);
    }
}

// The tolerance: an object lying in a cell face, or within the tolerance
// beyond it, is listed on both sides; one clearly beyond, on one side only.
TEST(GridLists, ObjectsTouchingAFaceAreListedOnBothSides)
{
    ScenePtr probe(rt_scene_new());
    ASSERT_EQ(rt_scene_add_sphere(probe.get(), rt_vec(0, 0, 0), 0.5), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(probe.get(), rt_vec(8, 8, 8), 0.5), RT_OK);
    GridPtr pg = make_grid(probe.get(), 4, 4, 4);
    ASSERT_TRUE(pg);
    const double plane = rt_grid_cell_box(pg.get(), 2, 0, 0).lo.x, tol = rt_grid_overlap_tolerance(pg.get());
    const struct {
        double x;
        bool left;
    } cases[] = {{plane, true}, {plane + 0.5 * tol, true}, {plane - 0.5 * tol, true}, {plane + 3 * tol, false}};
    for (const auto &c : cases) {
        SCOPED_TRACE("x = plane + " + std::to_string((c.x - plane) / tol) + " tol");
        TestScene ts;
        ts.sphere(rt_vec(0, 0, 0), 0.5);
        ts.sphere(rt_vec(8, 8, 8), 0.5);
        ts.polygon({rt_vec(c.x, 3, 3), rt_vec(c.x, 5, 3), rt_vec(c.x, 5, 5), rt_vec(c.x, 3, 5)});
        // A sphere whose lowest x is the polygon's, centred to the right.
        ts.sphere(rt_vec(c.x + 1.0, 1.0, 1.0), 1.0);
        GridPtr g = make_grid(ts.scene.get(), 4, 4, 4);
        ASSERT_TRUE(g);
        ASSERT_EQ(rt_grid_cell_box(g.get(), 2, 0, 0).lo.x, plane);  // same object space
        int d[3];
        rt_grid_dims(g.get(), d);
        for (int ix = 0; ix < 4; ix++) {
            const int32_t poly_cell[3] = {ix, 1, 2}, sphere_cell[3] = {ix, 0, 0};
            std::vector<uint32_t> lp = cell_list(g.get(), rt_grid_index(d, poly_cell));
            std::vector<uint32_t> ls = cell_list(g.get(), rt_grid_index(d, sphere_cell));
            bool want = ix == 2 || (ix == 1 && c.left);
            EXPECT_EQ(std::count(lp.begin(), lp.end(), 2u), want ? 1 : 0) << "polygon, x cell " << ix;
            EXPECT_EQ(std::count(ls.begin(), ls.end(), 3u), want ? 1 : 0) << "sphere, x cell " << ix;
        }
        expect_lists_match_oracle(ts, g.get());
    }
}

// Cones are listed conservatively: exactly in the cells their bounds reach.
TEST(GridLists, ConeListedWhereItsBoundsReach)
{
    ScenePtr s(rt_scene_new());
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(0, 0, 0), 0.5), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(10, 10, 10), 0.5), RT_OK);
    ASSERT_EQ(rt_scene_add_cone(s.get(), rt_vec(2, 3, 4), 1.0, rt_vec(7, 6, 5), 0.3), RT_OK);
    GridPtr g = make_grid(s.get(), 7, 7, 7);
    ASSERT_TRUE(g);
    rt_box cb = rt_scene_object_bounds(s.get(), 2);
    int d[3];
    rt_grid_dims(g.get(), d);
    for (int iz = 0; iz < 7; iz++)
        for (int iy = 0; iy < 7; iy++)
            for (int ix = 0; ix < 7; ix++) {
                rt_box b = grown_cell(g.get(), ix, iy, iz);
                bool want = cb.lo.x <= b.hi.x && cb.hi.x >= b.lo.x && cb.lo.y <= b.hi.y && cb.hi.y >= b.lo.y &&
                            cb.lo.z <= b.hi.z && cb.hi.z >= b.lo.z;
                const int32_t cell[3] = {ix, iy, iz};
                std::vector<uint32_t> l = cell_list(g.get(), rt_grid_index(d, cell));
                EXPECT_EQ(std::count(l.begin(), l.end(), 2u), want ? 1 : 0);
            }
}

TEST(GridSpace, BoundsArePaddedByOneMillionthOfTheDiagonal)
{
    ScenePtr s(rt_scene_new());
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(1, 2, 3), 1.0), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(5, 2, 3), 1.0), RT_OK);
    GridPtr g = make_grid(s.get(), 24, 24, 24);
    ASSERT_TRUE(g);
    // Unpadded box [0,6] x [1,3] x [2,4]: diagonal sqrt(36 + 4 + 4).
    double pad = 1e-6 * std::sqrt(44.0);
    rt_box b = rt_grid_bounds(g.get());
    EXPECT_NEAR(b.lo.x, 0 - pad, 1e-15);
    EXPECT_NEAR(b.hi.x, 6 + pad, 1e-15);
    EXPECT_NEAR(b.lo.y, 1 - pad, 1e-15);
    EXPECT_NEAR(b.hi.z, 4 + pad, 1e-15);
    rt_vec3 e = rt_vec_sub(b.hi, b.lo);
    EXPECT_DOUBLE_EQ(rt_grid_overlap_tolerance(g.get()), 1e-9 * rt_vec_length(e));
    rt_vec3 cs = rt_grid_cell_size(g.get());
    EXPECT_DOUBLE_EQ(cs.x, e.x / 24);
    EXPECT_DOUBLE_EQ(cs.z, e.z / 24);
    EXPECT_FALSE(rt_grid_is_empty(g.get()));
    EXPECT_EQ(rt_grid_cell_count(g.get()), 24u * 24u * 24u);
}

TEST(GridSpace, FlatSceneGetsThickness)
{
    ScenePtr s(rt_scene_new());
    for (int i = 0; i < 3; i++) {
        rt_vec3 q[4] = {rt_vec(i, 0, 0), rt_vec(i + 1, 0, 0), rt_vec(i + 1, 1, 0), rt_vec(i, 1, 0)};
        ASSERT_EQ(rt_scene_add_polygon(s.get(), q, 4), RT_OK);
    }
    GridPtr g = make_grid(s.get(), 24, 24, 24);
    ASSERT_TRUE(g);
    rt_box b = rt_grid_bounds(g.get());
    EXPECT_LT(b.lo.z, 0.0);
    EXPECT_GT(b.hi.z, 0.0);
    EXPECT_NEAR(b.hi.z - b.lo.z, 2e-6 * std::sqrt(10.0), 1e-15);
    EXPECT_GT(rt_grid_cell_size(g.get()).z, 0.0);
    EXPECT_GT(rt_grid_list_entries(g.get()), 0u);
}

TEST(GridSpace, ObjectsInOnePointArePaddedByTheirScale)
{
    // A radius too small to move the centre's bounds: the box is one point.
    ScenePtr s(rt_scene_new());
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(3, 4, 5), 1e-300), RT_OK);
    GridPtr g = make_grid(s.get(), 2, 2, 2);
    ASSERT_TRUE(g);
    rt_box b = rt_grid_bounds(g.get());
    EXPECT_NEAR(b.lo.x, 3 - 5e-6, 1e-15);
    EXPECT_NEAR(b.hi.z, 5 + 5e-6, 1e-15);
    EXPECT_FALSE(rt_grid_is_empty(g.get()));
}

TEST(GridSpace, EmptySceneGivesEmptyGrid)
{
    ScenePtr s(rt_scene_new());
    GridPtr g = make_grid(s.get(), 24, 24, 24);
    ASSERT_TRUE(g);
    EXPECT_TRUE(rt_grid_is_empty(g.get()));
    EXPECT_EQ(rt_grid_list_entries(g.get()), 0u);
    EXPECT_EQ(rt_grid_units_serial(g.get()), 0u);
    EXPECT_EQ(rt_grid_units_parallel(g.get(), 4), 0u);
    rt_box b = rt_grid_bounds(g.get());
    EXPECT_LT(b.lo.x, b.hi.x);
    for (size_t c = 0; c < rt_grid_cell_count(g.get()); c += 97) EXPECT_TRUE(cell_list(g.get(), c).empty());
}

TEST(GridSpace, OnlyZeroAreaPolygonsGiveEmptyGrid)
{
    ScenePtr s(rt_scene_new());
    rt_vec3 line[3] = {rt_vec(0, 0, 0), rt_vec(1, 1, 1), rt_vec(2, 2, 2)};
    ASSERT_EQ(rt_scene_add_polygon(s.get(), line, 3), RT_OK);
    GridPtr g = make_grid(s.get(), 4, 4, 4);
    ASSERT_TRUE(g);
    EXPECT_TRUE(rt_grid_is_empty(g.get()));
    EXPECT_EQ(rt_grid_list_entries(g.get()), 0u);
    EXPECT_EQ(rt_grid_units_of_object(g.get(), 0), 0u);
}

TEST(GridSpace, DegeneratePolygonIsSkippedAmongOthers)
{
    ScenePtr s(rt_scene_new());
    rt_vec3 line[3] = {rt_vec(0, 0, 0), rt_vec(1, 1, 1), rt_vec(2, 2, 2)};
    ASSERT_EQ(rt_scene_add_polygon(s.get(), line, 3), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(1, 1, 1), 1.0), RT_OK);
    GridPtr g = make_grid(s.get(), 3, 3, 3);
    ASSERT_TRUE(g);
    EXPECT_EQ(rt_grid_units_of_object(g.get(), 0), 0u);
    for (size_t c = 0; c < rt_grid_cell_count(g.get()); c++)
        for (uint32_t o : cell_list(g.get(), c)) EXPECT_EQ(o, 1u);
}

TEST(GridSpace, BadDimensionsAreRejected)
{
    ScenePtr s(rt_scene_new());
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(0, 0, 0), 1.0), RT_OK);
    char msg[RT_MSG_LEN] = "";
    EXPECT_EQ(rt_grid_new(s.get(), 0, 24, 24, msg, sizeof msg), nullptr);
    EXPECT_NE(std::string(msg).find("0x24x24"), std::string::npos) << msg;
    EXPECT_NE(std::string(msg).find("1 to 1024"), std::string::npos) << msg;
    msg[0] = '\0';
    EXPECT_EQ(rt_grid_new(s.get(), 24, -3, 24, msg, sizeof msg), nullptr);
    EXPECT_NE(std::string(msg).find("24x-3x24"), std::string::npos) << msg;
    EXPECT_EQ(rt_grid_new(s.get(), 24, 24, 1025, msg, sizeof msg), nullptr);
    msg[0] = '\0';
    EXPECT_EQ(rt_grid_new(s.get(), 1024, 1024, 17, msg, sizeof msg), nullptr);
    EXPECT_NE(std::string(msg).find("1024x1024x17"), std::string::npos) << msg;
    GridPtr ok(rt_grid_new(s.get(), 1024, 1, 1, msg, sizeof msg));
    EXPECT_TRUE(ok) << msg;
}

TEST(GridSpace, CellBoxesShareFacesExactly)
{
    TestScene ts;
    random_scene(ts, 6, 20, 0, 0, 0);
    GridPtr g = make_grid(ts.scene.get(), 5, 9, 13);
    ASSERT_TRUE(g);
    rt_box all = rt_grid_bounds(g.get());
    rt_box first = rt_grid_cell_box(g.get(), 0, 0, 0), last = rt_grid_cell_box(g.get(), 4, 8, 12);
    EXPECT_EQ(first.lo.x, all.lo.x);
    EXPECT_EQ(first.lo.z, all.lo.z);
    EXPECT_EQ(last.hi.x, all.hi.x);
    EXPECT_EQ(last.hi.y, all.hi.y);
    EXPECT_EQ(last.hi.z, all.hi.z);
    for (int i = 0; i + 1 < 13; i++) {
        int ix = std::min(i, 3), iy = std::min(i, 7);
        rt_box a = rt_grid_cell_box(g.get(), ix, iy, i), b = rt_grid_cell_box(g.get(), ix + 1, iy + 1, i + 1);
        EXPECT_EQ(a.hi.x, b.lo.x);
        EXPECT_EQ(a.hi.y, b.lo.y);
        EXPECT_EQ(a.hi.z, b.lo.z);
    }
}

TEST(GridUnits, SerialIsSumOfObjects)
{
    TestScene ts;
    random_scene(ts, 7, 30, 20, 10, 5);
    for (const auto &d : kDims) {
        GridPtr g = make_grid(ts.scene.get(), d[0], d[1], d[2]);
        ASSERT_TRUE(g);
        uint64_t sum = 0;
        for (size_t o = 0; o < ts.objects.size(); o++) sum += rt_grid_units_of_object(g.get(), o);
        EXPECT_EQ(rt_grid_units_serial(g.get()), sum);
        EXPECT_EQ(rt_grid_units_parallel(g.get(), 1), sum);
        if (d[0] == 1 && d[1] == 1 && d[2] == 1) {
            EXPECT_EQ(sum, 0u);  // nothing to split
        } else {
            EXPECT_GT(sum, 0u);
        }
    }
}

TEST(GridUnits, ParallelShrinksWithProcessors)
{
    ScenePtr s(rt_scene_new());
    TestRng rng(369);
    for (int i = 0; i < 369; i++)
        ASSERT_EQ(rt_scene_add_sphere(s.get(), rng.point(0, 100), rng.uniform(0.5, 4)), RT_OK);
    GridPtr g = make_grid(s.get(), 24, 24, 24);
    ASSERT_TRUE(g);
    uint64_t serial = rt_grid_units_serial(g.get());
    EXPECT_EQ(rt_grid_units_parallel(g.get(), 1), serial);
    EXPECT_EQ(rt_grid_units_parallel(g.get(), 0), serial);  // P < 1 counts as 1
    uint64_t prev = serial;
    for (int p : {2, 4, 8, 16, 32, 64}) {
        uint64_t u = rt_grid_units_parallel(g.get(), p);
        EXPECT_LE(u, prev) << "P = " << p;
        EXPECT_GE(u * uint64_t(p), serial) << "P = " << p;  // the busiest does at least the mean
        prev = u;
    }
    EXPECT_LT(rt_grid_units_parallel(g.get(), 16), serial);
    // More processors than objects: the busiest handles the costliest object.
    uint64_t worst = 0;
    for (size_t o = 0; o < 369; o++) worst = std::max(worst, rt_grid_units_of_object(g.get(), o));
    EXPECT_EQ(rt_grid_units_parallel(g.get(), 1000), worst);
}

TEST(GridUnits, ParallelDealsObjectsInTurn)
{
    TestScene ts;
    random_scene(ts, 8, 10, 0, 3, 0);
    GridPtr g = make_grid(ts.scene.get(), 24, 24, 24);
    ASSERT_TRUE(g);
    uint64_t sums[3] = {0, 0, 0};
    for (size_t o = 0; o < ts.objects.size(); o++) sums[o % 3] += rt_grid_units_of_object(g.get(), o);
    EXPECT_EQ(rt_grid_units_parallel(g.get(), 3), *std::max_element(sums, sums + 3));
}

// Spheres A (0,0,0) r 1 and B (100,100,100) r 1 span [-1, 101] on every axis
// (plus the 1e-6 pad); C at (10, 70, 30) r 0.01 lies well inside one cell.
//
// 2x2x2: one level, factor 2 per axis, plane at ~50.
//   x: "lo <= p1?" yes (first slab 0), "hi >= p1?" no (last 0): 2 units
//   y: "lo <= p1?" no -> first = last = 1, no (b) tests:        1 unit
//   z: as x:                                                     2 units
//   total 5.
// 24^3: levels 2, 2, 2, 3; cell size ~4.25, so C is in cell (2, 16, 7).
//   A factor-2 split costs 2 units for the lower half, 1 for the upper.
//   A factor-3 split costs 2 for slab 0 (yes; no), 3 for slab 1 (no, yes;
//   no), 2 for slab 2 (no, no).
//   x = 2:  [0,24) lower 2, [0,12) lower 2, [0,6) lower 2, [0,3) slab 2: 2 -> 8
//   y = 16: [0,24) upper 1, [12,24) lower 2, [12,18) upper 1, [15,18) slab 1: 3 -> 7
//   z = 7:  [0,24) lower 2, [0,12) upper 1, [6,12) lower 2, [6,9) slab 1: 3 -> 8
//   total 23.
TEST(GridUnits, HandCountedTinySphere)
{
    ScenePtr s(rt_scene_new());
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(0, 0, 0), 1.0), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(100, 100, 100), 1.0), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(10, 70, 30), 0.01), RT_OK);

    GridPtr g2 = make_grid(s.get(), 2, 2, 2);
    ASSERT_TRUE(g2);
    EXPECT_EQ(rt_grid_units_of_object(g2.get(), 2), 5u);
    int d2[3] = {2, 2, 2};
    const int32_t c2[3] = {0, 1, 0};
    EXPECT_EQ(cell_list(g2.get(), rt_grid_index(d2, c2)), (std::vector<uint32_t>{2}));

    GridPtr g = make_grid(s.get(), 24, 24, 24);
    ASSERT_TRUE(g);
    EXPECT_EQ(rt_grid_units_of_object(g.get(), 2), 23u);
    int d[3] = {24, 24, 24};
    size_t listed = 0;
    for (size_t c = 0; c < rt_grid_cell_count(g.get()); c++) {
        std::vector<uint32_t> l = cell_list(g.get(), c);
        listed += size_t(std::count(l.begin(), l.end(), 2u));
    }
    EXPECT_EQ(listed, 1u);
    const int32_t c[3] = {2, 16, 7};
    std::vector<uint32_t> l = cell_list(g.get(), rt_grid_index(d, c));
    EXPECT_EQ(std::count(l.begin(), l.end(), 2u), 1);
}

// The same scene under the per-plane rule: one unit per plane examined, so a factor-2 split
// costs 1 unit per axis wherever the extent lies, and a factor-3 split min(last + 1, 2).
//   2x2x2: 1 + 1 + 1 = 3.
//   24^3, x = 2:  1 + 1 + 1 + slab 2 of 3: 2 -> 5
//         y = 16: 1 + 1 + 1 + slab 1 of 3: 2 -> 5
//         z = 7:  1 + 1 + 1 + slab 1 of 3: 2 -> 5; total 15.
// A sphere's bounding sphere is itself: bounding-sphere counts what per-plane counts. The cell
// lists do not depend on the rule.
TEST(GridUnits, HandCountedPerPlaneAndBoundingSphere)
{
    ScenePtr s(rt_scene_new());
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(0, 0, 0), 1.0), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(100, 100, 100), 1.0), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(10, 70, 30), 0.01), RT_OK);
    char msg[RT_MSG_LEN] = "";
    for (rt_preprocess_count rule : {RT_COUNT_PER_PLANE, RT_COUNT_BOUNDING_SPHERE}) {
        GridPtr g2(rt_grid_new_counted(s.get(), 2, 2, 2, rule, nullptr, msg, sizeof msg));
        ASSERT_TRUE(g2) << msg;
        EXPECT_EQ(rt_grid_units_of_object(g2.get(), 2), 3u) << "rule " << rule;
        GridPtr g(rt_grid_new_counted(s.get(), 24, 24, 24, rule, nullptr, msg, sizeof msg));
        ASSERT_TRUE(g) << msg;
        EXPECT_EQ(rt_grid_units_of_object(g.get(), 2), 15u) << "rule " << rule;
        GridPtr seq = make_grid(s.get(), 24, 24, 24);
        ASSERT_TRUE(seq);
        EXPECT_EQ(rt_grid_list_entries(g.get()), rt_grid_list_entries(seq.get()));
        for (size_t c = 0; c < rt_grid_cell_count(g.get()); c++)
            ASSERT_EQ(cell_list(g.get(), c), cell_list(seq.get(), c)) << "cell " << c;
    }
}

// A polygon whose box lies in slab 0 of 3 but whose bounding sphere reaches past plane 1.
// Spheres at x = 0 and 119 (r 1) make x span [-1, 120]: planes at ~39.3 and ~79.7; y and z are
// one cell each (no tests). The square at x = 35, y and z in [-5, 5], has the box x = [35, 35]
// and the bounding sphere of radius sqrt(200) / 2 ~ 7.07, x = [27.9, 42.1].
//   sequential:      "lo <= p1?" yes, "hi >= p1?" no                  -> 2 units
//   per-plane:       plane 1: the box lies below it                   -> 1 unit
//   bounding-sphere: plane 1: across; plane 2: below                  -> 2 units
TEST(GridUnits, HandCountedBoundingSphereOfAPolygon)
{
    ScenePtr s(rt_scene_new());
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(0, 0, 0), 1.0), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(119, 0, 0), 1.0), RT_OK);
    const rt_vec3 square[4] = {rt_vec(35, -5, -5), rt_vec(35, 5, -5), rt_vec(35, 5, 5), rt_vec(35, -5, 5)};
    ASSERT_EQ(rt_scene_add_polygon(s.get(), square, 4), RT_OK);
    char msg[RT_MSG_LEN] = "";
    const std::pair<rt_preprocess_count, uint64_t> want[] = {
        {RT_COUNT_SEQUENTIAL, 2}, {RT_COUNT_PER_PLANE, 1}, {RT_COUNT_BOUNDING_SPHERE, 2}};
    for (const auto &[rule, units] : want) {
        GridPtr g(rt_grid_new_counted(s.get(), 3, 1, 1, rule, nullptr, msg, sizeof msg));
        ASSERT_TRUE(g) << msg;
        EXPECT_EQ(rt_grid_units_of_object(g.get(), 2), units) << "rule " << rule;
        EXPECT_EQ(cell_list(g.get(), 0), (std::vector<uint32_t>{0, 2})) << "rule " << rule;
        EXPECT_EQ(cell_list(g.get(), 1), (std::vector<uint32_t>{})) << "rule " << rule;
    }
}

// Prime factors in ascending order, shorter lists padded with 1s: a prime
// axis of 7 is split at the first level only (6 planes: up to 6 + 6 tests).
TEST(GridUnits, PrimeAxisSplitsOnce)
{
    ScenePtr s(rt_scene_new());
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(0, 0, 0), 1.0), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(70, 70, 70), 1.0), RT_OK);
    // Cell size 72/7 ~ 10.29: x = 35 lies in slab 3 of 7.
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(35, 35, 35), 0.01), RT_OK);
    GridPtr g = make_grid(s.get(), 7, 1, 1);
    ASSERT_TRUE(g);
    // (a) planes 1, 2, 3: no, no, no; plane 4: yes -> first = 3; (b) plane 4: no. 5 units.
    EXPECT_EQ(rt_grid_units_of_object(g.get(), 2), 5u);
}
