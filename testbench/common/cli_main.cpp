// cli_main.cpp - parsing and error reporting shared by the executables.
#include "cli_main.h"

#include <cstdio>
#include <string>

#include "user_error.h"

namespace torusrt {

namespace {

// The first option on the command line given an empty value ("--x ''" or "--x="), which would
// read as one not given and so silently as its default; "" if none. A machine file may hold
// empty values: --dump-config writes an option not set so.
std::string empty_value_option(const CLI::App &app, int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        std::string arg = argv[i];
        if (arg == "--") break;
        if (arg.size() < 2 || arg[0] != '-') continue;
        size_t eq = arg.rfind("--", 0) == 0 ? arg.find('=') : std::string::npos;
        std::string name = arg.substr(0, eq);
        const CLI::Option *o = app.get_option_no_throw(name);
        if (o == nullptr || o->get_type_size_max() == 0) continue;  // not an option, or a flag
        bool empty = eq != std::string::npos ? eq + 1 == arg.size() : i + 1 < argc && argv[i + 1][0] == '\0';
        if (empty) return name;
    }
    return "";
}

}  // namespace

int run_cli(const char *program, CLI::App &app, int argc, char **argv, const std::function<int()> &body,
            const char *extra_exit_statuses)
{
    app.set_version_flag("--version", std::string(program) + " " + TORUSRT_VERSION);
    app.footer(std::string("Exit status:\n  0 success\n  1 bad input file or failed run (a write error included)\n"
                           "  2 bad command line\n") + extra_exit_statuses);
    std::string empty = empty_value_option(app, argc, argv);
    if (!empty.empty()) {
        std::fprintf(stderr, "%s: %s: an empty value\nRun with --help for more information.\n", program, empty.c_str());
        return 2;
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError &e) {
        if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
        std::string what = e.what();
        const CLI::Option *config = app.get_config_ptr();  // name the --config file its errors come from
        if (dynamic_cast<const CLI::ConfigError *>(&e) && config != nullptr && config->count() > 0) {
            const std::string unknown = "INI was not able to parse ";  // CLI11's words for an unknown key
            if (what.rfind(unknown, 0) == 0) what = what.substr(unknown.size()) + ": not a machine option";
            what = config->as<std::string>() + ": " + what;
        }
        std::fprintf(stderr, "%s: %s\nRun with --help for more information.\n", program, what.c_str());
        return 2;
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
