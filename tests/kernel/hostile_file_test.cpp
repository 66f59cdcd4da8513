// hostile_file_test.cpp - input files that are not plain text files: a FIFO with no writer
// (must not hang), character devices such as /dev/zero (must not be read without bound),
// over-long timing lines, and control bytes that messages must never echo raw.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

#include "rt_nff.h"
#include "rt_timing.h"

namespace fs = std::filesystem;

namespace {

// A fresh folder under the test temp directory, removed with the object.
struct TempDir {
    fs::path path;
    TempDir() : path(fs::temp_directory_path() / ("torusrt_hostile_" + std::to_string(::getpid())))
    {
        fs::create_directories(path);
    }
    ~TempDir() { fs::remove_all(path); }
};

bool has_raw_control_byte(const std::string &s)
{
    for (unsigned char c : s)
        if (c < 0x20 || c == 0x7f) return true;
    return false;
}

rt_status load_nff(const std::string &path, std::string &msg)
{
    char m[RT_MSG_LEN] = "";
    rt_scene *s = nullptr;
    rt_status st = rt_nff_load(path.c_str(), &s, m, sizeof m, nullptr, nullptr);
    rt_scene_free(s);
    msg = m;
    return st;
}

rt_status load_timing(const std::string &path, std::string &msg)
{
    rt_timing t;
    rt_timing_defaults(&t);
    char m[RT_MSG_LEN] = "";
    rt_status st = rt_timing_load(path.c_str(), &t, m, sizeof m);
    msg = m;
    return st;
}

}  // namespace

TEST(HostileFiles, FifoWithNoWriterIsRefusedAtOnce)
{
    // A blocking open of a FIFO waits for a writer forever; the readers must not.
    TempDir dir;
    fs::path fifo = dir.path / "scene.nff";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    std::string msg;
    EXPECT_EQ(load_nff(fifo.string(), msg), RT_ERR_IO);
    EXPECT_NE(msg.find("scene.nff: is a FIFO, not a regular file"), std::string::npos) << msg;
    EXPECT_EQ(load_timing(fifo.string(), msg), RT_ERR_IO);
    EXPECT_NE(msg.find("not a regular file"), std::string::npos) << msg;
}

TEST(HostileFiles, DevZeroIsNotRead)
{
    std::string msg;
    EXPECT_EQ(load_timing("/dev/zero", msg), RT_ERR_IO);
    EXPECT_EQ(msg, "/dev/zero: is a character device, not a regular file");
    EXPECT_EQ(load_nff("/dev/zero", msg), RT_ERR_IO);
    EXPECT_EQ(msg, "/dev/zero: is a character device, not a regular file");
}

TEST(HostileFiles, TimingLineLengthIsBoundedWithFileAndLine)
{
    TempDir dir;
    fs::path f = dir.path / "long.timing";
    {
        std::ofstream(f) << "test_miss 1\n" << std::string(5000, '1') << "\n";
    }
    std::string msg;
    EXPECT_EQ(load_timing(f.string(), msg), RT_ERR_PARSE);
    EXPECT_EQ(msg.rfind(f.string() + ":2: line longer than", 0), 0u) << msg;
}

TEST(HostileFiles, TimingFileSizeIsBounded)
{
    TempDir dir;
    fs::path f = dir.path / "big.timing";
    {
        std::ofstream(f) << "# comment\n";
    }
    fs::resize_file(f, 64u * 1024u * 1024u);  // a sparse 64 MiB file of NUL bytes
    std::string msg;
    EXPECT_EQ(load_timing(f.string(), msg), RT_ERR_LIMIT);
    EXPECT_NE(msg.find("more than the limit"), std::string::npos) << msg;
}

TEST(HostileFiles, TimingMessagesEscapeControlBytes)
{
    TempDir dir;
    fs::path f = dir.path / "bell.timing";
    {
        std::ofstream(f) << "\x1b[31mtest\x07miss 5\n";
    }
    std::string msg;
    EXPECT_EQ(load_timing(f.string(), msg), RT_ERR_PARSE);
    EXPECT_FALSE(has_raw_control_byte(msg)) << msg;
    EXPECT_NE(msg.find("\\x1b[31mtest\\x07miss"), std::string::npos) << msg;
    rt_timing t;
    rt_timing_defaults(&t);
    char m[RT_MSG_LEN] = "";
    EXPECT_EQ(rt_timing_set(&t,
                            "a\x07"
                            "b",
                            1.0, m, sizeof m),
              RT_ERR_INVALID);
    EXPECT_FALSE(has_raw_control_byte(m)) << m;
}

TEST(HostileFiles, NffMessagesEscapeNamesAndNonAsciiTokens)
{
    // A path with a control byte (quoted back in every message) and a non-ASCII keyword.
    TempDir dir;
    fs::path f = dir.path / "be\x07ll.nff";
    {
        std::ofstream(f) << "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 45\nhither 1\nresolution 4 4\n"
                            "\xc2\x9b"
                            "31m 1 2 3\n";
    }
    std::string msg;
    EXPECT_EQ(load_nff(f.string(), msg), RT_ERR_PARSE);
    EXPECT_FALSE(has_raw_control_byte(msg)) << msg;
    EXPECT_NE(msg.find("be\\x07ll.nff:8: unknown keyword '\\xc2\\x9b31m'"), std::string::npos) << msg;
}
