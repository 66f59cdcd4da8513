// guess_scoreboard.h - adaptive's record of how well each guess of a frame's load served that
// frame: before frame k, every guess gives a table; once frame k has run, each table is scored
// by the mean work of the busiest nodes it would have had in frame k's measured load. The guess
// taken next is the one with the least mean ratio to each frame's best table over the last
// `window` frames scored, unless the first guess (frame k-1's load) is within `margin` of it: a
// margin asks for clear evidence before another guess replaces the plain one (remap_policy.h).
#pragma once

#include <cstddef>
#include <deque>
#include <string>
#include <vector>

namespace torusrt {

class GuessScoreboard {
  public:
    // `guesses` kinds of guess, judged over the last `window` (>= 1) frames scored; the first
    // is kept while its mean ratio is at most (1 + margin) times the least (margin >= 0).
    GuessScoreboard(size_t guesses, size_t window, double margin);
    // One frame's scores, one per guess: the busiest nodes' work under that guess's table in the
    // frame's measured load, seconds; negative for a guess that gave no table for the frame.
    void record(const std::vector<double> &busiest_s);
    // Guess g's mean of score / the frame's least score over the frames in the window it was
    // scored in; negative when it was scored in none.
    double mean_ratio(size_t g) const;
    // The guess with the least mean ratio (the first of those on a tie), or 0 when guess 0's is
    // within the margin of it; 0 before any frame is scored.
    size_t best() const;
    size_t frames() const { return m_ratios.size(); }  // frames in the window
    // "frame 1.000000, trend 1.012345, ..." for the guesses scored, with these names.
    std::string text(const std::vector<std::string> &names) const;

  private:
    size_t m_guesses, m_window;
    double m_margin;
    std::deque<std::vector<double>> m_ratios;  // per frame in the window, per guess (negative: none)
};

}  // namespace torusrt
