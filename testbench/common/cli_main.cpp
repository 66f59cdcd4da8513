// cli_main.cpp - parsing and error reporting shared by the executables.
#include "cli_main.h"

#include <cstdio>

#include "user_error.h"

namespace torusrt {

int run_cli(const char *program, CLI::App &app, int argc, char **argv, const std::function<int()> &body)
{
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError &e) {
        int code = app.exit(e);
        return code == 0 ? 0 : 2;
    }
    try {
        return body();
    } catch (const UserError &e) {
        std::fprintf(stderr, "%s: %s\n", program, e.what());
        return e.exit_code();
    } catch (const std::exception &e) {
        std::fprintf(stderr, "%s: %s\n", program, e.what());
        return 1;
    }
}

}  // namespace torusrt
