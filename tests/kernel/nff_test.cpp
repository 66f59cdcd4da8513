// nff_test.cpp - the NFF reader: the malformed corpus in tests/nff_bad, exact
// line numbers, and well-formed token-stream input read back through the scene API.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "rt_nff.h"
#include "rt_scene.h"
#include "rt_status.h"

namespace fs = std::filesystem;

namespace {

const fs::path kBadDir = fs::path(TORUSRT_SOURCE_DIR) / "tests" / "nff_bad";

// Collects warnings given to the callback.
void collect_warning(void *ctx, const char *message)
{
    static_cast<std::vector<std::string> *>(ctx)->push_back(message);
}

// The line number of "NAME:LINE: ..." or 0 if the message does not start that way.
long message_line(const std::string &msg, const std::string &name)
{
    if (msg.compare(0, name.size() + 1, name + ":") != 0) return 0;
    size_t i = name.size() + 1, start = i;
    long line = 0;
    while (i < msg.size() && msg[i] >= '0' && msg[i] <= '9' && i - start < 12) line = line * 10 + (msg[i++] - '0');
    if (i == start || i >= msg.size() || msg[i] != ':') return 0;
    return line;
}

struct Loaded {
    rt_status status = RT_OK;
    rt_scene *scene = nullptr;
    std::string msg;
    std::vector<std::string> warnings;
    ~Loaded() { rt_scene_free(scene); }
};

void load_file(const std::string &path, Loaded &r)
{
    char msg[RT_MSG_LEN] = "";
    r.scene = reinterpret_cast<rt_scene *>(&r);  // must be overwritten with NULL on failure
    r.status = rt_nff_load(path.c_str(), &r.scene, msg, sizeof msg, collect_warning, &r.warnings);
    r.msg = msg;
}

void parse_text(const std::string &text, Loaded &r, const char *name = "mem.nff")
{
    char msg[RT_MSG_LEN] = "";
    r.scene = reinterpret_cast<rt_scene *>(&r);
    r.status = rt_nff_parse(name, text.data(), text.size(), &r.scene, msg, sizeof msg, collect_warning, &r.warnings);
    r.msg = msg;
}

std::vector<fs::path> bad_files()
{
    std::vector<fs::path> files;
    for (const auto &entry : fs::directory_iterator(kBadDir))
        if (entry.path().extension() == ".nff") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

const char *kView = "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 45\nhither 1\nresolution 64 64\n";

}  // namespace

// ------------------------------------------------------------ the bad corpus

TEST(NffBad, EveryCorpusFileIsRejectedWithFileAndLine)
{
    std::vector<fs::path> files = bad_files();
    ASSERT_GE(files.size(), 35u) << "corpus in " << kBadDir;
    for (const fs::path &file : files) {
        SCOPED_TRACE(file.string());
        Loaded r;
        load_file(file.string(), r);
        EXPECT_NE(r.status, RT_OK);
        EXPECT_TRUE(r.scene == nullptr);
        r.scene = r.status == RT_OK ? r.scene : nullptr;
        EXPECT_GT(message_line(r.msg, file.string()), 0) << r.msg;
    }
}

TEST(NffBad, CorpusIsListedInReadme)
{
    std::ifstream in(kBadDir / "README.md");
    ASSERT_TRUE(in) << "tests/nff_bad/README.md";
    std::string readme((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (const fs::path &file : bad_files())
        EXPECT_NE(readme.find(file.filename().string()), std::string::npos)
            << file.filename() << " is not described in the README";
}

struct ExpectedError {
    const char *file;
    long line;
    rt_status status;
    const char *text;  // a fragment of the message
};

// Each line below was checked by hand against the file.
TEST(NffBad, HandCheckedLineNumbers)
{
    const ExpectedError cases[] = {
        {"unknown-keyword.nff", 9, RT_ERR_PARSE, "unknown keyword 'sphere'"},
        {"sphere-missing-radius.nff", 10, RT_ERR_PARSE, "radius of 's' (line 9)"},
        {"nan-coordinate.nff", 9, RT_ERR_PARSE, "'nan'"},
        {"no-view.nff", 5, RT_ERR_PARSE, "no 'v'"},
        {"empty.nff", 1, RT_ERR_PARSE, "no 'v'"},
        {"comment-only.nff", 2, RT_ERR_PARSE, "no 'v'"},
        {"huge-resolution.nff", 7, RT_ERR_LIMIT, "16384"},
        {"polygon-count-huge.nff", 9, RT_ERR_LIMIT, "100001"},
        {"polygon-count-two.nff", 9, RT_ERR_PARSE, "at least 3"},
        {"truncated-cone.nff", 11, RT_ERR_PARSE, "'c' at line 9 is missing its apex z"},
        {"truncated-view.nff", 5, RT_ERR_PARSE, "end of file"},
        {"binary-garbage.nff", 10, RT_ERR_PARSE, "binary data"},  // the file reader finds its NUL first
        {"utf16-text.nff", 1, RT_ERR_PARSE, "binary data"},
        {"nul-byte.nff", 8, RT_ERR_PARSE, "binary data"},
        {"negative-radius.nff", 9, RT_ERR_PARSE, "negative sphere radius (inside-only spheres) is not supported"},
        {"zero-radius.nff", 9, RT_ERR_PARSE, "sphere radius"},
        {"cone-both-radii-zero.nff", 9, RT_ERR_PARSE, "both radii zero"},
        {"two-views.nff", 10, RT_ERR_PARSE, "second 'v'"},
        {"degenerate-camera.nff", 1, RT_ERR_PARSE, "degenerate camera"},
        {"up-parallel-camera.nff", 3, RT_ERR_PARSE, "degenerate camera"},
        {"angle-180.nff", 5, RT_ERR_PARSE, "(0, 180)"},
        {"malformed-number-dots.nff", 9, RT_ERR_PARSE, "'1.2.3'"},
        {"hex-float.nff", 9, RT_ERR_PARSE, "'0x1p3'"},
        {"number-overflow.nff", 9, RT_ERR_PARSE, "out of the range"},
        {"extra-number.nff", 9, RT_ERR_PARSE, "unexpected value '2'"},
        {"too-many-lights.nff", 1032, RT_ERR_LIMIT, "too many lights"},
        {"view-keywords-out-of-order.nff", 2, RT_ERR_PARSE, "expected 'from'"},
        {"material-zero-ior.nff", 8, RT_ERR_PARSE, "ior"},
    };
    for (const ExpectedError &c : cases) {
        SCOPED_TRACE(c.file);
        std::string path = (kBadDir / c.file).string();
        Loaded r;
        load_file(path, r);
        EXPECT_EQ(r.status, c.status) << r.msg;
        EXPECT_TRUE(r.scene == nullptr);
        if (r.status == RT_OK) continue;
        r.scene = nullptr;
        EXPECT_EQ(message_line(r.msg, path), c.line) << r.msg;
        EXPECT_NE(r.msg.find(c.text), std::string::npos) << r.msg;
    }
}

TEST(NffBad, MissingFileIsAnIoError)
{
    std::string path = (kBadDir / "no-such-file.nff").string();
    Loaded r;
    load_file(path, r);
    EXPECT_EQ(r.status, RT_ERR_IO);
    EXPECT_TRUE(r.scene == nullptr);
    EXPECT_EQ(r.msg.rfind(path + ": cannot open: ", 0), 0u) << r.msg;
}

TEST(NffBad, DirectoryIsAnIoError)
{
    Loaded r;
    load_file(kBadDir.string(), r);
    EXPECT_EQ(r.status, RT_ERR_IO);
    EXPECT_TRUE(r.scene == nullptr);
    r.scene = nullptr;
}

TEST(NffBad, FileOverTheSizeLimitIsRejectedUnread)
{
    // A sparse file one byte over the limit: rejected from its size alone.
    fs::path dir = fs::temp_directory_path() / ("nff_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    fs::path big = dir / "big.nff";
    {
        std::ofstream(big) << "v";
    }
    fs::resize_file(big, static_cast<std::uintmax_t>(RT_NFF_MAX_FILE_BYTES) + 1);
    Loaded r;
    load_file(big.string(), r);
    EXPECT_EQ(r.status, RT_ERR_LIMIT) << r.msg;
    EXPECT_TRUE(r.scene == nullptr);
    r.scene = nullptr;
    EXPECT_EQ(message_line(r.msg, big.string()), 1) << r.msg;
    fs::remove_all(dir);
}

TEST(NffBad, ParseUsesTheNameAndCountsCrLfLines)
{
    Loaded r;
    parse_text("v\r\nfrom 0 0 5\r\nat 0 0 0\r\nup 0 1 0\r\nangle 45\r\nhither 1\r\n"
               "resolution 8 8\r\n# comment\r\ns 0 0 0 q\r\n",
               r, "scene-name");
    EXPECT_EQ(r.status, RT_ERR_PARSE);
    EXPECT_TRUE(r.scene == nullptr);
    r.scene = nullptr;
    EXPECT_EQ(message_line(r.msg, "scene-name"), 9) << r.msg;
}

TEST(NffBad, NumbersThatAreNotFiniteDecimals)
{
    const char *bad[] = {"nan", "NaN", "inf", "-inf", "+Infinity", "0x10",  "1.2.3", "1e",     "e5", ".",
                         "-",   "+",   "1e+", "1..",  "--1",       "1e5.5", "1e999", "-1e999", "1f"};
    for (const char *number : bad) {
        SCOPED_TRACE(number);
        Loaded r;
        parse_text(std::string(kView) + "s 0 0 0 " + number + "\n", r);
        EXPECT_NE(r.status, RT_OK);
        EXPECT_TRUE(r.scene == nullptr);
        r.scene = r.status == RT_OK ? r.scene : nullptr;
        EXPECT_EQ(message_line(r.msg, "mem.nff"), 8) << r.msg;
    }
}

TEST(NffBad, EveryPrefixOfAGoodFileIsSafe)
{
    // Truncation anywhere either still parses or fails cleanly with a line.
    const std::string text = std::string("b 0.1 0.2 0.3\n") + kView +
                             "l 1 2 3 1 1 1\nf 1 0 0 1 0 0 0 1\ns 0 0 0 1\n"
                             "c 0 0 0 1 0 1 0 0.5\npp 3 0 0 0 0 0 1 1 0 0 0 0 1 0 1 0 0 0 1\n";
    for (size_t cut = 0; cut <= text.size(); cut++) {
        Loaded r;
        std::vector<char> copy(text.begin(), text.begin() + static_cast<long>(cut));
        char msg[RT_MSG_LEN] = "";
        r.status = rt_nff_parse("cut.nff", copy.data(), copy.size(), &r.scene, msg, sizeof msg, nullptr, nullptr);
        r.msg = msg;
        if (r.status != RT_OK) {
            EXPECT_TRUE(r.scene == nullptr) << cut;
            EXPECT_GT(message_line(r.msg, "cut.nff"), 0) << cut << ": " << r.msg;
        }
    }
}

// ------------------------------------------------------------- good input

TEST(NffGood, TokenStreamReadsBack)
{
    const std::string text = "# SPD-like token stream: b before v, c on one line, 1e-16 and -0\n"
                             "b 0.1 0.2 0.3\n"            // line 2
                             "am 0.05 0.06 0.07\n"        // line 3
                             "v from 0 -0 10 at 0 0 0\n"  // line 4
                             "up 0 1 0 angle 45 hither 1e-16 resolution 32 24\n"
                             "l 5 5 5\n"                           // light without colour
                             "l -5 5 5 1 0.5 0.25   # coloured\n"  // light with colour
                             "s 0 0 0 1\n"                         // line 8: before any f
                             "s 2 0 0 0.5\n"                       // before any f again
                             "f 1 0 0 1 0 0 0 1\n"
                             "c 0 0 0 1 0 1 0 0.5\n"
                             "pp 4\n"
                             "0 0 0 0 0 1 1 0 0 0 0 1\n"
                             "1 1 0 0 0 1 0 1 0 0 0 1\n"
                             "p 3 0 0 0 1 0 0 0 1 -0\n"
                             "l 0 0 20\n";
    Loaded r;
    parse_text(text, r);
    ASSERT_EQ(r.status, RT_OK) << r.msg;
    ASSERT_TRUE(r.scene != nullptr);

    // 2 spheres + 1 cone + (4 - 2) patch triangles + 1 polygon.
    ASSERT_EQ(rt_scene_object_count(r.scene), 6u);
    EXPECT_EQ(rt_scene_object_kind(r.scene, 0), RT_OBJ_SPHERE);
    EXPECT_EQ(rt_scene_object_kind(r.scene, 1), RT_OBJ_SPHERE);
    EXPECT_EQ(rt_scene_object_kind(r.scene, 2), RT_OBJ_CONE);
    EXPECT_EQ(rt_scene_object_kind(r.scene, 3), RT_OBJ_TRIANGLE);
    EXPECT_EQ(rt_scene_object_kind(r.scene, 4), RT_OBJ_TRIANGLE);
    EXPECT_EQ(rt_scene_object_kind(r.scene, 5), RT_OBJ_POLYGON);

    const rt_camera *cam = rt_scene_camera(r.scene);
    EXPECT_EQ(cam->from.x, 0.0);
    EXPECT_EQ(cam->from.y, 0.0);
    EXPECT_TRUE(std::signbit(cam->from.y));  // "-0" is read as negative zero
    EXPECT_EQ(cam->from.z, 10.0);
    EXPECT_EQ(cam->up.y, 1.0);
    EXPECT_EQ(cam->angle, 45.0);
    EXPECT_EQ(cam->width, 32u);
    EXPECT_EQ(cam->height, 24u);

    rt_vec3 bg = rt_scene_background(r.scene);
    EXPECT_DOUBLE_EQ(bg.x, 0.1);
    EXPECT_DOUBLE_EQ(bg.y, 0.2);
    EXPECT_DOUBLE_EQ(bg.z, 0.3);
    rt_vec3 am = rt_scene_ambient(r.scene);
    EXPECT_DOUBLE_EQ(am.x, 0.05);
    EXPECT_DOUBLE_EQ(am.y, 0.06);
    EXPECT_DOUBLE_EQ(am.z, 0.07);

    ASSERT_EQ(rt_scene_light_count(r.scene), 3u);
    const double d = 1.0 / std::sqrt(3.0);  // uncoloured lights: (1,1,1)/sqrt(lights)
    EXPECT_DOUBLE_EQ(rt_scene_light(r.scene, 0)->position.x, 5.0);
    EXPECT_DOUBLE_EQ(rt_scene_light(r.scene, 0)->color.x, d);
    EXPECT_DOUBLE_EQ(rt_scene_light(r.scene, 1)->position.x, -5.0);
    EXPECT_DOUBLE_EQ(rt_scene_light(r.scene, 1)->color.x, 1.0);
    EXPECT_DOUBLE_EQ(rt_scene_light(r.scene, 1)->color.y, 0.5);
    EXPECT_DOUBLE_EQ(rt_scene_light(r.scene, 1)->color.z, 0.25);
    EXPECT_DOUBLE_EQ(rt_scene_light(r.scene, 2)->position.z, 20.0);
    EXPECT_DOUBLE_EQ(rt_scene_light(r.scene, 2)->color.z, d);

    // Objects before the `f` have the default material; one warning names line 8.
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_EQ(r.warnings[0], "mem.nff:8: warning: object before any 'f': using f 1 1 1 1 0 0 0 1");
    EXPECT_TRUE(rt_scene_used_default_material(r.scene));
    rt_material def = rt_material_default();
    const rt_material *m0 = rt_scene_object_material(r.scene, 1);
    EXPECT_EQ(m0->color.x, def.color.x);
    EXPECT_EQ(m0->kd, def.kd);
    EXPECT_EQ(m0->ior, def.ior);
    const rt_material *m2 = rt_scene_object_material(r.scene, 2);
    EXPECT_EQ(m2->color.x, 1.0);
    EXPECT_EQ(m2->color.y, 0.0);
}

TEST(NffGood, NoWarningWhenMaterialComesFirst)
{
    Loaded r;
    parse_text(std::string(kView) + "f 0.5 0.5 0.5 0.7 0.3 10 0 1\ns 0 0 0 1\n", r);
    ASSERT_EQ(r.status, RT_OK) << r.msg;
    EXPECT_TRUE(r.warnings.empty());
    EXPECT_FALSE(rt_scene_used_default_material(r.scene));
    EXPECT_EQ(rt_scene_object_material(r.scene, 0)->shine, 10.0);
}

TEST(NffGood, WarningWithoutCallbackIsHarmless)
{
    std::string text = std::string(kView) + "s 0 0 0 1\n";
    rt_scene *scene = nullptr;
    char msg[RT_MSG_LEN] = "";
    ASSERT_EQ(rt_nff_parse("x", text.data(), text.size(), &scene, msg, sizeof msg, nullptr, nullptr), RT_OK) << msg;
    EXPECT_EQ(rt_scene_object_count(scene), 1u);
    rt_scene_free(scene);
}

TEST(NffGood, NumberForms)
{
    // Accepted spellings: signs, leading/trailing dots, exponents, underflow to ~0.
    Loaded r;
    parse_text("v from +1 .5 5. at 1E+2 -0.0 1e-400 up 0 1 0 angle 4.5e1 hither 0 "
               "resolution +7 007\n",
               r);
    ASSERT_EQ(r.status, RT_OK) << r.msg;
    const rt_camera *cam = rt_scene_camera(r.scene);
    EXPECT_EQ(cam->from.x, 1.0);
    EXPECT_EQ(cam->from.y, 0.5);
    EXPECT_EQ(cam->from.z, 5.0);
    EXPECT_EQ(cam->at.x, 100.0);
    EXPECT_LT(std::fabs(cam->at.z), 1e-300);
    EXPECT_EQ(cam->angle, 45.0);
    EXPECT_EQ(cam->width, 7u);
    EXPECT_EQ(cam->height, 7u);
    EXPECT_EQ(rt_scene_object_count(r.scene), 0u);
}

TEST(NffGood, CommentsAndByteOrderMark)
{
    Loaded r;
    parse_text("\xEF\xBB\xBF# leading comment\n" + std::string(kView) +
                   "s 0 0 0 1# comment right after a number\n#s 9 9 9 9\n",
               r);
    ASSERT_EQ(r.status, RT_OK) << r.msg;
    EXPECT_EQ(rt_scene_object_count(r.scene), 1u);
}

TEST(NffGood, OneZeroRadiusConeIsATrueCone)
{
    Loaded r;
    parse_text(std::string(kView) + "f 1 1 1 1 0 0 0 1\nc 0 0 0 1 0 2 0 0\nc 0 0 0 0 0 2 0 1\n", r);
    ASSERT_EQ(r.status, RT_OK) << r.msg;
    EXPECT_EQ(rt_scene_object_count(r.scene), 2u);
}

TEST(NffGood, PatchAddsCountMinusTwoTriangles)
{
    std::string text = std::string(kView) + "f 1 1 1 1 0 0 0 1\npp 6\n";
    for (int i = 0; i < 6; i++) {
        double a = i * 2.0 * std::acos(-1.0) / 6.0;
        text += std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0 0 0 1\n";
    }
    Loaded r;
    parse_text(text, r);
    ASSERT_EQ(r.status, RT_OK) << r.msg;
    EXPECT_EQ(rt_scene_object_count(r.scene), 4u);
}

TEST(NffGood, LoadsFromAFile)
{
    fs::path dir = fs::temp_directory_path() / ("nff_good_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    fs::path file = dir / "one.nff";
    {
        std::ofstream(file) << kView << "l 1 1 1\nf 1 1 1 1 0 0 0 1\ns 0 0 0 1\n";
    }
    Loaded r;
    load_file(file.string(), r);
    EXPECT_EQ(r.status, RT_OK) << r.msg;
    ASSERT_TRUE(r.scene != nullptr);
    EXPECT_EQ(rt_scene_object_count(r.scene), 1u);
    EXPECT_EQ(rt_scene_light_count(r.scene), 1u);
    EXPECT_DOUBLE_EQ(rt_scene_light(r.scene, 0)->color.y, 1.0);
    fs::remove_all(dir);
}

// ------------------------------------------------- what NFF 3.9 allows (SPD output)

TEST(NffFormat, OpaqueSurfaceWithIorZeroAndHugeShineLoads)
{
    // SPD generators write ior 0 for opaque surfaces and Shine up to 100000.
    Loaded r;
    parse_text(std::string(kView) + "f 1 0.75 0.33 0.8 0 100000 0 0\ns 0 0 0 1\n", r);
    ASSERT_EQ(r.status, RT_OK) << r.msg;
    const rt_material *m = rt_scene_object_material(r.scene, 0);
    EXPECT_EQ(m->shine, 100000.0);
    EXPECT_EQ(m->ior, 0.0);
    EXPECT_EQ(m->t, 0.0);
}

TEST(NffFormat, NegativeIorWithoutTransmissionLoads)
{
    Loaded r;
    parse_text(std::string(kView) + "f 1 1 1 1 0 3 0 -1\ns 0 0 0 1\n", r);
    EXPECT_EQ(r.status, RT_OK) << r.msg;
}

TEST(NffFormat, TransmittingSurfaceStillNeedsAPositiveIor)
{
    for (const char *f : {"f 1 1 1 0 0 0 0.5 0\n", "f 1 1 1 0 0 0 1 -1.5\n"}) {
        SCOPED_TRACE(f);
        Loaded r;
        parse_text(std::string(kView) + f + "s 0 0 0 1\n", r);
        EXPECT_EQ(r.status, RT_ERR_PARSE);
        EXPECT_EQ(message_line(r.msg, "mem.nff"), 8) << r.msg;
        EXPECT_NE(r.msg.find("ior > 0"), std::string::npos) << r.msg;
    }
}

TEST(NffFormat, ColoursAndCoefficientsAreNotBounded)
{
    // NFF gives usual ranges but bounds none: colours above 1, Kd + Ks > 1, a negative
    // coefficient all load as written.
    Loaded r;
    parse_text(std::string(kView) + "b 2 0 1.5\nam 3 3 3\nf 1.5 -0.25 2 0.9 0.9 5 -0.5 1\n"
                                    "l 1 2 3 4 5 6\ns 0 0 0 1\n",
               r);
    ASSERT_EQ(r.status, RT_OK) << r.msg;
    const rt_material *m = rt_scene_object_material(r.scene, 0);
    EXPECT_EQ(m->color.x, 1.5);
    EXPECT_EQ(m->color.y, -0.25);
    EXPECT_EQ(m->kd + m->ks, 1.8);
    EXPECT_EQ(m->t, -0.5);
    EXPECT_EQ(rt_scene_background(r.scene).x, 2.0);
    EXPECT_EQ(rt_scene_light(r.scene, 0)->color.z, 6.0);
}

TEST(NffFormat, SpdLayoutHitherColourlessLightsAndOneLineCone)
{
    // `b` before `v`, a nonzero hither, lights with and without colour, a whole `c` on one
    // line, a `pp` whose vertex normals oppose each other.
    Loaded r;
    parse_text("b 0.078 0.361 0.753\nv\nfrom 2.1 1.3 1.7\nat 0 0 0\nup 0 0 1\nangle 45\n"
               "hither 0.001\nresolution 16 16\nl 4 3 2\nl 1 -4 4 0.5 0.5 0.5\n"
               "f 1 0.75 0.33 0.8 0 100000 0 0\nc 0 0 0 0.5 0 0 1 0.25\n"
               "pp 3\n0 0 0 -0.90 0 -0.43\n1 0 0 0.90 0 0.43\n0 1 0 0 0 1\n",
               r);
    ASSERT_EQ(r.status, RT_OK) << r.msg;
    EXPECT_EQ(rt_scene_light_count(r.scene), 2u);
    EXPECT_DOUBLE_EQ(rt_scene_light(r.scene, 0)->color.x, 1.0 / std::sqrt(2.0));
    EXPECT_EQ(rt_scene_light(r.scene, 1)->color.x, 0.5);
    EXPECT_EQ(rt_scene_object_count(r.scene), 2u);
    EXPECT_EQ(rt_scene_background(r.scene).z, 0.753);
}
