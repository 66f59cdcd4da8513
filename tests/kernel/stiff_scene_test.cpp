// stiff_scene_test.cpp - the stiff scenes of docs/design.md section 9, rendered in memory.
//
// The scenes come from scenes/gen_scenes.c and are read from SOURCE_DIR/scenes/NAME.nff
// (or from $TORUSRT_SCENE_DIR when that is set, e.g. a folder the generator just wrote).
// A missing scene file is a failure that names the file, never a skip.
//
// Checks: the scale scenes agree with scale-1 (byte for byte for the power-of-two
// factors, within 2 levels on 99.5 % of pixels and never more than 64 for 1e-6 and
// 1e6); tiny-sphere agrees with tiny-sphere-alone the same way; facing-mirrors makes ray
// packets down to depth 8 and none deeper; light-inside has directly lit pixels on every
// side of the light's image; empty is all background; one-pixel renders; every scene
// conserves packets and its grid image equals the brute-force image.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <deque>
#include <string>
#include <sys/stat.h>
#include <vector>

#include "rt_framebuffer.h"
#include "rt_grid.h"
#include "rt_nff.h"
#include "rt_packet.h"
#include "rt_render.h"
#include "rt_scene.h"
#include "rt_step.h"
#include "test_support.h"

using namespace torusrt_test;

namespace {

const char *const kStiffScenes[] = {
    "scale-1",     "scale-tiny",        "scale-huge",        "scale-pow2-tiny", "scale-pow2-huge",
    "tiny-sphere", "tiny-sphere-alone", "facing-mirrors",    "light-inside",    "tir",
    "grazing",     "axis-rays",         "grid-corners",      "eye-inside",      "empty",
    "one-cell",    "one-big-sphere",    "cones-and-patches", "one-pixel",       "opposing-normals"};

std::string scene_dir()
{
    const char *env = std::getenv("TORUSRT_SCENE_DIR");
    if (env && *env) return env;
    return std::string(TORUSRT_SOURCE_DIR) + "/scenes";
}

std::string scene_path(const std::string &name) { return scene_dir() + "/" + name + ".nff"; }

// Loads a scene; a missing or unreadable file is a test failure naming it.
ScenePtr load(const std::string &name)
{
    std::string path = scene_path(name);
    struct stat st;
    if (stat(path.c_str(), &st) != 0) {
        ADD_FAILURE() << "scene file missing: " << path
                      << " (write it with torusrt-genscenes, or set TORUSRT_SCENE_DIR)";
        return nullptr;
    }
    char msg[RT_MSG_LEN] = "";
    rt_scene *s = nullptr;
    rt_status status = rt_nff_load(path.c_str(), &s, msg, sizeof msg, nullptr, nullptr);
    if (status != RT_OK) {
        ADD_FAILURE() << "cannot load " << path << ": " << msg;
        return nullptr;
    }
    return ScenePtr(s);
}

Image render_named(const std::string &name, int cells = 24, bool brute = false)
{
    ScenePtr s = load(name);
    if (!s) return Image();
    return render(s.get(), cells, brute);
}

// Per-pixel largest channel difference.
std::vector<int> pixel_diffs(const Image &a, const Image &b)
{
    std::vector<int> d;
    if (a.rgb.size() != b.rgb.size()) return d;
    for (size_t i = 0; i < a.rgb.size(); i += 3) {
        int m = 0;
        for (int c = 0; c < 3; c++) m = std::max(m, std::abs(int(a.rgb[i + c]) - int(b.rgb[i + c])));
        d.push_back(m);
    }
    return d;
}

// max abs difference <= 2 levels on >= 99.5 % of pixels, and no pixel off by more than 64.
void expect_close(const Image &a, const Image &b, const std::string &what)
{
    ASSERT_TRUE(a.ok && b.ok) << what;
    ASSERT_EQ(a.w, b.w) << what;
    ASSERT_EQ(a.h, b.h) << what;
    std::vector<int> d = pixel_diffs(a, b);
    size_t within = size_t(std::count_if(d.begin(), d.end(), [](int x) { return x <= 2; }));
    int worst = d.empty() ? 0 : *std::max_element(d.begin(), d.end());
    EXPECT_GE(double(within), 0.995 * double(d.size()))
        << what << ": " << d.size() - within << " of " << d.size() << " pixels differ by more than 2 levels";
    EXPECT_LE(worst, 64) << what << ": largest difference " << worst << " levels";
}

// The shade tree of every pixel, walked here with rt_step (one owner, FIFO per pixel):
// ray packets made per depth, and which pixels a shadow packet lit.
struct TreeWalk {
    std::vector<uint64_t> rays_by_depth;
    std::vector<uint8_t> lit;  // per pixel: some shadow packet added light
    std::vector<uint8_t> rgb;
    uint64_t created[RT_PACKET_KINDS] = {0, 0}, consumed[RT_PACKET_KINDS] = {0, 0};
};

TreeWalk walk_trees(const rt_scene *s, const rt_grid *g, const rt_step_params &params)
{
    TreeWalk tw;
    const rt_camera *cam = rt_scene_camera(s);
    tw.lit.assign(size_t(cam->width) * cam->height, 0);
    FbPtr fb(rt_framebuffer_new(cam->width, cam->height));
    rt_step_result r;
    EXPECT_EQ(rt_step_result_init(&r, s), RT_OK);
    auto count_ray = [&](const rt_packet &p) {
        if (p.kind != RT_PACKET_RAY) return;
        if (tw.rays_by_depth.size() <= p.depth) tw.rays_by_depth.resize(p.depth + 1u, 0);
        tw.rays_by_depth[p.depth]++;
    };
    for (uint32_t y = 0; y < cam->height; y++)
        for (uint32_t x = 0; x < cam->width; x++) {
            rt_packet p;
            int enters = 0;
            EXPECT_EQ(rt_primary_packet(s, g, x, y, &p, &enters), RT_OK);
            if (!enters) {
                rt_framebuffer_add(fb.get(), x, y, rt_scene_background(s));
                continue;
            }
            std::deque<rt_packet> q{p};
            tw.created[RT_PACKET_RAY]++;
            count_ray(p);
            while (!q.empty()) {
                rt_packet cur = q.front();
                q.pop_front();
                EXPECT_EQ(rt_step(s, g, nullptr, 0, &params, &cur, &r), RT_OK);
                for (size_t i = 0; i < r.contrib_count; i++) {
                    rt_framebuffer_add(fb.get(), r.contrib[i].x, r.contrib[i].y, r.contrib[i].rgb);
                    if (cur.kind == RT_PACKET_SHADOW) tw.lit[size_t(y) * cam->width + x] = 1;
                }
                for (size_t i = 0; i < r.created_count; i++) {
                    tw.created[r.created[i].kind]++;
                    count_ray(r.created[i]);
                    q.push_back(r.created[i]);
                }
                EXPECT_NE(r.fate, RT_FATE_FORWARDED);
                tw.consumed[cur.kind]++;
            }
        }
    rt_step_result_release(&r);
    tw.rgb.resize(size_t(cam->width) * cam->height * 3);
    rt_framebuffer_to_rgb8(fb.get(), tw.rgb.data());
    return tw;
}

uint8_t to_byte(double v)
{
    v = v < 0 ? 0 : v > 1 ? 1 : v;
    return uint8_t(std::floor(v * 255 + 0.5));
}

}  // namespace

TEST(RenderStiffScenes, EverySceneFileIsPresent)
{
    for (const char *name : kStiffScenes) {
        struct stat st;
        EXPECT_EQ(stat(scene_path(name).c_str(), &st), 0) << "scene file missing: " << scene_path(name);
    }
}

TEST(RenderStiffScale, PowerOfTwoScalesAreByteIdentical)
{
    Image one = render_named("scale-1");
    ASSERT_TRUE(one.ok);
    for (const char *name : {"scale-pow2-tiny", "scale-pow2-huge"}) {
        Image im = render_named(name);
        ASSERT_TRUE(im.ok) << name;
        EXPECT_EQ(im.rgb, one.rgb) << name << " differs from scale-1";
        EXPECT_EQ(im.stats.ops.shadings, one.stats.ops.shadings) << name;
        EXPECT_EQ(im.stats.packets.created[RT_PACKET_RAY], one.stats.packets.created[RT_PACKET_RAY]) << name;
        EXPECT_EQ(im.stats.packets.created[RT_PACKET_SHADOW], one.stats.packets.created[RT_PACKET_SHADOW]) << name;
    }
}

TEST(RenderStiffScale, DecimalScalesAreClose)
{
    Image one = render_named("scale-1");
    ASSERT_TRUE(one.ok);
    // The scene is not trivial: it has several distinct colours.
    std::vector<bool> seen(256);
    for (uint8_t v : one.rgb) seen[v] = true;
    EXPECT_GT(std::count(seen.begin(), seen.end(), true), 30);
    for (const char *name : {"scale-tiny", "scale-huge"}) expect_close(render_named(name), one, name);
}

TEST(RenderStiffTiny, TinySphereBesideAHugeOneMatchesItAlone)
{
    Image with = render_named("tiny-sphere"), alone = render_named("tiny-sphere-alone");
    expect_close(with, alone, "tiny-sphere vs tiny-sphere-alone");
    // The tiny sphere is visible: not every pixel is one colour.
    ASSERT_TRUE(alone.ok);
    size_t differ = 0;
    for (size_t i = 3; i < alone.rgb.size(); i++) differ += alone.rgb[i] != alone.rgb[i % 3];
    EXPECT_GT(differ, alone.rgb.size() / 10);
}

TEST(RenderStiffMirrors, RaysReachDepthEightAndNoDeeper)
{
    ScenePtr s = load("facing-mirrors");
    ASSERT_TRUE(s);
    char msg[RT_MSG_LEN] = "";
    GridPtr g(rt_grid_new(s.get(), 24, 24, 24, msg, sizeof msg));
    ASSERT_TRUE(g) << msg;
    for (int max_depth : {8, 3, 0}) {
        SCOPED_TRACE("max_depth " + std::to_string(max_depth));
        rt_step_params prm = rt_step_params_default();
        prm.max_depth = max_depth;
        TreeWalk tw = walk_trees(s.get(), g.get(), prm);
        ASSERT_EQ(tw.rays_by_depth.size(), size_t(max_depth) + 1) << "deepest ray packet made";
        EXPECT_GT(tw.rays_by_depth[max_depth], 100u) << "many rays bounce all the way to the limit";
        for (int k = 0; k < RT_PACKET_KINDS; k++) EXPECT_EQ(tw.created[k], tw.consumed[k]);
        // The renderer agrees with this walk, image and packet counts.
        Image im = render(s.get(), 24, false, max_depth);
        ASSERT_TRUE(im.ok);
        EXPECT_EQ(im.rgb, tw.rgb);
        EXPECT_EQ(im.stats.packets.created[RT_PACKET_RAY], tw.created[RT_PACKET_RAY]);
        EXPECT_EQ(im.stats.packets.created[RT_PACKET_SHADOW], tw.created[RT_PACKET_SHADOW]);
        uint64_t secondary = 0;
        for (size_t d = 1; d < tw.rays_by_depth.size(); d++) secondary += tw.rays_by_depth[d];
        EXPECT_EQ(im.stats.ops.reflection_vectors + im.stats.ops.refraction_vectors, secondary)
            << "every secondary ray packet came from one reflection or refraction vector";
    }
}

TEST(RenderStiffLight, LitOnEverySideOfTheLight)
{
    ScenePtr s = load("light-inside");
    ASSERT_TRUE(s);
    ASSERT_EQ(rt_scene_light_count(s.get()), 1u);
    char msg[RT_MSG_LEN] = "";
    GridPtr g(rt_grid_new(s.get(), 24, 24, 24, msg, sizeof msg));
    ASSERT_TRUE(g) << msg;
    rt_vec3 L = rt_scene_light(s.get(), 0)->position;
    rt_box space = rt_grid_bounds(g.get());
    EXPECT_TRUE(L.x > space.lo.x && L.x < space.hi.x && L.y > space.lo.y && L.y < space.hi.y && L.z > space.lo.z &&
                L.z < space.hi.z)
        << "the light should lie inside the object space";
    // Where the light appears in the image (docs/design.md section 3 camera).
    const rt_camera *cam = rt_scene_camera(s.get());
    rt_vec3 w = rt_vec_normalize(rt_vec_sub(cam->at, cam->from));
    rt_vec3 u = rt_vec_normalize(rt_vec_cross(w, cam->up));
    rt_vec3 v = rt_vec_cross(u, w);
    double sp = 2 * std::tan(cam->angle * M_PI / 360) / std::max<double>(std::max(cam->width, cam->height) - 1, 1);
    rt_vec3 dl = rt_vec_sub(L, cam->from);
    ASSERT_GT(rt_vec_dot(dl, w), 0.0);
    double li = (cam->width - 1) / 2.0 + rt_vec_dot(dl, u) / rt_vec_dot(dl, w) / sp;
    double lj = (cam->height - 1) / 2.0 - rt_vec_dot(dl, v) / rt_vec_dot(dl, w) / sp;
    TreeWalk tw = walk_trees(s.get(), g.get(), rt_step_params_default());
    int quadrant_lit[4] = {0, 0, 0, 0};
    for (uint32_t y = 0; y < cam->height; y++)
        for (uint32_t x = 0; x < cam->width; x++) {
            if (!tw.lit[size_t(y) * cam->width + x]) continue;
            int q = (x < li ? 0 : 1) + (y < lj ? 0 : 2);
            quadrant_lit[q]++;
        }
    const char *names[4] = {"upper left", "upper right", "lower left", "lower right"};
    for (int q = 0; q < 4; q++)
        EXPECT_GT(quadrant_lit[q], 10) << "directly lit pixels " << names[q] << " of the light's image at (" << li
                                       << ", " << lj << ")";
    // Lit pixels are brighter than the background there.
    Image im = render(s.get());
    ASSERT_TRUE(im.ok);
    EXPECT_EQ(im.rgb, tw.rgb);
}

TEST(RenderStiffEmpty, AllBackground)
{
    ScenePtr s = load("empty");
    ASSERT_TRUE(s);
    EXPECT_EQ(rt_scene_object_count(s.get()), 0u);
    rt_vec3 b = rt_scene_background(s.get());
    uint8_t want[3] = {to_byte(b.x), to_byte(b.y), to_byte(b.z)};
    for (bool brute : {false, true}) {
        Image im = render(s.get(), 24, brute);
        ASSERT_TRUE(im.ok);
        for (size_t i = 0; i < im.rgb.size(); i++) ASSERT_EQ(im.rgb[i], want[i % 3]) << "byte " << i;
        EXPECT_EQ(im.stats.ops.shadings, 0u);
        EXPECT_EQ(im.stats.ops.tests_hit + im.stats.ops.tests_missed, 0u);
        if (!brute) {
            EXPECT_EQ(im.stats.packets.primary_missed, uint64_t(im.w) * im.h);
        }
    }
}

TEST(RenderStiffOnePixel, RendersOnePixel)
{
    ScenePtr s = load("one-pixel");
    ASSERT_TRUE(s);
    const rt_camera *cam = rt_scene_camera(s.get());
    ASSERT_EQ(cam->width, 1u);
    ASSERT_EQ(cam->height, 1u);
    // The one ray goes exactly along the view direction.
    rt_vec3 d = rt_primary_direction(cam, 0, 0);
    rt_vec3 w = rt_vec_normalize(rt_vec_sub(cam->at, cam->from));
    EXPECT_NEAR(d.x, w.x, 1e-15);
    EXPECT_NEAR(d.y, w.y, 1e-15);
    EXPECT_NEAR(d.z, w.z, 1e-15);
    Image im = render(s.get()), bf = render(s.get(), 1, true);
    ASSERT_TRUE(im.ok && bf.ok);
    ASSERT_EQ(im.rgb.size(), 3u);
    EXPECT_EQ(im.rgb, bf.rgb);
    EXPECT_GE(im.stats.ops.shadings, 1u) << "the single ray hits the sphere";
    rt_vec3 b = rt_scene_background(s.get());
    std::vector<uint8_t> background = {to_byte(b.x), to_byte(b.y), to_byte(b.z)};
    EXPECT_NE(im.rgb, background);
}

TEST(RenderStiffScenes, EverySceneConservesPacketsAndMatchesBruteForce)
{
    for (const char *name : kStiffScenes) {
        SCOPED_TRACE(name);
        ScenePtr s = load(name);
        if (!s) continue;  // load() has already failed the test, naming the file
        Image grid = render(s.get(), 24, false);
        Image bf = render(s.get(), 1, true);
        ASSERT_TRUE(grid.ok && bf.ok);
        for (const Image *im : {&grid, &bf})
            for (int k = 0; k < RT_PACKET_KINDS; k++)
                EXPECT_EQ(im->stats.packets.created[k], im->stats.packets.consumed[k]) << "kind " << k;
        EXPECT_EQ(grid.rgb, bf.rgb) << "grid image differs from brute force";
        Image again = render(s.get(), 24, false);
        EXPECT_EQ(again.rgb, grid.rgb) << "two renders differ";
        for (int cells : {1, 7}) {
            Image other = render(s.get(), cells, false);
            EXPECT_EQ(other.rgb, bf.rgb) << "cells " << cells;
        }
    }
}
