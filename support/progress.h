// progress.h - a one-line progress indicator on stderr, shown only on a terminal.
#pragma once

#include <cstdint>
#include <string>

namespace torusrt {

class Progress {
  public:
    Progress(std::string label, bool quiet);
    ~Progress();
    // Shows done/total as a percentage (throttled to whole percents).
    void update(uint64_t done, uint64_t total);
    // Clears the line.
    void finish();

  private:
    std::string m_label;
    bool m_enabled;
    int m_last_percent = -1;
};

}  // namespace torusrt
