// timing_test.cpp - the timing table: defaults, files, costs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "rt_timing.h"

namespace {

// Writes `text` to a fresh file under the test temp directory.
std::string write_file(const std::string &name, const std::string &text)
{
    std::string path = testing::TempDir() + "torusrt_timing_" + name;
    FILE *f = std::fopen(path.c_str(), "w");
    EXPECT_NE(f, nullptr) << path;
    if (f) {
        std::fputs(text.c_str(), f);
        std::fclose(f);
    }
    return path;
}

struct LoadResult {
    rt_status status;
    std::string msg;
    rt_timing timing;
};

LoadResult load(const std::string &name, const std::string &text)
{
    LoadResult r;
    rt_timing_defaults(&r.timing);
    char msg[RT_MSG_LEN] = "";
    std::string path = write_file(name, text);
    r.status = rt_timing_load(path.c_str(), &r.timing, msg, sizeof msg);
    r.msg = msg;
    std::remove(path.c_str());
    return r;
}

}  // namespace

TEST(Timing, Defaults)
{
    rt_timing t;
    rt_timing_defaults(&t);
    EXPECT_EQ(t.test_miss_us, 1300);
    EXPECT_EQ(t.test_hit_us, 1750);
    EXPECT_EQ(t.dda_step_us, 340);
    EXPECT_EQ(t.shading_us, 4600);
    EXPECT_EQ(t.reflection_us, 680);
    EXPECT_EQ(t.refraction_us, 1100);
    EXPECT_EQ(t.packet_analysis_us, 580);
    EXPECT_EQ(t.packet_creation_us, 1600);
    EXPECT_EQ(t.fb_write_us, 0);
    EXPECT_EQ(t.link_us, 50);
    EXPECT_EQ(t.link_bytes_per_us, 0);
    EXPECT_EQ(t.packet_bytes, 28);
    EXPECT_EQ(t.host_inject_us, 0);
    EXPECT_EQ(t.bus_width_bytes, 2);
    EXPECT_EQ(t.bus_cycle_us, 4.0) << "the fitted profile";
    EXPECT_EQ(t.bus_arbitration_us, 0.25);
    EXPECT_EQ(t.memory_access_us, 0.5);
    EXPECT_EQ(t.handover_send_us, 0);
    EXPECT_EQ(t.handover_receive_us, 0);
    EXPECT_EQ(t.preprocess_unit_us, 340) << "a next-cell determination's time";
    EXPECT_EQ(t.cell_step_packet_us, 580) << "the packet analysis at every cell step";
}

TEST(Timing, KeysNameEveryField)
{
    rt_timing t;
    rt_timing_defaults(&t);
    ASSERT_EQ(rt_timing_key_count(), sizeof(rt_timing) / sizeof(double));  // a key for every field
    EXPECT_STREQ(rt_timing_key_name(0), "test_miss");
    EXPECT_EQ(rt_timing_get(&t, 0), 1300);
    bool seen_link = false, seen_width = false;
    for (size_t i = 0; i < rt_timing_key_count(); i++) {
        std::string k = rt_timing_key_name(i);
        bool ends_us = k.size() > 3 && k.compare(k.size() - 3, 3, "_us") == 0;
        EXPECT_EQ(ends_us, k == "link_bytes_per_us") << k;  // the unit suffix is dropped
        seen_link |= k == "link";
        seen_width |= k == "bus_width_bytes";
        // Setting through the key changes what get reports.
        char msg[RT_MSG_LEN] = "";
        ASSERT_EQ(rt_timing_set(&t, k.c_str(), 7.0 + double(i), msg, sizeof msg), RT_OK) << msg;
        EXPECT_EQ(rt_timing_get(&t, i), 7.0 + double(i));
    }
    EXPECT_TRUE(seen_link);
    EXPECT_TRUE(seen_width);
    EXPECT_EQ(rt_timing_key_name(rt_timing_key_count()), nullptr);
    EXPECT_TRUE(std::isnan(rt_timing_get(&t, rt_timing_key_count())));
}

TEST(Timing, SetRejectsBadValues)
{
    rt_timing t;
    rt_timing_defaults(&t);
    char msg[RT_MSG_LEN] = "";
    EXPECT_EQ(rt_timing_set(&t, "test_misses", 1, msg, sizeof msg), RT_ERR_INVALID);
    EXPECT_NE(std::string(msg).find("unknown key 'test_misses'"), std::string::npos) << msg;
    EXPECT_EQ(rt_timing_set(&t, "test_miss", -1, msg, sizeof msg), RT_ERR_INVALID);
    EXPECT_NE(std::string(msg).find("'test_miss' needs a non-negative number"), std::string::npos) << msg;
    EXPECT_EQ(rt_timing_set(&t, "link", NAN, msg, sizeof msg), RT_ERR_INVALID);
    EXPECT_EQ(rt_timing_set(&t, "link", INFINITY, msg, sizeof msg), RT_ERR_INVALID);
    EXPECT_EQ(rt_timing_set(&t, "packet_bytes", 0, msg, sizeof msg), RT_ERR_INVALID);
    EXPECT_EQ(rt_timing_set(&t, "bus_width_bytes", 0, msg, sizeof msg), RT_ERR_INVALID);
    EXPECT_EQ(rt_timing_set(&t, "test_miss", 0, msg, sizeof msg), RT_OK);
    EXPECT_EQ(t.test_miss_us, 0);
    EXPECT_EQ(t.packet_bytes, 28);  // failed sets change nothing
}

TEST(Timing, LoadParsesCommentsAndBothForms)
{
    LoadResult r = load("good.timing", "# a faster IP\n"
                                       "\n"
                                       "test_miss 650   # half\n"
                                       "test_hit = 875\n"
                                       "   dda_step=170\n"
                                       "link_bytes_per_us 14\n"
                                       "bus_cycle 0.125\n"
                                       "shading 1e3\n"
                                       "\t# indented comment\n");
    ASSERT_EQ(r.status, RT_OK) << r.msg;
    EXPECT_EQ(r.timing.test_miss_us, 650);
    EXPECT_EQ(r.timing.test_hit_us, 875);
    EXPECT_EQ(r.timing.dda_step_us, 170);
    EXPECT_EQ(r.timing.link_bytes_per_us, 14);
    EXPECT_EQ(r.timing.bus_cycle_us, 0.125);
    EXPECT_EQ(r.timing.shading_us, 1000);
    EXPECT_EQ(r.timing.refraction_us, 1100);  // untouched keys keep their values
}

TEST(Timing, LoadWithoutFinalNewline)
{
    LoadResult r = load("nonl.timing", "link 75");
    ASSERT_EQ(r.status, RT_OK) << r.msg;
    EXPECT_EQ(r.timing.link_us, 75);
}

TEST(Timing, LoadErrorsCarryFileAndLine)
{
    struct Case {
        const char *text, *expect;
    } cases[] = {
        {"test_miss 1\nbogus 3\n", ":2: unknown key 'bogus'"},
        {"# c\n\ntest_miss -5\n", ":3: 'test_miss' needs a non-negative number"},
        {"test_hit\n", ":1: expected 'key value'"},
        {"test_hit =\n", ":1: expected 'key value'"},
        {"link 1\nlink fast\n", ":2: 'link' given twice"},
        {"link fast\n", ":1: 'link' needs a decimal number"},
        {"link 12us\n", ":1: 'link' needs a decimal number"},
        {"link 0x1p3\n", ":1: 'link' needs a decimal number"},
        {"link 1 2\n", ":1: expected 'key value'"},
        {"packet_bytes 0\n", ":1: 'packet_bytes' needs a positive number"},
        {"link 1e-400\n", ":1: 'link' value '1e-400' is too close to 0 for a double"},
        {"link 050\n",
         ":1: 'link' value '050' has a leading zero (decimal only: it could be read as octal): write '50'"},
        {"link -007.5\n", ":1: 'link' value '-007.5' has a leading zero (decimal only: it could be read as octal): "
                          "write '-7.5'"},
    };
    int i = 0;
    for (const Case &c : cases) {
        std::string name = "bad" + std::to_string(i++) + ".timing";
        LoadResult r = load(name, c.text);
        EXPECT_EQ(r.status, RT_ERR_PARSE) << c.text;
        EXPECT_NE(r.msg.find(name + c.expect), std::string::npos) << "message: " << r.msg;
        // A failed load leaves the table as it was.
        EXPECT_EQ(r.timing.test_miss_us, 1300);
        EXPECT_EQ(r.timing.link_us, 50);
    }
}

TEST(Timing, LoadMissingFileIsIoError)
{
    rt_timing t;
    rt_timing_defaults(&t);
    char msg[RT_MSG_LEN] = "";
    std::string path = testing::TempDir() + "torusrt_no_such_dir/x.timing";
    EXPECT_EQ(rt_timing_load(path.c_str(), &t, msg, sizeof msg), RT_ERR_IO);
    EXPECT_NE(std::string(msg).find(path), std::string::npos) << msg;
}

TEST(Timing, StepCostIsTheHandSum)
{
    rt_timing t;
    rt_timing_defaults(&t);
    rt_op_counts ops = {1, 2, 3, 4, 5, 6, 7, 8, 9, 0, 0, 0};
    // 1*1300 + 2*1750 + 3*340 + 4*4600 + 5*680 + 6*1100 + 7*580 + 8*1600 + 9*0
    // = 1300 + 3500 + 1020 + 18400 + 3400 + 6600 + 4060 + 12800 = 51080
    EXPECT_EQ(rt_timing_step_us(&t, &ops), 51080.0);
    t.fb_write_us = 10;
    EXPECT_EQ(rt_timing_step_us(&t, &ops), 51170.0);
    rt_op_counts none = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    EXPECT_EQ(rt_timing_step_us(&t, &none), 0.0);
}

TEST(Timing, HandOversHaveTheirOwnKeys)
{
    rt_timing t;
    rt_timing_defaults(&t);
    ASSERT_EQ(rt_timing_set(&t, "handover_send", 100, nullptr, 0), RT_OK);
    ASSERT_EQ(rt_timing_set(&t, "handover_receive", 7, nullptr, 0), RT_OK);
    rt_op_counts ops{};
    ops.handovers_sent = 3;
    ops.handovers_received = 2;
    EXPECT_EQ(rt_timing_step_us(&t, &ops), 3 * 100.0 + 2 * 7.0);
    ops.packets_created = 1;  // a new packet stays at packet_creation
    EXPECT_EQ(rt_timing_step_us(&t, &ops), 314.0 + t.packet_creation_us);
}

TEST(Timing, CellStepPacketCostIsItsOwnKeyAndZeroOutsideTheFit)
{
    rt_timing t;
    rt_timing_defaults(&t);
    for (size_t i = 0; i < rt_timing_profile_count(); i++) {
        rt_timing p;
        const std::string name = rt_timing_profile_name(i);
        ASSERT_EQ(rt_timing_profile(name.c_str(), &p, nullptr, 0), RT_OK);
        EXPECT_EQ(p.cell_step_packet_us, name == "fitted" ? 580.0 : 0.0) << name;
    }
    ASSERT_EQ(rt_timing_set(&t, "cell_step_packet", 0, nullptr, 0), RT_OK);
    rt_op_counts none{};
    none.cell_steps = 4;
    EXPECT_EQ(rt_timing_step_us(&t, &none), 0.0) << "set to 0, a cell step costs nothing";
    ASSERT_EQ(rt_timing_set(&t, "cell_step_packet", 580, nullptr, 0), RT_OK);
    rt_op_counts ops{};
    ops.cell_steps = 4;
    EXPECT_EQ(rt_timing_step_us(&t, &ops), 4 * 580.0);
    ops.dda_steps = 4;  // the next-cell determination stays dda_step's
    EXPECT_EQ(rt_timing_step_us(&t, &ops), 4 * 580.0 + 4 * t.dda_step_us);
}

TEST(Timing, ProfilesDifferOnlyInTheHandOver)
{
    rt_timing lit, cal, def, fit;
    char msg[RT_MSG_LEN] = "";
    rt_timing_defaults(&def);
    ASSERT_EQ(rt_timing_profile("literal", &lit, msg, sizeof msg), RT_OK) << msg;
    ASSERT_EQ(rt_timing_profile("calibrated", &cal, msg, sizeof msg), RT_OK) << msg;
    ASSERT_EQ(rt_timing_profile("fitted", &fit, msg, sizeof msg), RT_OK) << msg;
    EXPECT_EQ(lit.handover_send_us, lit.packet_creation_us) << "literal: a hand-over is a creation";
    EXPECT_EQ(lit.handover_receive_us, lit.packet_analysis_us) << "... and an analysis";
    for (size_t i = 0; i < rt_timing_key_count(); i++) {
        std::string k = rt_timing_key_name(i);
        if (k.rfind("handover_", 0) == 0) continue;
        EXPECT_EQ(rt_timing_get(&lit, i), rt_timing_get(&cal, i)) << k;
    }
    for (size_t i = 0; i < rt_timing_key_count(); i++)
        EXPECT_EQ(rt_timing_get(&def, i), rt_timing_get(&fit, i)) << rt_timing_key_name(i) << ": the default is fitted";
    EXPECT_STREQ(rt_timing_default_profile(), "fitted");
    EXPECT_EQ(rt_timing_profile("nonesuch", &lit, msg, sizeof msg), RT_ERR_INVALID);
    EXPECT_NE(std::string(msg).find("nonesuch"), std::string::npos) << msg;
}

// The fitted profile is the calibrated one with the fidelity study's packet cost per cell step
// (the table's packet analysis) and bus and memory timing; round one's fit, the calibrated one
// with a 2 us bus cycle and memory access and nothing per cell step.
TEST(Timing, FittedProfilesAreCalibratedWithTheirFits)
{
    rt_timing fit, one, cal;
    char msg[RT_MSG_LEN] = "";
    ASSERT_EQ(rt_timing_profile("fitted", &fit, msg, sizeof msg), RT_OK) << msg;
    ASSERT_EQ(rt_timing_profile("round-one", &one, msg, sizeof msg), RT_OK) << msg;
    ASSERT_EQ(rt_timing_profile("calibrated", &cal, msg, sizeof msg), RT_OK) << msg;
    EXPECT_EQ(fit.bus_cycle_us, 4.0);
    EXPECT_EQ(fit.memory_access_us, 0.5);
    EXPECT_EQ(fit.cell_step_packet_us, fit.packet_analysis_us) << "the packet analysis at every cell step";
    EXPECT_EQ(one.bus_cycle_us, 2.0);
    EXPECT_EQ(one.memory_access_us, 2.0);
    EXPECT_EQ(one.cell_step_packet_us, 0.0);
    for (size_t i = 0; i < rt_timing_key_count(); i++) {
        std::string k = rt_timing_key_name(i);
        if (k == "bus_cycle" || k == "memory_access" || k == "cell_step_packet") continue;
        EXPECT_EQ(rt_timing_get(&fit, i), rt_timing_get(&cal, i)) << k;
        EXPECT_EQ(rt_timing_get(&one, i), rt_timing_get(&cal, i)) << k;
    }
}

// Each built-in profile's file in timing/ holds its values, every key written out; the machine
// files' timing file is the fitted profile.
TEST(Timing, ProfileFilesHoldTheProfiles)
{
    ASSERT_EQ(rt_timing_profile_count(), 4u);
    EXPECT_EQ(rt_timing_profile_name(4), nullptr);
    const std::string src = TORUSRT_SOURCE_DIR;
    std::vector<std::pair<std::string, std::string>> pairs;
    for (size_t p = 0; p < rt_timing_profile_count(); p++)
        pairs.emplace_back(rt_timing_profile_name(p), src + "/timing/" + rt_timing_profile_name(p) + ".timing");
    pairs.emplace_back("fitted", src + "/machines/timing/fitted.timing");
    for (const auto &[name, path] : pairs) {
        rt_timing want, got;
        char msg[RT_MSG_LEN] = "";
        ASSERT_EQ(rt_timing_profile(name.c_str(), &want, msg, sizeof msg), RT_OK) << msg;
        /* Loaded over values no key has, so a key the file leaves out shows. */
        rt_timing_defaults(&got);
        for (size_t i = 0; i < rt_timing_key_count(); i++)
            ASSERT_EQ(rt_timing_set(&got, rt_timing_key_name(i), 12345.0, msg, sizeof msg), RT_OK) << msg;
        ASSERT_EQ(rt_timing_load(path.c_str(), &got, msg, sizeof msg), RT_OK) << msg;
        for (size_t i = 0; i < rt_timing_key_count(); i++)
            EXPECT_EQ(rt_timing_get(&got, i), rt_timing_get(&want, i)) << path << ": " << rt_timing_key_name(i);
    }
}

TEST(Timing, LinkAndBusTimes)
{
    rt_timing t;
    rt_timing_defaults(&t);
    EXPECT_EQ(rt_timing_link_packet_us(&t), 50.0);
    t.link_bytes_per_us = 14;  // 28 bytes over 14 bytes/us
    EXPECT_EQ(rt_timing_link_packet_us(&t), 2.0);
    t.packet_bytes = 35;
    EXPECT_EQ(rt_timing_link_packet_us(&t), 2.5);
    // A set-up time comes before the transfer, with a bandwidth and with a time per packet.
    t.link_setup_us = 1.5;
    EXPECT_EQ(rt_timing_link_packet_us(&t), 4.0);
    t.link_bytes_per_us = 0;
    EXPECT_EQ(rt_timing_link_packet_us(&t), 51.5);
    t.link_setup_us = 0;
    // ceil(bytes / 2) cycles of 0.5 us.
    t.bus_cycle_us = 0.5;
    EXPECT_EQ(rt_timing_bus_transfer_us(&t, 28), 7.0);
    EXPECT_EQ(rt_timing_bus_transfer_us(&t, 5), 1.5);
    EXPECT_EQ(rt_timing_bus_transfer_us(&t, 1), 0.5);
    EXPECT_EQ(rt_timing_bus_transfer_us(&t, 0), 0.0);
    t.bus_width_bytes = 4;
    EXPECT_EQ(rt_timing_bus_transfer_us(&t, 28), 3.5);
}
