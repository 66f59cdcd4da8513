// number_test.cpp - the one decimal number syntax of every torusrt format: what is a number, what
// each refusal is, and the edges of the range.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "rt_number.h"

namespace {

rt_number_fault real(const char *text, double *v) { return rt_number_real(text, std::strlen(text), v); }

}  // namespace

TEST(Number, ReadsPlainDecimalReals)
{
    struct Case {
        const char *text;
        double value;
    };
    const Case ok[] = {{"0", 0},           {"-0", -0.0},       {"0.5", 0.5},    {"-12.25", -12.25},
                       {"1e3", 1000},      {"2E-3", 0.002},    {"7e+2", 700},   {"0e-999", 0},
                       {"1e-300", 1e-300}, {"4e-320", 4e-320}, {"1e308", 1e308}};
    for (const Case &c : ok) {
        double v = 99;
        EXPECT_EQ(real(c.text, &v), RT_NUMBER_OK) << c.text;
        EXPECT_EQ(v, c.value) << c.text;
    }
}

TEST(Number, RefusesEveryOtherFormAndNamesWhy)
{
    struct Case {
        const char *text;
        rt_number_fault fault;
    };
    const Case bad[] = {
        {"", RT_NUMBER_SYNTAX},          {"+5", RT_NUMBER_SYNTAX},          {".5", RT_NUMBER_SYNTAX},
        {"5.", RT_NUMBER_SYNTAX},        {"-.5", RT_NUMBER_SYNTAX},         {"1e", RT_NUMBER_SYNTAX},
        {"nan", RT_NUMBER_SYNTAX},       {"inf", RT_NUMBER_SYNTAX},         {"1 ", RT_NUMBER_SYNTAX},
        {"010", RT_NUMBER_LEADING_ZERO}, {"-00.5", RT_NUMBER_LEADING_ZERO}, {"0x10", RT_NUMBER_HEX},
        {"0x1p3", RT_NUMBER_HEX},        {"1e309", RT_NUMBER_TOO_LARGE},    {"-1e400", RT_NUMBER_TOO_LARGE},
        {"1e-400", RT_NUMBER_UNDERFLOW}, {"-1e-330", RT_NUMBER_UNDERFLOW}};
    for (const Case &c : bad) {
        double v = 99;
        EXPECT_EQ(real(c.text, &v), c.fault) << c.text;
        EXPECT_EQ(v, 99) << c.text << ": the value is left alone";
        EXPECT_NE(std::string(rt_number_fault_text(c.fault)), rt_number_fault_text(RT_NUMBER_OK)) << c.text;
    }
}

TEST(Number, ReadsWholeNumbersUpToTheirMaximum)
{
    unsigned long long v = 7;
    EXPECT_EQ(rt_number_whole("0", 1, 0, &v), RT_NUMBER_OK);
    EXPECT_EQ(v, 0u);
    EXPECT_EQ(rt_number_whole("100000", 6, 100000, &v), RT_NUMBER_OK);
    EXPECT_EQ(v, 100000u);
    EXPECT_EQ(rt_number_whole("100001", 6, 100000, &v), RT_NUMBER_TOO_LARGE);
    EXPECT_EQ(rt_number_whole("5", 1, 0, &v), RT_NUMBER_TOO_LARGE);
    EXPECT_EQ(rt_number_whole("18446744073709551615", 20, ~0ull, &v), RT_NUMBER_OK);
    EXPECT_EQ(v, ~0ull);
    EXPECT_EQ(rt_number_whole("18446744073709551616", 20, ~0ull, &v), RT_NUMBER_TOO_LARGE);
    for (const char *bad : {"", "+1", "-1", "1.0", "1e3", " 1"})
        EXPECT_EQ(rt_number_whole(bad, std::strlen(bad), 9, &v), RT_NUMBER_SYNTAX) << bad;
    EXPECT_EQ(rt_number_whole("01", 2, 9, &v), RT_NUMBER_LEADING_ZERO);
    EXPECT_EQ(rt_number_whole("0x1", 3, 9, &v), RT_NUMBER_HEX);
}

TEST(Number, ReadsOnlyTheGivenLength)
{
    double v = 0;
    EXPECT_EQ(rt_number_real("12.5xyz", 4, &v), RT_NUMBER_OK);
    EXPECT_EQ(v, 12.5);
}
