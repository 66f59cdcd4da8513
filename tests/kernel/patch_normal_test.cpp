// patch_normal_test.cpp - `pp` shading normals where the vertex normals cancel
// (scenes/opposing-normals.nff, the poles of Haines' teapot): for every camera hit on a
// patch the shading normal is unit, finite and on the vertex normals' side of the face,
// and the rendered lid has no isolated dark pixel (a speckle).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "rt_nff.h"
#include "rt_packet.h"
#include "test_support.h"

// Kernel-internal C headers without C++ guards.
extern "C" {
#include "intersect.h"
#include "scene_internal.h"
}

using namespace torusrt_test;

namespace {

ScenePtr load_opposing()
{
    std::string path = std::string(TORUSRT_SOURCE_DIR) + "/scenes/opposing-normals.nff";
    char msg[RT_MSG_LEN] = "";
    rt_scene *s = nullptr;
    EXPECT_EQ(rt_nff_load(path.c_str(), &s, msg, sizeof msg, nullptr, nullptr), RT_OK) << msg;
    return ScenePtr(s);
}

// The nearest object a ray hits, by testing every object; -1 for none.
long nearest(const rt_scene *s, rt_vec3 o, rt_vec3 d, rt_hit *best)
{
    long found = -1;
    for (uint32_t i = 0; i < rt_scene_object_count(s); i++) {
        rt_hit h;
        if (rt_intersect_object(s, i, o, d, 0.0, INFINITY, &h) && (found < 0 || h.t < best->t)) {
            *best = h;
            found = long(i);
        }
    }
    return found;
}

}  // namespace

TEST(PatchNormal, UnitFiniteAndOnTheVertexNormalsSideForEveryHit)
{
    ScenePtr s = load_opposing();
    ASSERT_TRUE(s);
    GridPtr g = make_grid(s.get(), 8, 8, 8);
    ASSERT_TRUE(g);
    const rt_camera *cam = rt_scene_camera(s.get());
    int patch_hits = 0;
    // Four rays per pixel: the rounding noise of a cancelled sum shows on few of them.
    const int sub = 4;
    for (uint32_t y = 0; y < cam->height * sub; y++)
        for (uint32_t x = 0; x < cam->width * sub; x++) {
            rt_packet p;
            int enters = 0;
            ASSERT_EQ(rt_primary_packet(s.get(), g.get(), x / sub, y / sub, &p, &enters), RT_OK);
            // Spread the sub-rays inside the pixel by tilting the primary direction.
            double du = ((x % sub) + 0.5) / sub - 0.5, dv = ((y % sub) + 0.5) / sub - 0.5;
            rt_vec3 d = rt_vec_normalize(rt_vec_add(p.dir, rt_vec(du * 0.01, dv * 0.01, 0)));
            rt_hit h;
            long o = nearest(s.get(), p.origin, d, &h);
            if (o < 0 || rt_scene_object_kind(s.get(), size_t(o)) != RT_OBJ_TRIANGLE) continue;
            patch_hits++;
            const rt_triangle_data &t = s->objects[o].u.triangle;
            rt_vec3 sum = rt_vec_add(t.n[0], rt_vec_add(t.n[1], t.n[2]));
            rt_vec3 face = rt_vec_scale(t.normal, rt_vec_dot(sum, t.normal) < 0 ? -1.0 : 1.0);
            rt_vec3 pt = rt_vec_add(p.origin, rt_vec_scale(d, h.t));
            rt_vec3 ng, ns;
            rt_object_normals(s.get(), uint32_t(o), pt, &h, &ng, &ns);
            ASSERT_TRUE(rt_vec_is_finite(ns)) << "object " << o;
            ASSERT_NEAR(rt_vec_length(ns), 1.0, 1e-12) << "object " << o;
            ASSERT_GT(rt_vec_dot(ns, face), 0.0)
                << "object " << o << " at u " << h.u << " v " << h.v << ": shading normal (" << ns.x << ", " << ns.y
                << ", " << ns.z << ") is behind the face";
        }
    EXPECT_GT(patch_hits, 1000) << "the camera must see the lid";
}

TEST(PatchNormal, RenderedLidHasNoIsolatedDarkPixel)
{
    ScenePtr s = load_opposing();
    ASSERT_TRUE(s);
    Image im = render(s.get(), 24);
    ASSERT_TRUE(im.ok);
    GridPtr g = make_grid(s.get(), 24, 24, 24);
    ASSERT_TRUE(g);
    // Which pixels see the lid, from the centre primary ray.
    std::vector<uint8_t> lid(size_t(im.w) * im.h, 0);
    for (uint32_t y = 0; y < im.h; y++)
        for (uint32_t x = 0; x < im.w; x++) {
            rt_packet p;
            int enters = 0;
            ASSERT_EQ(rt_primary_packet(s.get(), g.get(), x, y, &p, &enters), RT_OK);
            rt_hit h;
            long o = nearest(s.get(), p.origin, p.dir, &h);
            lid[y * im.w + x] = o >= 0 && rt_scene_object_kind(s.get(), size_t(o)) == RT_OBJ_TRIANGLE;
        }
    auto level = [&](uint32_t x, uint32_t y) {
        const uint8_t *px = &im.rgb[(size_t(y) * im.w + x) * 3];
        return int(px[0]) + px[1] + px[2];
    };
    int speckles = 0;
    for (uint32_t y = 1; y + 1 < im.h; y++)
        for (uint32_t x = 1; x + 1 < im.w; x++) {
            if (!lid[y * im.w + x]) continue;
            // A speckle: darker than half of every lid neighbour, all 8 of them on the lid.
            int darker_than = 0, neighbours = 0;
            for (int dy = -1; dy <= 1; dy++)
                for (int dx = -1; dx <= 1; dx++) {
                    if (!dx && !dy) continue;
                    uint32_t nx = x + dx, ny = y + dy;
                    if (!lid[ny * im.w + nx]) continue;
                    neighbours++;
                    if (2 * level(x, y) < level(nx, ny)) darker_than++;
                }
            if (neighbours == 8 && darker_than == 8) {
                speckles++;
                ADD_FAILURE() << "speckle at pixel (" << x << ", " << y << ")";
            }
        }
    EXPECT_EQ(speckles, 0);
}
