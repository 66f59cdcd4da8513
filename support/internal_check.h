// internal_check.h - invariants of the model itself, not of the user's input. When one fails the
// program has a bug: the message says so and names the check's file and line (as pbrt's CHECK
// does), where a UserError would blame the input. The run then fails (exit 1) and writes nothing.
#pragma once

#include <stdexcept>
#include <string>

namespace torusrt {

class InternalError : public std::logic_error {
  public:
    InternalError(const char *file, int line, const char *condition, const std::string &detail)
        : std::logic_error(std::string("internal error (a bug, not a problem with the input) at ") + file + ":" +
                           std::to_string(line) + ": " + condition + " does not hold: " + detail)
    {
    }
};

}  // namespace torusrt

// TORUSRT_CHECK(condition, detail): throws InternalError when the condition is false; the detail
// (a std::string expression) is built only then.
#define TORUSRT_CHECK(condition, detail)                                                                               \
    do {                                                                                                               \
        if (!(condition)) throw ::torusrt::InternalError(__FILE__, __LINE__, #condition, (detail));                    \
    } while (0)
