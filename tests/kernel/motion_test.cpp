// motion_test.cpp - the motion file's reader and its errors, keyframe interpolation, moving
// spheres, polygons, patches and cones, and the object space over every frame.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "rt_motion.h"
#include "rt_scene.h"
#include "scene_internal.h"
#include "test_support.h"

namespace {

using torusrt_test::ScenePtr;

struct MotionDeleter {
    void operator()(rt_motion *m) const { rt_motion_free(m); }
};
using MotionPtr = std::unique_ptr<rt_motion, MotionDeleter>;

// Parses `text` as motion file "t.motion"; the message (empty on success) in *error.
MotionPtr parse(const std::string &text, std::string *error = nullptr, rt_status *status = nullptr)
{
    char msg[512] = "";
    rt_motion *m = nullptr;
    rt_status st = rt_motion_parse("t.motion", text.data(), text.size(), &m, msg, sizeof msg);
    if (status) *status = st;
    if (error) *error = msg;
    EXPECT_EQ(st == RT_OK, m != nullptr);
    return MotionPtr(m);
}

// The message of a refused text; fails the test if it was accepted.
std::string refused(const std::string &text)
{
    std::string error;
    MotionPtr m = parse(text, &error);
    EXPECT_EQ(m, nullptr) << "accepted:\n" << text;
    return error;
}

// Two unit spheres at (-2, 0, 0) and (2, 0, 0), a triangle, a polygon and a cone.
ScenePtr five_objects()
{
    ScenePtr s(rt_scene_new());
    rt_scene_set_view(s.get(), rt_vec(0, 0, 10), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45, 16, 16);
    rt_scene_add_sphere(s.get(), rt_vec(-2, 0, 0), 1);
    rt_scene_add_sphere(s.get(), rt_vec(2, 0, 0), 1);
    const rt_vec3 tri[3] = {rt_vec(0, 0, 0), rt_vec(1, 0, 0), rt_vec(0, 1, 0)};
    const rt_vec3 nrm[3] = {rt_vec(0, 0, 1), rt_vec(0, 0, 1), rt_vec(0, 0, 1)};
    rt_scene_add_patch(s.get(), tri, nrm, 3);
    const rt_vec3 quad[4] = {rt_vec(0, 0, -1), rt_vec(1, 0, -1), rt_vec(1, 1, -1), rt_vec(0, 1, -1)};
    rt_scene_add_polygon(s.get(), quad, 4);
    rt_scene_add_cone(s.get(), rt_vec(0, 0, 0), 1, rt_vec(0, 2, 0), 0.5);
    rt_scene_finish(s.get(), nullptr, 0);
    return s;
}

rt_vec3 center(const rt_scene *s, size_t o) { return s->objects[o].u.sphere.center; }

void expect_near(rt_vec3 got, rt_vec3 want, double tol = 1e-12)
{
    EXPECT_NEAR(got.x, want.x, tol);
    EXPECT_NEAR(got.y, want.y, tol);
    EXPECT_NEAR(got.z, want.z, tol);
}

// Moves a clone of `s` to frame k; the moved flags in *moved.
ScenePtr at_frame(const rt_motion *m, const rt_scene *s, uint32_t k, std::vector<uint8_t> *moved = nullptr)
{
    ScenePtr f(rt_scene_clone(s));
    std::vector<uint8_t> flags(rt_scene_object_count(s));
    char msg[256] = "";
    EXPECT_EQ(rt_motion_apply(m, s, f.get(), k, flags.data(), msg, sizeof msg), RT_OK) << msg;
    if (moved) *moved = flags;
    return f;
}

TEST(MotionFile, ReadsEveryStatement)
{
    MotionPtr m = parse("# a comment\n"
                        "frames 8   # eight\n"
                        "objects 0 1\r\n"
                        "pivot 1 2 3\n"
                        "axis 0 0 2\n"
                        "key 0\n"
                        "key 4 move 1 0 0 turn 90 scale 2\r"
                        "\r\n"
                        "objects 3\n"
                        "key 2 scale 0.5 move 0 1 0\n");
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(rt_motion_frame_count(m.get()), 8u);
    ASSERT_EQ(rt_motion_entry_count(m.get()), 2u);
    rt_motion_entry_info a = rt_motion_entry(m.get(), 0), b = rt_motion_entry(m.get(), 1);
    EXPECT_EQ(a.line, 3u);
    EXPECT_EQ(a.first, 0u);
    EXPECT_EQ(a.last, 1u);
    EXPECT_EQ(a.keys, 2u);
    EXPECT_EQ(b.line, 9u); /* a lone "\r", then "\r\n" ending a blank line */
    EXPECT_EQ(b.first, 3u);
    EXPECT_EQ(b.last, 3u);
}

TEST(MotionFile, FrameCountFromTheLastKey)
{
    MotionPtr m = parse("objects 0\nkey 0\nkey 63 move 1 0 0\nobjects 1\nkey 10\n");
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(rt_motion_frame_count(m.get()), 64u);
    MotionPtr still = parse("frames 5\n");
    ASSERT_NE(still, nullptr);
    EXPECT_EQ(rt_motion_frame_count(still.get()), 5u);
    EXPECT_EQ(rt_motion_entry_count(still.get()), 0u);
}

TEST(MotionFile, EveryErrorNamesFileAndLine)
{
    struct Case {
        const char *text, *want;
    } cases[] = {
        {"frames 0\n", "t.motion:1: frames 0"},
        {"frames 2\nframes 3\n", "t.motion:2: a second 'frames' line (the first is line 1)"},
        {"frames x\n", "t.motion:1: frames 'x' is not a whole number"},
        {"frames 100001\n", "t.motion:1: frames 100001 is above 100000"},
        {"frames -1\n", "t.motion:1: frames '-1' is not a whole number"},
        {"frames 4 5\n", "t.motion:1: 'frames' takes one number"},
        {"\n\nwobble 3\n", "t.motion:3: unknown statement 'wobble'"},
        {"key 0\n", "t.motion:1: 'key' before any 'objects' line"},
        {"pivot 0 0 0\n", "t.motion:1: 'pivot' before any 'objects' line"},
        {"objects\n", "t.motion:1: 'objects' takes FIRST [LAST]"},
        {"objects 3 1\nkey 0\n", "t.motion:1: objects 3 1: LAST is below FIRST"},
        {"objects 0 4\nkey 0\nobjects 4 6\nkey 0\n", "t.motion:3: objects 4-6 overlap objects 0-4 of line 1"},
        {"objects 4000000\n", "t.motion:1: objects FIRST 4000000 is above 3999999"},
        {"objects 0\nkey 0\nobjects 1\n", "t.motion:3: objects 1-1 have no 'key' line"},
        {"objects 0\npivot 1 2\n", "t.motion:2: 'pivot' takes three numbers"},
        {"objects 0\npivot 0 0 0\npivot 1 1 1\n",
         "t.motion:3: a second 'pivot' line in this entry (the first is line 2)"},
        {"objects 0\naxis 0 0 0\n", "t.motion:2: axis 0 0 0: a rotation axis needs a direction"},
        {"objects 0\naxis -0 0e5 0.0\n", "t.motion:2: axis -0 0e5 0.0: a rotation axis needs a direction"},
        /* The overlap is found wherever it is in the file, and said at the later line. */
        {"objects 0 9\nkey 0\nobjects 20\nkey 0\nobjects 12\nkey 0\nobjects 9 11\nkey 0\n",
         "t.motion:7: objects 9-11 overlap objects 0-9 of line 1"},
        {"objects 30\nkey 0\nobjects 5 40\nkey 0\nobjects 6\nkey 0\n",
         "t.motion:3: objects 5-40 overlap objects 30-30 of line 1"},
        {"objects 0\naxis 0 nan 1\n", "t.motion:2: axis 'nan' is not a number"},
        {"objects 0\nkey 0 move 1 2\n", "t.motion:2: move needs three numbers"},
        /* One decimal syntax (rt_number.h): no leading zero, sign, bare point or underflow. */
        {"frames 010\n", "t.motion:1: frames '010' has a leading zero"},
        {"objects 0\nkey 0 move +5 0 0\n", "t.motion:2: move '+5' is not a number"},
        {"objects 0\nkey 0 move 0 .5 0\n", "t.motion:2: move '.5' is not a number"},
        {"objects 0\nkey 0 scale 5.\n", "t.motion:2: scale '5.' is not a number"},
        {"objects 0\nkey 0 move 1e-400 0 0\n", "t.motion:2: move '1e-400' is too close to 0"},
        {"objects 0\nkey 0 move 1e31 0 0\n", "t.motion:2: move '1e31' is above 1e30 in magnitude"},
        {"objects 0\nkey 0 spin 3\n", "t.motion:2: unknown key part 'spin'"},
        {"objects 0\nkey 0 scale 2 scale 3\n", "t.motion:2: 'scale' twice in one key"},
        {"objects 0\nkey 0 scale 0\n", "t.motion:2: scale 0: must be from 1e-06 to 1e+06"},
        {"objects 0\nkey 0 scale -1\n", "t.motion:2: scale -1: must be from"},
        {"objects 0\nkey 0 scale\n", "t.motion:2: 'scale' needs a number"},
        {"objects 0\naxis 0 1 0\nkey 0 turn 2e6\n", "t.motion:3: turn 2e6: at most 1e+06 degrees"},
        {"objects 0\nkey 0 turn 30\n", "t.motion:2: key 0 turns: give the entry an 'axis X Y Z' line"},
        {"objects 0\nkey 5\nkey 5\n", "t.motion:3: key 5: frames must increase within an entry"},
        {"objects 0\nkey 5\nkey 2\n", "t.motion:3: key 2: frames must increase"},
        {"objects 0\nkey 1000001\n", "t.motion:2: key frame 1000001 is above 1000000"},
        {"objects 0\nkey 100000\n", "t.motion:2: no 'frames' line, and the last key (frame 100000) makes more than"},
        {"", "t.motion:1: no 'frames' line and no key"},
        {"# only a comment\n", "t.motion:1: no 'frames' line and no key"},
        {"frames 2\nobjects 0\x01\n", "t.motion:2: binary data (byte 0x01)"},
        {"a b c d e f g h i j k l m n o p q\n", "t.motion:1: more than 16 words on one line"},
    };
    for (const Case &c : cases) {
        std::string error = refused(c.text);
        EXPECT_EQ(error.rfind(c.want, 0), 0u) << "text:\n" << c.text << "\ngot: " << error << "\nwant: " << c.want;
    }
}

TEST(MotionFile, NulByteAndLongLineAreRefused)
{
    std::string nul("frames 2\nobjects 0", 19);
    nul += '\0';
    nul += "\nkey 0\n";
    EXPECT_EQ(refused(nul).rfind("t.motion:2: binary data (byte 0x00)", 0), 0u);
    rt_status st = RT_OK;
    std::string error;
    MotionPtr m = parse("frames 2 #" + std::string(5000, 'x') + "\n", &error, &st);
    EXPECT_EQ(st, RT_ERR_LIMIT);
    EXPECT_EQ(error.rfind("t.motion:1: line longer than 4096 bytes", 0), 0u) << error;
}

TEST(MotionFile, LoadReadsThroughTheFileReader)
{
    std::string path = testing::TempDir() + "torusrt_motion_load.motion";
    FILE *f = std::fopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    std::fputs("\xEF\xBB\xBF"
               "frames 3\nobjects 1\nkey 2 move 0 0 1\n",
               f); /* a byte-order mark first */
    std::fclose(f);
    char msg[256] = "";
    rt_motion *m = nullptr;
    ASSERT_EQ(rt_motion_load(path.c_str(), &m, msg, sizeof msg), RT_OK) << msg;
    EXPECT_EQ(rt_motion_frame_count(m), 3u);
    rt_motion_free(m);
    EXPECT_EQ(rt_motion_load("/nonexistent/x.motion", &m, msg, sizeof msg), RT_ERR_IO);
    EXPECT_EQ(m, nullptr);
    EXPECT_NE(std::string(msg).find("/nonexistent/x.motion"), std::string::npos) << msg;
}

TEST(MotionApply, TranslationIsInterpolatedAndHeld)
{
    ScenePtr s = five_objects();
    MotionPtr m = parse("frames 12\nobjects 1\nkey 2\nkey 6 move 0 4 -8\nkey 10 move 0 0 0\n");
    ASSERT_NE(m, nullptr);
    std::vector<uint8_t> moved;
    expect_near(center(at_frame(m.get(), s.get(), 0, &moved).get(), 1), rt_vec(2, 0, 0), 0);
    EXPECT_EQ(moved, std::vector<uint8_t>(5, 0)); /* the first key is the identity: nothing moved */
    expect_near(center(at_frame(m.get(), s.get(), 3, &moved).get(), 1), rt_vec(2, 1, -2), 0);
    EXPECT_EQ(moved, (std::vector<uint8_t>{0, 1, 0, 0, 0}));
    expect_near(center(at_frame(m.get(), s.get(), 6).get(), 1), rt_vec(2, 4, -8), 0);
    expect_near(center(at_frame(m.get(), s.get(), 8).get(), 1), rt_vec(2, 2, -4), 0);
    expect_near(center(at_frame(m.get(), s.get(), 11).get(), 1), rt_vec(2, 0, 0), 0);
    /* Sphere 0 never moves; its bounds follow sphere 1's centre. */
    ScenePtr f = at_frame(m.get(), s.get(), 6);
    expect_near(center(f.get(), 0), rt_vec(-2, 0, 0), 0);
    rt_box b = rt_scene_object_bounds(f.get(), 1);
    expect_near(b.lo, rt_vec(1, 3, -9), 0);
    expect_near(b.hi, rt_vec(3, 5, -7), 0);
}

TEST(MotionApply, RotationAboutAPivotByHand)
{
    ScenePtr s = five_objects();
    /* Sphere 1 at (2,0,0) turned about the z axis through (1,0,0): 90 degrees takes it to
     * (1,1,0), 180 to (0,0,0); 45 (frame 1, halfway to 90) to (1 + cos45, sin45, 0). */
    MotionPtr m = parse("objects 1\npivot 1 0 0\naxis 0 0 1\nkey 0\nkey 2 turn 90\nkey 4 turn 180\n");
    ASSERT_NE(m, nullptr);
    expect_near(center(at_frame(m.get(), s.get(), 2).get(), 1), rt_vec(1, 1, 0), 0);
    expect_near(center(at_frame(m.get(), s.get(), 4).get(), 1), rt_vec(0, 0, 0), 0);
    double h = std::sqrt(0.5);
    expect_near(center(at_frame(m.get(), s.get(), 1).get(), 1), rt_vec(1 + h, h, 0), 1e-15);
    EXPECT_EQ(s->objects[1].u.sphere.radius, at_frame(m.get(), s.get(), 1)->objects[1].u.sphere.radius);
}

// An axis of tiny or huge components keeps its direction: its squares would underflow to 0 or
// overflow, so it is scaled before it is normalised.
TEST(MotionApply, TinyAndHugeAxesTurnLikeUnitOnes)
{
    ScenePtr s = five_objects();
    const char *unit = "objects 1\npivot 1 0 0\naxis 0 0 1\nkey 0\nkey 1 turn 90\n";
    MotionPtr want = parse(unit);
    ASSERT_NE(want, nullptr);
    rt_vec3 c = center(at_frame(want.get(), s.get(), 1).get(), 1);
    for (const char *axis : {"0 0 1e-200", "0 0 4e-320", "0 0 1e30", "1e-300 -1e-300 1e30"}) {
        std::string text = std::string("objects 1\npivot 1 0 0\naxis ") + axis + "\nkey 0\nkey 1 turn 90\n";
        MotionPtr m = parse(text);
        ASSERT_NE(m, nullptr) << axis;
        expect_near(center(at_frame(m.get(), s.get(), 1).get(), 1), c, 1e-15);
    }
    expect_near(c, rt_vec(1, 1, 0), 0);
}

// At the limit of 'objects' lines, with one pair overlapping far apart in the file.
TEST(MotionFile, ManyEntriesAndOneOverlapFarApart)
{
    std::string text = "frames 2\n";
    for (unsigned i = 0; i < RT_MOTION_MAX_ENTRIES - 1; i++) text += "objects " + std::to_string(2 * i) + "\nkey 0\n";
    MotionPtr m = parse(text);
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(rt_motion_entry_count(m.get()), RT_MOTION_MAX_ENTRIES - 1);
    std::string error = refused(text + "objects 3 4\nkey 0\n");
    EXPECT_EQ(error, "t.motion:" + std::to_string(2 * RT_MOTION_MAX_ENTRIES) +
                         ": objects 3-4 overlap objects 4-4 of line 6 (an object moves by one entry)");
}

TEST(MotionApply, ZeroAndFullTurnsAreExactlyTheIdentity)
{
    ScenePtr s = five_objects();
    MotionPtr m = parse("frames 3\nobjects 0 4\npivot 0.3 0.7 -0.1\naxis 1 2 3\nkey 0 turn 0\nkey 1 turn 360\n"
                        "key 2 turn -720\n");
    ASSERT_NE(m, nullptr);
    for (uint32_t k = 0; k < 3; k++) {
        std::vector<uint8_t> moved;
        ScenePtr f = at_frame(m.get(), s.get(), k, &moved);
        EXPECT_EQ(moved, std::vector<uint8_t>(5, 0)) << "frame " << k;
        for (size_t o = 0; o < 5; o++)
            EXPECT_EQ(std::memcmp(&f->objects[o], &s->objects[o], sizeof(rt_object)), 0)
                << "frame " << k << " object " << o;
        EXPECT_EQ(std::memcmp(f->vertices, s->vertices, s->vertex_count * sizeof(rt_vec3)), 0);
    }
}

TEST(MotionApply, ScaleAboutThePivot)
{
    ScenePtr s = five_objects();
    MotionPtr m = parse("objects 0 4\npivot 0 0 0\nkey 0 scale 2\n");
    ASSERT_NE(m, nullptr);
    ScenePtr f = at_frame(m.get(), s.get(), 0);
    expect_near(center(f.get(), 0), rt_vec(-4, 0, 0), 0);
    EXPECT_EQ(f->objects[0].u.sphere.radius, 2.0);
    const rt_triangle_data &t = f->objects[2].u.triangle;
    expect_near(t.v[1], rt_vec(2, 0, 0), 0);
    expect_near(t.normal, rt_vec(0, 0, 1), 0);
    rt_box pb = rt_scene_object_bounds(f.get(), 3);
    expect_near(pb.lo, rt_vec(0, 0, -2), 0);
    expect_near(pb.hi, rt_vec(2, 2, -2), 0);
    EXPECT_NEAR(f->objects[3].u.polygon.offset, -2.0, 1e-15);
    const rt_cone_data &c = f->objects[4].u.cone;
    expect_near(c.apex, rt_vec(0, 4, 0), 0);
    EXPECT_EQ(c.base_radius, 2.0);
    EXPECT_EQ(c.apex_radius, 1.0);
    EXPECT_EQ(c.height, 4.0);
}

TEST(MotionApply, TurnedPatchKeepsItsNormalsWithIt)
{
    ScenePtr s = five_objects();
    /* 90 degrees about x: the triangle in z = 0 facing +z ends up in y = 0 facing -y. */
    MotionPtr m = parse("objects 2\naxis 1 0 0\nkey 0 turn 90\n");
    ASSERT_NE(m, nullptr);
    ScenePtr f = at_frame(m.get(), s.get(), 0);
    const rt_triangle_data &t = f->objects[2].u.triangle;
    expect_near(t.v[2], rt_vec(0, 0, 1), 0);
    expect_near(t.normal, rt_vec(0, -1, 0), 1e-15);
    for (int k = 0; k < 3; k++) expect_near(t.n[k], rt_vec(0, -1, 0), 0);
}

TEST(MotionApply, EntryPastTheSceneIsRefused)
{
    ScenePtr s = five_objects();
    MotionPtr m = parse("frames 2\nobjects 3 5\nkey 0\n");
    ASSERT_NE(m, nullptr);
    ScenePtr f(rt_scene_clone(s.get()));
    char msg[256] = "";
    EXPECT_EQ(rt_motion_apply(m.get(), s.get(), f.get(), 0, nullptr, msg, sizeof msg), RT_ERR_INVALID);
    EXPECT_EQ(std::string(msg).rfind("t.motion:2: objects 3-5: the scene has 5 objects", 0), 0u) << msg;
    rt_box space;
    EXPECT_EQ(rt_motion_space(m.get(), s.get(), &space, msg, sizeof msg), RT_ERR_PARSE);
    EXPECT_EQ(std::string(msg).rfind("t.motion:2: objects 3-5", 0), 0u) << msg;
}

TEST(MotionSpace, IsTheBoxOverEveryFrame)
{
    ScenePtr s = five_objects();
    /* Sphere 1 goes up 10 by frame 4 and back; only frames 0..4 count (frames 5). */
    MotionPtr m = parse("frames 5\nobjects 1\nkey 0\nkey 4 move 0 10 0\nkey 8 move 0 100 0\n");
    ASSERT_NE(m, nullptr);
    rt_box space;
    char msg[256] = "";
    ASSERT_EQ(rt_motion_space(m.get(), s.get(), &space, msg, sizeof msg), RT_OK) << msg;
    expect_near(space.lo, rt_vec(-3, -1, -1), 0);
    expect_near(space.hi, rt_vec(3, 11, 1), 0);
}

TEST(MotionSpace, MovesPastTheLimitOrToSizeZeroAreRefused)
{
    ScenePtr s = five_objects();
    char msg[256] = "";
    rt_box space;
    MotionPtr far = parse("frames 2\nobjects 0\npivot -1e30 0 0\nkey 0\nkey 1 scale 3\n"); /* to 2e30 */
    ASSERT_NE(far, nullptr);
    EXPECT_EQ(rt_motion_space(far.get(), s.get(), &space, msg, sizeof msg), RT_ERR_PARSE);
    EXPECT_EQ(std::string(msg).rfind("t.motion:2: frame 1 moves object 0 past 1e30", 0), 0u) << msg;

    ScenePtr tiny(rt_scene_new());
    rt_scene_set_view(tiny.get(), rt_vec(0, 0, 10), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45, 4, 4);
    rt_scene_add_sphere(tiny.get(), rt_vec(0, 0, 0), 1e-320);
    MotionPtr shrink = parse("objects 0\nkey 0 scale 1e-6\n");
    ASSERT_NE(shrink, nullptr);
    EXPECT_EQ(rt_motion_space(shrink.get(), tiny.get(), &space, msg, sizeof msg), RT_ERR_PARSE);
    EXPECT_NE(std::string(msg).find("to size 0"), std::string::npos) << msg;
}

TEST(MotionDescribe, SaysWhatEachEntryMatched)
{
    ScenePtr s = five_objects();
    MotionPtr m = parse("objects 0 1\nkey 0\nkey 3\n\nobjects 2 4\nkey 0\n");
    ASSERT_NE(m, nullptr);
    char buf[256];
    rt_motion_describe(m.get(), s.get(), 0, buf, sizeof buf);
    EXPECT_STREQ(buf, "t.motion:1: objects 0-1 (2 spheres), 2 keys");
    rt_motion_describe(m.get(), s.get(), 1, buf, sizeof buf);
    EXPECT_STREQ(buf, "t.motion:5: objects 2-4 (1 polygon, 1 patch triangle, 1 cone), 1 key");
}

}  // namespace
