// shading_test.cpp - the packet step (rt_step) against docs/design.md section 3, the frame
// buffer's fixed-point arithmetic, and the reference renderer.
//
// Shading* and Step*: one-object (or two-object) scenes where every number can be worked
// out by hand: ambient, the shadow packet's value and t_light, reflection and refraction
// directions and weights, the depth and weight cut-offs, blocked and unblocked shadows,
// a light inside the grid, escape to the background, forwarding between two owners and
// the operation counts. Every case runs with the brute-force oracle and with the grid.
// Framebuffer*: order independence, rounding and clamping. Render*: determinism, grid
// against brute force on a random scene at several grid sizes, packet conservation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "rt_dda.h"
#include "rt_framebuffer.h"
#include "rt_grid.h"
#include "rt_packet.h"
#include "rt_render.h"
#include "rt_scene.h"
#include "rt_step.h"
#include "test_support.h"

using namespace torusrt_test;

namespace {

rt_material mat(rt_vec3 c, double kd, double ks, double shine, double t, double ior)
{
    rt_material m;
    m.color = c;
    m.kd = kd;
    m.ks = ks;
    m.shine = shine;
    m.t = t;
    m.ior = ior;
    return m;
}

// A scene under construction: camera set so rt_scene_finish succeeds.
ScenePtr new_scene()
{
    ScenePtr s(rt_scene_new());
    EXPECT_EQ(rt_scene_set_view(s.get(), rt_vec(0, 0, 10), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45, 8, 8), RT_OK);
    return s;
}

void finish(rt_scene *s)
{
    char msg[RT_MSG_LEN] = "";
    ASSERT_EQ(rt_scene_finish(s, msg, sizeof msg), RT_OK) << msg;
}

// The two ways every shading case runs.
struct Mode {
    const char *name;
    bool brute;
    int cells;
};
const Mode kModes[] = {{"brute force", true, 24}, {"grid 1", false, 1}, {"grid 24", false, 24}, {"grid 7", false, 7}};

rt_step_params params_for(const Mode &m)
{
    rt_step_params p = rt_step_params_default();
    p.brute_force = m.brute ? 1 : 0;
    return p;
}

// A packet at its start; in grid mode its walk starts where the ray meets the space.
rt_packet make_packet(const rt_grid *g, rt_packet_kind kind, rt_vec3 o, rt_vec3 d, rt_vec3 w, int depth = 0,
                      double t_light = INFINITY, bool *enters = nullptr)
{
    rt_packet p;
    std::memset(&p, 0, sizeof p);
    p.kind = uint8_t(kind);
    p.origin = o;
    p.dir = d;
    p.weight = w;
    p.depth = uint16_t(depth);
    p.t_light = t_light;
    p.x = 3;
    p.y = 5;
    int e = rt_dda_start(g, o, d, 0.0, &p.dda);
    if (enters) *enters = e != 0;
    return p;
}

struct StepOut {
    rt_status status;
    rt_fate fate;
    uint32_t next_cell;
    rt_op_counts ops;
    std::vector<rt_contribution> contrib;
    std::vector<rt_packet> created;
    rt_packet after;
};

StepOut run_step(const rt_scene *s, const rt_grid *g, const rt_step_params &params, rt_packet p,
                 const int32_t *owner = nullptr, int32_t me = 0)
{
    rt_step_result r;
    EXPECT_EQ(rt_step_result_init(&r, s), RT_OK);
    StepOut out;
    out.status = rt_step(s, g, owner, me, &params, &p, &r);
    out.fate = r.fate;
    out.next_cell = r.next_cell;
    out.ops = r.ops;
    out.contrib.assign(r.contrib, r.contrib + r.contrib_count);
    out.created.assign(r.created, r.created + r.created_count);
    out.after = p;
    rt_step_result_release(&r);
    return out;
}

// Steps a packet until it is absorbed or leaves (following it across forwards, which
// cannot happen without owners). Returns the sum of its contributions.
rt_vec3 run_to_end(const rt_scene *s, const rt_grid *g, const rt_step_params &params, rt_packet p,
                   std::vector<rt_packet> *created = nullptr, rt_fate *fate = nullptr)
{
    StepOut o = run_step(s, g, params, p);
    EXPECT_EQ(o.status, RT_OK);
    rt_vec3 sum = rt_vec(0, 0, 0);
    for (auto &c : o.contrib) sum = rt_vec_add(sum, c.rgb);
    if (created) *created = o.created;
    if (fate) *fate = o.fate;
    return sum;
}

::testing::AssertionResult vec_near(rt_vec3 a, rt_vec3 b, double rel, double abs_tol = 0)
{
    double scale = std::max(rt_vec_max_abs(a), rt_vec_max_abs(b));
    double tol = rel * scale + abs_tol;
    if (std::fabs(a.x - b.x) <= tol && std::fabs(a.y - b.y) <= tol && std::fabs(a.z - b.z) <= tol)
        return ::testing::AssertionSuccess();
    std::ostringstream m;
    m.precision(17);
    m << "(" << a.x << ", " << a.y << ", " << a.z << ") vs (" << b.x << ", " << b.y << ", " << b.z << "), tolerance "
      << tol;
    return ::testing::AssertionFailure() << m.str();
}

const rt_packet *find_kind(const std::vector<rt_packet> &v, rt_packet_kind k, int nth = 0)
{
    for (auto &p : v)
        if (p.kind == k && nth-- == 0) return &p;
    return nullptr;
}

size_t count_kind(const std::vector<rt_packet> &v, rt_packet_kind k)
{
    return size_t(std::count_if(v.begin(), v.end(), [&](const rt_packet &p) { return p.kind == k; }));
}

// Every created packet must carry something and, in grid mode, start in the cell its
// origin's ray enters.
void check_created(const rt_grid *g, const Mode &m, const std::vector<rt_packet> &created)
{
    for (auto &p : created) {
        EXPECT_FALSE(rt_vec_is_zero(p.weight)) << "a packet with zero weight was made";
        EXPECT_NEAR(rt_vec_length(p.dir), 1.0, 1e-12);
        if (m.brute) continue;
        rt_dda d;
        ASSERT_TRUE(rt_dda_start(g, p.origin, p.dir, 0.0, &d)) << "a created packet that never enters the space";
        EXPECT_EQ(std::memcmp(d.cell, p.dda.cell, sizeof d.cell), 0) << "created packet's start cell";
        EXPECT_EQ(d.t_enter, p.dda.t_enter);
    }
}

}  // namespace

// --- shading -----------------------------------------------------------------

TEST(ShadingAmbient, WeightTimesColourTimesAmbient)
{
    ScenePtr s = new_scene();
    ASSERT_EQ(rt_scene_set_ambient(s.get(), rt_vec(0.2, 0.3, 0.5)), RT_OK);
    rt_material m = mat(rt_vec(0.8, 0.6, 0.4), 0.7, 0, 0, 0, 1);
    ASSERT_EQ(rt_scene_set_material(s.get(), &m), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(0, 0, 0), 1.0), RT_OK);
    finish(s.get());
    for (const Mode &md : kModes) {
        SCOPED_TRACE(md.name);
        GridPtr g = make_grid(s.get(), md.cells, md.cells, md.cells);
        rt_vec3 w = rt_vec(1, 0.5, 0.25);
        rt_packet p = make_packet(g.get(), RT_PACKET_RAY, rt_vec(0.1, 0.2, 5), rt_vec(0, 0, -1), w);
        StepOut o = run_step(s.get(), g.get(), params_for(md), p);
        ASSERT_EQ(o.status, RT_OK);
        EXPECT_EQ(o.fate, RT_FATE_ABSORBED);
        ASSERT_EQ(o.contrib.size(), 1u);
        EXPECT_TRUE(vec_near(o.contrib[0].rgb, rt_vec(1 * 0.8 * 0.2, 0.5 * 0.6 * 0.3, 0.25 * 0.4 * 0.5), 1e-15));
        EXPECT_EQ(o.contrib[0].x, 3u);
        EXPECT_EQ(o.contrib[0].y, 5u);
        EXPECT_TRUE(o.created.empty()) << "no lights, no Ks, no T: nothing to make";
        EXPECT_EQ(o.ops.shadings, 1u);
        EXPECT_EQ(o.ops.fb_writes, 1u);
        EXPECT_EQ(o.ops.packets_created, 0u);
    }
}

TEST(ShadingAmbient, ZeroAmbientWritesNothing)
{
    ScenePtr s = new_scene();
    rt_material m = mat(rt_vec(0.8, 0.6, 0.4), 0.7, 0, 0, 0, 1);
    ASSERT_EQ(rt_scene_set_material(s.get(), &m), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(0, 0, 0), 1.0), RT_OK);
    finish(s.get());
    for (const Mode &md : kModes) {
        SCOPED_TRACE(md.name);
        GridPtr g = make_grid(s.get(), md.cells, md.cells, md.cells);
        StepOut o = run_step(s.get(), g.get(), params_for(md),
                             make_packet(g.get(), RT_PACKET_RAY, rt_vec(0, 0, 5), rt_vec(0, 0, -1), rt_vec(1, 1, 1)));
        EXPECT_EQ(o.fate, RT_FATE_ABSORBED);
        EXPECT_TRUE(o.contrib.empty());
        EXPECT_EQ(o.ops.fb_writes, 0u);
        EXPECT_EQ(o.ops.shadings, 1u);
    }
}

TEST(ShadingShadow, ValueDirectionAndTLight)
{
    // Sphere at the origin, radius 1; the ray comes down the z axis and hits (0, 0, 1),
    // N = (0, 0, 1), D = (0, 0, -1), R = (0, 0, 1). Light at (3, 4, 5).
    const rt_vec3 C = rt_vec(0.8, 0.6, 0.4), I = rt_vec(0.9, 0.8, 0.7), Lpos = rt_vec(3, 4, 5);
    const double kd = 0.7, ks = 0.3, shine = 5;
    ScenePtr s = new_scene();
    rt_material m = mat(C, kd, ks, shine, 0, 1);
    ASSERT_EQ(rt_scene_set_material(s.get(), &m), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(0, 0, 0), 1.0), RT_OK);
    ASSERT_EQ(rt_scene_add_light(s.get(), Lpos, &I), RT_OK);
    finish(s.get());
    const rt_vec3 P = rt_vec(0, 0, 1);
    const rt_vec3 L = rt_vec_normalize(rt_vec_sub(Lpos, P));
    const double c = L.z;                           // N.L
    const double spec = ks * std::pow(L.z, shine);  // R.L = L.z
    const rt_vec3 w = rt_vec(1, 0.5, 0.25);
    const rt_vec3 want =
        rt_vec(w.x * I.x * (kd * c * C.x + spec), w.y * I.y * (kd * c * C.y + spec), w.z * I.z * (kd * c * C.z + spec));
    for (const Mode &md : kModes) {
        SCOPED_TRACE(md.name);
        GridPtr g = make_grid(s.get(), md.cells, md.cells, md.cells);
        StepOut o = run_step(s.get(), g.get(), params_for(md),
                             make_packet(g.get(), RT_PACKET_RAY, rt_vec(0, 0, 5), rt_vec(0, 0, -1), w, 2));
        ASSERT_EQ(o.status, RT_OK);
        EXPECT_EQ(o.fate, RT_FATE_ABSORBED);
        check_created(g.get(), md, o.created);
        ASSERT_EQ(count_kind(o.created, RT_PACKET_SHADOW), 1u);
        const rt_packet *sh = find_kind(o.created, RT_PACKET_SHADOW);
        EXPECT_TRUE(vec_near(sh->weight, want, 1e-13));
        EXPECT_EQ(sh->depth, 2) << "a shadow packet keeps its ray's depth";
        EXPECT_EQ(sh->x, 3u);
        EXPECT_EQ(sh->y, 5u);
        // Starts just off the surface, outside, and points at the light; t_light reaches it.
        EXPECT_TRUE(vec_near(sh->origin, P, 0, 1e-8));
        EXPECT_GT(sh->origin.z, 1.0) << "the shadow ray starts outside the surface";
        EXPECT_TRUE(vec_near(sh->dir, rt_vec_normalize(rt_vec_sub(Lpos, sh->origin)), 1e-14));
        EXPECT_NEAR(sh->t_light, rt_vec_length(rt_vec_sub(Lpos, sh->origin)), 1e-13);
        EXPECT_TRUE(vec_near(rt_vec_add(sh->origin, rt_vec_scale(sh->dir, sh->t_light)), Lpos, 1e-14));
        // The reflection: along R with weight w * Ks, one level deeper.
        ASSERT_EQ(count_kind(o.created, RT_PACKET_RAY), 1u);
        const rt_packet *rf = find_kind(o.created, RT_PACKET_RAY);
        EXPECT_TRUE(vec_near(rf->dir, rt_vec(0, 0, 1), 1e-15));
        EXPECT_TRUE(vec_near(rf->weight, rt_vec_scale(w, ks), 1e-15));
        EXPECT_EQ(rf->depth, 3);
        EXPECT_TRUE(std::isinf(rf->t_light));
        EXPECT_GT(rf->origin.z, 1.0);
        EXPECT_EQ(o.ops.reflection_vectors, 1u);
        EXPECT_EQ(o.ops.refraction_vectors, 0u);
        EXPECT_EQ(o.ops.packets_created, 2u);
        // The shadow packet reaches its light (outside the space): it adds its value.
        rt_fate f;
        rt_vec3 got = run_to_end(s.get(), g.get(), params_for(md), *sh, nullptr, &f);
        EXPECT_TRUE(vec_near(got, want, 1e-15));
        EXPECT_NE(f, RT_FATE_FORWARDED);
    }
}

TEST(ShadingShadow, OnlyLitSidesAndNoHighlightWithoutShine)
{
    // Two lights: one above the hit point, one below the surface's tangent plane.
    const rt_vec3 C = rt_vec(0.5, 0.5, 0.5);
    ScenePtr s = new_scene();
    rt_material m = mat(C, 1.0, 0.5, 0.0, 0, 1);  // Ks > 0 but Shine 0: no highlight
    ASSERT_EQ(rt_scene_set_material(s.get(), &m), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(0, 0, 0), 1.0), RT_OK);
    rt_vec3 white = rt_vec(1, 1, 1);
    ASSERT_EQ(rt_scene_add_light(s.get(), rt_vec(0, 0, 4), &white), RT_OK);
    ASSERT_EQ(rt_scene_add_light(s.get(), rt_vec(0, 0, -4), &white), RT_OK);
    ASSERT_EQ(rt_scene_add_light(s.get(), rt_vec(5, 0, 1), &white),
              RT_OK);  // exactly in the tangent plane: c = 0
    finish(s.get());
    for (const Mode &md : kModes) {
        SCOPED_TRACE(md.name);
        GridPtr g = make_grid(s.get(), md.cells, md.cells, md.cells);
        StepOut o = run_step(s.get(), g.get(), params_for(md),
                             make_packet(g.get(), RT_PACKET_RAY, rt_vec(0, 0, 5), rt_vec(0, 0, -1), rt_vec(1, 1, 1)));
        ASSERT_EQ(count_kind(o.created, RT_PACKET_SHADOW), 1u) << "only the light with N.L > 0 gets a shadow packet";
        const rt_packet *sh = find_kind(o.created, RT_PACKET_SHADOW);
        EXPECT_TRUE(vec_near(sh->weight, C, 1e-15)) << "Kd * 1 * C, no highlight term";
        EXPECT_GT(sh->dir.z, 0.99);
    }
}

TEST(ShadingShadow, PolygonsAndPatchesAreLitFromTheSideTheRayIsOn)
{
    // A square (vertex-order normal +z) and a `pp` triangle (vertex normals tilted, +z side),
    // seen from below with a light below and another above: only the light on the ray's
    // side makes a shadow packet, with c = Nf.L for the flipped (shading) normal.
    rt_vec3 white = rt_vec(1, 1, 1);
    for (bool patch : {false, true}) {
        SCOPED_TRACE(patch ? "pp triangle" : "polygon");
        ScenePtr s = new_scene();
        rt_material m = mat(rt_vec(1, 1, 1), 1, 0, 0, 0, 1);
        ASSERT_EQ(rt_scene_set_material(s.get(), &m), RT_OK);
        rt_vec3 nshade = rt_vec(0, 0, 1);
        if (patch) {
            rt_vec3 v[3] = {rt_vec(-2, -2, 0), rt_vec(2, -2, 0), rt_vec(0, 2, 0)};
            rt_vec3 n[3] = {rt_vec(0.2, 0, 1), rt_vec(0.2, 0, 1), rt_vec(0.2, 0, 1)};
            ASSERT_EQ(rt_scene_add_patch(s.get(), v, n, 3), RT_OK);
            nshade = rt_vec_normalize(n[0]);
        } else {
            rt_vec3 v[4] = {rt_vec(-2, -2, 0), rt_vec(2, -2, 0), rt_vec(2, 2, 0), rt_vec(-2, 2, 0)};
            ASSERT_EQ(rt_scene_add_polygon(s.get(), v, 4), RT_OK);
        }
        const rt_vec3 below = rt_vec(1, 0, -4);
        ASSERT_EQ(rt_scene_add_light(s.get(), below, &white), RT_OK);
        ASSERT_EQ(rt_scene_add_light(s.get(), rt_vec(0, 0, 4), &white), RT_OK);
        finish(s.get());
        for (const Mode &md : kModes) {
            SCOPED_TRACE(md.name);
            GridPtr g = make_grid(s.get(), md.cells, md.cells, md.cells);
            StepOut o =
                run_step(s.get(), g.get(), params_for(md),
                         make_packet(g.get(), RT_PACKET_RAY, rt_vec(0, 0, -5), rt_vec(0, 0, 1), rt_vec(1, 1, 1)));
            ASSERT_EQ(o.fate, RT_FATE_ABSORBED);
            ASSERT_EQ(count_kind(o.created, RT_PACKET_SHADOW), 1u);
            const rt_packet *sh = find_kind(o.created, RT_PACKET_SHADOW);
            EXPECT_LT(sh->dir.z, 0.0) << "toward the light below";
            EXPECT_LT(sh->origin.z, 0.0) << "starts on the ray's side of the surface";
            rt_vec3 L = rt_vec_normalize(below);  // from the hit point (0, 0, 0)
            double c = rt_vec_dot(rt_vec_scale(nshade, -1), L);
            EXPECT_TRUE(vec_near(sh->weight, rt_vec(c, c, c), 1e-12));
        }
    }
}

TEST(ShadingShadow, ZeroValueMakesNoPacket)
{
    // A red surface under a cyan light: the value is zero in every channel.
    ScenePtr s = new_scene();
    rt_material m = mat(rt_vec(1, 0, 0), 1.0, 0, 0, 0, 1);
    ASSERT_EQ(rt_scene_set_material(s.get(), &m), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(0, 0, 0), 1.0), RT_OK);
    rt_vec3 cyan = rt_vec(0, 1, 1), black = rt_vec(0, 0, 0);
    ASSERT_EQ(rt_scene_add_light(s.get(), rt_vec(0, 0, 4), &cyan), RT_OK);
    ASSERT_EQ(rt_scene_add_light(s.get(), rt_vec(1, 0, 4), &black), RT_OK);
    finish(s.get());
    for (const Mode &md : kModes) {
        SCOPED_TRACE(md.name);
        GridPtr g = make_grid(s.get(), md.cells, md.cells, md.cells);
        StepOut o = run_step(s.get(), g.get(), params_for(md),
                             make_packet(g.get(), RT_PACKET_RAY, rt_vec(0, 0, 5), rt_vec(0, 0, -1), rt_vec(1, 1, 1)));
        EXPECT_EQ(o.fate, RT_FATE_ABSORBED);
        EXPECT_TRUE(o.created.empty());
        EXPECT_TRUE(o.contrib.empty());
        EXPECT_EQ(o.ops.packets_created, 0u);
    }
}

TEST(ShadingShadow, TinyValueIsStillSent)
{
    // min_weight limits ray packets only: a faint but non-zero shadow packet is made.
    ScenePtr s = new_scene();
    rt_material m = mat(rt_vec(1, 1, 1), 1.0, 0, 0, 0, 1);
    ASSERT_EQ(rt_scene_set_material(s.get(), &m), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(0, 0, 0), 1.0), RT_OK);
    rt_vec3 faint = rt_vec(1e-6, 1e-6, 1e-6);
    ASSERT_EQ(rt_scene_add_light(s.get(), rt_vec(0, 0, 4), &faint), RT_OK);
    finish(s.get());
    for (const Mode &md : kModes) {
        SCOPED_TRACE(md.name);
        GridPtr g = make_grid(s.get(), md.cells, md.cells, md.cells);
        rt_step_params prm = params_for(md);
        StepOut o = run_step(
            s.get(), g.get(), prm,
            make_packet(g.get(), RT_PACKET_RAY, rt_vec(0, 0, 5), rt_vec(0, 0, -1), rt_vec(1, 1, 1), prm.max_depth));
        ASSERT_EQ(count_kind(o.created, RT_PACKET_SHADOW), 1u);
        EXPECT_TRUE(vec_near(find_kind(o.created, RT_PACKET_SHADOW)->weight, faint, 1e-12));
    }
}

TEST(ShadingShadow, BlockedByAnObjectButNotByOneBeyondTheLight)
{
    // Lit sphere at the origin, light at (0, 0, 6). A blocker between them kills the shadow
    // packet; a sphere beyond the light does not.
    for (bool blocker_between : {true, false}) {
        SCOPED_TRACE(blocker_between ? "blocker between" : "sphere beyond the light");
        ScenePtr s = new_scene();
        rt_material m = mat(rt_vec(1, 1, 1), 1.0, 0, 0, 0, 1);
        ASSERT_EQ(rt_scene_set_material(s.get(), &m), RT_OK);
        ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(0, 0, 0), 1.0), RT_OK);
        ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(0, 0, blocker_between ? 3.5 : 8.5), 0.5), RT_OK);
        rt_vec3 white = rt_vec(1, 1, 1);
        ASSERT_EQ(rt_scene_add_light(s.get(), rt_vec(0, 0, 6), &white), RT_OK);
        finish(s.get());
        for (const Mode &md : kModes) {
            SCOPED_TRACE(md.name);
            GridPtr g = make_grid(s.get(), md.cells, md.cells, md.cells);
            // Primary ray from the side, along (1, 0, -1), onto the top of the sphere at (0, 0, 1).
            rt_vec3 o = rt_vec(-3, 0, 4);
            StepOut st =
                run_step(s.get(), g.get(), params_for(md),
                         make_packet(g.get(), RT_PACKET_RAY, o, rt_vec_normalize(rt_vec(1, 0, -1)), rt_vec(1, 1, 1)));
            ASSERT_EQ(st.fate, RT_FATE_ABSORBED);
            ASSERT_EQ(count_kind(st.created, RT_PACKET_SHADOW), 1u);
            const rt_packet *sh = find_kind(st.created, RT_PACKET_SHADOW);
            EXPECT_TRUE(vec_near(sh->weight, rt_vec(1, 1, 1), 1e-12)) << "N = L = (0, 0, 1)";
            rt_fate f;
            rt_vec3 got = run_to_end(s.get(), g.get(), params_for(md), *sh, nullptr, &f);
            EXPECT_EQ(f, RT_FATE_ABSORBED) << "the light is inside the object space: absorbed either way";
            if (blocker_between) {
                EXPECT_TRUE(rt_vec_is_zero(got)) << "a blocked shadow packet adds nothing";
            } else {
                EXPECT_TRUE(vec_near(got, sh->weight, 0)) << "reached the light inside a cell";
            }
        }
    }
}

TEST(ShadingShadow, LightInsideTheGridIsReachedInsideACell)
{
    // A ring of spheres around a light at the centre of the space.
    ScenePtr s = new_scene();
    rt_material m = mat(rt_vec(1, 1, 1), 1.0, 0, 0, 0, 1);
    ASSERT_EQ(rt_scene_set_material(s.get(), &m), RT_OK);
    for (int k = 0; k < 6; k++) {
        double a = k * M_PI / 3;
        ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(5 * std::cos(a), 5 * std::sin(a), 0), 1.0), RT_OK);
    }
    rt_vec3 white = rt_vec(1, 1, 1);
    const rt_vec3 Lpos = rt_vec(0.3, 0.2, 0.1);
    ASSERT_EQ(rt_scene_add_light(s.get(), Lpos, &white), RT_OK);
    finish(s.get());
    for (const Mode &md : kModes) {
        SCOPED_TRACE(md.name);
        GridPtr g = make_grid(s.get(), md.cells, md.cells, md.cells);
        // A ray from the light outward hits sphere 0 on its inner side, facing the light.
        StepOut o = run_step(s.get(), g.get(), params_for(md),
                             make_packet(g.get(), RT_PACKET_RAY, rt_vec(0, 0, 0), rt_vec(1, 0, 0), rt_vec(1, 1, 1)));
        ASSERT_EQ(o.fate, RT_FATE_ABSORBED);
        ASSERT_EQ(count_kind(o.created, RT_PACKET_SHADOW), 1u);
        const rt_packet *sh = find_kind(o.created, RT_PACKET_SHADOW);
        rt_vec3 P = rt_vec(4, 0, 0);
        rt_vec3 L = rt_vec_normalize(rt_vec_sub(Lpos, P));
        EXPECT_TRUE(vec_near(sh->weight, rt_vec(-L.x, -L.x, -L.x), 1e-12)) << "Kd * (Nf.L) * C with Nf = (-1, 0, 0)";
        StepOut so = run_step(s.get(), g.get(), params_for(md), *sh);
        ASSERT_EQ(so.status, RT_OK);
        EXPECT_EQ(so.fate, RT_FATE_ABSORBED) << "reached the light inside a cell";
        ASSERT_EQ(so.contrib.size(), 1u);
        EXPECT_TRUE(vec_near(so.contrib[0].rgb, sh->weight, 0));
        if (!md.brute) {
            // It stopped in the light's cell, not at the edge of the space.
            rt_dda ld;
            ASSERT_TRUE(rt_dda_start(g.get(), Lpos, rt_vec(1, 0, 0), 0.0, &ld));
            EXPECT_EQ(std::memcmp(so.after.dda.cell, ld.cell, sizeof ld.cell), 0);
        }
    }
}

TEST(ShadingReflection, DirectionAndWeightOnAnObliqueHit)
{
    TestRng rng(101);
    ScenePtr s = new_scene();
    const double ks = 0.6;
    rt_material m = mat(rt_vec(0.3, 0.3, 0.3), 0.2, ks, 0, 0, 1);
    ASSERT_EQ(rt_scene_set_material(s.get(), &m), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(1, 2, 3), 2.0), RT_OK);
    finish(s.get());
    for (const Mode &md : kModes) {
        SCOPED_TRACE(md.name);
        GridPtr g = make_grid(s.get(), md.cells, md.cells, md.cells);
        for (int i = 0; i < 200; i++) {
            rt_vec3 n = rng.unit();
            rt_vec3 P = rt_vec_add(rt_vec(1, 2, 3), rt_vec_scale(n, 2.0));
            rt_vec3 o = rt_vec_add(P, rt_vec_scale(rt_vec_normalize(rt_vec_add(n, rt_vec_scale(rng.unit(), 0.9))), 6));
            rt_vec3 D = rt_vec_normalize(rt_vec_sub(P, o));
            if (rt_vec_dot(D, n) > -0.05) continue;
            bool enters;
            rt_vec3 w = rt_vec(rng.uniform(0.1, 1), rng.uniform(0.1, 1), rng.uniform(0.1, 1));
            rt_packet p = make_packet(g.get(), RT_PACKET_RAY, o, D, w, 0, INFINITY, &enters);
            ASSERT_TRUE(enters);
            StepOut st = run_step(s.get(), g.get(), params_for(md), p);
            ASSERT_EQ(st.fate, RT_FATE_ABSORBED);
            check_created(g.get(), md, st.created);
            ASSERT_EQ(st.created.size(), 1u);
            const rt_packet &r = st.created[0];
            rt_vec3 R = rt_vec_sub(D, rt_vec_scale(n, 2 * rt_vec_dot(D, n)));
            EXPECT_TRUE(vec_near(r.dir, R, 1e-9));
            EXPECT_TRUE(vec_near(r.weight, rt_vec_scale(w, ks), 1e-15));
            EXPECT_TRUE(vec_near(r.origin, P, 0, 1e-8));
            EXPECT_GT(rt_vec_length(rt_vec_sub(r.origin, rt_vec(1, 2, 3))), 2.0) << "reflection starts outside";
        }
    }
}

namespace {

// Angle between a and b, accurate near 0 and pi.
double angle_between(rt_vec3 a, rt_vec3 b) { return std::atan2(rt_vec_length(rt_vec_cross(a, b)), rt_vec_dot(a, b)); }

}  // namespace

TEST(ShadingRefraction, SnellEnteringAndLeavingASphere)
{
    const double ior = 1.5, T = 0.9;
    ScenePtr s = new_scene();
    rt_material m = mat(rt_vec(1, 1, 1), 0, 0, 0, T, ior);
    ASSERT_EQ(rt_scene_set_material(s.get(), &m), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(0, 0, 0), 1.0), RT_OK);
    finish(s.get());
    for (double h : {0.0, 0.1, 0.5, 0.8, 0.99}) {
        for (const Mode &md : kModes) {
            SCOPED_TRACE(std::string(md.name) + " offset " + std::to_string(h));
            GridPtr g = make_grid(s.get(), md.cells, md.cells, md.cells);
            rt_vec3 D = rt_vec(0, 0, -1), w = rt_vec(1, 0.8, 0.6);
            StepOut in =
                run_step(s.get(), g.get(), params_for(md), make_packet(g.get(), RT_PACKET_RAY, rt_vec(0, h, 5), D, w));
            ASSERT_EQ(in.fate, RT_FATE_ABSORBED);
            check_created(g.get(), md, in.created);
            ASSERT_EQ(in.created.size(), 1u);
            EXPECT_EQ(in.ops.refraction_vectors, 1u);
            const rt_packet &t1 = in.created[0];
            rt_vec3 N = rt_vec(0, h, std::sqrt(1 - h * h));
            // Entering, eta = 1/ior: sin(theta_t) = sin(theta_i) / ior.
            double theta_i = angle_between(rt_vec_scale(D, -1), N);
            double theta_t = angle_between(t1.dir, rt_vec_scale(N, -1));
            EXPECT_NEAR(theta_i, std::asin(h), 1e-12);
            EXPECT_NEAR(theta_t, std::asin(std::sin(theta_i) / ior), 1e-12);
            EXPECT_NEAR(rt_vec_dot(rt_vec_cross(D, N), t1.dir), 0.0, 1e-12) << "in the plane of incidence";
            EXPECT_LT(rt_vec_dot(t1.dir, N), 0.0);
            if (h > 0) {
                EXPECT_LT(t1.dir.y, 0.0) << "bent toward the normal, past the axis side";
            }
            EXPECT_TRUE(vec_near(t1.weight, rt_vec_scale(w, T), 1e-15));
            EXPECT_EQ(t1.depth, 1);
            EXPECT_LT(rt_vec_length(t1.origin), 1.0) << "the transmitted ray starts inside";
            EXPECT_TRUE(vec_near(t1.origin, N, 0, 1e-8));

            // Leaving, eta = ior: the internal angle equals theta_t, so the exit angle is theta_i.
            StepOut out = run_step(s.get(), g.get(), params_for(md), t1);
            ASSERT_EQ(out.fate, RT_FATE_ABSORBED);
            check_created(g.get(), md, out.created);
            ASSERT_EQ(out.created.size(), 1u);
            const rt_packet &t2 = out.created[0];
            double od = rt_vec_dot(t1.origin, t1.dir);
            double t_far = -od + std::sqrt(od * od - (rt_vec_dot(t1.origin, t1.origin) - 1));
            rt_vec3 P2 = rt_vec_add(t1.origin, rt_vec_scale(t1.dir, t_far));
            rt_vec3 N2 = rt_vec_normalize(P2);
            // Snell exactly at the actual second hit; the surface offset of the inner ray
            // (2^-32 relative) moves that hit a little, so the symmetry holds more loosely.
            double inner = angle_between(t1.dir, N2);
            EXPECT_NEAR(angle_between(t2.dir, N2), std::asin(ior * std::sin(inner)), 1e-11);
            EXPECT_NEAR(inner, theta_t, 1e-7);
            EXPECT_NEAR(angle_between(t2.dir, N2), theta_i, 1e-6);
            EXPECT_GT(rt_vec_dot(t2.dir, N2), 0.0);
            EXPECT_GT(rt_vec_length(t2.origin), 1.0) << "the leaving ray starts outside";
            EXPECT_TRUE(vec_near(t2.weight, rt_vec_scale(w, T * T), 1e-15));
            EXPECT_EQ(t2.depth, 2);
        }
    }
}

TEST(ShadingRefraction, TotalInternalReflectionGoesAlongR)
{
    const double ior = 1.5, T = 0.9;
    ScenePtr s = new_scene();
    rt_material m = mat(rt_vec(1, 1, 1), 0, 0, 0, T, ior);
    ASSERT_EQ(rt_scene_set_material(s.get(), &m), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(0, 0, 0), 1.0), RT_OK);
    finish(s.get());
    for (const Mode &md : kModes) {
        SCOPED_TRACE(md.name);
        GridPtr g = make_grid(s.get(), md.cells, md.cells, md.cells);
        // From inside at (0, 0.9, 0) along +z: sin(theta_i) = 0.9 > 1/1.5.
        rt_vec3 D = rt_vec(0, 0, 1), w = rt_vec(1, 1, 1);
        StepOut st =
            run_step(s.get(), g.get(), params_for(md), make_packet(g.get(), RT_PACKET_RAY, rt_vec(0, 0.9, 0), D, w));
        ASSERT_EQ(st.fate, RT_FATE_ABSORBED);
        check_created(g.get(), md, st.created);
        ASSERT_EQ(st.created.size(), 1u);
        EXPECT_EQ(st.ops.refraction_vectors, 1u);
        const rt_packet &t = st.created[0];
        rt_vec3 N = rt_vec(0, 0.9, std::sqrt(1 - 0.81));
        rt_vec3 R = rt_vec_sub(D, rt_vec_scale(N, 2 * rt_vec_dot(D, N)));
        EXPECT_TRUE(vec_near(t.dir, R, 1e-12));
        EXPECT_TRUE(vec_near(t.weight, rt_vec_scale(w, T), 1e-15));
        EXPECT_LT(rt_vec_length(t.origin), 1.0) << "a totally reflected ray stays inside";
        // Just below the critical angle it leaves: sin = 0.66 < 1/1.5.
        StepOut st2 =
            run_step(s.get(), g.get(), params_for(md), make_packet(g.get(), RT_PACKET_RAY, rt_vec(0, 0.66, 0), D, w));
        ASSERT_EQ(st2.created.size(), 1u);
        EXPECT_GT(rt_vec_length(st2.created[0].origin), 1.0);
        EXPECT_NEAR(angle_between(st2.created[0].dir, rt_vec(0, 0.66, std::sqrt(1 - 0.66 * 0.66))),
                    std::asin(0.66 * 1.5), 1e-9);
    }
}

TEST(ShadingLimits, MaxDepthAndMinWeight)
{
    const double ks = 0.5, T = 0.5;
    ScenePtr s = new_scene();
    rt_material m = mat(rt_vec(1, 1, 1), 0, ks, 0, T, 1.0);
    ASSERT_EQ(rt_scene_set_material(s.get(), &m), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(0, 0, 0), 1.0), RT_OK);
    finish(s.get());
    for (const Mode &md : kModes) {
        SCOPED_TRACE(md.name);
        GridPtr g = make_grid(s.get(), md.cells, md.cells, md.cells);
        rt_step_params prm = params_for(md);
        auto created_at = [&](int depth, rt_vec3 w, const rt_step_params &pp) {
            StepOut o = run_step(s.get(), g.get(), pp,
                                 make_packet(g.get(), RT_PACKET_RAY, rt_vec(0, 0, 5), rt_vec(0, 0, -1), w, depth));
            EXPECT_EQ(o.fate, RT_FATE_ABSORBED);
            check_created(g.get(), md, o.created);
            for (auto &p : o.created) {
                EXPECT_LE(int(p.depth), pp.max_depth);
                EXPECT_GE(rt_vec_max_component(p.weight), pp.min_weight);
            }
            EXPECT_EQ(o.ops.reflection_vectors + o.ops.refraction_vectors, o.created.size())
                << "vectors are computed only for packets made";
            return o.created.size();
        };
        rt_vec3 one = rt_vec(1, 1, 1);
        EXPECT_EQ(created_at(prm.max_depth - 1, one, prm), 2u) << "depth max_depth is allowed";
        EXPECT_EQ(created_at(prm.max_depth, one, prm), 0u) << "no packet deeper than max_depth";
        // Weight: w * 0.5 against 1/512 = 0.001953125, by the largest channel.
        EXPECT_EQ(created_at(0, rt_vec(0.00390625, 0.00390625, 0.00390625), prm), 2u) << "exactly min_weight";
        EXPECT_EQ(created_at(0, rt_vec(0.0039, 0.0039, 0.0039), prm), 0u) << "below min_weight";
        EXPECT_EQ(created_at(0, rt_vec(1e-9, 0.004, 0), prm), 2u) << "the largest channel decides";
        rt_step_params p2 = prm;
        p2.max_depth = 2;
        p2.min_weight = 0.3;
        EXPECT_EQ(created_at(1, one, p2), 2u);
        EXPECT_EQ(created_at(2, one, p2), 0u);
        EXPECT_EQ(created_at(0, rt_vec(0.59, 0.59, 0.59), p2), 0u);
        EXPECT_EQ(created_at(0, rt_vec(0.61, 0, 0), p2), 2u);
        p2.max_depth = 0;
        p2.min_weight = 0;
        EXPECT_EQ(created_at(0, one, p2), 0u) << "max_depth 0: primaries only";
        EXPECT_EQ(created_at(0, rt_vec(0, 0, 0), prm), 0u) << "zero weight: never a packet";
    }
}

TEST(StepEscape, RayLeavingTheSpaceAddsWeightTimesBackground)
{
    ScenePtr s = new_scene();
    ASSERT_EQ(rt_scene_set_background(s.get(), rt_vec(0.1, 0.2, 0.3)), RT_OK);
    rt_material m = mat(rt_vec(1, 1, 1), 1, 0, 0, 0, 1);
    ASSERT_EQ(rt_scene_set_material(s.get(), &m), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(0, 0, 0), 1.0), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(6, 6, 6), 1.0), RT_OK);
    finish(s.get());
    rt_vec3 w = rt_vec(0.5, 0.25, 1);
    for (const Mode &md : kModes) {
        SCOPED_TRACE(md.name);
        GridPtr g = make_grid(s.get(), md.cells, md.cells, md.cells);
        // Crosses the space between the spheres.
        bool enters;
        rt_packet p = make_packet(g.get(), RT_PACKET_RAY, rt_vec(-5, 5, 0), rt_vec(1, 0, 0), w, 1, INFINITY, &enters);
        ASSERT_TRUE(enters);
        StepOut o = run_step(s.get(), g.get(), params_for(md), p);
        ASSERT_EQ(o.status, RT_OK);
        EXPECT_EQ(o.fate, RT_FATE_LEFT);
        ASSERT_EQ(o.contrib.size(), 1u);
        EXPECT_TRUE(vec_near(o.contrib[0].rgb, rt_vec(0.05, 0.05, 0.3), 1e-15));
        EXPECT_TRUE(o.created.empty());
        EXPECT_EQ(o.ops.shadings, 0u);
        EXPECT_EQ(o.ops.tests_hit, 0u);
    }
}

// Sphere A (radius 1) at x = 0, sphere B (radius 2) at x = 10, one white light above B.
static void add_two_spheres(rt_scene *s)
{
    rt_material m = mat(rt_vec(1, 1, 1), 1, 0, 0, 0, 1);
    ASSERT_EQ(rt_scene_set_material(s, &m), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(s, rt_vec(0, 0, 0), 1.0), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(s, rt_vec(10, 0, 0), 2.0), RT_OK);
    rt_vec3 white = rt_vec(1, 1, 1);
    ASSERT_EQ(rt_scene_add_light(s, rt_vec(10, 10, 0), &white), RT_OK);
    finish(s);
}

TEST(StepForward, NextCellWithAnotherOwner)
{
    // Sphere A (radius 1) at x = 0, sphere B (radius 2) at x = 10: the space is
    // [-1, 12] x [-2, 2] x [-2, 2], two cells along x split at 5.5, owned by 0 and 1.
    ScenePtr s = new_scene();
    ASSERT_NO_FATAL_FAILURE(add_two_spheres(s.get()));
    GridPtr g = make_grid(s.get(), 2, 1, 1);
    ASSERT_TRUE(g);
    const int32_t owner[2] = {0, 1};
    rt_step_params prm = rt_step_params_default();
    // Misses A (passes at y = 1.5), hits B at x = 10 - sqrt(4 - 2.25).
    rt_packet p = make_packet(g.get(), RT_PACKET_RAY, rt_vec(-5, 1.5, 0), rt_vec(1, 0, 0), rt_vec(1, 1, 1));
    ASSERT_EQ(p.dda.cell[0], 0);
    StepOut a = run_step(s.get(), g.get(), prm, p, owner, 0);
    ASSERT_EQ(a.status, RT_OK);
    EXPECT_EQ(a.fate, RT_FATE_FORWARDED);
    EXPECT_EQ(a.next_cell, 1u);
    EXPECT_EQ(a.after.dda.cell[0], 1) << "the packet is updated to its next cell";
    EXPECT_EQ(rt_packet_cell(g.get(), &a.after), 1u);
    EXPECT_TRUE(a.contrib.empty());
    EXPECT_TRUE(a.created.empty());
    EXPECT_EQ(a.ops.packets_analysed, 1u);
    EXPECT_EQ(a.ops.packets_created, 0u) << "a forward is a hand-over, not a packet made";
    EXPECT_EQ(a.ops.handovers_sent, 1u);
    EXPECT_EQ(a.ops.handovers_received, 0u);
    EXPECT_EQ(a.after.handed_over, 1u);
    EXPECT_EQ(a.ops.tests_missed, 1u) << "A tested in cell 0";
    EXPECT_EQ(a.ops.tests_hit, 0u);
    EXPECT_EQ(a.ops.dda_steps, 1u);
    EXPECT_EQ(a.ops.shadings, 0u);
    // The same packet at processor 0 again: not its cell, passed on untouched.
    StepOut again = run_step(s.get(), g.get(), prm, a.after, owner, 0);
    EXPECT_EQ(again.fate, RT_FATE_FORWARDED);
    EXPECT_EQ(again.next_cell, 1u);
    EXPECT_EQ(again.ops.handovers_received, 1u);
    EXPECT_EQ(again.ops.handovers_sent, 1u);
    EXPECT_EQ(again.ops.packets_analysed + again.ops.packets_created, 0u);
    EXPECT_EQ(again.ops.tests_missed + again.ops.tests_hit + again.ops.dda_steps, 0u);
    EXPECT_EQ(std::memcmp(&again.after.dda, &a.after.dda, sizeof a.after.dda), 0);
    // Processor 1 finishes it.
    StepOut b = run_step(s.get(), g.get(), prm, a.after, owner, 1);
    ASSERT_EQ(b.status, RT_OK);
    EXPECT_EQ(b.fate, RT_FATE_ABSORBED);
    EXPECT_EQ(b.ops.tests_hit, 1u);
    EXPECT_EQ(b.ops.tests_missed, 0u);
    EXPECT_EQ(b.ops.shadings, 1u);
    EXPECT_EQ(b.ops.dda_steps, 1u) << "the shadow packet's start cell";
    EXPECT_EQ(b.ops.packets_created, 1u);
    EXPECT_EQ(b.ops.handovers_received, 1u) << "taken up after a hand-over";
    EXPECT_EQ(b.ops.packets_analysed, 0u);
    EXPECT_EQ(b.ops.handovers_sent, 0u);
    ASSERT_EQ(b.created.size(), 1u);
    EXPECT_EQ(b.created[0].handed_over, 0u) << "a new packet is not a hand-over";
    EXPECT_EQ(b.created[0].kind, RT_PACKET_SHADOW);
    EXPECT_EQ(rt_packet_cell(g.get(), &b.created[0]), 1u);
    // The whole path with no owners gives the same hit as brute force.
    rt_step_params bf = prm;
    bf.brute_force = 1;
    StepOut ob = run_step(s.get(), g.get(), bf, p);
    ASSERT_EQ(ob.created.size(), 1u);
    EXPECT_TRUE(vec_near(ob.created[0].weight, b.created[0].weight, 0));
    EXPECT_TRUE(vec_near(ob.created[0].origin, b.created[0].origin, 0));
    // A shadow packet forwarded back toward cell 0.
    rt_packet sh =
        make_packet(g.get(), RT_PACKET_SHADOW, rt_vec(8, 0, 1.9), rt_vec(-1, 0, 0), rt_vec(0.5, 0.5, 0.5), 0, 7.0);
    ASSERT_EQ(sh.dda.cell[0], 1);
    StepOut sf = run_step(s.get(), g.get(), prm, sh, owner, 1);
    EXPECT_EQ(sf.fate, RT_FATE_FORWARDED);
    EXPECT_EQ(sf.next_cell, 0u);
}

TEST(StepOps, HandCountedGridAndBruteForce)
{
    // The scene of StepForward with no owners: the ray tests A in cell 0 (miss), steps to
    // cell 1, tests B (hit), shades and makes one shadow packet (one start-cell step).
    ScenePtr s = new_scene();
    ASSERT_NO_FATAL_FAILURE(add_two_spheres(s.get()));
    GridPtr g = make_grid(s.get(), 2, 1, 1);
    ASSERT_TRUE(g);
    rt_step_params prm = rt_step_params_default();
    rt_packet p = make_packet(g.get(), RT_PACKET_RAY, rt_vec(-5, 1.5, 0), rt_vec(1, 0, 0), rt_vec(1, 1, 1));
    StepOut o = run_step(s.get(), g.get(), prm, p);
    EXPECT_EQ(o.fate, RT_FATE_ABSORBED);
    EXPECT_EQ(o.ops.tests_missed, 1u);
    EXPECT_EQ(o.ops.tests_hit, 1u);
    EXPECT_EQ(o.ops.dda_steps, 2u);
    EXPECT_EQ(o.ops.cell_steps, 1u) << "cell 0 -> 1; the shadow's start cell is no move";
    EXPECT_EQ(o.ops.shadings, 1u);
    EXPECT_EQ(o.ops.reflection_vectors, 0u);
    EXPECT_EQ(o.ops.refraction_vectors, 0u);
    EXPECT_EQ(o.ops.packets_analysed, 1u);
    EXPECT_EQ(o.ops.packets_created, 1u);
    EXPECT_EQ(o.ops.fb_writes, 0u);
    ASSERT_EQ(o.created.size(), 1u);
    // The shadow packet: tests B in cell 1 (a miss: it leaves B's surface), then leaves
    // the space through y = 2 (one failed step) and adds its value.
    StepOut so = run_step(s.get(), g.get(), prm, o.created[0]);
    EXPECT_EQ(so.fate, RT_FATE_LEFT);
    EXPECT_EQ(so.ops.tests_missed, 1u);
    EXPECT_EQ(so.ops.tests_hit, 0u);
    EXPECT_EQ(so.ops.dda_steps, 1u);
    EXPECT_EQ(so.ops.cell_steps, 0u) << "the step that leaves the space enters no cell";
    EXPECT_EQ(so.ops.shadings, 0u);
    EXPECT_EQ(so.ops.packets_analysed, 1u);
    EXPECT_EQ(so.ops.packets_created, 0u);
    EXPECT_EQ(so.ops.fb_writes, 1u);
    ASSERT_EQ(so.contrib.size(), 1u);
    EXPECT_TRUE(vec_near(so.contrib[0].rgb, o.created[0].weight, 0));
    // Brute force: both objects tested once, no DDA work.
    prm.brute_force = 1;
    StepOut ob = run_step(s.get(), g.get(), prm, p);
    EXPECT_EQ(ob.ops.tests_missed, 1u);
    EXPECT_EQ(ob.ops.tests_hit, 1u);
    EXPECT_EQ(ob.ops.dda_steps, 0u);
    EXPECT_EQ(ob.ops.cell_steps, 0u);
    EXPECT_EQ(ob.ops.shadings, 1u);
    EXPECT_EQ(ob.ops.packets_created, 1u);
    StepOut obs = run_step(s.get(), g.get(), prm, ob.created[0]);
    EXPECT_EQ(obs.ops.tests_missed, 2u);
    EXPECT_EQ(obs.ops.tests_hit, 0u);
    EXPECT_EQ(obs.ops.fb_writes, 1u);
    // A ray hitting both objects in the same cell: both tested, both counted as hits. The
    // nearest hit, (-1, 0, 0) on A, faces away from the light: no shadow packet.
    GridPtr g1 = make_grid(s.get(), 1, 1, 1);
    rt_step_params pg = rt_step_params_default();
    StepOut both = run_step(s.get(), g1.get(), pg,
                            make_packet(g1.get(), RT_PACKET_RAY, rt_vec(-5, 0, 0), rt_vec(1, 0, 0), rt_vec(1, 1, 1)));
    EXPECT_EQ(both.ops.tests_hit, 2u);
    EXPECT_EQ(both.ops.tests_missed, 0u);
    EXPECT_EQ(both.ops.shadings, 1u);
    EXPECT_EQ(both.ops.dda_steps, 0u);
    EXPECT_EQ(both.ops.packets_created, 0u);
}

TEST(StepTies, ObjectListedFirstWinsATie)
{
    // The same sphere twice, and the same square twice: red listed first, blue second.
    for (bool spheres : {true, false}) {
        SCOPED_TRACE(spheres ? "spheres" : "squares");
        ScenePtr s = new_scene();
        ASSERT_EQ(rt_scene_set_ambient(s.get(), rt_vec(1, 1, 1)), RT_OK);
        rt_material red = mat(rt_vec(1, 0, 0), 0, 0, 0, 0, 1), blue = mat(rt_vec(0, 0, 1), 0, 0, 0, 0, 1);
        rt_vec3 sq[4] = {rt_vec(-1, -1, 0), rt_vec(1, -1, 0), rt_vec(1, 1, 0), rt_vec(-1, 1, 0)};
        for (const rt_material *m : {&red, &blue}) {
            ASSERT_EQ(rt_scene_set_material(s.get(), m), RT_OK);
            if (spheres) {
                ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(0.1, 0.2, 0.3), 1.0), RT_OK);
            } else {
                ASSERT_EQ(rt_scene_add_polygon(s.get(), sq, 4), RT_OK);
            }
        }
        finish(s.get());
        TestRng rng(77);
        for (const Mode &md : kModes) {
            SCOPED_TRACE(md.name);
            GridPtr g = make_grid(s.get(), md.cells, md.cells, md.cells);
            for (int i = 0; i < 200; i++) {
                rt_vec3 o = rt_vec(rng.uniform(-0.9, 0.9), rng.uniform(-0.9, 0.9), 5);
                // Aimed within 0.5 of the sphere's centre on x and y, or into the square.
                rt_vec3 aim = spheres ? rt_vec(0.1 + rng.uniform(-0.5, 0.5), 0.2 + rng.uniform(-0.5, 0.5), 0.3)
                                      : rt_vec(rng.uniform(-0.9, 0.9), rng.uniform(-0.9, 0.9), 0);
                rt_vec3 d = rt_vec_normalize(rt_vec_sub(aim, o));
                bool enters;
                rt_packet p = make_packet(g.get(), RT_PACKET_RAY, o, d, rt_vec(1, 1, 1), 0, INFINITY, &enters);
                ASSERT_TRUE(enters);
                StepOut st = run_step(s.get(), g.get(), params_for(md), p);
                ASSERT_EQ(st.fate, RT_FATE_ABSORBED);
                ASSERT_EQ(st.contrib.size(), 1u);
                EXPECT_TRUE(vec_near(st.contrib[0].rgb, rt_vec(1, 0, 0), 0)) << "ray " << i;
            }
        }
    }
}

TEST(StepErrors, CapacityAndBadPackets)
{
    ScenePtr s = new_scene();
    ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(0, 0, 0), 1.0), RT_OK);
    rt_vec3 white = rt_vec(1, 1, 1);
    ASSERT_EQ(rt_scene_add_light(s.get(), rt_vec(0, 0, 5), &white), RT_OK);
    finish(s.get());
    GridPtr g = make_grid(s.get(), 4, 4, 4);
    rt_step_result r;
    ASSERT_EQ(rt_step_result_init(&r, s.get()), RT_OK);
    rt_step_params prm = rt_step_params_default();
    rt_packet p = make_packet(g.get(), RT_PACKET_RAY, rt_vec(0, 0, 5), rt_vec(0, 0, -1), rt_vec(1, 1, 1));
    size_t cap = r.created_capacity;
    r.created_capacity = 0;
    EXPECT_EQ(rt_step(s.get(), g.get(), nullptr, 0, &prm, &p, &r), RT_ERR_CAPACITY);
    r.created_capacity = cap;
    rt_packet bad = p;
    bad.dda.cell[1] = 4;
    EXPECT_EQ(rt_step(s.get(), g.get(), nullptr, 0, &prm, &bad, &r), RT_ERR_INVALID);
    bad = p;
    bad.kind = 7;
    EXPECT_EQ(rt_step(s.get(), g.get(), nullptr, 0, &prm, &bad, &r), RT_ERR_INVALID);
    EXPECT_EQ(rt_step(s.get(), g.get(), nullptr, 0, &prm, &p, &r), RT_OK);
    rt_step_result_release(&r);
}

// --- frame buffer --------------------------------------------------------------

TEST(FramebufferOrder, TenThousandContributionsInTwoOrders)
{
    const uint32_t W = 16, H = 12;
    TestRng rng(555);
    std::vector<rt_contribution> c(10000);
    for (auto &x : c) {
        x.x = rng.below(W);
        x.y = rng.below(H);
        // Mixed magnitudes and signs, values that are not multiples of 2^-32.
        x.rgb = rt_vec(rng.uniform(-0.01, 0.05), rng.uniform(0, 1e-3) * rng.uniform(0, 1),
                       std::pow(10.0, rng.uniform(-12, -1)));
    }
    FbPtr a(rt_framebuffer_new(W, H)), b(rt_framebuffer_new(W, H));
    ASSERT_TRUE(a && b);
    for (auto &x : c) rt_framebuffer_add(a.get(), x.x, x.y, x.rgb);
    std::vector<size_t> order(c.size());
    for (size_t i = 0; i < order.size(); i++) order[i] = i;
    for (size_t i = order.size() - 1; i > 0; i--) std::swap(order[i], order[rng.below(uint32_t(i + 1))]);
    for (size_t i : order) rt_framebuffer_add(b.get(), c[i].x, c[i].y, c[i].rgb);
    std::vector<uint8_t> pa(W * H * 3), pb(W * H * 3);
    rt_framebuffer_to_rgb8(a.get(), pa.data());
    rt_framebuffer_to_rgb8(b.get(), pb.data());
    EXPECT_EQ(pa, pb);
    bool any_nonzero = false;
    for (uint32_t y = 0; y < H; y++)
        for (uint32_t x = 0; x < W; x++) {
            rt_vec3 va = rt_framebuffer_get(a.get(), x, y), vb = rt_framebuffer_get(b.get(), x, y);
            EXPECT_EQ(va.x, vb.x);
            EXPECT_EQ(va.y, vb.y);
            EXPECT_EQ(va.z, vb.z);
            any_nonzero = any_nonzero || pa[(y * W + x) * 3] != 0;
        }
    EXPECT_TRUE(any_nonzero);
    // The sums are what the contributions add up to (each within half a unit of 2^-32).
    std::vector<double> want(W * H * 3, 0.0);
    for (auto &x : c) {
        want[(x.y * W + x.x) * 3 + 0] += x.rgb.x;
        want[(x.y * W + x.x) * 3 + 1] += x.rgb.y;
        want[(x.y * W + x.x) * 3 + 2] += x.rgb.z;
    }
    for (uint32_t y = 0; y < H; y++)
        for (uint32_t x = 0; x < W; x++) {
            rt_vec3 v = rt_framebuffer_get(a.get(), x, y);
            EXPECT_NEAR(v.x, want[(y * W + x) * 3 + 0], 1e-6);
            EXPECT_NEAR(v.y, want[(y * W + x) * 3 + 1], 1e-6);
            EXPECT_NEAR(v.z, want[(y * W + x) * 3 + 2], 1e-6);
        }
}

TEST(FramebufferRounding, FloorTimes255PlusHalf)
{
    FbPtr fb(rt_framebuffer_new(1, 1));
    ASSERT_TRUE(fb);
    TestRng rng(7);
    std::vector<double> values = {0.0,        1.0,        0.5,         0.25,         1.0 / 255,   0.5 / 255,
                                  0.49 / 255, 0.51 / 255, 254.5 / 255, 254.49 / 255, 127.5 / 255, 100.5 / 255};
    for (int i = 0; i < 20000; i++) values.push_back(rng.uniform(0, 1));
    for (int k = 0; k < 255; k++) {
        values.push_back((k + 0.5) / 255 + 1e-7);
        values.push_back((k + 0.5) / 255 - 1e-7);
    }
    for (double v : values) {
        FbPtr f(rt_framebuffer_new(1, 1));
        rt_framebuffer_add(f.get(), 0, 0, rt_vec(v, v, v));
        uint8_t px[3];
        rt_framebuffer_to_rgb8(f.get(), px);
        // The stored sum is v to within 2^-33: the byte is floor(sum * 255 + 0.5), exactly.
        double sum = rt_framebuffer_get(f.get(), 0, 0).x;
        EXPECT_NEAR(sum, v, 0x1p-32);
        long double want = floorl((long double)sum * 255 + 0.5L);
        ASSERT_EQ(px[0], uint8_t(want)) << v;
        EXPECT_EQ(px[1], px[0]);
        EXPECT_EQ(px[2], px[0]);
        // Away from a rounding boundary the byte is that of v itself.
        double frac = v * 255 + 0.5 - std::floor(v * 255 + 0.5);
        if (frac > 1e-6 && frac < 1 - 1e-6) {
            EXPECT_EQ(px[0], uint8_t(std::floor(v * 255 + 0.5))) << v;
        }
    }
    // Exact half-way points: k + 0.5 rounds up.
    for (int k = 0; k < 255; k += 17) {
        FbPtr f(rt_framebuffer_new(1, 1));
        // (k + 0.5) / 255 is not a multiple of 2^-32, so go through the integer grid:
        // the smallest multiple of 2^-32 at or above it.
        double v = std::ceil((k + 0.5) / 255 * 0x1p32) / 0x1p32;
        rt_framebuffer_add(f.get(), 0, 0, rt_vec(v, 0, 0));
        uint8_t px[3];
        rt_framebuffer_to_rgb8(f.get(), px);
        EXPECT_EQ(px[0], uint8_t(k + 1)) << k;
    }
}

TEST(FramebufferClamp, ClampAtTheEndNotPerContribution)
{
    FbPtr fb(rt_framebuffer_new(4, 2));
    ASSERT_TRUE(fb);
    rt_framebuffer_add(fb.get(), 0, 0, rt_vec(1.7, -0.3, 5e5));  // 255, 0, 255
    rt_framebuffer_add(fb.get(), 1, 0, rt_vec(0.75, 0.75, 0.75));
    rt_framebuffer_add(fb.get(), 1, 0, rt_vec(0.75, -1.0, -0.25));  // 1.5, -0.25, 0.5
    rt_framebuffer_add(fb.get(), 2, 0, rt_vec(3.0, 3.0, 3.0));
    rt_framebuffer_add(fb.get(), 2, 0, rt_vec(-2.5, -2.5, -2.5));     // 0.5: not clamped on the way
    rt_framebuffer_add(fb.get(), 3, 0, rt_vec(NAN, 0.25, INFINITY));  // NaN adds nothing
    rt_framebuffer_add(fb.get(), 4, 0, rt_vec(1, 1, 1));              // outside: ignored
    rt_framebuffer_add(fb.get(), 0, 2, rt_vec(1, 1, 1));              // outside: ignored
    uint8_t px[4 * 2 * 3];
    rt_framebuffer_to_rgb8(fb.get(), px);
    const uint8_t want_row0[12] = {255, 0, 255, 255, 0, 128, 128, 128, 128, 0, 64, 255};
    for (int i = 0; i < 12; i++) EXPECT_EQ(px[i], want_row0[i]) << "byte " << i;
    for (int i = 12; i < 24; i++) EXPECT_EQ(px[i], 0) << "row 1 untouched, byte " << i;
    EXPECT_EQ(rt_framebuffer_get(fb.get(), 2, 0).x, 0.5);
    EXPECT_EQ(rt_framebuffer_get(fb.get(), 1, 0).y, -0.25) << "negative sums are kept until the end";
    EXPECT_EQ(rt_framebuffer_new(0, 5), nullptr);
    EXPECT_EQ(rt_framebuffer_new(5, 0), nullptr);
}

TEST(FramebufferClamp, ContributionClampIsTheDocumentedTwoToThe20)
{
    // rt_framebuffer.h: each contribution is "clamped to +-2^20 per contribution". A
    // contribution of 2^19 is inside that range and must be kept; 2^25 becomes 2^20.
    FbPtr fb(rt_framebuffer_new(2, 1));
    ASSERT_TRUE(fb);
    rt_framebuffer_add(fb.get(), 0, 0, rt_vec(0x1p19, -0x1p19, 1000.0));
    rt_framebuffer_add(fb.get(), 1, 0, rt_vec(0x1p25, -0x1p25, 0));
    rt_vec3 a = rt_framebuffer_get(fb.get(), 0, 0), b = rt_framebuffer_get(fb.get(), 1, 0);
    EXPECT_EQ(a.z, 1000.0);
    EXPECT_EQ(a.x, 0x1p19) << "a contribution of 2^19 is within the documented +-2^20";
    EXPECT_EQ(a.y, -0x1p19);
    EXPECT_EQ(b.x, 0x1p20) << "clamped to the documented 2^20";
    EXPECT_EQ(b.y, -0x1p20);
}

// --- the reference renderer ----------------------------------------------------------

namespace {

// A random scene: 40 spheres and some polygons and triangles, mixed materials, lights
// inside and outside the object space.
// Every coordinate and size is multiplied by `scale`; eye_inside puts the camera in the
// middle of the object space.
ScenePtr random_scene(uint64_t seed, uint32_t size, double scale = 1.0, bool eye_inside = false)
{
    TestRng rng(seed);
    ScenePtr s(rt_scene_new());
    auto P = [scale](double x, double y, double z) { return rt_vec(x * scale, y * scale, z * scale); };
    if (eye_inside) {
        EXPECT_EQ(rt_scene_set_view(s.get(), P(5.1, 5.2, 5.3), P(2, 3, -1), rt_vec(0, 1, 0), 100, size, size), RT_OK);
    } else {
        EXPECT_EQ(rt_scene_set_view(s.get(), P(5, 4, 22), P(5, 5, 5), rt_vec(0, 1, 0), 50, size, size), RT_OK);
    }
    EXPECT_EQ(rt_scene_set_background(s.get(), rt_vec(0.1, 0.15, 0.3)), RT_OK);
    EXPECT_EQ(rt_scene_set_ambient(s.get(), rt_vec(0.1, 0.1, 0.1)), RT_OK);
    rt_vec3 l1 = rt_vec(0.8, 0.8, 0.7), l2 = rt_vec(0.4, 0.5, 0.6);
    EXPECT_EQ(rt_scene_add_light(s.get(), P(-10, 20, 20), &l1), RT_OK);
    EXPECT_EQ(rt_scene_add_light(s.get(), P(5, 5.5, 4), &l2), RT_OK);  // inside the space
    for (int i = 0; i < 40; i++) {
        if (i % 5 == 0) {
            int kind = (i / 5) % 3;
            rt_material m = kind == 0
                                ? mat(rt_vec(rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, 1)), 0.8, 0, 0, 0, 1)
                            : kind == 1 ? mat(rt_vec(0.9, 0.9, 0.9), 0.3, 0.6, 20, 0, 1)
                                        : mat(rt_vec(1, 1, 1), 0.1, 0.2, 50, 0.7, 1.5);
            EXPECT_EQ(rt_scene_set_material(s.get(), &m), RT_OK);
        }
        rt_vec3 c = P(rng.uniform(0, 10), rng.uniform(0, 10), rng.uniform(0, 10));
        if (eye_inside && rt_vec_length(rt_vec_sub(c, P(5.1, 5.2, 5.3))) < 2 * scale) c = P(rng.uniform(0, 3), 0, 0);
        EXPECT_EQ(rt_scene_add_sphere(s.get(), c, rng.uniform(0.2, 1.5) * scale), RT_OK);
    }
    rt_material floor_m = mat(rt_vec(0.7, 0.7, 0.6), 0.7, 0.3, 0, 0, 1);
    EXPECT_EQ(rt_scene_set_material(s.get(), &floor_m), RT_OK);
    rt_vec3 fl[4] = {P(-5, -0.5, -5), P(-5, -0.5, 15), P(15, -0.5, 15), P(15, -0.5, -5)};
    EXPECT_EQ(rt_scene_add_polygon(s.get(), fl, 4), RT_OK);
    for (int i = 0; i < 6; i++) {
        rt_vec3 c = P(rng.uniform(0, 10), rng.uniform(0, 10), rng.uniform(0, 10));
        std::vector<rt_vec3> v;
        int n = 3 + i % 4;
        rt_vec3 nrm = rng.unit();
        rt_vec3 u = rt_vec_normalize(rt_vec_cross(nrm, rng.unit())), w = rt_vec_cross(nrm, u);
        for (int k = 0; k < n; k++) {
            double a = 2 * M_PI * k / n, r = (k % 2 ? 0.8 : 2.0) * scale;
            v.push_back(rt_vec_add(c, rt_vec_add(rt_vec_scale(u, r * std::cos(a)), rt_vec_scale(w, r * std::sin(a)))));
        }
        EXPECT_EQ(rt_scene_add_polygon(s.get(), v.data(), v.size()), RT_OK);
    }
    rt_vec3 tv[4] = {P(1, 7, 1), P(4, 8, 1), P(4, 9, 4), P(1, 8, 3)};
    rt_vec3 tn[4] = {rt_vec(0, 1, 0), rt_vec(0.3, 1, 0), rt_vec(0, 1, 0.3), rt_vec(-0.2, 1, 0)};
    EXPECT_EQ(rt_scene_add_patch(s.get(), tv, tn, 4), RT_OK);
    EXPECT_EQ(rt_scene_add_cone(s.get(), P(8, 1, 2), 0.7 * scale, P(9, 4, 3), 0.2 * scale), RT_OK);
    EXPECT_EQ(rt_scene_add_cone(s.get(), P(2, 2, 8), 0.5 * scale, P(2, 5, 8), 0.5 * scale), RT_OK);
    char msg[RT_MSG_LEN] = "";
    EXPECT_EQ(rt_scene_finish(s.get(), msg, sizeof msg), RT_OK) << msg;
    return s;
}

size_t differing_bytes(const std::vector<uint8_t> &a, const std::vector<uint8_t> &b)
{
    size_t n = 0;
    for (size_t i = 0; i < a.size() && i < b.size(); i++) n += a[i] != b[i];
    return n + (a.size() > b.size() ? a.size() - b.size() : b.size() - a.size());
}

void expect_conserved(const rt_render_stats &st)
{
    for (int k = 0; k < RT_PACKET_KINDS; k++) EXPECT_EQ(st.packets.created[k], st.packets.consumed[k]) << "kind " << k;
    EXPECT_EQ(st.packets.forwarded, 0u);
    EXPECT_EQ(st.ops.packets_analysed, st.packets.consumed[0] + st.packets.consumed[1]);
}

}  // namespace

TEST(RenderDeterminism, TwoRendersAreByteIdentical)
{
    ScenePtr s = random_scene(1, 48);
    Image a = render(s.get(), 24, false), b = render(s.get(), 24, false);
    EXPECT_EQ(a.rgb, b.rgb);
    EXPECT_EQ(std::memcmp(&a.stats.ops, &b.stats.ops, sizeof a.stats.ops), 0);
    EXPECT_EQ(a.stats.packets.created[0], b.stats.packets.created[0]);
    EXPECT_EQ(a.stats.packets.created[1], b.stats.packets.created[1]);
    expect_conserved(a.stats);
}

TEST(RenderGridVsBruteForce, RandomSceneAtSeveralGridSizes)
{
    for (uint64_t seed : {1ull, 2ull, 3ull}) {
        ScenePtr s = random_scene(seed, 64);
        Image bf = render(s.get(), 1, true);
        expect_conserved(bf.stats);
        EXPECT_EQ(bf.stats.ops.dda_steps, 0u);
        // The image is not trivial: many distinct byte values.
        std::vector<bool> seen(256);
        for (uint8_t v : bf.rgb) seen[v] = true;
        EXPECT_GT(std::count(seen.begin(), seen.end(), true), 100);
        for (int cells : {1, 7, 24, 64}) {
            SCOPED_TRACE("seed " + std::to_string(seed) + " cells " + std::to_string(cells));
            Image gr = render(s.get(), cells, false);
            EXPECT_EQ(differing_bytes(gr.rgb, bf.rgb), 0u) << "grid image differs from brute force";
            expect_conserved(gr.stats);
            // Same shade tree: the same packets and the same shading work.
            // Brute force makes a packet of every ray; the grid adds a ray that never meets the
            // space to the frame buffer at once instead.
            EXPECT_EQ(bf.stats.packets.primary_missed, 0u);
            EXPECT_LE(gr.stats.packets.created[0] + gr.stats.packets.primary_missed, bf.stats.packets.created[0]);
            EXPECT_EQ(gr.stats.ops.shadings, bf.stats.ops.shadings);
            EXPECT_EQ(gr.stats.ops.reflection_vectors, bf.stats.ops.reflection_vectors);
            EXPECT_EQ(gr.stats.ops.refraction_vectors, bf.stats.ops.refraction_vectors);
        }
    }
}

TEST(RenderGridVsBruteForce, TinyHugeAndEyeInside)
{
    for (double scale : {1e-6, 1.0, 1e6}) {
        for (bool inside : {false, true}) {
            ScenePtr s = random_scene(4, 40, scale, inside);
            Image bf = render(s.get(), 1, true);
            for (int cells : {1, 7, 24}) {
                SCOPED_TRACE("scale " + std::to_string(scale) + (inside ? " eye inside" : "") + " cells " +
                             std::to_string(cells));
                Image gr = render(s.get(), cells, false);
                EXPECT_EQ(differing_bytes(gr.rgb, bf.rgb), 0u) << "grid image differs from brute force";
                expect_conserved(gr.stats);
                if (inside) {
                    EXPECT_EQ(gr.stats.packets.primary_missed, 0u) << "every primary ray starts inside";
                }
            }
        }
    }
}

TEST(RenderConservation, PacketsCreatedEqualConsumed)
{
    ScenePtr s = random_scene(9, 32);
    for (int cells : {1, 3, 24}) {
        for (bool brute : {false, true}) {
            Image r = render(s.get(), cells, brute);
            expect_conserved(r.stats);
            EXPECT_GT(r.stats.packets.created[RT_PACKET_SHADOW], 0u);
            // Primary packets plus misses cover every pixel once.
            EXPECT_GE(r.stats.packets.created[RT_PACKET_RAY] + r.stats.packets.primary_missed, 32u * 32u);
        }
    }
}

TEST(ShadingHighlight, HugeShineGivesFiniteValuesWhereRLIsOne)
{
    // A light straight along the mirror direction makes R.L 1 up to rounding, which can
    // land above 1: pow of that to a huge Shine must not overflow. SPD files use Shine
    // up to 100000; any finite Shine >= 0 is accepted.
    TestRng rng(99);
    for (double shine : {100000.0, 1e300}) {
        SCOPED_TRACE(shine);
        for (int i = 0; i < 400; i++) {
            ScenePtr s = new_scene();
            rt_material m = mat(rt_vec(0.5, 0.5, 0.5), 0.5, 0.5, shine, 0, 1);
            ASSERT_EQ(rt_scene_set_material(s.get(), &m), RT_OK);
            ASSERT_EQ(rt_scene_add_sphere(s.get(), rt_vec(0, 0, 0), 1.0), RT_OK);
            rt_vec3 eye = rt_vec_scale(rng.unit(), 5.0);
            rt_vec3 aim = rt_vec_scale(rng.unit(), 0.5);
            rt_vec3 d = rt_vec_normalize(rt_vec_sub(aim, eye));
            // Where the ray meets the sphere, and the mirror direction there.
            double b = rt_vec_dot(eye, d), c = rt_vec_dot(eye, eye) - 1.0;
            double t = -b - std::sqrt(b * b - c);
            rt_vec3 p = rt_vec_add(eye, rt_vec_scale(d, t)), n = rt_vec_normalize(p);
            rt_vec3 r = rt_vec_sub(d, rt_vec_scale(n, 2.0 * rt_vec_dot(d, n)));
            rt_vec3 white = rt_vec(1, 1, 1);
            ASSERT_EQ(rt_scene_add_light(s.get(), rt_vec_add(p, rt_vec_scale(r, 3.0)), &white), RT_OK);
            finish(s.get());
            GridPtr g = make_grid(s.get(), 4, 4, 4);
            rt_step_params prm = rt_step_params_default();
            StepOut o = run_step(s.get(), g.get(), prm, make_packet(g.get(), RT_PACKET_RAY, eye, d, white));
            ASSERT_EQ(o.status, RT_OK);
            for (const rt_packet &pk : o.created) {
                ASSERT_TRUE(rt_vec_is_finite(pk.weight)) << "packet " << i;
                EXPECT_LE(rt_vec_max_component(pk.weight), 0.5 * 0.5 + 0.5 + 1e-12);
            }
            for (const rt_contribution &ct : o.contrib) ASSERT_TRUE(rt_vec_is_finite(ct.rgb));
        }
    }
}
