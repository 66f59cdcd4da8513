// intersect_test.cpp - ray-object intersection and normals (src/intersect.h) on analytic
// cases: spheres (front, inside, tangent, just missed, tiny and huge, checked against
// a long double solution), polygons (square, concave star, bow-ties, zero area, edge-on
// rays, vertex-order normals), `pp` triangles (barycentrics, interpolated and geometric
// normals) and open cones and cylinders (inside, outside, beyond the open ends).
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <vector>

#include "rt_scene.h"
#include "rt_vec.h"

// intersect.h is a kernel-internal C header without C++ guards.
extern "C" {
#include "intersect.h"
}

#include "test_support.h"

using namespace torusrt_test;

namespace {

const double kInf = INFINITY;

struct Hit {
    bool hit;
    double t;
    rt_hit h;
    rt_vec3 point, n_geo, n_shade;
};

Hit shoot(const rt_scene *s, uint32_t obj, rt_vec3 o, rt_vec3 d, double t_min = 0.0, double t_max = kInf)
{
    Hit r{};
    r.hit = rt_intersect_object(s, obj, o, d, t_min, t_max, &r.h) != 0;
    if (r.hit) {
        r.t = r.h.t;
        r.point = rt_vec_add(o, rt_vec_scale(d, r.t));
        rt_object_normals(s, obj, r.point, &r.h, &r.n_geo, &r.n_shade);
    }
    return r;
}

ScenePtr one_sphere(rt_vec3 c, double r) { return scene_with_spheres({{c, r}}); }

ScenePtr one_polygon(const std::vector<rt_vec3> &v)
{
    ScenePtr s(rt_scene_new());
    EXPECT_EQ(rt_scene_add_polygon(s.get(), v.data(), v.size()), RT_OK);
    return s;
}

ScenePtr one_cone(rt_vec3 base, double rb, rt_vec3 apex, double ra)
{
    ScenePtr s(rt_scene_new());
    EXPECT_EQ(rt_scene_add_cone(s.get(), base, rb, apex, ra), RT_OK);
    return s;
}

// Nearest t > 0 of the ray on the sphere, in long double from the same double inputs.
// Returns -1 for a miss.
long double sphere_t_ld(rt_vec3 o, rt_vec3 d, rt_vec3 c, double r)
{
    long double ox = (long double)o.x - c.x, oy = (long double)o.y - c.y, oz = (long double)o.z - c.z;
    long double a = (long double)d.x * d.x + (long double)d.y * d.y + (long double)d.z * d.z;
    long double b = (ox * d.x + oy * d.y + oz * d.z) / a;  // t of the point nearest the centre
    long double px = ox - b * d.x, py = oy - b * d.y, pz = oz - b * d.z;
    long double disc = ((long double)r * r - (px * px + py * py + pz * pz)) / a;
    if (disc < 0) return -1;
    long double h = sqrtl(disc);
    if (-b - h > 0) return -b - h;
    if (-b + h > 0) return -b + h;
    return -1;
}

void expect_unit(rt_vec3 v, double tol = 1e-12) { EXPECT_NEAR(rt_vec_length(v), 1.0, tol); }

void expect_vec_near(rt_vec3 a, rt_vec3 b, double tol)
{
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

// Even-odd test in the x-y plane, written here.
bool inside_xy(const std::vector<rt_vec3> &poly, double px, double py)
{
    bool in = false;
    for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        const rt_vec3 &a = poly[i], &b = poly[j];
        if ((a.y > py) != (b.y > py) && px < a.x + (py - a.y) / (b.y - a.y) * (b.x - a.x)) in = !in;
    }
    return in;
}

// Distance in the x-y plane from (px, py) to the polygon's boundary.
double edge_distance_xy(const std::vector<rt_vec3> &poly, double px, double py)
{
    double best = INFINITY;
    for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        double ax = poly[j].x, ay = poly[j].y, bx = poly[i].x, by = poly[i].y;
        double ex = bx - ax, ey = by - ay, len2 = ex * ex + ey * ey;
        double t = len2 > 0 ? ((px - ax) * ex + (py - ay) * ey) / len2 : 0;
        t = t < 0 ? 0 : t > 1 ? 1 : t;
        double dx = px - (ax + t * ex), dy = py - (ay + t * ey);
        best = std::fmin(best, std::sqrt(dx * dx + dy * dy));
    }
    return best;
}

// A five-pointed star, outer radius 1, inner radius 0.4: concave, not self-crossing.
std::vector<rt_vec3> star(double z)
{
    std::vector<rt_vec3> v;
    for (int k = 0; k < 10; k++) {
        double a = M_PI / 2 + k * M_PI / 5, r = k % 2 ? 0.4 : 1.0;
        v.push_back(rt_vec(r * std::cos(a), r * std::sin(a), z));
    }
    return v;
}

}  // namespace

// --- spheres -------------------------------------------------------------

TEST(IntersectSphere, FrontHitPointAndNormal)
{
    ScenePtr s = one_sphere(rt_vec(0, 0, 5), 1.0);
    Hit h = shoot(s.get(), 0, rt_vec(0, 0, 0), rt_vec(0, 0, 1));
    ASSERT_TRUE(h.hit);
    EXPECT_DOUBLE_EQ(h.t, 4.0);
    expect_vec_near(h.n_geo, rt_vec(0, 0, -1), 1e-15);
    expect_vec_near(h.n_shade, h.n_geo, 0);
    // Oblique: aimed at the point at 60 degrees from the near pole.
    rt_vec3 target = rt_vec(0, std::sin(M_PI / 3), 5 - std::cos(M_PI / 3));
    rt_vec3 o = rt_vec(0, 0, -3);
    rt_vec3 d = rt_vec_normalize(rt_vec_sub(target, o));
    h = shoot(s.get(), 0, o, d);
    ASSERT_TRUE(h.hit);
    EXPECT_NEAR(h.t, rt_vec_length(rt_vec_sub(target, o)), 1e-12);
    expect_vec_near(h.n_geo, rt_vec(0, std::sin(M_PI / 3), -std::cos(M_PI / 3)), 1e-12);
    EXPECT_LT(rt_vec_dot(h.n_geo, d), 0.0);
}

TEST(IntersectSphere, RandomHitsMatchLongDouble)
{
    TestRng rng(5);
    for (int i = 0; i < 5000; i++) {
        rt_vec3 c = rt_vec(rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(-10, 10));
        double r = std::pow(10.0, rng.uniform(-2, 1));
        ScenePtr s = one_sphere(c, r);
        rt_vec3 o = rt_vec(rng.uniform(-20, 20), rng.uniform(-20, 20), rng.uniform(-20, 20));
        // Aim at a random point of the sphere's inside (or anywhere, for misses).
        rt_vec3 aim = rt_vec_add(c, rt_vec_scale(rng.unit(), r * rng.uniform(0, i % 4 ? 0.999 : 3)));
        rt_vec3 d = rt_vec_normalize(rt_vec_sub(aim, o));
        long double want = sphere_t_ld(o, d, c, r);
        Hit h = shoot(s.get(), 0, o, d);
        if (want < 0) {
            // Misses by a clear margin must miss.
            long double ox = o.x - c.x, oy = o.y - c.y, oz = o.z - c.z;
            long double b = ox * d.x + oy * d.y + oz * d.z;
            long double p2 = ox * ox + oy * oy + oz * oz - b * b;
            if (p2 > (long double)r * r * (1 + 1e-9) || rt_vec_length(rt_vec_sub(o, c)) > r * (1 + 1e-9)) {
                EXPECT_FALSE(h.hit) << i;
            }
            continue;
        }
        ASSERT_TRUE(h.hit) << i;
        EXPECT_NEAR(h.t, (double)want, 1e-12 * (double)want + 1e-14 * rt_vec_max_abs(o)) << i;
        expect_unit(h.n_geo);
        // The normal points from the centre through the hit point.
        rt_vec3 radial = rt_vec_scale(rt_vec_sub(h.point, c), 1.0 / r);
        expect_vec_near(h.n_geo, radial, 1e-9);
    }
}

TEST(IntersectSphere, FromInsideHitsTheFarSideWithOutwardNormal)
{
    ScenePtr s = one_sphere(rt_vec(1, 2, 3), 2.0);
    TestRng rng(11);
    for (int i = 0; i < 200; i++) {
        rt_vec3 d = rng.unit();
        Hit h = shoot(s.get(), 0, rt_vec(1, 2, 3), d);
        ASSERT_TRUE(h.hit);
        EXPECT_NEAR(h.t, 2.0, 1e-14);
        expect_vec_near(h.n_geo, d, 1e-14);
        EXPECT_GT(rt_vec_dot(h.n_geo, d), 0.0) << "outward normal: D.N > 0 leaving";
        // Off centre.
        rt_vec3 o = rt_vec_add(rt_vec(1, 2, 3), rt_vec_scale(rng.unit(), 1.5));
        h = shoot(s.get(), 0, o, d);
        ASSERT_TRUE(h.hit);
        EXPECT_NEAR(h.t, (double)sphere_t_ld(o, d, rt_vec(1, 2, 3), 2.0), 1e-13);
        EXPECT_GT(rt_vec_dot(h.n_geo, d), 0.0);
    }
}

TEST(IntersectSphere, TangentAndJustMissed)
{
    ScenePtr s = one_sphere(rt_vec(0, 0, 5), 1.0);
    // Exactly tangent (discriminant 0): a hit, if any, is at the tangent point.
    Hit h = shoot(s.get(), 0, rt_vec(0, 1, 0), rt_vec(0, 0, 1));
    if (h.hit) {
        EXPECT_NEAR(h.t, 5.0, 1e-12);
        EXPECT_NEAR(rt_vec_dot(h.n_geo, rt_vec(0, 0, 1)), 0.0, 1e-12);
    }
    // Grazing inside by 1e-9 of the radius: discriminant ~ 2e-9, still accurate.
    rt_vec3 o = rt_vec(0, 1 - 1e-9, 0), d = rt_vec(0, 0, 1);
    h = shoot(s.get(), 0, o, d);
    ASSERT_TRUE(h.hit);
    long double want = sphere_t_ld(o, d, rt_vec(0, 0, 5), 1.0);
    EXPECT_NEAR(h.t, (double)want, 1e-12 * 5);
    EXPECT_LT(rt_vec_dot(h.n_geo, d), 0.0);
    // Just outside: one ulp and a relative 1e-12 beyond the radius.
    for (double y : {std::nextafter(1.0, 2.0), 1 + 1e-12, 1 + 1e-6, -1 - 1e-12}) {
        EXPECT_FALSE(shoot(s.get(), 0, rt_vec(0, y, 0), d).hit) << y;
        EXPECT_FALSE(shoot(s.get(), 0, rt_vec(y, 0, 0), d).hit) << y;
    }
    // Oblique grazing ray, 1e-12 outside along the perpendicular.
    rt_vec3 dd = rt_vec_normalize(rt_vec(1, 0, 1));
    rt_vec3 perp = rt_vec_normalize(rt_vec(1, 0, -1));
    rt_vec3 touch = rt_vec_add(rt_vec(0, 0, 5), rt_vec_scale(perp, 1 + 1e-12));
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec_sub(touch, rt_vec_scale(dd, 3)), dd).hit);
}

TEST(IntersectSphere, BehindAndInterval)
{
    ScenePtr s = one_sphere(rt_vec(0, 0, 5), 1.0);
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(0, 0, 0), rt_vec(0, 0, -1)).hit);
    // t_max before the near root: no hit; t_min between the roots: the far root.
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(0, 0, 0), rt_vec(0, 0, 1), 0.0, 3.9).hit);
    Hit h = shoot(s.get(), 0, rt_vec(0, 0, 0), rt_vec(0, 0, 1), 4.5, kInf);
    ASSERT_TRUE(h.hit);
    EXPECT_DOUBLE_EQ(h.t, 6.0);
    expect_vec_near(h.n_geo, rt_vec(0, 0, 1), 1e-15);
    // The interval is open: t == t_min or t == t_max is not a hit.
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(0, 0, 0), rt_vec(0, 0, 1), 0.0, 4.0).hit);
    h = shoot(s.get(), 0, rt_vec(0, 0, 0), rt_vec(0, 0, 1), 4.0, kInf);
    ASSERT_TRUE(h.hit);
    EXPECT_DOUBLE_EQ(h.t, 6.0);
}

TEST(IntersectSphere, TinySphereSeenFromDistanceOne)
{
    TestRng rng(17);
    const double r = 1e-6;
    for (int i = 0; i < 2000; i++) {
        rt_vec3 c = rt_vec_scale(rng.unit(), 1.0);  // at distance 1 from the origin
        ScenePtr s = one_sphere(c, r);
        rt_vec3 o = rt_vec(0, 0, 0);
        rt_vec3 aim = rt_vec_add(c, rt_vec_scale(rng.unit(), r * rng.uniform(0, 0.999)));
        rt_vec3 d = rt_vec_normalize(aim);
        long double want = sphere_t_ld(o, d, c, r);
        ASSERT_GT(want, 0) << i;
        Hit h = shoot(s.get(), 0, o, d);
        ASSERT_TRUE(h.hit) << i;
        EXPECT_NEAR(h.t, (double)want, 1e-12 * (double)want) << i;
        EXPECT_LT(rt_vec_dot(h.n_geo, d), 0.0);
        expect_unit(h.n_geo, 1e-9);
        // Aimed a relative 1e-3 of the radius beside the sphere: a miss.
        rt_vec3 side = rt_vec_normalize(rt_vec_cross(rt_vec_normalize(c), rng.unit()));
        rt_vec3 miss_aim = rt_vec_add(c, rt_vec_scale(side, r * 1.001));
        rt_vec3 dm = rt_vec_normalize(miss_aim);
        if (sphere_t_ld(o, dm, c, r) < 0) {
            EXPECT_FALSE(shoot(s.get(), 0, o, dm).hit) << i;
        }
    }
}

TEST(IntersectSphere, HugeSphere)
{
    TestRng rng(23);
    const double r = 1e6;
    rt_vec3 c = rt_vec(0, 0, 3e6);
    ScenePtr s = one_sphere(c, r);
    for (int i = 0; i < 2000; i++) {
        // From outside, at distance 2e6 from the surface.
        rt_vec3 o = rt_vec(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
        rt_vec3 aim = rt_vec_add(c, rt_vec_scale(rng.unit(), r * rng.uniform(0, 0.999)));
        rt_vec3 d = rt_vec_normalize(rt_vec_sub(aim, o));
        long double want = sphere_t_ld(o, d, c, r);
        ASSERT_GT(want, 0);
        Hit h = shoot(s.get(), 0, o, d);
        ASSERT_TRUE(h.hit);
        EXPECT_NEAR(h.t, (double)want, 1e-12 * (double)want) << i;
        // From inside, one unit from the surface: t ~ 1 against a radius of 1e6.
        rt_vec3 n = rng.unit();
        rt_vec3 oi = rt_vec_add(c, rt_vec_scale(n, r - 1.0));
        want = sphere_t_ld(oi, n, c, r);
        h = shoot(s.get(), 0, oi, n);
        ASSERT_TRUE(h.hit);
        EXPECT_NEAR(h.t, (double)want, 1e-9) << "t ~ 1 from inside, rounding of 1e6 coordinates allows ~1e-10";
        EXPECT_GT(rt_vec_dot(h.n_geo, n), 0.0);
    }
}

// --- polygons ------------------------------------------------------------

TEST(IntersectPolygon, SquareFrontAndBack)
{
    std::vector<rt_vec3> sq = {rt_vec(0, 0, 0), rt_vec(1, 0, 0), rt_vec(1, 1, 0), rt_vec(0, 1, 0)};
    ScenePtr s = one_polygon(sq);
    Hit h = shoot(s.get(), 0, rt_vec(0.25, 0.5, 2), rt_vec(0, 0, -1));
    ASSERT_TRUE(h.hit);
    EXPECT_DOUBLE_EQ(h.t, 2.0);
    // Counter-clockwise seen from +z: the outward normal is +z, whichever side the ray is on.
    expect_vec_near(h.n_geo, rt_vec(0, 0, 1), 1e-15);
    expect_vec_near(h.n_shade, rt_vec(0, 0, 1), 1e-15);
    h = shoot(s.get(), 0, rt_vec(0.25, 0.5, -3), rt_vec(0, 0, 1));
    ASSERT_TRUE(h.hit);
    EXPECT_DOUBLE_EQ(h.t, 3.0);
    expect_vec_near(h.n_geo, rt_vec(0, 0, 1), 1e-15);
    // Outside the square, and behind the origin.
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(1.5, 0.5, 2), rt_vec(0, 0, -1)).hit);
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(0.5, -1e-9, 2), rt_vec(0, 0, -1)).hit);
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(0.5, 0.5, 2), rt_vec(0, 0, 1)).hit);
    // Oblique.
    rt_vec3 d = rt_vec_normalize(rt_vec(0.3, -0.2, -1));
    h = shoot(s.get(), 0, rt_vec(0.2, 0.7, 1), d);
    ASSERT_TRUE(h.hit);
    EXPECT_NEAR(h.t, 1.0 / -d.z, 1e-15);
    // Clockwise order: normal -z.
    std::vector<rt_vec3> cw(sq.rbegin(), sq.rend());
    ScenePtr s2 = one_polygon(cw);
    h = shoot(s2.get(), 0, rt_vec(0.5, 0.5, 1), rt_vec(0, 0, -1));
    ASSERT_TRUE(h.hit);
    expect_vec_near(h.n_geo, rt_vec(0, 0, -1), 1e-15);
}

TEST(IntersectPolygon, TiltedPolygonNewellNormal)
{
    // A regular hexagon in a tilted plane, counter-clockwise about n.
    rt_vec3 n = rt_vec_normalize(rt_vec(1, 2, 3));
    rt_vec3 u = rt_vec_normalize(rt_vec_cross(n, rt_vec(0, 0, 1)));
    rt_vec3 v = rt_vec_cross(n, u);
    rt_vec3 c = rt_vec(4, -1, 2);
    std::vector<rt_vec3> hex;
    for (int k = 0; k < 6; k++)
        hex.push_back(rt_vec_add(
            c, rt_vec_add(rt_vec_scale(u, std::cos(k * M_PI / 3)), rt_vec_scale(v, std::sin(k * M_PI / 3)))));
    ScenePtr s = one_polygon(hex);
    rt_vec3 o = rt_vec_add(c, rt_vec_scale(n, 5));
    Hit h = shoot(s.get(), 0, o, rt_vec_scale(n, -1));
    ASSERT_TRUE(h.hit);
    EXPECT_NEAR(h.t, 5.0, 1e-13);
    expect_vec_near(h.n_geo, n, 1e-14);
    // Just inside and just outside a vertex direction.
    rt_vec3 near_in = rt_vec_add(c, rt_vec_scale(u, 0.999));
    rt_vec3 near_out = rt_vec_add(c, rt_vec_scale(u, 1.001));
    EXPECT_TRUE(shoot(s.get(), 0, rt_vec_add(near_in, n), rt_vec_scale(n, -1)).hit);
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec_add(near_out, n), rt_vec_scale(n, -1)).hit);
}

TEST(IntersectPolygon, ConcaveStarNotchesMiss)
{
    std::vector<rt_vec3> st = star(0.0);
    ScenePtr s = one_polygon(st);
    rt_vec3 down = rt_vec(0, 0, -1);
    // Centre and arms hit.
    EXPECT_TRUE(shoot(s.get(), 0, rt_vec(0, 0, 1), down).hit);
    for (int k = 0; k < 5; k++) {
        double a = M_PI / 2 + k * 2 * M_PI / 5;
        EXPECT_TRUE(shoot(s.get(), 0, rt_vec(0.8 * std::cos(a), 0.8 * std::sin(a), 1), down).hit) << "arm " << k;
        // The notch between two arms, beyond the inner vertex: outside the star.
        double b = a + M_PI / 5;
        EXPECT_FALSE(shoot(s.get(), 0, rt_vec(0.6 * std::cos(b), 0.6 * std::sin(b), 1), down).hit) << "notch " << k;
        EXPECT_FALSE(shoot(s.get(), 0, rt_vec(0.95 * std::cos(b), 0.95 * std::sin(b), 1), down).hit) << k;
    }
    // Random points against the even-odd oracle, away from the boundary.
    TestRng rng(3);
    int hits = 0, misses = 0;
    for (int i = 0; i < 20000; i++) {
        double x = rng.uniform(-1.1, 1.1), y = rng.uniform(-1.1, 1.1);
        if (edge_distance_xy(st, x, y) < 1e-9) continue;
        bool want = inside_xy(st, x, y);
        Hit h = shoot(s.get(), 0, rt_vec(x, y, 1), down);
        ASSERT_EQ(h.hit, want) << x << " " << y;
        (want ? hits : misses)++;
    }
    EXPECT_GT(hits, 1000);
    EXPECT_GT(misses, 1000);
}

TEST(IntersectPolygon, AsymmetricBowTieLobesHitMiddleMisses)
{
    // Edges (0,0)-(4,2) and (4,0)-(0,1) cross at (4/3, 2/3): lobes of area 2/3 and 8/3.
    std::vector<rt_vec3> bow = {rt_vec(0, 0, 0), rt_vec(4, 2, 0), rt_vec(4, 0, 0), rt_vec(0, 1, 0)};
    ScenePtr s = one_polygon(bow);
    rt_vec3 down = rt_vec(0, 0, -1);
    EXPECT_TRUE(shoot(s.get(), 0, rt_vec(0.3, 0.5, 1), down).hit);   // left lobe
    EXPECT_TRUE(shoot(s.get(), 0, rt_vec(3.5, 1.0, 1), down).hit);   // right lobe
    EXPECT_TRUE(shoot(s.get(), 0, rt_vec(2.0, 0.75, 1), down).hit);  // right lobe, narrow part
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(2.0, 0.3, 1), down).hit);  // below the crossing
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(0.3, 1.5, 1), down).hit);  // above the left lobe
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(1.0, 1.2, 1), down).hit);  // between the lobes, above
    // The Newell normal follows the larger lobe: clockwise in x-y, so -z.
    Hit h = shoot(s.get(), 0, rt_vec(3.5, 1.0, 1), down);
    ASSERT_TRUE(h.hit);
    expect_vec_near(h.n_geo, rt_vec(0, 0, -1), 1e-15);
    TestRng rng(8);
    for (int i = 0; i < 20000; i++) {
        double x = rng.uniform(-0.5, 4.5), y = rng.uniform(-0.5, 2.5);
        if (edge_distance_xy(bow, x, y) < 1e-9) continue;
        ASSERT_EQ(shoot(s.get(), 0, rt_vec(x, y, 1), down).hit, inside_xy(bow, x, y)) << x << " " << y;
    }
}

TEST(IntersectPolygon, PentagramCentreIsOutsideByEvenOdd)
{
    // {5/2}: the points are crossed once (inside), the central pentagon twice (outside by
    // even-odd, though its winding number is 2).
    std::vector<rt_vec3> pg;
    for (int k = 0; k < 5; k++) {
        double a = M_PI / 2 + k * 4 * M_PI / 5;
        pg.push_back(rt_vec(std::cos(a), std::sin(a), 0));
    }
    ScenePtr s = one_polygon(pg);
    rt_vec3 down = rt_vec(0, 0, -1);
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(0, 0, 1), down).hit) << "centre of a pentagram";
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(0.1, 0.1, 1), down).hit);
    for (int k = 0; k < 5; k++) {
        double a = M_PI / 2 + k * 2 * M_PI / 5;
        EXPECT_TRUE(shoot(s.get(), 0, rt_vec(0.7 * std::cos(a), 0.7 * std::sin(a), 1), down).hit) << "point " << k;
    }
    TestRng rng(41);
    for (int i = 0; i < 20000; i++) {
        double x = rng.uniform(-1.1, 1.1), y = rng.uniform(-1.1, 1.1);
        if (edge_distance_xy(pg, x, y) < 1e-9) continue;
        ASSERT_EQ(shoot(s.get(), 0, rt_vec(x, y, 1), down).hit, inside_xy(pg, x, y)) << x << " " << y;
    }
}

TEST(IntersectPolygon, SymmetricBowTieIsHit)
{
    // A self-crossing polygon whose two lobes have equal area: its Newell vector is zero
    // (the signed areas cancel), yet it covers an area of 2 and docs/design.md section 3 says
    // self-crossing polygons work and only zero-area polygons are never hit.
    std::vector<rt_vec3> bow = {rt_vec(0, 0, 0), rt_vec(2, 2, 0), rt_vec(2, 0, 0), rt_vec(0, 2, 0)};
    ScenePtr s = one_polygon(bow);
    rt_vec3 down = rt_vec(0, 0, -1);
    EXPECT_TRUE(shoot(s.get(), 0, rt_vec(0.4, 1.0, 1), down).hit) << "left lobe of a symmetric bow-tie";
    EXPECT_TRUE(shoot(s.get(), 0, rt_vec(1.6, 1.0, 1), down).hit) << "right lobe of a symmetric bow-tie";
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(1.0, 0.3, 1), down).hit);
    rt_box b = rt_scene_object_bounds(s.get(), 0);
    EXPECT_LE(b.lo.x, b.hi.x) << "a symmetric bow-tie has area, so it has bounds (and grid cells)";
}

TEST(IntersectPolygon, ZeroAreaPolygonsAreNeverHit)
{
    TestRng rng(19);
    std::vector<std::vector<rt_vec3>> degenerate = {
        {rt_vec(0, 0, 0), rt_vec(1, 0, 0), rt_vec(2, 0, 0)},                         // collinear
        {rt_vec(0, 0, 0), rt_vec(1, 1, 1), rt_vec(2, 2, 2), rt_vec(0.5, 0.5, 0.5)},  // collinear, 4
        {rt_vec(1, 1, 1), rt_vec(1, 1, 1), rt_vec(1, 1, 1)},                         // one point
        {rt_vec(0, 0, 0), rt_vec(1, 0, 0), rt_vec(0, 0, 0), rt_vec(1, 0, 0)},        // back and forth
    };
    for (size_t k = 0; k < degenerate.size(); k++) {
        ScenePtr s = one_polygon(degenerate[k]);
        rt_box b = rt_scene_object_bounds(s.get(), 0);
        EXPECT_FALSE(b.lo.x <= b.hi.x && b.lo.y <= b.hi.y && b.lo.z <= b.hi.z) << "polygon " << k;
        for (int i = 0; i < 2000; i++) {
            // Rays through points of the segment from every direction, including along it.
            rt_vec3 p = rt_vec_add(degenerate[k][0],
                                   rt_vec_scale(rt_vec_sub(degenerate[k][1], degenerate[k][0]), rng.uniform(0, 1)));
            rt_vec3 d = rng.unit();
            if (i == 0) d = rt_vec_normalize(rt_vec_sub(degenerate[k][1], degenerate[k][0]));
            if (rt_vec_is_zero(d)) d = rt_vec(0, 0, 1);
            EXPECT_FALSE(shoot(s.get(), 0, rt_vec_sub(p, rt_vec_scale(d, 3)), d).hit)
                << "polygon " << k << " ray " << i;
        }
    }
}

TEST(IntersectPolygon, EdgeOnRaysNeverHit)
{
    std::vector<rt_vec3> sq = {rt_vec(0, 0, 0), rt_vec(1, 0, 0), rt_vec(1, 1, 0), rt_vec(0, 1, 0)};
    ScenePtr s = one_polygon(sq);
    // In the plane, across the inside.
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(-1, 0.5, 0), rt_vec(1, 0, 0)).hit);
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(-1, -1, 0), rt_vec_normalize(rt_vec(1, 1, 0))).hit);
    // Starting inside the polygon, moving in its plane.
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(0.5, 0.5, 0), rt_vec(0, 1, 0)).hit);
    // Parallel just above and below.
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(-1, 0.5, 1e-12), rt_vec(1, 0, 0)).hit);
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(-1, 0.5, -1e-300), rt_vec(1, 0, 0)).hit);
    // Star and tilted plane too.
    ScenePtr s2 = one_polygon(star(2.0));
    EXPECT_FALSE(shoot(s2.get(), 0, rt_vec(-3, 0.01, 2), rt_vec(1, 0, 0)).hit);
    EXPECT_FALSE(shoot(s2.get(), 0, rt_vec(0, -3, 2), rt_vec(0, 1, 0)).hit);
}

// --- pp triangles ---------------------------------------------------------

TEST(IntersectTriangle, BarycentricsAndInterpolatedNormal)
{
    ScenePtr s(rt_scene_new());
    rt_vec3 v[3] = {rt_vec(0, 0, 0), rt_vec(2, 0, 0), rt_vec(0, 2, 0)};
    rt_vec3 n[3] = {rt_vec(0, 0, 2), rt_vec(1, 0, 1), rt_vec(0, -3, 3)};  // not unit: normalised by the scene
    ASSERT_EQ(rt_scene_add_patch(s.get(), v, n, 3), RT_OK);
    ASSERT_EQ(rt_scene_object_count(s.get()), 1u);
    ASSERT_EQ(rt_scene_object_kind(s.get(), 0), RT_OBJ_TRIANGLE);
    rt_vec3 un[3] = {rt_vec_normalize(n[0]), rt_vec_normalize(n[1]), rt_vec_normalize(n[2])};
    TestRng rng(29);
    for (int i = 0; i < 1000; i++) {
        double a = rng.uniform(0.001, 0.998), b = rng.uniform(0.001, 0.998 - a);
        double w = 1 - a - b;
        rt_vec3 p = rt_vec_add(rt_vec_scale(v[0], w), rt_vec_add(rt_vec_scale(v[1], a), rt_vec_scale(v[2], b)));
        bool from_above = i % 2 == 0;
        rt_vec3 o = rt_vec_add(p, rt_vec(0.1, -0.2, from_above ? 1 : -1));
        rt_vec3 d = rt_vec_normalize(rt_vec_sub(p, o));
        Hit h = shoot(s.get(), 0, o, d);
        ASSERT_TRUE(h.hit) << i;
        EXPECT_NEAR(h.t, rt_vec_length(rt_vec_sub(p, o)), 1e-13);
        EXPECT_NEAR(h.h.u, a, 1e-12);
        EXPECT_NEAR(h.h.v, b, 1e-12);
        // Geometric normal from the vertex order (counter-clockwise about +z), either side.
        expect_vec_near(h.n_geo, rt_vec(0, 0, 1), 1e-15);
        rt_vec3 want = rt_vec_normalize(
            rt_vec_add(rt_vec_scale(un[0], w), rt_vec_add(rt_vec_scale(un[1], a), rt_vec_scale(un[2], b))));
        expect_vec_near(h.n_shade, want, 1e-12);
        expect_unit(h.n_shade);
    }
    // At the vertices the shading normal is the vertex normal.
    for (int k = 0; k < 3; k++) {
        rt_vec3 c = rt_vec(2.0 / 3, 2.0 / 3, 0);
        rt_vec3 p = rt_vec_add(v[k], rt_vec_scale(rt_vec_sub(c, v[k]), 1e-9));
        Hit h = shoot(s.get(), 0, rt_vec_add(p, rt_vec(0, 0, 1)), rt_vec(0, 0, -1));
        ASSERT_TRUE(h.hit);
        expect_vec_near(h.n_shade, un[k], 1e-8);
    }
    // Outside the triangle.
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(1.1, 1.1, 1), rt_vec(0, 0, -1)).hit);
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(-0.01, 0.5, 1), rt_vec(0, 0, -1)).hit);
    // Edge-on.
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(-1, 0.5, 0), rt_vec(1, 0, 0)).hit);
}

TEST(IntersectTriangle, VertexOrderGivesGeometricNormal)
{
    ScenePtr s(rt_scene_new());
    rt_vec3 v[3] = {rt_vec(0, 0, 0), rt_vec(0, 2, 0), rt_vec(2, 0, 0)};  // clockwise about +z
    rt_vec3 n[3] = {rt_vec(0, 0, 1), rt_vec(0, 0, 1), rt_vec(0, 0, 1)};
    ASSERT_EQ(rt_scene_add_patch(s.get(), v, n, 3), RT_OK);
    Hit h = shoot(s.get(), 0, rt_vec(0.5, 0.5, 1), rt_vec(0, 0, -1));
    ASSERT_TRUE(h.hit);
    expect_vec_near(h.n_geo, rt_vec(0, 0, -1), 1e-15);
    // The vertex normals are used as given for shading (the step flips them toward the ray).
    expect_vec_near(h.n_shade, rt_vec(0, 0, 1), 1e-15);
}

TEST(IntersectTriangle, PatchIsAFanAndZeroAreaTrianglesNeverHit)
{
    ScenePtr s(rt_scene_new());
    rt_vec3 v[5] = {rt_vec(0, 0, 0), rt_vec(1, 0, 0), rt_vec(1, 1, 0), rt_vec(0.5, 1.5, 0), rt_vec(0, 1, 0)};
    rt_vec3 n[5] = {rt_vec(0, 0, 1), rt_vec(0, 0, 1), rt_vec(0, 0, 1), rt_vec(0, 0, 1), rt_vec(0, 0, 1)};
    ASSERT_EQ(rt_scene_add_patch(s.get(), v, n, 5), RT_OK);
    ASSERT_EQ(rt_scene_object_count(s.get()), 3u);
    // Triangle (0,1,2) holds (0.8, 0.3); (0,2,3) holds (0.6, 1.1); (0,3,4) holds (0.1, 0.9).
    struct {
        double x, y;
        int obj;
    } cases[] = {{0.8, 0.3, 0}, {0.6, 1.1, 1}, {0.1, 0.9, 2}};
    for (auto &c : cases)
        for (uint32_t o = 0; o < 3; o++)
            EXPECT_EQ(shoot(s.get(), o, rt_vec(c.x, c.y, 1), rt_vec(0, 0, -1)).hit, int(o) == c.obj)
                << c.x << "," << c.y << " object " << o;
    // A degenerate triangle.
    ScenePtr z(rt_scene_new());
    rt_vec3 zv[3] = {rt_vec(0, 0, 0), rt_vec(1, 1, 0), rt_vec(2, 2, 0)};
    ASSERT_EQ(rt_scene_add_patch(z.get(), zv, n, 3), RT_OK);
    EXPECT_FALSE(shoot(z.get(), 0, rt_vec(1, 1, 1), rt_vec(0, 0, -1)).hit);
    EXPECT_FALSE(shoot(z.get(), 0, rt_vec(-1, -1, 0), rt_vec_normalize(rt_vec(1, 1, 0))).hit);
}

// --- cones and cylinders -----------------------------------------------------

TEST(IntersectCone, CylinderOutsideInsideAndBeyondTheEnds)
{
    ScenePtr s = one_cone(rt_vec(0, 0, 0), 1.0, rt_vec(0, 0, 2), 1.0);
    // From outside.
    Hit h = shoot(s.get(), 0, rt_vec(-5, 0, 1), rt_vec(1, 0, 0));
    ASSERT_TRUE(h.hit);
    EXPECT_NEAR(h.t, 4.0, 1e-14);
    expect_vec_near(h.n_geo, rt_vec(-1, 0, 0), 1e-14);
    // From inside: the far wall, outward normal.
    h = shoot(s.get(), 0, rt_vec(0, 0, 1), rt_vec(1, 0, 0));
    ASSERT_TRUE(h.hit);
    EXPECT_NEAR(h.t, 1.0, 1e-14);
    expect_vec_near(h.n_geo, rt_vec(1, 0, 0), 1e-14);
    EXPECT_GT(rt_vec_dot(h.n_geo, rt_vec(1, 0, 0)), 0.0);
    // Oblique: in through the open top, onto the inner wall at (1, 0, 1).
    rt_vec3 d = rt_vec_normalize(rt_vec(1, 0, -2));
    h = shoot(s.get(), 0, rt_vec(0, 0, 3), d);
    ASSERT_TRUE(h.hit);
    EXPECT_NEAR(h.t, std::sqrt(5.0), 1e-14);
    expect_vec_near(h.point, rt_vec(1, 0, 1), 1e-14);
    expect_vec_near(h.n_geo, rt_vec(1, 0, 0), 1e-14);
    // Beyond the ends: no caps, so these miss.
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(-5, 0, 2.5), rt_vec(1, 0, 0)).hit);
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(-5, 0, -0.01), rt_vec(1, 0, 0)).hit);
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(0, 0, -1), rt_vec(0, 0, 1)).hit) << "up the axis through both open ends";
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(0.5, 0.2, 1), rt_vec(0, 0, 1)).hit) << "inside, out through the top";
    // Hits the side only over its height: a ray through the wall at z = 2.5 misses.
    d = rt_vec_normalize(rt_vec(1, 0, 0.5));
    h = shoot(s.get(), 0, rt_vec(-3, 0, 0), d);
    // Enters at x = -1 (z = 1), leaves at x = 1 (z = 2): the near wall is hit.
    ASSERT_TRUE(h.hit);
    expect_vec_near(h.point, rt_vec(-1, 0, 1), 1e-13);
    // Along a wall line, just outside: parallel to the axis.
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(1 + 1e-9, 0, -1), rt_vec(0, 0, 1)).hit);
}

TEST(IntersectCone, TrueConeNormalAndHits)
{
    // Base radius 1 at z = 0, apex at z = 2: radius 1 - z/2.
    ScenePtr s = one_cone(rt_vec(0, 0, 0), 1.0, rt_vec(0, 0, 2), 0.0);
    Hit h = shoot(s.get(), 0, rt_vec(-5, 0, 1), rt_vec(1, 0, 0));
    ASSERT_TRUE(h.hit);
    EXPECT_NEAR(h.t, 4.5, 1e-14);
    expect_vec_near(h.n_geo, rt_vec_normalize(rt_vec(-1, 0, 0.5)), 1e-14);
    // From inside at the base centre, toward the wall.
    h = shoot(s.get(), 0, rt_vec(0, 0, 0.5), rt_vec(0, 1, 0));
    ASSERT_TRUE(h.hit);
    EXPECT_NEAR(h.t, 0.75, 1e-14);
    expect_vec_near(h.n_geo, rt_vec_normalize(rt_vec(0, 1, 0.5)), 1e-14);
    EXPECT_GT(rt_vec_dot(h.n_geo, rt_vec(0, 1, 0)), 0.0);
    // Above the apex and below the base: miss (also the mirror nappe above the apex).
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(-5, 0, 3), rt_vec(1, 0, 0)).hit);
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(-5, 0, 2.5), rt_vec(1, 0, 0)).hit);
    EXPECT_FALSE(shoot(s.get(), 0, rt_vec(-5, 0, -0.5), rt_vec(1, 0, 0)).hit);
    // Up through the open base: the inside of the wall is hit.
    {
        rt_vec3 d = rt_vec_normalize(rt_vec(0.2, 0, 1));
        h = shoot(s.get(), 0, rt_vec(0, 0, -1), d);
        ASSERT_TRUE(h.hit);
        // Point on the surface: radius 1 - z/2.
        double r = std::hypot(h.point.x, h.point.y);
        EXPECT_NEAR(r, 1 - h.point.z / 2, 1e-13);
        EXPECT_GT(rt_vec_dot(h.n_geo, d), 0.0) << "seen from inside";
    }
}

TEST(IntersectCone, RandomOrientedConesHitPointsLieOnTheSurface)
{
    TestRng rng(37);
    int hits = 0;
    for (int i = 0; i < 3000; i++) {
        rt_vec3 base = rt_vec(rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5));
        rt_vec3 axis = rng.unit();
        double len = rng.uniform(0.5, 4);
        rt_vec3 apex = rt_vec_add(base, rt_vec_scale(axis, len));
        double rb = rng.uniform(0, 2), ra = i % 3 == 0 ? 0.0 : rng.uniform(0.1, 2);
        if (rb == 0 && ra == 0) continue;
        ScenePtr s = one_cone(base, rb, apex, ra);
        // A random point P on the surface; a ray from outside aimed at it must hit at or before P.
        double hgt = rng.uniform(0.01, 0.99) * len;
        double rad = rb + (ra - rb) * hgt / len;
        rt_vec3 side = rt_vec_normalize(rt_vec_cross(axis, rng.unit()));
        rt_vec3 P = rt_vec_add(rt_vec_add(base, rt_vec_scale(axis, hgt)), rt_vec_scale(side, rad));
        rt_vec3 o = rt_vec_add(P, rt_vec_scale(rng.unit(), rng.uniform(3, 10)));
        rt_vec3 d = rt_vec_normalize(rt_vec_sub(P, o));
        double tp = rt_vec_length(rt_vec_sub(P, o));
        Hit h = shoot(s.get(), 0, o, d);
        ASSERT_TRUE(h.hit) << i;
        hits++;
        EXPECT_LE(h.t, tp * (1 + 1e-10)) << i;
        // The hit point is on the surface within the height.
        rt_vec3 q = rt_vec_sub(h.point, base);
        double hq = rt_vec_dot(q, axis);
        double rq = rt_vec_length(rt_vec_sub(q, rt_vec_scale(axis, hq)));
        EXPECT_GE(hq, -1e-9) << i;
        EXPECT_LE(hq, len + 1e-9) << i;
        EXPECT_NEAR(rq, rb + (ra - rb) * hq / len, 1e-8) << i;
        // The normal is unit, perpendicular to the surface line through the point, outward.
        expect_unit(h.n_geo);
        rt_vec3 radial = rt_vec_normalize(rt_vec_sub(q, rt_vec_scale(axis, hq)));
        rt_vec3 line =
            rt_vec_sub(rt_vec_add(rt_vec_scale(axis, len), rt_vec_scale(radial, ra)), rt_vec_scale(radial, rb));
        EXPECT_NEAR(rt_vec_dot(h.n_geo, rt_vec_normalize(line)), 0.0, 1e-9) << i;
        EXPECT_GT(rt_vec_dot(h.n_geo, radial), 0.0) << i;
    }
    EXPECT_GT(hits, 2000);
}
