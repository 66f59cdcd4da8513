// timing_key_table_test.cpp - the kernel's timing key table is the one list of keys: each key has
// its unit and meaning, and docs/timing.md's key table lists the same keys in the same order with
// their defaults (or "profile"). The files in timing/ are checked against the profiles by
// timing_test.cpp (Timing.ProfileFilesHoldTheProfiles).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "rt_timing.h"

namespace {

const std::string kSource = TORUSRT_SOURCE_DIR;

std::string number(double v)
{
    char s[32];
    std::snprintf(s, sizeof s, "%g", v);
    return s;
}

}  // namespace

TEST(TimingKeyTable, EveryKeyHasAUnitAndAMeaning)
{
    for (size_t i = 0; i < rt_timing_key_count(); i++) {
        const std::string unit = rt_timing_key_unit(i);
        EXPECT_TRUE(unit == "us" || unit == "bytes" || unit == "bytes/us") << rt_timing_key_name(i);
        EXPECT_NE(std::string(rt_timing_key_meaning(i)), "") << rt_timing_key_name(i);
    }
    EXPECT_EQ(rt_timing_key_unit(rt_timing_key_count()), nullptr);
}

TEST(TimingKeyTable, DocsKeyTableListsTheKeysInOrderWithTheirDefaults)
{
    std::ifstream in(kSource + "/docs/timing.md");
    std::string text;
    std::vector<std::pair<std::string, std::string>> rows;  // key, default column
    while (std::getline(in, text)) {
        if (text.rfind("| `", 0) != 0) continue;
        size_t key_end = text.find("` |", 3);
        if (key_end == std::string::npos) continue;
        size_t next = text.find(" |", key_end + 3);
        rows.emplace_back(text.substr(3, key_end - 3), text.substr(key_end + 4, next - key_end - 4));
        if (rows.size() == rt_timing_key_count()) break;  // the profile table follows
    }
    rt_timing defaults;
    rt_timing_defaults(&defaults);
    ASSERT_EQ(rows.size(), rt_timing_key_count());
    for (size_t i = 0; i < rows.size(); i++) {
        EXPECT_EQ(rows[i].first, rt_timing_key_name(i)) << "docs/timing.md key table, row " << i + 1;
        if (rows[i].second != "profile") {
            EXPECT_EQ(rows[i].second, number(rt_timing_get(&defaults, i))) << rows[i].first;
        }
    }
}
