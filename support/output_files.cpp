// output_files.cpp - result files go to temporaries that are renamed together once all are
// written over the names their links resolve to; standard output and error and non-regular
// targets are written in place (renaming would replace a device node or a link).
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

#include "option_parsing.h"
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

// 1 or 2 if the file `sp` describes is this process's standard output or error (a pipe, a tty,
// or the file it is redirected to), else 0. A non-tty device (/dev/null) is no stream.
int standard_stream(const struct stat &sp)
{
    for (int fd : {STDOUT_FILENO, STDERR_FILENO}) {
        struct stat so;
        if (fstat(fd, &so) == 0 && sp.st_dev == so.st_dev && sp.st_ino == so.st_ino &&
            !(S_ISCHR(so.st_mode) && !isatty(fd)))
            return fd;
    }
    return 0;
}

const char *stream_name(int fd) { return fd == STDOUT_FILENO ? "standard output" : "standard error"; }

// The name a chain of symbolic links starting at `path` ends at (`path` itself if it is none):
// a relative link is read from the link's folder. Magic links (/proc/self/fd/N) give the name
// the kernel has for the open file.
std::string link_target(const std::string &option, const std::string &path)
{
    std::string cur = path;
    for (int hops = 0; hops < 40; hops++) {  // Linux's own limit
        struct stat ls;
        if (lstat(cur.c_str(), &ls) != 0 || !S_ISLNK(ls.st_mode)) return cur;
        char text[PATH_MAX];
        ssize_t n = readlink(cur.c_str(), text, sizeof text - 1);
        if (n <= 0) return cur;
        std::string next(text, static_cast<size_t>(n));
        cur = next[0] == '/' ? next : folder_of(cur) + "/" + next;
    }
    throw UserError(option + " '" + path + "': too many levels of symbolic links", 2);
}

FILE *open_for_writing(const std::string &path, const std::string &shown)
{
    int fd = open_output_fd(path);
    FILE *f = fd < 0 ? nullptr : fdopen(fd, "wb");
    if (!f) {
        int err = errno;
        if (fd >= 0) close(fd);
        throw UserError(shown + ": cannot write: " + std::strerror(err));
    }
    return f;
}

// Closes `f`; throws naming `shown` if the close (the last flush) fails or `failed` is set.
void close_checked(FILE *f, const std::string &shown, bool failed, int err)
{
    if (std::fclose(f) != 0 && !failed) {
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

// Throws UserError (exit 2) if the new file `target` (what `path` names) or its temporary
// (".NAME.XXXXXX", 8 bytes longer) would be refused by the file system as too long: found
// before the run, not at its end.
void check_name_length(const std::string &option, const std::string &path, const std::string &target,
                       const std::string &dir)
{
    long name_max = pathconf(dir.c_str(), _PC_NAME_MAX);
    if (name_max <= 0) name_max = NAME_MAX;
    size_t base = base_of(target).size();
    std::string what = option + " '" + shown_text(path) + "': ";  // a path of 4 KB shown cut
    if (base > static_cast<size_t>(name_max))
        throw UserError(what + "the file name is too long (" + std::to_string(base) + " bytes; the file system takes " +
                            std::to_string(name_max) + ")",
                        2);
    if (target.size() + 8 >= PATH_MAX)
        throw UserError(what + "the path is too long (" + std::to_string(target.size()) +
                            " bytes; with its temporary " + "it must stay under " + std::to_string(PATH_MAX - 8) + ")",
                        2);
}

// Where a name points: its folder's identity and the last component.
using NameKey = std::tuple<dev_t, ino_t, std::string>;
using FileKey = std::pair<dev_t, ino_t>;

}  // namespace

void divert_stderr()
{
    int fd = open("/dev/tty", O_WRONLY | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) fd = open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (fd >= 0 && fd != STDERR_FILENO) {
        dup2(fd, STDERR_FILENO);
        close(fd);
    }
}

namespace {

// Whether `path`, its links followed one by one, is a stream the process holds open (a name
// under /dev or /proc: /dev/stdout, /dev/fd/1, a link to one) rather than a file in a folder.
bool names_a_stream(const std::string &path)
{
    std::string cur = path;
    for (int hops = 0; hops < 40; hops++) {
        if (cur.rfind("/dev/", 0) == 0 || cur.rfind("/proc/", 0) == 0) return true;
        struct stat ls;
        if (lstat(cur.c_str(), &ls) != 0 || !S_ISLNK(ls.st_mode)) return false;
        char text[PATH_MAX];
        ssize_t n = readlink(cur.c_str(), text, sizeof text - 1);
        if (n <= 0) return false;
        std::string next(text, static_cast<size_t>(n));
        cur = next[0] == '/' ? next : folder_of(cur) + "/" + next;
    }
    return false;
}

// The files a machine file may name: every quoted string in its first megabyte, taken from the
// machine file's folder as a run takes them. Read without parsing, so that a file the run will
// refuse, or one past a simple reader, still names its inputs before the streams are checked.
std::vector<std::string> machine_file_names(const std::string &machine)
{
    std::vector<std::string> names;
    int fd = open(machine.c_str(), O_RDONLY | O_NONBLOCK);
    if (fd < 0) return names;
    struct stat st;
    std::string text;
    if (fstat(fd, &st) == 0 && S_ISREG(st.st_mode)) {
        text.resize(1 << 20);
        ssize_t n = read(fd, &text[0], text.size());
        text.resize(n > 0 ? static_cast<size_t>(n) : 0);
    }
    close(fd);
    const std::string folder = folder_of(machine);
    for (size_t i = 0; i < text.size(); i++) {
        char quote = text[i];
        if (quote != '"' && quote != '\'') continue;
        size_t end = i + 1;
        while (end < text.size() && text[end] != quote && text[end] != '\n') end += text[end] == '\\' ? 2 : 1;
        if (end >= text.size() || text[end] != quote) break;
        std::string name = text.substr(i + 1, end - i - 1);
        if (!name.empty()) names.push_back(name[0] == '/' ? name : folder + "/" + name);
        i = end;
    }
    return names;
}

}  // namespace

void check_streams_before_parsing(int argc, char **argv, const std::vector<std::string> &output_options)
{
    for (int fd : {STDERR_FILENO, STDOUT_FILENO}) {
        struct stat so;
        if (fstat(fd, &so) != 0 || !S_ISREG(so.st_mode)) continue;
        for (int i = 1; i < argc; i++) {
            std::string word = argv[i], option = i > 1 ? argv[i - 1] : "";
            size_t eq = word.find('=');
            if (word.rfind("--", 0) == 0 && eq != std::string::npos) {
                option = word.substr(0, eq);
                word = word.substr(eq + 1);
            } else if (word.size() > 2 && word[0] == '-' && word[1] == 'o') {
                option = "-o";  // -oFILE
                word = word.substr(2);
            }
            bool output = false;
            for (const std::string &o : output_options) output = output || option == o;
            std::vector<std::string> named{word};
            if (option == "--config" && !word.empty())  // the files its machine file names are inputs too
                for (std::string &n : machine_file_names(word)) named.push_back(n);
            for (size_t k = 0; k < named.size(); k++) {
                const std::string &name = named[k];
                struct stat st;
                if (output || name.empty() || stat(name.c_str(), &st) != 0 || st.st_dev != so.st_dev ||
                    st.st_ino != so.st_ino || names_a_stream(name))
                    continue;
                if (fd == STDERR_FILENO) divert_stderr();  // the message must not land in the file
                throw UserError(std::string(stream_name(fd)) + " is redirected to '" + name + "', " +
                                    (k == 0 ? std::string("a file the command line names (an input)")
                                            : "a file the machine file '" + word + "' names (an input)"),
                                2);
            }
        }
    }
}

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
    e.target = path;
    struct stat st;
    if (stat(path.c_str(), &st) == 0) {
        if (S_ISDIR(st.st_mode)) throw UserError(option + " '" + path + "': is a folder", 2);
        e.exists = true;
        e.dev = st.st_dev;
        e.ino = st.st_ino;
        e.stream = standard_stream(st);
        e.special = e.stream != 0 || !S_ISREG(st.st_mode);
        e.sink = e.stream == 0 && S_ISCHR(st.st_mode);
        if (!e.special) {
            e.target = link_target(option, path);
            struct stat tt;  // a name the file no longer has ("(deleted)"): written in place
            if (stat(e.target.c_str(), &tt) != 0 || tt.st_dev != st.st_dev || tt.st_ino != st.st_ino) {
                e.target = path;
                e.special = true;
            } else {  // replaced through a temporary beside it: refused now if that cannot be made
                check_name_length(option, path, e.target, folder_of(e.target));
            }
        }
    } else {
        e.target = link_target(option, path);  // a link to a file not made yet: that file
        std::string dir = folder_of(e.target);
        struct stat ds;
        if (stat(dir.c_str(), &ds) != 0 || !S_ISDIR(ds.st_mode))
            throw UserError(option + " '" + path + "': folder '" + dir + "' does not exist" +
                                (e.target == path ? "" : " (the link names '" + e.target + "')"),
                            2);
        check_name_length(option, path, e.target, dir);
    }
    m_entries.push_back(std::move(e));
    return m_entries.size() - 1;
}

bool OutputSet::writes_stream(int stream) const
{
    for (const Entry &e : m_entries)
        if (e.stream == stream) return true;
    return false;
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
    // The summary and the messages go to standard output and error: neither may be an input.
    // Standard error first: when it is an input, it is diverted before any message is written.
    for (int fd : {STDERR_FILENO, STDOUT_FILENO}) {
        struct stat st;
        if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) continue;
        auto in = inputs.find({st.st_dev, st.st_ino});
        if (in == inputs.end()) continue;
        if (fd == STDERR_FILENO) divert_stderr();  // the message must not land in the input
        throw UserError(std::string(stream_name(fd)) + " is redirected to the " + in->second + ", an input", 2);
    }
    std::map<std::string, FileKey> folders;  // one stat per folder, not per output
    std::map<NameKey, const Entry *> names;
    std::map<FileKey, const Entry *> files;
    for (const auto &e : m_entries) {
        const std::string what = e.option + " '" + e.path + "': ";
        if (e.exists) {
            auto in = inputs.find({e.dev, e.ino});
            if (in != inputs.end()) throw UserError(what + "is the " + in->second + ", an input", 2);
            if (!e.sink) {
                auto other = files.emplace(FileKey{e.dev, e.ino}, &e);
                const Entry *o = other.first->second;
                if (!other.second && (e.stream != 0 || o->stream != 0))
                    throw UserError(what + "is " + stream_name(e.stream ? e.stream : o->stream) + ", also written by " +
                                        o->option + " '" + o->path + "'",
                                    2);
                if (!other.second) throw UserError(what + "is also the file of " + o->option + " '" + o->path + "'", 2);
            }
        }
        if (e.special) continue;
        std::string dir = folder_of(e.target);
        auto f = folders.find(dir);
        if (f == folders.end()) {
            struct stat st;
            if (stat(dir.c_str(), &st) != 0) throw UserError(what + "folder '" + dir + "' does not exist", 2);
            f = folders.emplace(dir, FileKey{st.st_dev, st.st_ino}).first;
        }
        auto other = names.emplace(NameKey{f->second.first, f->second.second, base_of(e.target)}, &e);
        const Entry *o = other.first->second;
        if (!other.second) throw UserError(what + "is also the file of " + o->option + " '" + o->path + "'", 2);
    }
}

std::string OutputSet::staged(Id id)
{
    Entry &e = m_entries[id];
    if (e.special) return e.path;
    if (!e.tmp.empty()) return e.tmp;
    std::string name = temporary_pattern(e.target);
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
        if (std::rename(e.tmp.c_str(), e.target.c_str()) != 0)
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
        std::fclose(f);
        throw UserError(prefix + msg);
    }
    try {
        close_checked(f, shown, false, 0);
    } catch (const UserError &e) {
        throw UserError(prefix + e.what());
    }
}

int open_output_fd(const std::string &write_path)
{
    struct stat st;
    int stream = stat(write_path.c_str(), &st) == 0 ? standard_stream(st) : 0;
    if (stream != 0) {
        std::fflush(stream == STDOUT_FILENO ? stdout : stderr);  // what was printed comes first
        return fcntl(stream, F_DUPFD_CLOEXEC, 0);
    }
    return open(write_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
}

void check_output_folder(const std::string &option, const std::string &path)
{
    std::string dir = folder_of(path);
    struct stat st;
    if (stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
        throw UserError(option + " '" + path + "': folder '" + dir + "' does not exist", 2);
}

}  // namespace torusrt
