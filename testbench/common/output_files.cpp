// output_files.cpp - result files go to temporaries that are renamed together once all are
// written; non-regular targets are written in place (renaming would replace a device node).
#include "output_files.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <sys/stat.h>
#include <unistd.h>

#include "rt_png.h"
#include "user_error.h"

namespace torusrt {

namespace {

std::string folder_of(const std::string &path)
{
    auto slash = path.rfind('/');
    return slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
}

// The same file when both exist (hard links too), else the same name in the same folder.
bool same_file(const std::string &a, const std::string &b)
{
    struct stat sa, sb;
    if (stat(a.c_str(), &sa) == 0 && stat(b.c_str(), &sb) == 0)
        return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
    auto base = [](const std::string &p) { return p.substr(p.rfind('/') == std::string::npos ? 0 : p.rfind('/') + 1); };
    struct stat da, db;
    return base(a) == base(b) && stat(folder_of(a).c_str(), &da) == 0 && stat(folder_of(b).c_str(), &db) == 0 &&
           da.st_dev == db.st_dev && da.st_ino == db.st_ino;
}

// The path names this process's standard output (/dev/stdout, /dev/fd/1, or the file it is
// redirected to): written through stdout, whose position the shell's redirection owns.
bool names_stdout(const std::string &path)
{
    struct stat sp, so;
    return stat(path.c_str(), &sp) == 0 && fstat(STDOUT_FILENO, &so) == 0 && sp.st_dev == so.st_dev &&
           sp.st_ino == so.st_ino;
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

}  // namespace

bool is_special_file(const std::string &path)
{
    struct stat st;
    return stat(path.c_str(), &st) == 0 && (!S_ISREG(st.st_mode) || names_stdout(path));
}

OutputSet::~OutputSet()
{
    for (const auto &e : m_entries)
        if (!e.tmp.empty()) std::remove(e.tmp.c_str());
}

std::string OutputSet::add(const std::string &option, const std::string &path, const std::string &input)
{
    check_output_folder(option, path);
    struct stat st;
    if (stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
        throw UserError(option + " '" + path + "': is a folder", 2);
    bool special = is_special_file(path);
    if (!special && !input.empty() && same_file(path, input))
        throw UserError(option + " '" + path + "': is the input file " + input, 2);
    for (const auto &e : m_entries)
        if (!special && same_file(e.path, path))
            throw UserError(option + " '" + path + "': is also the file of " + e.option, 2);
    Entry e{option, path, special ? "" : path + ".tmp." + std::to_string(getpid())};
    m_entries.push_back(e);
    return special ? path : e.tmp;
}

void OutputSet::check_not_input(const std::string &option, const std::string &input) const
{
    if (input.empty() || is_special_file(input)) return;
    for (const auto &e : m_entries)
        if (!e.tmp.empty() && same_file(e.path, input))
            throw UserError(e.option + " '" + e.path + "': is the " + option + " file " + input, 2);
}

void OutputSet::commit() { commit(""); }

void OutputSet::commit(const std::string &option)
{
    for (auto &e : m_entries) {
        if (e.tmp.empty() || (!option.empty() && e.option != option)) continue;
        if (std::rename(e.tmp.c_str(), e.path.c_str()) != 0)
            throw UserError(e.path + ": cannot write: " + std::strerror(errno));
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
    FILE *f = open_for_writing(write_path, shown);
    char msg[RT_MSG_LEN] = "";
    if (rt_png_write_stream(f, shown.c_str(), width, height, rgb8.data(), msg, sizeof msg) != RT_OK) {
        if (f != stdout) std::fclose(f);
        throw UserError(msg);
    }
    close_checked(f, shown, false, 0);
}

void check_output_folder(const std::string &option, const std::string &path)
{
    std::string dir = folder_of(path);
    struct stat st;
    if (stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
        throw UserError(option + " '" + path + "': folder '" + dir + "' does not exist", 2);
}

}  // namespace torusrt
