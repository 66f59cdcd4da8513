// guess_scoreboard.cpp - the windowed score of adaptive's guesses.
#include "guess_scoreboard.h"

#include <cstdio>
#include <stdexcept>

namespace torusrt {

GuessScoreboard::GuessScoreboard(size_t guesses, size_t window, double margin)
    : m_guesses(guesses), m_window(window), m_margin(margin)
{
    if (guesses == 0 || window == 0) throw std::invalid_argument("GuessScoreboard: no guesses or an empty window");
    if (!(margin >= 0)) throw std::invalid_argument("GuessScoreboard: a negative margin");
}

void GuessScoreboard::record(const std::vector<double> &busiest_s)
{
    if (busiest_s.size() != m_guesses) throw std::invalid_argument("GuessScoreboard::record: one score per guess");
    double least = -1;
    for (double s : busiest_s)
        if (s >= 0 && (least < 0 || s < least)) least = s;
    if (least < 0) return;  // no guess gave a table: nothing to learn
    std::vector<double> ratios(m_guesses, -1);
    for (size_t g = 0; g < m_guesses; g++)
        if (busiest_s[g] >= 0) ratios[g] = least > 0 ? busiest_s[g] / least : 1;  // an empty frame ties all
    m_ratios.push_back(std::move(ratios));
    if (m_ratios.size() > m_window) m_ratios.pop_front();
}

double GuessScoreboard::mean_ratio(size_t g) const
{
    double sum = 0;
    size_t n = 0;
    for (const std::vector<double> &frame : m_ratios)
        if (frame[g] >= 0) sum += frame[g], n++;
    return n > 0 ? sum / static_cast<double>(n) : -1;
}

size_t GuessScoreboard::best() const
{
    size_t best = 0;
    double best_r = -1;
    for (size_t g = 0; g < m_guesses; g++) {
        double r = mean_ratio(g);
        if (r >= 0 && (best_r < 0 || r < best_r)) best = g, best_r = r;
    }
    double first = mean_ratio(0);
    return first >= 0 && first <= best_r * (1 + m_margin) ? 0 : best;
}

std::string GuessScoreboard::text(const std::vector<std::string> &names) const
{
    std::string out;
    for (size_t g = 0; g < m_guesses && g < names.size(); g++) {
        double r = mean_ratio(g);
        if (r < 0) continue;
        char buf[64];
        std::snprintf(buf, sizeof buf, "%s%s %.6f", out.empty() ? "" : ", ", names[g].c_str(), r);
        out += buf;
    }
    return out;
}

}  // namespace torusrt
