// vcd_stream.h - SystemC writes its VCD through stdio and never reports a failed write. It is
// handed a FIFO instead; a thread copies the stream to the real file with every write checked
// (a full disk fails the run) and, given a time window, keeps only the changes inside it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <thread>

namespace torusrt {

class VcdStream {
  public:
    // Copies into `out_path` (named `shown` in messages), keeping times in [from_ps, to_ps].
    // Throws UserError if the FIFO or `out_path` cannot be created.
    VcdStream(const std::string &out_path, const std::string &shown, uint64_t from_ps, uint64_t to_ps);
    ~VcdStream();
    VcdStream(const VcdStream &) = delete;
    VcdStream &operator=(const VcdStream &) = delete;
    // The name to give sc_create_vcd_trace_file (it appends ".vcd").
    const std::string &systemc_name() const { return m_sc_name; }
    // Call after SystemC closed the trace: waits for the copy. Throws UserError on a write error.
    void finish();

  private:
    void copy_loop();
    void stop();

    std::string m_shown, m_dir, m_sc_name;
    uint64_t m_from_ps, m_to_ps;
    int m_read_fd = -1, m_hold_fd = -1, m_out_fd = -1;
    int m_error = 0;                         // errno of the first failed write or close
    size_t m_dir_slot = 0, m_fifo_slot = 0;  // their signal_cleanup registrations
    std::thread m_thread;
};

}  // namespace torusrt
