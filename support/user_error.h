// user_error.h - an error caused by the user's input or options: printed, exit status 1 or 2.
#pragma once

#include <stdexcept>
#include <string>

namespace torusrt {

class UserError : public std::runtime_error {
  public:
    // exit_code 2 = bad command line, 1 = bad input file or failed run.
    explicit UserError(const std::string &message, int exit_code = 1)
        : std::runtime_error(message), m_exit_code(exit_code)
    {
    }
    int exit_code() const { return m_exit_code; }

  private:
    int m_exit_code;
};

}  // namespace torusrt
