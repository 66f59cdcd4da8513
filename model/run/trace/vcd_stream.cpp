// vcd_stream.cpp - the FIFO between SystemC's VCD writer and the trace file.
#include "vcd_stream.h"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <map>
#include <sys/stat.h>
#include <unistd.h>

#include "option_parsing.h"
#include "output_files.h"
#include "signal_cleanup.h"
#include "user_error.h"

namespace torusrt {

namespace {

// Keeps the value changes of a VCD body that fall in a time window. Before the window it only
// remembers each signal's last value; at the window's start it writes them all.
class WindowFilter {
  public:
    WindowFilter(uint64_t from, uint64_t to) : m_from(from), m_to(to) {}
    // One line without its newline; appends what to keep to `out`.
    void line(const std::string &l, std::string &out)
    {
        if (m_header) {
            out += l + "\n";
            if (l.find("$enddefinitions") != std::string::npos) m_header = false;
            return;
        }
        if (m_done || l.empty()) return;
        if (l[0] == '#') {
            uint64_t t = std::strtoull(l.c_str() + 1, nullptr, 10);
            if (!m_started && t >= m_from) start(out);
            if (m_started && t > m_to) {
                out += "#" + std::to_string(m_to) + "\n";
                m_done = true;
            } else if (m_started && t != m_from) {
                out += l + "\n";
            }
            return;
        }
        if (m_started) {
            out += l + "\n";
            return;
        }
        std::string id = signal_id(l);
        if (!id.empty()) m_last[id] = l;
    }
    // At the end of the stream: a window that starts after the run still shows the final state.
    void end(std::string &out)
    {
        if (!m_header && !m_started) start(out);
    }

  private:
    static std::string signal_id(const std::string &l)
    {
        if (l[0] == 'b' || l[0] == 'B' || l[0] == 'r' || l[0] == 'R') {
            auto sp = l.find(' ');
            return sp == std::string::npos ? "" : l.substr(sp + 1);
        }
        if (std::strchr("01xXzZ", l[0])) return l.substr(1);
        return "";  // $dumpvars, $end, comments
    }
    void start(std::string &out)
    {
        out += "#" + std::to_string(m_from) + "\n";
        for (const auto &kv : m_last) out += kv.second + "\n";
        m_last.clear();
        m_started = true;
    }

    uint64_t m_from, m_to;
    bool m_header = true, m_started = false, m_done = false;
    std::map<std::string, std::string> m_last;
};

bool write_all(int fd, const char *p, size_t n)
{
    while (n > 0) {
        ssize_t w = ::write(fd, p, n);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) return false;
        p += w;
        n -= static_cast<size_t>(w);
    }
    return true;
}

}  // namespace

VcdStream::VcdStream(const std::string &out_path, const std::string &shown, uint64_t from_ps, uint64_t to_ps)
    : m_shown(shown), m_from_ps(from_ps), m_to_ps(to_ps)
{
    const char *tmpdir = std::getenv("TMPDIR");
    const std::string folder = tmpdir && *tmpdir ? tmpdir : "/tmp";
    std::string pattern = folder + "/torusrt-vcd.XXXXXX";
    std::string fifo;
    {
        // A stopping signal between making the folder and registering it would leave it behind.
        SignalsBlocked blocked;
        if (!mkdtemp(pattern.data())) {
            const std::string why = std::strerror(errno);
            throw UserError("--vcd: cannot create a temporary folder in " +
                            std::string(tmpdir && *tmpdir ? "TMPDIR '" : "'") + shown_text(folder) + "': " + why);
        }
        m_dir = pattern;
        m_sc_name = m_dir + "/trace";
        fifo = m_sc_name + ".vcd";
        m_dir_slot = remove_on_signal(m_dir, true);
        m_fifo_slot = remove_on_signal(fifo);
    }
    // The second, write-only descriptor keeps the FIFO open, so reads block (instead of seeing
    // end of file) until SystemC has opened and closed it and finish() drops this one.
    if (mkfifo(fifo.c_str(), 0600) != 0 || (m_read_fd = open(fifo.c_str(), O_RDONLY | O_NONBLOCK)) < 0 ||
        (m_hold_fd = open(fifo.c_str(), O_WRONLY)) < 0 || fcntl(m_read_fd, F_SETFL, 0) != 0) {
        int err = errno;
        stop();
        throw UserError("--vcd: cannot create a FIFO in " + m_dir + ": " + std::strerror(err));
    }
    m_out_fd = open_output_fd(out_path);  // standard output through its own descriptor
    if (m_out_fd < 0) {
        int err = errno;
        stop();
        throw UserError(shown + ": cannot write: " + std::strerror(err));
    }
    SignalsBlocked blocked;  // the copy thread inherits the mask: stopping signals go to the main thread
    try {
        m_thread = std::thread([this] { copy_loop(); });
    } catch (...) {  // no stack for the thread: the destructor of a half-made stream does not run
        stop();
        throw;
    }
}

void VcdStream::copy_loop()
{
    bool window = m_from_ps > 0 || m_to_ps != UINT64_MAX;
    WindowFilter filter(m_from_ps, m_to_ps);
    std::string pending, out, head;
    bool dated = false;  // the header's $date block is passed (see below)
    auto copy = [&](const char *data, size_t size) {
        if (!window) {
            if (!write_all(m_out_fd, data, size)) m_error = errno ? errno : EIO;
            return;
        }
        pending.append(data, size);
        size_t start = 0, nl;
        while ((nl = pending.find('\n', start)) != std::string::npos) {
            filter.line(pending.substr(start, nl - start), out);
            start = nl + 1;
        }
        pending.erase(0, start);
        if (!write_all(m_out_fd, out.data(), out.size())) m_error = errno ? errno : EIO;
        out.clear();
    };
    char buf[1 << 16];
    for (;;) {
        ssize_t n = ::read(m_read_fd, buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        if (m_error) continue;  // keep draining so the writer never blocks
        if (dated) {
            copy(buf, static_cast<size_t>(n));
            continue;
        }
        // SystemC writes the wall clock's date into the header: the same run's trace would differ
        // from second to second. The date block goes out without it.
        head.append(buf, static_cast<size_t>(n));
        size_t date = head.find("$date"), end = date == std::string::npos ? date : head.find("$end", date);
        if (end == std::string::npos && head.size() < 4096) continue;
        if (end != std::string::npos)
            head.replace(date, end - date, "$date\n    not recorded: the same run gives the same trace\n");
        dated = true;
        copy(head.data(), head.size());
    }
    if (!dated && !head.empty() && !m_error) copy(head.data(), head.size());
    if (window && !m_error) {
        if (!pending.empty()) filter.line(pending, out);
        filter.end(out);
        if (!write_all(m_out_fd, out.data(), out.size())) m_error = errno ? errno : EIO;
    }
}

void VcdStream::finish()
{
    if (m_hold_fd >= 0) close(m_hold_fd);
    m_hold_fd = -1;
    if (m_thread.joinable()) m_thread.join();
    if (m_out_fd >= 0 && close(m_out_fd) != 0 && !m_error) m_error = errno;
    m_out_fd = -1;
    int err = m_error;
    stop();
    if (err == EPIPE) raise(SIGPIPE);  // the copy thread blocks it: a closed pipe ends the run here
    if (err) throw UserError(m_shown + ": cannot write: " + std::strerror(err));
}

void VcdStream::stop()
{
    if (m_hold_fd >= 0) close(m_hold_fd);
    m_hold_fd = -1;
    if (m_thread.joinable()) m_thread.join();
    for (int *fd : {&m_read_fd, &m_out_fd})
        if (*fd >= 0) close(*fd);
    m_read_fd = m_out_fd = -1;
    if (!m_dir.empty()) {
        unlink((m_sc_name + ".vcd").c_str());
        rmdir(m_dir.c_str());
        forget_on_signal(m_fifo_slot);
        forget_on_signal(m_dir_slot);
        m_dir.clear();
    }
}

VcdStream::~VcdStream() { stop(); }

}  // namespace torusrt
