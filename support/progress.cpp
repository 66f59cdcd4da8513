// progress.cpp - progress on stderr: rewritten in place on a terminal, timed lines in a log.
#include "progress.h"

#include <cmath>
#include <cstdio>
#include <unistd.h>

#include "wall_clock.h"

namespace torusrt {

namespace {

// Wall time left from the share done so far and the time it took (< 0: not known yet).
double time_left_s(double elapsed_s, uint64_t done, uint64_t total)
{
    if (done == 0 || total == 0 || done > total) return -1;
    return elapsed_s * static_cast<double>(total - done) / static_cast<double>(done);
}

}  // namespace

std::string wall_time_text(double seconds)
{
    if (seconds < 0) return "unknown";
    long s = std::lround(seconds);
    char text[48];
    if (s < 60) std::snprintf(text, sizeof text, "%ld s", s);
    else if (s < 3600) std::snprintf(text, sizeof text, "%ld min %02ld s", s / 60, s % 60);
    else std::snprintf(text, sizeof text, "%ld h %02ld min", s / 3600, s / 60 % 60);
    return text;
}

Progress::Progress(std::string label, const ProgressSettings &settings)
    : m_label(std::move(label)), m_every_s(settings.every_s), m_start_s(wall_clock_s()),
      m_next_line_s(m_start_s + settings.every_s)
{
    if (settings.quiet || settings.stderr_is_output) m_mode = Mode::off;
    else if (isatty(STDERR_FILENO)) m_mode = Mode::terminal;
    else m_mode = settings.every_s > 0 ? Mode::batch : Mode::off;
}

Progress::~Progress() { finish(); }

void Progress::update(uint64_t done, uint64_t total, double sim_s)
{
    if (m_mode == Mode::off || done < m_base || total <= m_base) return;
    done -= m_base;
    total -= m_base;
    int percent = static_cast<int>(done * 100 / total);
    if (m_mode == Mode::terminal) {
        if (percent == m_last_percent) return;
        m_last_percent = percent;
        std::string left = wall_time_text(time_left_s(wall_clock_s() - m_start_s, done, total));
        int n = std::fprintf(stderr, "\r%s: %3d%%, about %s left   ", m_label.c_str(), percent, left.c_str());
        if (n > 0 && static_cast<size_t>(n) > m_shown) m_shown = static_cast<size_t>(n);
        std::fflush(stderr);
        return;
    }
    double now = wall_clock_s();
    if (now < m_next_line_s) return;
    m_next_line_s = now + m_every_s;
    std::string left = wall_time_text(time_left_s(now - m_start_s, done, total));
    if (sim_s >= 0)
        std::fprintf(stderr, "%s: progress: simulated %.6f s, %llu packets done, %d %%, about %s left\n",
                     m_label.c_str(), sim_s, static_cast<unsigned long long>(done), percent, left.c_str());
    else
        std::fprintf(stderr, "%s: progress: %llu of %llu done, %d %%, about %s left\n", m_label.c_str(),
                     static_cast<unsigned long long>(done), static_cast<unsigned long long>(total), percent,
                     left.c_str());
    std::fflush(stderr);
}

void Progress::finish()
{
    if (m_mode == Mode::terminal && m_shown > 0) std::fprintf(stderr, "\r%*s\r", static_cast<int>(m_shown), "");
    m_shown = 0;
    m_last_percent = -1;
}

}  // namespace torusrt
