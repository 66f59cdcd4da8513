// staged_outputs.h - several result files committed together or not at all.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace torusrt {

// Each file is written whole to a temporary name beside its final name; commit() renames them
// all. If commit() is never reached (an exception, a failed frame) the destructor removes every
// temporary, and a rename failing part-way removes the files already renamed.
class StagedOutputs {
  public:
    StagedOutputs() = default;
    StagedOutputs(const StagedOutputs &) = delete;
    StagedOutputs &operator=(const StagedOutputs &) = delete;
    ~StagedOutputs();

    void add_png(const std::string &path, unsigned width, unsigned height,
                 const std::vector<uint8_t> &rgb8);
    void add_text(const std::string &path, const std::string &text);
    // Renames every temporary to its final name. Throws UserError on failure.
    void commit();

  private:
    std::string stage_name(const std::string &path) const;
    std::vector<std::pair<std::string, std::string>> m_files; // (temporary, final)
    bool m_committed = false;
};

}  // namespace torusrt
