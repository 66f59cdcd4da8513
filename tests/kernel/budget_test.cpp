// budget_test.cpp - the memory budget: sizes as written on the command line, reserving, and
// the packet share left for a run.
#include <gtest/gtest.h>

#include <string>

#include "rt_budget.h"

TEST(Budget, ParsesSizesWithBinaryUnits)
{
    struct Case {
        const char *text;
        uint64_t bytes;
    };
    const Case ok[] = {{"0", 0},
                       {"1000000", 1000000},
                       {"512M", 512ull << 20},
                       {"4G", 4ull << 30},
                       {"1.5G", 3ull << 29},
                       {"64KiB", 64ull << 10},
                       {"2TB", 2ull << 40},
                       {"100B", 100}};
    for (const Case &c : ok) {
        uint64_t b = 1;
        EXPECT_EQ(rt_budget_parse(c.text, &b, nullptr, 0), RT_OK) << c.text;
        EXPECT_EQ(b, c.bytes) << c.text;
    }
    for (const char *bad :
         {"", "G", "-1", "4Q", "4 G", "1e9", "nan", ".", ".5G", "5.G", "010M", "99999999999999999999T"}) {
        uint64_t b = 7;
        char msg[RT_MSG_LEN] = "";
        EXPECT_EQ(rt_budget_parse(bad, &b, msg, sizeof msg), RT_ERR_INVALID) << bad;
        EXPECT_EQ(b, 7u) << bad;
        EXPECT_NE(std::string(msg).find("512M"), std::string::npos) << msg;
    }
    // Under one byte is not "no limit" (0): refused, not rounded down to 0.
    for (const char *tiny : {"0.5", "0.9999", "0.0000001K"}) {
        uint64_t b = 7;
        char msg[RT_MSG_LEN] = "";
        EXPECT_EQ(rt_budget_parse(tiny, &b, msg, sizeof msg), RT_ERR_INVALID) << tiny;
        EXPECT_EQ(b, 7u) << tiny;
        EXPECT_NE(std::string(msg).find("less than one byte"), std::string::npos) << msg;
    }
}

TEST(Budget, ReserveTakesFromWhatIsLeftAndNamesTheOverrun)
{
    rt_budget b = rt_budget_make(1000);
    char msg[RT_MSG_LEN] = "";
    EXPECT_EQ(rt_budget_reserve(&b, 600, "first", msg, sizeof msg), RT_OK);
    EXPECT_EQ(rt_budget_left(&b), 400u);
    EXPECT_EQ(rt_budget_reserve(&b, 500, "the frame buffer", msg, sizeof msg), RT_ERR_LIMIT);
    EXPECT_EQ(b.used, 600u) << "a refused reservation takes nothing";
    EXPECT_EQ(std::string(msg),
              "memory budget exceeded: the frame buffer would take 500 bytes, 100 bytes more than the "
              "400 bytes left of the 1000 bytes budget (raise it with --memory-budget)");
    EXPECT_EQ(rt_budget_packets_allowed(&b, 100), 4u);
}

TEST(Budget, ZeroIsNoLimit)
{
    rt_budget b = rt_budget_make(0);
    EXPECT_EQ(rt_budget_reserve(&b, UINT64_MAX, "all", nullptr, 0), RT_OK);
    EXPECT_EQ(rt_budget_left(&b), UINT64_MAX);
    EXPECT_EQ(rt_budget_packets_allowed(&b, 176), UINT64_MAX);
    EXPECT_EQ(rt_budget_left(nullptr), UINT64_MAX);
}
