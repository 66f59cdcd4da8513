// test_support.h - helpers shared by the kernel tests (tests/kernel/*.cpp, all linked into
// the one kernel_tests binary). Helpers used by a single test file stay in that file.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <initializer_list>
#include <memory>
#include <vector>

#include "rt_framebuffer.h"
#include "rt_grid.h"
#include "rt_render.h"
#include "rt_scene.h"
#include "rt_topology.h"
#include "rt_vec.h"

namespace torusrt_test {

// The topology registered as `name` on dims[0] x dims[1] x dims[2] nodes (a failed test if none).
inline rt_topology make_topology(const char *name, const int dims[3])
{
    rt_topology t{};
    char msg[256] = "";
    EXPECT_EQ(rt_topology_make(name, dims, &t, msg, sizeof msg), RT_OK) << msg;
    return t;
}

// Frees a scene owned by a ScenePtr.
struct SceneDeleter {
    void operator()(rt_scene *s) const { rt_scene_free(s); }
};
// Frees a grid owned by a GridPtr.
struct GridDeleter {
    void operator()(rt_grid *g) const { rt_grid_free(g); }
};
// Frees a frame buffer owned by an FbPtr.
struct FbDeleter {
    void operator()(rt_framebuffer *f) const { rt_framebuffer_free(f); }
};
using ScenePtr = std::unique_ptr<rt_scene, SceneDeleter>;
using GridPtr = std::unique_ptr<rt_grid, GridDeleter>;
using FbPtr = std::unique_ptr<rt_framebuffer, FbDeleter>;

// splitmix64: the same numbers on every platform and library.
class TestRng {
  public:
    explicit TestRng(uint64_t seed) : state_(seed) {}
    uint64_t next()
    {
        uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    double uniform(double lo, double hi) { return lo + (hi - lo) * double(next() >> 11) * 0x1.0p-53; }
    // An integer in [0, n), of n's type (int or uint32_t in the tests).
    template <typename T> T below(T n) { return T(next() % uint64_t(n)); }
    // A point with each coordinate uniform in [lo, hi).
    rt_vec3 point(double lo, double hi) { return rt_vec(uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)); }
    // A random unit vector (rejection sampling in the unit ball, away from its centre).
    rt_vec3 unit()
    {
        for (;;) {
            rt_vec3 v = point(-1, 1);
            double l = rt_vec_length(v);
            if (l > 0.1 && l <= 1.0) return rt_vec_scale(v, 1.0 / l);
        }
    }

  private:
    uint64_t state_;
};

// A sphere for scene_with_spheres.
struct Sphere {
    rt_vec3 center;
    double radius;
};

// A new scene (no view, default material) holding these spheres in order; a failed add is a
// test failure.
inline ScenePtr scene_with_spheres(std::initializer_list<Sphere> spheres)
{
    ScenePtr s(rt_scene_new());
    for (const Sphere &sp : spheres) EXPECT_EQ(rt_scene_add_sphere(s.get(), sp.center, sp.radius), RT_OK);
    return s;
}

// A grid of nx x ny x nz cells over s; when it cannot be built, a test failure with the reason
// and a null GridPtr.
inline GridPtr make_grid(const rt_scene *s, int nx, int ny, int nz)
{
    char msg[RT_MSG_LEN] = "";
    GridPtr g(rt_grid_new(s, nx, ny, nz, msg, sizeof msg));
    EXPECT_TRUE(g) << msg;
    return g;
}

// An image rendered in memory by render(): 8-bit RGB rows, the render's statistics, and ok
// when the grid was built and rt_render succeeded.
struct Image {
    uint32_t w = 0, h = 0;
    std::vector<uint8_t> rgb;
    rt_render_stats stats{};
    bool ok = false;
};

// Renders a finished scene at its camera's size on a cells^3 grid, with the brute-force oracle
// when brute is set and at max_depth when it is not negative; failures are test failures.
inline Image render(const rt_scene *s, int cells = 24, bool brute = false, int max_depth = -1)
{
    Image im;
    GridPtr g = make_grid(s, cells, cells, cells);
    if (!g) return im;
    const rt_camera *cam = rt_scene_camera(s);
    im.w = cam->width;
    im.h = cam->height;
    FbPtr fb(rt_framebuffer_new(im.w, im.h));
    rt_render_options o = rt_render_options_default();
    o.step.brute_force = brute ? 1 : 0;
    if (max_depth >= 0) o.step.max_depth = max_depth;
    char msg[RT_MSG_LEN] = "";
    rt_status st = rt_render(s, g.get(), &o, fb.get(), &im.stats, msg, sizeof msg);
    EXPECT_EQ(st, RT_OK) << msg;
    im.rgb.resize(size_t(im.w) * im.h * 3);
    rt_framebuffer_to_rgb8(fb.get(), im.rgb.data());
    im.ok = st == RT_OK;
    return im;
}

}  // namespace torusrt_test
