// png_test.cpp - writing and reading 8-bit RGB PNG files.
#include <gtest/gtest.h>
#include <png.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <dirent.h>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

#include "rt_png.h"

namespace {

// A fresh, empty directory per test.
std::string fresh_dir(const std::string &name)
{
    std::string dir = testing::TempDir() + "torusrt_png_" + name + "_" + std::to_string(getpid());
    std::string cmd = "rm -rf '" + dir + "'";
    EXPECT_EQ(std::system(cmd.c_str()), 0);
    EXPECT_EQ(mkdir(dir.c_str(), 0755), 0) << dir;
    return dir;
}

std::vector<std::string> list_dir(const std::string &dir)
{
    std::vector<std::string> names;
    if (DIR *d = opendir(dir.c_str())) {
        while (dirent *e = readdir(d)) {
            std::string n = e->d_name;
            if (n != "." && n != "..") names.push_back(n);
        }
        closedir(d);
    }
    return names;
}

std::vector<uint8_t> pattern(uint32_t w, uint32_t h)
{
    std::vector<uint8_t> px(size_t(w) * h * 3);
    uint32_t s = 7;
    for (uint8_t &b : px) {
        s = s * 1103515245u + 12345u;
        b = uint8_t(s >> 24);
    }
    return px;
}

// Writes a grey-scale PNG with libpng directly, to test rejection.
void write_gray(const std::string &path)
{
    FILE *f = std::fopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    ASSERT_EQ(setjmp(png_jmpbuf(png)), 0);
    png_init_io(png, f);
    png_set_IHDR(png, info, 2, 2, 8, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    uint8_t row[2] = {10, 200};
    png_write_row(png, row);
    png_write_row(png, row);
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
}

// The kernel writes to a stream its caller opens (the output committer, in the programs).
rt_status write_png(const std::string &path, uint32_t w, uint32_t h, const uint8_t *px, char *msg, size_t len)
{
    FILE *f = std::fopen(path.c_str(), "wb");
    if (!f) return RT_ERR_IO;
    rt_status st = rt_png_write_stream(f, path.c_str(), w, h, px, msg, len);
    std::fclose(f);
    return st;
}

}  // namespace

TEST(Png, RoundTripIsExact)
{
    std::string dir = fresh_dir("roundtrip");
    std::string path = dir + "/img.png";
    const uint32_t w = 37, h = 23;
    std::vector<uint8_t> px = pattern(w, h);
    char msg[RT_MSG_LEN] = "";
    ASSERT_EQ(write_png(path, w, h, px.data(), msg, sizeof msg), RT_OK) << msg;
    uint32_t rw = 0, rh = 0;
    uint8_t *back = nullptr;
    ASSERT_EQ(rt_png_read(path.c_str(), &rw, &rh, &back, msg, sizeof msg), RT_OK) << msg;
    EXPECT_EQ(rw, w);
    EXPECT_EQ(rh, h);
    EXPECT_EQ(std::vector<uint8_t>(back, back + px.size()), px);
    std::free(back);
    EXPECT_EQ(list_dir(dir), (std::vector<std::string>{"img.png"}));
}

TEST(Png, OverwriteReplacesTheFile)
{
    std::string dir = fresh_dir("overwrite");
    std::string path = dir + "/img.png";
    char msg[RT_MSG_LEN] = "";
    std::vector<uint8_t> a = pattern(4, 4), b(3 * 2 * 5, 99);
    ASSERT_EQ(write_png(path, 4, 4, a.data(), msg, sizeof msg), RT_OK) << msg;
    ASSERT_EQ(write_png(path, 2, 5, b.data(), msg, sizeof msg), RT_OK) << msg;
    uint32_t w, h;
    uint8_t *back = nullptr;
    ASSERT_EQ(rt_png_read(path.c_str(), &w, &h, &back, msg, sizeof msg), RT_OK) << msg;
    EXPECT_EQ(w, 2u);
    EXPECT_EQ(h, 5u);
    EXPECT_EQ(std::vector<uint8_t>(back, back + b.size()), b);
    std::free(back);
    EXPECT_EQ(list_dir(dir).size(), 1u);
}

TEST(Png, FullDeviceIsReportedWithItsErrno)
{
    FILE *f = std::fopen("/dev/full", "wb");
    if (!f) GTEST_SKIP() << "no /dev/full";
    std::vector<uint8_t> px = pattern(64, 64);
    char msg[RT_MSG_LEN] = "";
    EXPECT_EQ(rt_png_write_stream(f, "full.png", 64, 64, px.data(), msg, sizeof msg), RT_ERR_IO);
    std::fclose(f);
    EXPECT_EQ(std::string(msg), "full.png: cannot write: No space left on device");
}

TEST(Png, WriteRejectsEmptyImage)
{
    std::string dir = fresh_dir("empty");
    std::string path = dir + "/img.png";
    uint8_t px[3] = {0, 0, 0};
    char msg[RT_MSG_LEN] = "";
    EXPECT_EQ(write_png(path, 0, 1, px, msg, sizeof msg), RT_ERR_INVALID);
    EXPECT_NE(std::string(msg).find("0x1"), std::string::npos) << msg;
}

TEST(Png, ReadRejectsOtherFormats)
{
    std::string dir = fresh_dir("formats");
    char msg[RT_MSG_LEN] = "";
    uint32_t w, h;
    uint8_t *px = nullptr;

    std::string gray = dir + "/gray.png";
    write_gray(gray);
    EXPECT_EQ(rt_png_read(gray.c_str(), &w, &h, &px, msg, sizeof msg), RT_ERR_INVALID);
    EXPECT_NE(std::string(msg).find(gray), std::string::npos) << msg;
    EXPECT_EQ(px, nullptr);

    std::string text = dir + "/text.png";
    FILE *f = std::fopen(text.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs("not a picture at all\n", f);
    std::fclose(f);
    EXPECT_EQ(rt_png_read(text.c_str(), &w, &h, &px, msg, sizeof msg), RT_ERR_INVALID);

    EXPECT_EQ(rt_png_read((dir + "/absent.png").c_str(), &w, &h, &px, msg, sizeof msg), RT_ERR_IO);
}

TEST(Png, ReadTruncatedFileIsIoError)
{
    std::string dir = fresh_dir("truncated");
    std::string path = dir + "/img.png";
    std::vector<uint8_t> px = pattern(64, 64);
    char msg[RT_MSG_LEN] = "";
    ASSERT_EQ(write_png(path, 64, 64, px.data(), msg, sizeof msg), RT_OK) << msg;
    struct stat st;
    ASSERT_EQ(stat(path.c_str(), &st), 0);
    ASSERT_EQ(truncate(path.c_str(), st.st_size / 2), 0);
    uint32_t w, h;
    uint8_t *back = nullptr;
    EXPECT_EQ(rt_png_read(path.c_str(), &w, &h, &back, msg, sizeof msg), RT_ERR_IO);
    EXPECT_NE(std::string(msg).find(path), std::string::npos) << msg;
    EXPECT_EQ(back, nullptr);
}
