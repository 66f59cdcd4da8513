// progress.cpp - progress on stderr when it is a terminal.
#include "progress.h"

#include <cstdio>
#include <unistd.h>

namespace torusrt {

Progress::Progress(std::string label, bool quiet)
    : m_label(std::move(label)), m_enabled(!quiet && isatty(STDERR_FILENO))
{
}

Progress::~Progress() { finish(); }

void Progress::update(uint64_t done, uint64_t total)
{
    if (!m_enabled || total == 0) return;
    int percent = static_cast<int>(done * 100 / total);
    if (percent == m_last_percent) return;
    m_last_percent = percent;
    std::fprintf(stderr, "\r%s: %3d%%", m_label.c_str(), percent);
    std::fflush(stderr);
}

void Progress::finish()
{
    if (m_enabled && m_last_percent >= 0) std::fprintf(stderr, "\r%*s\r", static_cast<int>(m_label.size()) + 6, "");
    m_last_percent = -1;
}

}  // namespace torusrt
