// output_files.cpp - result files are written to a temporary name and renamed, so a
// failed run never leaves a partial file behind.
#include "output_files.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <sys/stat.h>
#include <unistd.h>

#include "rt_png.h"
#include "user_error.h"

namespace torusrt {

void write_text_file(const std::string &path, const std::string &text)
{
    std::string tmp = path + ".tmp." + std::to_string(getpid());
    FILE *f = std::fopen(tmp.c_str(), "wb");
    if (!f) throw UserError(path + ": cannot write: " + std::strerror(errno));
    bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    ok = (std::fclose(f) == 0) && ok;
    if (!ok || std::rename(tmp.c_str(), path.c_str()) != 0) {
        std::remove(tmp.c_str());
        throw UserError(path + ": cannot write: " + std::strerror(errno));
    }
}

void write_png_file(const std::string &path, unsigned width, unsigned height,
                    const std::vector<uint8_t> &rgb8)
{
    char msg[RT_MSG_LEN] = "";
    if (rt_png_write(path.c_str(), width, height, rgb8.data(), msg, sizeof msg) != RT_OK)
        throw UserError(msg);
}

void remove_file(const std::string &path) { std::remove(path.c_str()); }

void check_output_folder(const std::string &option, const std::string &path)
{
    auto slash = path.rfind('/');
    std::string dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
    struct stat st;
    if (stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
        throw UserError(option + " '" + path + "': folder '" + dir + "' does not exist", 2);
}

}  // namespace torusrt
