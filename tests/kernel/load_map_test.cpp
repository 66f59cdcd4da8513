// load_map_test.cpp - the load map's work per node, its time labels and its layout.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "rt_load_map.h"

namespace {

bool white(const rt_canvas *c, uint32_t x, uint32_t y)
{
    const uint8_t *p = c->rgb + (static_cast<size_t>(y) * c->width + x) * 3;
    return p[0] == 255 && p[1] == 255 && p[2] == 255;
}

// Share of the pixels of [x0, x1) x [y0, y1) that are drawn (not white).
double drawn(const rt_canvas *c, uint32_t x0, uint32_t y0, uint32_t x1, uint32_t y1)
{
    size_t n = 0;
    for (uint32_t y = y0; y < y1; y++)
        for (uint32_t x = x0; x < x1; x++) n += !white(c, x, y);
    return static_cast<double>(n) / ((x1 - x0) * (y1 - y0));
}

}  // namespace

TEST(LoadMap, WorkPerNodeSumsTheCellsEachNodeOwns)
{
    const int d[3] = {2, 2, 2};
    std::vector<double> work = {1, 2, 3, 4, 5, 6, 7, 8};
    std::vector<int32_t> owner = {0, 1, 0, 1, 2, 2, 2, 9};  // 9: no such node, ignored
    std::vector<double> node(3, -1);
    rt_node_work(d, work.data(), owner.data(), 3, node.data());
    EXPECT_DOUBLE_EQ(node[0], 1 + 3);
    EXPECT_DOUBLE_EQ(node[1], 2 + 4);
    EXPECT_DOUBLE_EQ(node[2], 5 + 6 + 7);
}

TEST(LoadMap, TimesAreWrittenInTheUnitThatReadsBest)
{
    char b[32];
    rt_time_label(850, b, sizeof b);
    EXPECT_STREQ(b, "850 us");
    rt_time_label(3251.04, b, sizeof b);
    EXPECT_STREQ(b, "3.251 ms");
    rt_time_label(3.251e6, b, sizeof b);
    EXPECT_STREQ(b, "3.251 s");
    rt_time_label(0, b, sizeof b);
    EXPECT_STREQ(b, "0 us");
}

TEST(LoadMap, EveryPartOfThePictureIsUsed)
{
    const int d[3] = {24, 24, 24};
    std::vector<double> work(24 * 24 * 24);
    std::vector<int32_t> owner(work.size());
    for (size_t i = 0; i < work.size(); i++) {
        work[i] = static_cast<double>(i % 97) * 100;
        owner[i] = static_cast<int32_t>(i % 16);
    }
    rt_canvas *c = rt_load_map_draw(d, work.data(), owner.data(), 16);
    ASSERT_NE(c, nullptr);
    uint32_t w = c->width, h = c->height;
    // The two maps side by side above, the chart below: no quarter of the canvas is left empty.
    EXPECT_GT(drawn(c, 0, 0, w / 2, h / 2), 0.25);
    EXPECT_GT(drawn(c, w / 2, 0, w, h / 2), 0.25);
    EXPECT_GT(drawn(c, 0, h / 2, w / 2, h), 0.10);
    EXPECT_GT(drawn(c, w / 2, h / 2, w, h), 0.10);
    rt_canvas_free(c);
}

// A 24^3 grid over 16 nodes with uneven work, drawn with `caption` (nullptr: none).
static rt_canvas *uneven_map(const char *caption)
{
    const int d[3] = {24, 24, 24};
    std::vector<double> work(24 * 24 * 24);
    std::vector<int32_t> owner(work.size());
    for (size_t i = 0; i < work.size(); i++) {
        work[i] = static_cast<double>(i % 97) * 100;
        owner[i] = static_cast<int32_t>(i % 16);
    }
    return rt_load_map_draw_replicas(d, work.data(), owner.data(), nullptr, 16, caption);
}

TEST(LoadMap, TheCaptionNamesTheRunAcrossTheTop)
{
    const char *caption = "paper-image1.nff, 4x4x4 torus, cost mapping";
    rt_canvas *c = uneven_map(caption);
    ASSERT_NE(c, nullptr);
    rt_canvas *alone = rt_canvas_new(c->width, c->height);  // the caption's letters on white
    ASSERT_NE(alone, nullptr);
    const uint8_t black[3] = {0, 0, 0};
    rt_canvas_text(alone, 4, 4, 2, caption, black);
    size_t letters = 0, same = 0, strip = static_cast<size_t>(c->width) * 16;
    for (size_t i = 0; i < strip * 3; i += 3) {
        letters += alone->rgb[i] == 0;
        same += c->rgb[i] == alone->rgb[i] && c->rgb[i + 1] == alone->rgb[i + 1] && c->rgb[i + 2] == alone->rgb[i + 2];
    }
    EXPECT_GT(letters, 100u);
    EXPECT_EQ(same, strip) << "the top 16 rows hold the caption and nothing else";
    rt_canvas_free(alone);
    rt_canvas_free(c);
}

TEST(LoadMap, TheNodeChartIsLabelledAtEachQuarter)
{
    rt_canvas *c = uneven_map(nullptr);
    ASSERT_NE(c, nullptr);
    // The chart takes the 160 rows above the last 20; its value labels sit left of its axis (x
    // 55). Runs of rows with ink there: 0, a quarter, a half, three quarters and the busiest.
    int runs = 0;
    bool inked_before = false;
    for (uint32_t y = c->height - 190; y < c->height - 14; y++) {
        bool inked = drawn(c, 0, y, 50, y + 1) > 0;
        runs += inked && !inked_before;
        inked_before = inked;
    }
    EXPECT_EQ(runs, 5);
    rt_canvas_free(c);
}

TEST(LoadMap, AnEmptyGridDrawsNothing)
{
    const int d[3] = {0, 4, 4};
    EXPECT_EQ(rt_load_map_draw(d, nullptr, nullptr, 4), nullptr);
}
