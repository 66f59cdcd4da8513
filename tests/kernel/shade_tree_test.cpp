// shade_tree_test.cpp - the worst-case shade tree of one pixel from the materials
// (rt_shade_tree.h): diffuse scenes make one ray at any depth, mirrors a chain, glass that also
// reflects a binary tree cut by depth and weight; the bound is never below what a render makes,
// and the budget check refuses only what cannot fit, naming --max-depth and --min-weight.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "rt_nff.h"
#include "rt_shade_tree.h"
#include "test_support.h"

using namespace torusrt_test;

namespace {

// Two lights, a floor of material `floor` and a sphere of material `ball`.
ScenePtr scene_of(const char *floor, const char *ball)
{
    std::string text = std::string("v from 0 3 6 at 0 0 0 up 0 1 0 angle 45 hither 1 resolution 12 12\n"
                                   "l 4 6 4\nl -4 6 4\nf ") +
                       floor + "\np 4 -5 0 -5  5 0 -5  5 0 5  -5 0 5\nf " + ball + "\ns 0 1 0 1\n";
    char msg[RT_MSG_LEN] = "";
    rt_scene *s = nullptr;
    EXPECT_EQ(rt_nff_parse("tree.nff", text.c_str(), text.size(), &s, msg, sizeof msg, nullptr, nullptr), RT_OK) << msg;
    return ScenePtr(s);
}

const char *kDiffuse = "0.8 0.8 0.8 1 0 0 0 1";
const char *kMirror = "0.8 0.8 0.8 0.1 0.9 30 0 1";
const char *kGlass = "0.9 0.9 0.9 0.05 0.5 60 0.5 1.5";
const char *kClearGlass = "0.9 0.9 0.9 0.1 0 0 0.9 1.5";

}  // namespace

TEST(ShadeTree, DiffuseSceneMakesOneRayAtAnyDepth)
{
    ScenePtr s = scene_of(kDiffuse, kDiffuse);
    ASSERT_TRUE(s);
    // One ray and a shadow packet per light (2).
    EXPECT_EQ(rt_shade_tree_packets(s.get(), 1000, 0.0), 3.0);
    rt_step_params p = rt_step_params_default();
    p.max_depth = 1000;
    p.min_weight = 0.0;
    rt_budget b = rt_budget_make(1024);
    char msg[RT_MSG_LEN] = "";
    EXPECT_EQ(rt_shade_tree_check(s.get(), &p, &b, 176, msg, sizeof msg), RT_OK) << msg;
}

TEST(ShadeTree, OneBranchPerHitIsAChain)
{
    // Mirrors only, and glass that does not reflect: each hit makes one ray at most.
    for (const char *m : {kMirror, kClearGlass}) {
        ScenePtr s = scene_of(kDiffuse, m);
        ASSERT_TRUE(s);
        EXPECT_EQ(rt_shade_tree_packets(s.get(), 1000, 0.0), 1001.0 * 3.0) << m;
        EXPECT_EQ(rt_shade_tree_packets(s.get(), 8, 0.0), 9.0 * 3.0) << m;
    }
    // Weight 0.9^d stays >= 1/512 up to d = 59; weights are rounded up to steps of 2^(1/16),
    // so the bound may go a little deeper, but the cut by weight holds.
    ScenePtr s = scene_of(kDiffuse, kMirror);
    double cut = rt_shade_tree_packets(s.get(), 1000, 1.0 / 512.0);
    EXPECT_GE(cut, 60.0 * 3.0);
    EXPECT_LE(cut, 80.0 * 3.0);
}

TEST(ShadeTree, ReflectingGlassBranchesTwice)
{
    ScenePtr s = scene_of(kDiffuse, kGlass);
    ASSERT_TRUE(s);
    // Ks 0.5 and T 0.5: every node splits, weights 2^-d; depth 8 holds all 2^9 - 1 rays.
    EXPECT_EQ(rt_shade_tree_packets(s.get(), 8, 0.0), 511.0 * 3.0);
    // min-weight 1/512 stops at depth 9 whatever --max-depth says.
    EXPECT_EQ(rt_shade_tree_packets(s.get(), 1000, 1.0 / 512.0), 1023.0 * 3.0);
    EXPECT_EQ(rt_shade_tree_packets(s.get(), 1000, 1.0 / 1024.0), 2047.0 * 3.0);
    // No cut at all: 2^1001 - 1 rays, beyond any budget.
    EXPECT_GE(rt_shade_tree_packets(s.get(), 1000, 0.0), 1e300);
}

TEST(ShadeTree, BoundIsNeverBelowWhatARenderMakes)
{
    for (const char *ball : {kDiffuse, kMirror, kGlass, kClearGlass})
        for (int depth : {0, 1, 3, 8}) {
            ScenePtr s = scene_of(kMirror, ball);
            ASSERT_TRUE(s);
            Image im = render(s.get(), 8, false, depth);
            ASSERT_TRUE(im.ok);
            double made = 0;
            for (int k = 0; k < RT_PACKET_KINDS; k++) made += double(im.stats.packets.created[k]);
            double bound = rt_shade_tree_packets(s.get(), depth, 1.0 / 512.0);
            EXPECT_LE(made, bound * im.w * im.h) << ball << " at depth " << depth;
        }
}

// paper-image2's mirrors (Ks 0.9) and glass (Ks 0.1, T 0.9): one branch keeps nine tenths of
// the weight, the other one tenth, so a cut at 1/65536 leaves a tree far smaller than 2^33.
TEST(ShadeTree, EachSurfaceBranchesByItsOwnCoefficients)
{
    ScenePtr s = scene_of("0.8 0.8 0.8 0.1 0.9 30 0 1", "0.9 0.9 0.9 0.05 0.1 60 0.9 1.5");
    ASSERT_TRUE(s);
    double bound = rt_shade_tree_packets(s.get(), 32, 1.0 / 65536.0);
    EXPECT_LT(bound, 1e7);
    EXPECT_GE(bound, 33.0 * 3.0);  // the chain through the mirrors alone
}

TEST(ShadeTree, CheckRefusesWhatCannotFitAndNamesTheLimits)
{
    ScenePtr s = scene_of(kMirror, kGlass);
    ASSERT_TRUE(s);
    rt_step_params p = rt_step_params_default();
    char msg[RT_MSG_LEN] = "";
    rt_budget b = rt_budget_make(64ull << 20);
    EXPECT_EQ(rt_shade_tree_check(s.get(), &p, &b, 176, msg, sizeof msg), RT_OK) << msg;
    p.max_depth = 1000;
    p.min_weight = 0.0;
    ASSERT_EQ(rt_shade_tree_check(s.get(), &p, &b, 176, msg, sizeof msg), RT_ERR_LIMIT);
    std::string m = msg;
    EXPECT_EQ(m.rfind("memory budget exceeded:", 0), 0u) << m;
    EXPECT_NE(m.find("--max-depth 1000"), std::string::npos) << m;
    EXPECT_NE(m.find("--min-weight 0"), std::string::npos) << m;
    EXPECT_NE(m.find("packets"), std::string::npos) << m;
    // Without a limit nothing is refused.
    rt_budget none = rt_budget_make(0);
    EXPECT_EQ(rt_shade_tree_check(s.get(), &p, &none, 176, msg, sizeof msg), RT_OK);
}
