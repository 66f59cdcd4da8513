// output_files.cpp - result files go to temporaries that are renamed together once all are
// written; non-regular targets are written in place (renaming would replace a device node).
#include "output_files.h"

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <map>
#include <sys/stat.h>
#include <tuple>
#include <unistd.h>

#include "rt_png.h"
#include "signal_cleanup.h"
#include "user_error.h"

namespace torusrt {

namespace {

std::string folder_of(const std::string &path)
{
    auto slash = path.rfind('/');
    return slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
}

std::string base_of(const std::string &path)
{
    auto slash = path.rfind('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

// The path names this process's standard output (/dev/stdout, /dev/fd/1, or the file it is
// redirected to): written through stdout, whose position the shell's redirection owns.
bool names_stdout(const struct stat &sp)
{
    struct stat so;
    return fstat(STDOUT_FILENO, &so) == 0 && sp.st_dev == so.st_dev && sp.st_ino == so.st_ino;
}

bool names_stdout(const std::string &path)
{
    struct stat sp;
    return stat(path.c_str(), &sp) == 0 && names_stdout(sp);
}

FILE *open_for_writing(const std::string &path, const std::string &shown)
{
    if (names_stdout(path)) return stdout;
    FILE *f = std::fopen(path.c_str(), "wb");
    if (!f) throw UserError(shown + ": cannot write: " + std::strerror(errno));
    return f;
}

// Closes `f`; throws naming `shown` if the close (the last flush) fails or `failed` is set.
void close_checked(FILE *f, const std::string &shown, bool failed, int err)
{
    if ((f == stdout ? std::fflush(f) : std::fclose(f)) != 0 && !failed) {
        failed = true;
        err = errno;
    }
    if (failed) throw UserError(shown + ": cannot write: " + std::strerror(err ? err : EIO));
}

// The mode a new file gets from open(..., 0666): mkstemp makes 0600.
mode_t new_file_mode()
{
    static const mode_t mode = [] {
        mode_t mask = umask(0);
        umask(mask);
        return 0666 & ~mask;
    }();
    return mode;
}

// ".NAME.XXXXXX" beside PATH, NAME cut so that the temporary's name fits NAME_MAX.
std::string temporary_pattern(const std::string &path)
{
    const std::string suffix = ".XXXXXX";
    std::string base = base_of(path);
    size_t room = NAME_MAX - 1 - suffix.size();
    if (base.size() > room) base.resize(room);
    std::string dir = folder_of(path);
    return (dir == "/" ? "/" : dir + "/") + "." + base + suffix;
}

// Where a name points: its folder's identity and the last component.
using NameKey = std::tuple<dev_t, ino_t, std::string>;
using FileKey = std::pair<dev_t, ino_t>;

}  // namespace

OutputSet::~OutputSet()
{
    for (auto &e : m_entries)
        if (!e.tmp.empty() && !e.special) {
            unlink(e.tmp.c_str());
            forget_on_signal(e.slot);
        }
}

OutputSet::Id OutputSet::add(const std::string &option, const std::string &path)
{
    if (path.empty()) throw UserError(option + ": an empty file name", 2);
    Entry e;
    e.option = option;
    e.path = path;
    struct stat st;
    if (stat(path.c_str(), &st) == 0) {
        if (S_ISDIR(st.st_mode)) throw UserError(option + " '" + path + "': is a folder", 2);
        e.exists = true;
        e.special = !S_ISREG(st.st_mode) || names_stdout(st);
        e.dev = st.st_dev;
        e.ino = st.st_ino;
    } else {
        check_output_folder(option, path);
    }
    m_entries.push_back(std::move(e));
    return m_entries.size() - 1;
}

void OutputSet::add_input(const std::string &option, const std::string &path)
{
    if (!path.empty()) m_inputs.push_back({option, path});
}

void OutputSet::check() const
{
    std::map<FileKey, std::string> inputs;  // what reads each existing input
    for (const auto &in : m_inputs) {
        struct stat st;
        if (stat(in.path.c_str(), &st) == 0 && S_ISREG(st.st_mode))
            inputs.emplace(FileKey{st.st_dev, st.st_ino}, in.option + " file " + in.path);
    }
    std::map<std::string, FileKey> folders;  // one stat per folder, not per output
    std::map<NameKey, const Entry *> names;
    std::map<FileKey, const Entry *> files;
    for (const auto &e : m_entries) {
        if (e.special) continue;
        const std::string what = e.option + " '" + e.path + "': ";
        if (e.exists) {
            auto in = inputs.find({e.dev, e.ino});
            if (in != inputs.end()) throw UserError(what + "is the " + in->second + ", an input", 2);
            auto other = files.emplace(FileKey{e.dev, e.ino}, &e);
            if (!other.second) throw UserError(what + "is also the file of " + other.first->second->option, 2);
        }
        std::string dir = folder_of(e.path);
        auto f = folders.find(dir);
        if (f == folders.end()) {
            struct stat st;
            if (stat(dir.c_str(), &st) != 0) throw UserError(what + "folder '" + dir + "' does not exist", 2);
            f = folders.emplace(dir, FileKey{st.st_dev, st.st_ino}).first;
        }
        auto other = names.emplace(NameKey{f->second.first, f->second.second, base_of(e.path)}, &e);
        if (!other.second) throw UserError(what + "is also the file of " + other.first->second->option, 2);
    }
}

std::string OutputSet::staged(Id id)
{
    Entry &e = m_entries[id];
    if (e.special) return e.path;
    if (!e.tmp.empty()) return e.tmp;
    std::string name = temporary_pattern(e.path);
    int fd;
    {
        // A stopping signal between making the file and registering it would leave it behind.
        SignalsBlocked blocked;
        fd = mkstemp(name.data());
        if (fd >= 0) e.slot = remove_on_signal(name);
    }
    if (fd < 0) throw UserError(e.path + ": cannot write: " + std::strerror(errno));
    e.tmp = name;
    bool ok = fchmod(fd, new_file_mode()) == 0;
    int err = errno;
    close(fd);
    if (!ok) throw UserError(e.path + ": cannot write: " + std::strerror(err));
    return e.tmp;
}

void OutputSet::commit() { commit(""); }

void OutputSet::commit(const std::string &option)
{
    for (auto &e : m_entries) {
        if (e.tmp.empty() || e.special || (!option.empty() && e.option != option)) continue;
        SignalsBlocked blocked;  // renamed and forgotten together
        if (std::rename(e.tmp.c_str(), e.path.c_str()) != 0)
            throw UserError(e.path + ": cannot write: " + std::strerror(errno));
        forget_on_signal(e.slot);
        e.tmp.clear();
    }
}

void write_text_file(const std::string &write_path, const std::string &shown, const std::string &text)
{
    FILE *f = open_for_writing(write_path, shown);
    bool failed = std::fwrite(text.data(), 1, text.size(), f) != text.size() || std::fflush(f) != 0;
    close_checked(f, shown, failed, errno);
}

void write_png_file(const std::string &write_path, const std::string &shown, unsigned width, unsigned height,
                    const std::vector<uint8_t> &rgb8)
{
    write_stream_file(write_path, shown, "", [&](FILE *f, char *msg, size_t msg_len) {
        return rt_png_write_stream(f, shown.c_str(), width, height, rgb8.data(), msg, msg_len);
    });
}

void write_stream_file(const std::string &write_path, const std::string &shown, const std::string &option,
                       const StreamWriter &write)
{
    FILE *f = open_for_writing(write_path, shown);
    char msg[RT_MSG_LEN] = "";
    const std::string prefix = option.empty() ? "" : option + ": ";
    if (write(f, msg, sizeof msg) != RT_OK) {
        if (f != stdout) std::fclose(f);
        throw UserError(prefix + msg);
    }
    try {
        close_checked(f, shown, false, 0);
    } catch (const UserError &e) {
        throw UserError(prefix + e.what());
    }
}

void check_output_folder(const std::string &option, const std::string &path)
{
    std::string dir = folder_of(path);
    struct stat st;
    if (stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
        throw UserError(option + " '" + path + "': folder '" + dir + "' does not exist", 2);
}

}  // namespace torusrt
