// input_file_check.cpp - the CLI11 face of the one input reader.
#include "input_file_check.h"

#include <cstdlib>
#include <string>

#include "rt_file_read.h"

namespace torusrt {

CLI::Validator input_file_check(size_t max_bytes)
{
    return CLI::Validator(
        [max_bytes](std::string &path) -> std::string {
            char *text = nullptr;
            size_t length = 0;
            char msg[RT_MSG_LEN] = "";
            if (rt_read_regular_file(path.c_str(), max_bytes, &text, &length, msg, sizeof msg) != RT_OK) return msg;
            std::free(text);
            return "";
        },
        "");  // no description: the help shows the option's own type name alone ("FILE", not "FILE:FILE")
}

}  // namespace torusrt
