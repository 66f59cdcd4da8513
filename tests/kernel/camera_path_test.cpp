// camera_path_test.cpp - orbit poses (Rodrigues rotation), the camera path file, per-frame cameras.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "rt_camera_path.h"
#include "rt_grid.h"
#include "rt_scene.h"

namespace {

const double kPi = 3.14159265358979323846;

rt_camera_pose pose(rt_vec3 from, rt_vec3 at, rt_vec3 up, double angle)
{
    rt_camera_pose p = {from, at, up, angle};
    return p;
}

double dist(rt_vec3 a, rt_vec3 b) { return rt_vec_length(rt_vec_sub(a, b)); }

std::string write_file(const std::string &name, const std::string &text)
{
    std::string path = testing::TempDir() + "torusrt_campath_" + name;
    FILE *f = std::fopen(path.c_str(), "w");
    EXPECT_NE(f, nullptr) << path;
    if (f) {
        std::fputs(text.c_str(), f);
        std::fclose(f);
    }
    return path;
}

// Loads `text` as a camera path file and returns the message (empty on success).
std::string load_error(const std::string &name, const std::string &text, rt_status *status)
{
    std::string path = write_file(name, text);
    rt_camera_path *cp = nullptr;
    char msg[RT_MSG_LEN] = "";
    *status = rt_camera_path_load(path.c_str(), &cp, msg, sizeof msg);
    if (*status == RT_OK) EXPECT_NE(cp, nullptr);
    else EXPECT_EQ(cp, nullptr);
    rt_camera_path_free(cp);
    return *status == RT_OK ? "" : msg;
}

TEST(CameraOrbit, FrameZeroIsTheStartPoseBitForBit)
{
    rt_camera_pose s = pose(rt_vec(0.1, 0.7, -3.3), rt_vec(0.3, 0.2, 0.1), rt_vec(0.2, 1, 0.1), 40);
    for (double deg : {0.0, 37.5, 360.0, -720.0}) {
        rt_camera_pose p = rt_camera_orbit_pose(&s, deg, 7, 0);
        EXPECT_EQ(0, std::memcmp(&p, &s, sizeof p)) << deg;
    }
    rt_camera_pose p = rt_camera_orbit_pose(&s, 0.0, 3, 2);
    EXPECT_EQ(0, std::memcmp(&p, &s, sizeof p));
}

TEST(CameraOrbit, FrameKTurnsByKTimesTheStep)
{
    // Eye on +x, up +z: turning by a about z puts it at (r cos a, r sin a, h) (right-handed).
    rt_camera_pose s = pose(rt_vec(5, 0, 2), rt_vec(0, 0, 0), rt_vec(0, 0, 3), 45);
    const unsigned n = 12;
    for (unsigned k = 0; k < n; k++) {
        rt_camera_pose p = rt_camera_orbit_pose(&s, 360.0, n, k);
        double a = 2 * kPi * k / n;
        EXPECT_NEAR(p.from.x, 5 * std::cos(a), 1e-12) << k;
        EXPECT_NEAR(p.from.y, 5 * std::sin(a), 1e-12) << k;
        EXPECT_NEAR(p.from.z, 2, 1e-12) << k;
        EXPECT_EQ(p.angle, 45);
    }
}

TEST(CameraOrbit, HalfTurnMirrorsTheEyeThroughTheAxisExactly)
{
    rt_camera_pose s = pose(rt_vec(1, 2, 9), rt_vec(1, 2, 3), rt_vec(0, 1, 0), 30);
    rt_camera_pose p = rt_camera_orbit_pose(&s, 360.0, 4, 2);
    EXPECT_EQ(p.from.x, 1);
    EXPECT_EQ(p.from.y, 2);
    EXPECT_EQ(p.from.z, -3);                                   // 2 at - from, the eye offset being orthogonal to up
    rt_camera_pose q = rt_camera_orbit_pose(&s, 360.0, 4, 1);  // a quarter turn about +y
    EXPECT_EQ(q.from.x, 7);
    EXPECT_EQ(q.from.y, 2);
    EXPECT_EQ(q.from.z, 3);
}

TEST(CameraOrbit, DistanceAndUpAnglePreservedViewNeverFlips)
{
    rt_camera_pose s = pose(rt_vec(3, -1, 4), rt_vec(0.5, 0.25, -1), rt_vec(0.3, 1, -0.2), 50);
    rt_vec3 axis = rt_vec_normalize(s.up);
    double r0 = dist(s.from, s.at);
    rt_vec3 w0 = rt_vec_normalize(rt_vec_sub(s.at, s.from));
    double elevation0 = rt_vec_dot(w0, axis);
    for (unsigned k = 0; k < 17; k++) {
        rt_camera_pose p = rt_camera_orbit_pose(&s, 300.0, 17, k);
        EXPECT_NEAR(dist(p.from, p.at), r0, 1e-12 * r0) << k;
        EXPECT_EQ(0, std::memcmp(&p.up, &s.up, sizeof p.up)) << k;
        EXPECT_EQ(0, std::memcmp(&p.at, &s.at, sizeof p.at)) << k;
        rt_vec3 w = rt_vec_normalize(rt_vec_sub(p.at, p.from));
        EXPECT_NEAR(rt_vec_dot(w, axis), elevation0, 1e-12) << k;
        // The image basis stays orthonormal and the image's up keeps pointing along `up`.
        rt_vec3 u = rt_vec_normalize(rt_vec_cross(w, p.up));
        rt_vec3 v = rt_vec_cross(u, w);
        EXPECT_NEAR(rt_vec_dot(u, w), 0, 1e-12);
        EXPECT_NEAR(rt_vec_dot(v, w), 0, 1e-12);
        EXPECT_NEAR(rt_vec_length(v), 1, 1e-12);
        EXPECT_GT(rt_vec_dot(v, axis), 0.5) << k;
        EXPECT_EQ(rt_camera_pose_check(&p, nullptr, 0), RT_OK);
    }
}

TEST(CameraOrbit, PathRejectsZeroFramesAndBadInput)
{
    rt_camera_pose s = pose(rt_vec(0, 0, 5), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45);
    rt_camera_path *cp = nullptr;
    char msg[RT_MSG_LEN];
    EXPECT_EQ(rt_camera_path_orbit(&s, 90, 0, &cp, msg, sizeof msg), RT_ERR_INVALID);
    EXPECT_EQ(rt_camera_path_orbit(&s, 90, RT_CAMERA_PATH_MAX_FRAMES + 1, &cp, msg, sizeof msg), RT_ERR_INVALID);
    EXPECT_EQ(rt_camera_path_orbit(&s, NAN, 3, &cp, msg, sizeof msg), RT_ERR_INVALID);
    EXPECT_EQ(cp, nullptr);
    ASSERT_EQ(rt_camera_path_orbit(&s, 90, 3, &cp, msg, sizeof msg), RT_OK);
    EXPECT_EQ(rt_camera_path_count(cp), 3u);
    EXPECT_NEAR(rt_camera_path_pose(cp, 2)->from.x, 5 * std::sin(kPi / 3), 1e-12);
    EXPECT_EQ(rt_camera_path_pose(cp, 3), nullptr);
    rt_camera_path_free(cp);
}

TEST(CameraPathFile, ReadsPosesCommentsAndBlankLines)
{
    std::string path = write_file("good.txt", "# eye, target, up, angle\n"
                                              "\n"
                                              "0 0 5  0 0 0  0 1 0  45   # first\n"
                                              "\t1e1 -0 5 0 0 0 0 1 0 30\r\n"
                                              "   \n");
    rt_camera_path *cp = nullptr;
    char msg[RT_MSG_LEN] = "";
    ASSERT_EQ(rt_camera_path_load(path.c_str(), &cp, msg, sizeof msg), RT_OK) << msg;
    ASSERT_EQ(rt_camera_path_count(cp), 2u);
    EXPECT_EQ(rt_camera_path_pose(cp, 0)->from.z, 5);
    EXPECT_EQ(rt_camera_path_pose(cp, 0)->angle, 45);
    EXPECT_EQ(rt_camera_path_pose(cp, 1)->from.x, 10);
    EXPECT_EQ(rt_camera_path_pose(cp, 1)->angle, 30);
    rt_camera_path_free(cp);
}

TEST(CameraPathFile, ErrorsNameTheFileAndLine)
{
    struct Case {
        const char *name, *text, *line, *words;
        rt_status status;
    } cases[] = {
        {"fields", "0 0 5 0 0 0 0 1 0 45\n0 0 5 0 0 0 0 1 0\n", ":2: ", "9 numbers", RT_ERR_PARSE},
        {"extra", "0 0 5 0 0 0 0 1 0 45 1\n", ":1: ", "more than 10", RT_ERR_PARSE},
        {"nan", "\n0 0 nan 0 0 0 0 1 0 45\n", ":2: ", "from_z", RT_ERR_PARSE},
        {"inf", "0 0 5 0 0 0 0 1 0 inf\n", ":1: ", "angle", RT_ERR_PARSE},
        {"hex", "0x1 0 5 0 0 0 0 1 0 45\n", ":1: ", "from_x", RT_ERR_PARSE},
        {"huge", "0 0 1e31 0 0 0 0 1 0 45\n", ":1: ", "1e30", RT_ERR_PARSE},
        {"overflow", "0 0 1e999 0 0 0 0 1 0 45\n", ":1: ", "finite", RT_ERR_PARSE},
        {"same", "# c\n1 2 3 1 2 3 0 1 0 45\n", ":2: ", "same point", RT_ERR_PARSE},
        {"parallel", "0 0 5 0 0 0 0 0 2 45\n", ":1: ", "parallel", RT_ERR_PARSE},
        {"zero_up", "0 0 5 0 0 0 0 0 0 45\n", ":1: ", "parallel", RT_ERR_PARSE},
        {"angle0", "0 0 5 0 0 0 0 1 0 0\n", ":1: ", "(0, 180)", RT_ERR_PARSE},
        {"angle180", "0 0 5 0 0 0 0 1 0 180\n", ":1: ", "(0, 180)", RT_ERR_PARSE},
        {"empty", "# nothing\n\n", ":2: ", "no frame", RT_ERR_PARSE},
        {"binary", "0 0 5 0 0 0 0 1 0 45\n\x01\n", ":2: ", "binary", RT_ERR_PARSE},
        {"lone_cr", "0 0 5 0 0 0 0 1 0 45\r\r0 0 5 0 0 0 0 1 0\r", ":3: ", "9 numbers", RT_ERR_PARSE},
    };
    for (const Case &c : cases) {
        rt_status st;
        std::string msg = load_error(c.name, c.text, &st);
        EXPECT_EQ(st, c.status) << c.name << ": " << msg;
        EXPECT_NE(msg.find(std::string("torusrt_campath_") + c.name + c.line), std::string::npos)
            << c.name << ": " << msg;
        EXPECT_NE(msg.find(c.words), std::string::npos) << c.name << ": " << msg;
    }
}

TEST(CameraPathFile, LimitsOnLineLengthAndFrameCount)
{
    rt_status st;
    std::string long_line = "0 0 5 0 0 0 0 1 0 45" + std::string(RT_CAMERA_PATH_MAX_LINE, ' ') + "\n";
    std::string msg = load_error("long", "0 0 5 0 0 0 0 1 0 45\n" + long_line, &st);
    EXPECT_EQ(st, RT_ERR_LIMIT);
    EXPECT_NE(msg.find("long:2: "), std::string::npos) << msg;
    std::string many;
    for (unsigned i = 0; i <= RT_CAMERA_PATH_MAX_FRAMES; i++) many += "0 0 5 0 0 0 0 1 0 45\n";
    msg = load_error("many", many, &st);
    EXPECT_EQ(st, RT_ERR_LIMIT);
    EXPECT_NE(msg.find("many:" + std::to_string(RT_CAMERA_PATH_MAX_FRAMES + 1) + ": "), std::string::npos) << msg;
}

TEST(CameraPathFile, OnlyRegularFilesAreRead)
{
    rt_camera_path *cp = nullptr;
    char msg[RT_MSG_LEN] = "";
    EXPECT_EQ(rt_camera_path_load(testing::TempDir().c_str(), &cp, msg, sizeof msg), RT_ERR_IO);
    EXPECT_NE(std::string(msg).find("is a folder, not a regular file"), std::string::npos) << msg;
    EXPECT_EQ(rt_camera_path_load("/nonexistent/path.txt", &cp, msg, sizeof msg), RT_ERR_IO);
    EXPECT_NE(std::string(msg).find("/nonexistent/path.txt: "), std::string::npos) << msg;
    EXPECT_EQ(cp, nullptr);
}

TEST(SceneCamera, SetCameraKeepsResolutionAndTheGridIgnoresTheEye)
{
    rt_scene *s = rt_scene_new();
    ASSERT_NE(s, nullptr);
    ASSERT_EQ(rt_scene_set_view(s, rt_vec(0, 0, 10), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45, 32, 24), RT_OK);
    ASSERT_EQ(rt_scene_add_sphere(s, rt_vec(0, 0, 0), 1), RT_OK);
    ASSERT_EQ(rt_scene_finish(s, nullptr, 0), RT_OK);
    char msg[RT_MSG_LEN];
    rt_grid *g1 = rt_grid_new(s, 4, 4, 4, msg, sizeof msg);
    rt_camera_pose far = pose(rt_vec(100, -50, 30), rt_vec(1, 0, 0), rt_vec(0, 0, 1), 20);
    ASSERT_EQ(rt_scene_set_camera(s, &far, msg, sizeof msg), RT_OK) << msg;
    const rt_camera *cam = rt_scene_camera(s);
    EXPECT_EQ(cam->from.x, 100);
    EXPECT_EQ(cam->angle, 20);
    EXPECT_EQ(cam->width, 32u);
    EXPECT_EQ(cam->height, 24u);
    rt_grid *g2 = rt_grid_new(s, 4, 4, 4, msg, sizeof msg);
    ASSERT_NE(g1, nullptr);
    ASSERT_NE(g2, nullptr);
    rt_box b1 = rt_grid_bounds(g1), b2 = rt_grid_bounds(g2);
    EXPECT_EQ(0, std::memcmp(&b1, &b2, sizeof b1));  // the object space is the objects' box
    EXPECT_LT(b1.hi.x, 2.0);
    rt_camera_pose bad = pose(rt_vec(1, 0, 0), rt_vec(1, 0, 0), rt_vec(0, 0, 1), 20);
    EXPECT_EQ(rt_scene_set_camera(s, &bad, msg, sizeof msg), RT_ERR_INVALID);
    EXPECT_EQ(rt_scene_camera(s)->from.x, 100);  // unchanged
    rt_grid_free(g1);
    rt_grid_free(g2);
    rt_scene_free(s);
}

}  // namespace
