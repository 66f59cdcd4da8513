// staged_outputs.cpp - result files staged under temporary names and renamed at the end.
#include "staged_outputs.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <unistd.h>

#include "output_files.h"
#include "user_error.h"

namespace torusrt {

StagedOutputs::~StagedOutputs()
{
    if (m_committed) return;
    for (const auto &f : m_files) remove_file(f.first);
}

std::string StagedOutputs::stage_name(const std::string &path) const
{
    return path + ".stage." + std::to_string(getpid());
}

void StagedOutputs::add_png(const std::string &path, unsigned width, unsigned height,
                            const std::vector<uint8_t> &rgb8)
{
    std::string tmp = stage_name(path);
    write_png_file(tmp, width, height, rgb8);
    m_files.emplace_back(tmp, path);
}

void StagedOutputs::add_text(const std::string &path, const std::string &text)
{
    std::string tmp = stage_name(path);
    write_text_file(tmp, text);
    m_files.emplace_back(tmp, path);
}

void StagedOutputs::commit()
{
    for (size_t i = 0; i < m_files.size(); i++) {
        if (std::rename(m_files[i].first.c_str(), m_files[i].second.c_str()) == 0) continue;
        std::string why = std::strerror(errno);
        for (size_t j = 0; j < i; j++) remove_file(m_files[j].second);
        for (size_t j = i; j < m_files.size(); j++) remove_file(m_files[j].first);
        m_committed = true;
        throw UserError(m_files[i].second + ": cannot write: " + why);
    }
    m_committed = true;
}

}  // namespace torusrt
