// progress.h - progress on stderr: on a terminal a line rewritten in place (percent and time
// left); in a batch log (stderr a file or a pipe) a line every few seconds with the simulated
// time, the packets done and the time left. None when stderr is itself one of the outputs.
#pragma once

#include <cstdint>
#include <string>

namespace torusrt {

struct ProgressSettings {
    bool quiet = false;
    double every_s = 0;             // seconds between batch-log lines (0: none)
    bool stderr_is_output = false;  // an output is written to stderr: no progress at all
};

class Progress {
  public:
    Progress(std::string label, const ProgressSettings &settings);
    ~Progress();
    // Shows done/total (the terminal's line throttled to whole percents); `sim_s` >= 0 adds
    // the simulated time to a batch line.
    void update(uint64_t done, uint64_t total, double sim_s = -1);
    // Whether anything is shown at all (the caller need not report otherwise).
    bool active() const { return m_mode != Mode::off; }
    // Counts done (and total) from `done`: a frame's progress after the frames before it.
    void start_from(uint64_t done) { m_base = done; }
    // Clears the terminal's line.
    void finish();

  private:
    enum class Mode { off, terminal, batch };
    std::string m_label;
    Mode m_mode;
    double m_every_s, m_start_s, m_next_line_s;
    uint64_t m_base = 0;
    int m_last_percent = -1;
    size_t m_shown = 0;  // characters of the terminal's line
};

// "45 s", "3 min 05 s", "2 h 07 min": a wall time left as a log reads it.
std::string wall_time_text(double seconds);

}  // namespace torusrt
