// smooth_triangle_test.cpp - thin `pp` triangles whose vertex normals tilt far from the face, as
// the spout of Haines' teapot at size factor 1: a flat fin in the plane y = 0 whose vertex
// normals are those of the tube it stands for, so they lie in the fin's plane, off it only by
// rounding (the generator writes y components like 7.3e-17 and -6.8e-17). The image must not
// depend on that rounding, the fin must have no dark pixels, and a tilted shading normal that
// faces a light must not be shadowed by its own triangle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "rt_nff.h"
#include "test_support.h"

using namespace torusrt_test;

namespace {

ScenePtr parse(const std::string &text)
{
    char msg[RT_MSG_LEN] = "";
    rt_scene *s = nullptr;
    EXPECT_EQ(rt_nff_parse("fin.nff", text.c_str(), text.size(), &s, msg, sizeof msg, nullptr, nullptr), RT_OK) << msg;
    return ScenePtr(s);
}

// The fin: a long thin quad (x 0..3, z 0.9..2.4) as four `pp` triangles, above a mirror floor,
// seen from above and aside as the teapot is. The vertex normals of the lower edge point down,
// those of the upper edge up, all in the plane y = 0 but for `noise` in their y component, with
// signs that differ from vertex to vertex. With `mask`, the fin alone in ambient white on black.
std::string fin_scene(double noise, bool mask = false)
{
    const char *setting = mask ? "b 0 0 0\nam 1 1 1\nf 1 1 1 0 0 0 0 0\n"
                               : "b 0.078 0.361 0.753\nl -3.1 9.8 12.1\nl 11.3 5.1 8.8\n"
                                 "f 0.5 0.5 0.5 0.5 0.5 4.8 0 0\np 4 -2 -3 0  5 -3 0  5 3 0  -2 3 0\n"
                                 "f 1 0.5 0.1 0.75 0.25 3.08 0 0\n";
    char buf[2048];
    std::snprintf(buf, sizeof buf,
                  "v from 4.86 7.2 5.4 at 1.5 0 1.2 up 0 0 1 angle 40 hither 1 resolution 64 64\n%s"
                  "pp 3  0 0 0.9 -0.16 %g -0.99  1.5 0 0.9 -0.6 %g -0.8  1.5 0 2.4 0.6 %g 0.8\n"
                  "pp 3  1.5 0 2.4 0.6 %g 0.8  0 0 2.4 0.16 %g 0.99  0 0 0.9 -0.16 %g -0.99\n"
                  "pp 3  1.5 0 0.9 -0.6 %g -0.8  3 0 0.9 0.38 %g -0.92  3 0 2.4 -0.41 %g 0.91\n"
                  "pp 3  3 0 2.4 -0.41 %g 0.91  1.5 0 2.4 0.6 %g 0.8  1.5 0 0.9 -0.6 %g -0.8\n",
                  setting, noise, -noise, noise, noise, -noise, -noise, -noise, noise, -noise, -noise, noise, -noise);
    return buf;
}

// Pixels whose primary ray hits the fin.
std::vector<uint8_t> fin_mask(double noise)
{
    ScenePtr s = parse(fin_scene(noise, true));
    Image im = render(s.get(), 8, true);
    std::vector<uint8_t> mask(size_t(im.w) * im.h, 0);
    for (size_t i = 0; i < mask.size() && im.ok; i++) mask[i] = im.rgb[3 * i] > 128;
    return mask;
}

int level(const Image &im, uint32_t x, uint32_t y)
{
    const uint8_t *p = &im.rgb[(size_t(y) * im.w + x) * 3];
    return int(p[0]) + p[1] + p[2];
}

}  // namespace

TEST(SmoothTriangle, RoundingInTheFinsNormalsDoesNotChangeTheImage)
{
    ScenePtr exact = parse(fin_scene(0.0)), noisy = parse(fin_scene(7.3e-17));
    ASSERT_TRUE(exact && noisy);
    Image a = render(exact.get()), b = render(noisy.get());
    ASSERT_TRUE(a.ok && b.ok);
    int differ = 0, worst = 0;
    for (size_t i = 0; i < a.rgb.size(); i++) {
        int d = std::abs(int(a.rgb[i]) - int(b.rgb[i]));
        differ += d > 2;
        if (d > worst) worst = d;
    }
    EXPECT_EQ(differ, 0) << "channels off by more than 2 levels (worst " << worst << ")";
}

// Both lights are above the fin, on the camera's side: every fin pixel gets light from one of
// them (POV-Ray on the same triangles agrees). A dark pixel is one whose shadow or mirror ray
// hit its own triangle, or whose shading normal was turned away from the camera.
TEST(SmoothTriangle, FinHasNoDarkPixel)
{
    ScenePtr s = parse(fin_scene(7.3e-17));
    ASSERT_TRUE(s);
    Image im = render(s.get());
    ASSERT_TRUE(im.ok);
    std::vector<uint8_t> fin = fin_mask(7.3e-17);
    std::vector<int> levels;
    for (uint32_t y = 0; y < im.h; y++)
        for (uint32_t x = 0; x < im.w; x++)
            if (fin[y * im.w + x]) levels.push_back(level(im, x, y));
    ASSERT_GT(levels.size(), 200u) << "the camera must see the fin";
    std::vector<int> sorted = levels;
    std::sort(sorted.begin(), sorted.end());
    int median = sorted[sorted.size() / 2], dark = 0;
    for (int l : levels) dark += 4 * l < median;
    EXPECT_EQ(dark, 0) << "fin pixels darker than a quarter of the fin's median level " << median << " (of "
                       << levels.size() << ")";
}

// One triangle facing the camera (+z), its vertex normals tilted toward +x, and one light far
// out at +x slightly behind the plane: the shading normal faces the light, the face does not.
// Nothing but the triangle itself lies between them, so the pixel gets the light's diffuse term.
TEST(SmoothTriangle, TiltedNormalIsNotShadowedByItsOwnTriangle)
{
    const char *text = "v from 0 0 5 at 0 0 0 up 0 1 0 angle 10 hither 1 resolution 3 3\n"
                       "l 100 0 -10 1 1 1\n"
                       "f 1 1 1 1 0 0 0 0\n"
                       "pp 3 -1 -1 0 0.8 0 0.6  1 -1 0 0.8 0 0.6  0 1 0 0.8 0 0.6\n";
    ScenePtr s = parse(text);
    ASSERT_TRUE(s);
    Image im = render(s.get(), 4);
    ASSERT_TRUE(im.ok);
    // c = N.L with N = (0.8, 0, 0.6) and L nearly (1, 0, -0.1): about 0.74, 189 of 255.
    const uint8_t *centre = &im.rgb[(1 * im.w + 1) * 3];
    EXPECT_GT(int(centre[0]), 150) << "the centre pixel is shadowed by its own triangle";
}
