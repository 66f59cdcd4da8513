// guess_scoreboard_test.cpp - adaptive's windowed judgement of its guesses (guess_scoreboard.h):
// ratios to each frame's best, guesses missing from some frames, the window's length, ties,
// the margin the first guess keeps.
// No simulation: the scoreboard is arithmetic.
#include <systemc>
#include <vector>

#include "guess_scoreboard.h"
#include "model_test.h"

using namespace torusrt;

TEST(GuessScoreboard, NothingScoredTakesTheFirstGuess)
{
    GuessScoreboard b(3, 4, 0);
    EXPECT_EQ(b.best(), 0u);
    EXPECT_EQ(b.frames(), 0u);
    EXPECT_LT(b.mean_ratio(1), 0);
    EXPECT_EQ(b.text({"a", "b", "c"}), "");
}

TEST(GuessScoreboard, RatiosToEachFramesBest)
{
    GuessScoreboard b(3, 4, 0);
    b.record({2.0, 1.0, 4.0});  // ratios 2, 1, 4
    b.record({1.0, 2.0, 1.0});  // ratios 1, 2, 1
    EXPECT_DOUBLE_EQ(b.mean_ratio(0), 1.5);
    EXPECT_DOUBLE_EQ(b.mean_ratio(1), 1.5);
    EXPECT_DOUBLE_EQ(b.mean_ratio(2), 2.5);
    EXPECT_EQ(b.best(), 0u);  // a tie between 0 and 1 goes to the first
    EXPECT_EQ(b.text({"a", "b", "c"}), "a 1.500000, b 1.500000, c 2.500000");
}

TEST(GuessScoreboard, OnlyTheLastWindowFramesCount)
{
    GuessScoreboard b(2, 2, 0);
    b.record({1.0, 3.0});  // falls out of the window below
    b.record({1.2, 1.0});
    b.record({1.1, 1.0});
    EXPECT_EQ(b.frames(), 2u);
    EXPECT_DOUBLE_EQ(b.mean_ratio(0), 1.15);
    EXPECT_EQ(b.best(), 1u);

    GuessScoreboard last(2, 1, 0);  // a window of one frame: frame k-1's winner
    last.record({1.0, 3.0});
    last.record({1.2, 1.0});
    EXPECT_EQ(last.best(), 1u);
}

TEST(GuessScoreboard, AGuessMissingFromSomeFramesIsJudgedOnTheOthers)
{
    GuessScoreboard b(2, 4, 0);
    b.record({1.0, -1});  // guess 1 gave no table (the trend before it can be made)
    b.record({1.1, 1.0});
    EXPECT_DOUBLE_EQ(b.mean_ratio(0), 1.05);
    EXPECT_DOUBLE_EQ(b.mean_ratio(1), 1.0);
    EXPECT_EQ(b.best(), 1u);
    EXPECT_EQ(b.text({"frame", "trend"}), "frame 1.050000, trend 1.000000");
}

TEST(GuessScoreboard, AnEmptyFrameTiesEveryGuessAndNoTableLearnsNothing)
{
    GuessScoreboard b(2, 4, 0);
    b.record({0.0, 0.0});
    EXPECT_DOUBLE_EQ(b.mean_ratio(1), 1.0);
    b.record({-1, -1});
    EXPECT_EQ(b.frames(), 1u);
    EXPECT_EQ(b.best(), 0u);
}

TEST(GuessScoreboard, RejectsAnEmptyWindowAndAWrongNumberOfScores)
{
    EXPECT_THROW(GuessScoreboard(2, 0, 0), std::invalid_argument);
    EXPECT_THROW(GuessScoreboard(0, 2, 0), std::invalid_argument);
    EXPECT_THROW(GuessScoreboard(2, 2, -0.01), std::invalid_argument);
    GuessScoreboard b(2, 2, 0);
    EXPECT_THROW(b.record({1.0}), std::invalid_argument);
}

TEST(GuessScoreboard, TheFirstGuessKeepsItsPlaceWithinTheMargin)
{
    GuessScoreboard b(3, 1, 0.03);
    b.record({1.02, 1.0, 1.5});  // the first within 3 % of the best: kept
    EXPECT_EQ(b.best(), 0u);
    b.record({1.031, 1.0, 1.5});  // just past the margin: the best replaces it
    EXPECT_EQ(b.best(), 1u);
    b.record({1.05, 1.0, 1.5});  // 5 % worse: the best replaces it
    EXPECT_EQ(b.best(), 1u);
    b.record({1.0, 1.01, 1.5});  // the first is the best itself
    EXPECT_EQ(b.best(), 0u);

    GuessScoreboard none(2, 1, 0);  // no margin: the least ratio alone
    none.record({1.001, 1.0});
    EXPECT_EQ(none.best(), 1u);
}

TEST(GuessScoreboard, AMarginDoesNotHelpAFirstGuessThatWasNeverScored)
{
    GuessScoreboard b(2, 1, 0.5);
    b.record({-1, 1.0});  // the first gave no table this frame
    EXPECT_EQ(b.best(), 1u);
}
