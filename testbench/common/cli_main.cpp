// cli_main.cpp - parsing and error reporting shared by the executables.
#include "cli_main.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <new>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "machine_file_reader.h"
#include "memory_reserve.h"
#include "option_parsing.h"
#include "option_registration.h"
#include "option_spec.h"
#include "output_files.h"
#include "run_stage.h"
#include "signal_cleanup.h"
#include "startup_memory.h"
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

// The first option on the command line followed by another option where its value should be
// ("--ips --map cost"), which CLI11 would report as "cost" not expected; "" if none. Its value
// is the next word unless given with "=".
std::string missing_value_option(const CLI::App &app, int argc, char **argv)
{
    for (int i = 1; i + 1 < argc; i++) {
        std::string arg = argv[i];
        if (arg == "--") break;
        if (arg.size() < 2 || arg[0] != '-' || arg.find('=') != std::string::npos) continue;
        const CLI::Option *o = app.get_option_no_throw(arg);
        if (o == nullptr || o->get_expected_max() == 0) continue;  // not an option, or a flag
        std::string next = argv[i + 1];
        if (next.size() < 2 || next[0] != '-') continue;
        if (app.get_option_no_throw(next.substr(0, next.find('='))) != nullptr) return arg + " " + next;
    }
    return "";
}

// A message as printed: control bytes escaped as \xNN (the user's bytes in it are quoted with
// shown_text already; this keeps any that were not from reaching the terminal raw); its line
// breaks stay.
std::string printable(const std::string &message)
{
    std::string out;
    for (char ch : message) {
        unsigned char c = static_cast<unsigned char>(ch);
        if ((c < 0x20 && c != '\n') || c == 0x7f) {
            char esc[8];
            std::snprintf(esc, sizeof esc, "\\x%02x", c);
            out += esc;
        } else {
            out += ch;
        }
    }
    return out;
}

// CLI11's words for an option it does not know, with the nearest name as a hint.
std::string with_suggestion(const CLI::App &app, const CLI::ParseError &e, const std::string &what)
{
    if (dynamic_cast<const CLI::ExtrasError *>(&e) == nullptr) return what;
    std::string hints;
    for (const std::string &extra : app.remaining()) {
        std::string name = extra.substr(0, extra.find('='));
        std::string hint = name.rfind("-", 0) == 0 ? option_suggestion(app, name) : "";
        if (!hint.empty()) hints += "\n" + name + ": " + hint;
    }
    return what + hints;
}

// CLI11's count words in the project's: "--output: At Most 1 required but received 2" is an
// option given twice.
std::string reworded(const std::string &what)
{
    const std::string words = ": At Most 1 required but received ";
    size_t at = what.find(words);
    if (at == std::string::npos) return what;
    return what.substr(0, at) + ": given " + what.substr(at + words.size()) + " times; give it once";
}

// The message for an allocation the system refused: what the run was doing, and what bounds the
// memory a run takes. Built without allocating.
void report_out_of_memory(const char *program, const char *what)
{
    const char *stage = run_stage();
    std::fprintf(stderr,
                 "%s: out of memory%s%s: %s (--memory-budget bounds the cell lists, frame buffer and packets; a "
                 "smaller machine, scene or --size needs less)\n",
                 program, stage[0] ? " while " : "", stage, what);
}

// Exit status 1 with a message if what was printed on standard output could not all be written
// (a closed pipe with SIGPIPE ignored, a full disk): the summary is part of the result.
int check_standard_output(const char *program, int status)
{
    errno = 0;
    bool flushed = std::fflush(stdout) == 0;
    if (flushed && !std::ferror(stdout)) return status;
    // A failed flush here has its reason; an earlier one's errno is gone.
    std::string why = !flushed && errno != 0 ? std::strerror(errno) : "some of the summary was lost";
    std::fprintf(stderr, "%s: standard output: cannot write: %s\n", program, why.c_str());
    return status == 0 ? 1 : status;
}

// --help and --version: CLI11's text written here, so that a write that fails keeps the
// system's reason (std::cout's would be lost by the time standard output is checked).
int print_help_or_version(const char *program, CLI::App &app, const CLI::ParseError &e)
{
    std::ostringstream text;
    int status = app.exit(e, text, std::cerr);
    const std::string out = text.str();
    errno = 0;
    bool written = std::fwrite(out.data(), 1, out.size(), stdout) == out.size() && std::fflush(stdout) == 0;
    if (written) return status;
    std::fprintf(stderr, "%s: standard output: cannot write: %s\n", program, std::strerror(errno != 0 ? errno : EIO));
    return 1;
}

// The names of the options of the "Outputs" group (-o, --output, --stats, --vcd, ...): a file
// one names may be the one standard output is redirected to, and is then written through it.
std::vector<std::string> output_option_names(const CLI::App &app)
{
    std::vector<std::string> names;
    for (const CLI::Option *o : app.get_options()) {
        if (o->get_group() != group_title(OptionGroup::outputs)) continue;
        for (const std::string &n : o->get_lnames()) names.push_back("--" + n);
        for (const std::string &n : o->get_snames()) names.push_back("-" + n);
    }
    return names;
}

}  // namespace

int run_cli(const char *program, CLI::App &app, int argc, char **argv, const std::function<int()> &body,
            const char *extra_exit_statuses)
{
    startup_done();
    stop_on_signals(program);
    keep_memory_reserve();
    app.set_version_flag("--version", std::string(program) + " " + TORUSRT_VERSION, "print the version and exit")
        ->group(group_title(OptionGroup::run));
    app.set_help_flag("-h,--help", "print this help and exit")->group(group_title(OptionGroup::run));  // listed last
    app.footer(std::string("Exit status:\n  0 success\n  1 bad input file or failed run (a write error or memory "
                           "running out included)\n  2 bad command line\n") +
               extra_exit_statuses +
               "  128+N stopped by signal N: INT 130, TERM 143, HUP 129, QUIT 131, USR1 138, USR2 140,\n"
               "        ALRM 142, PIPE 141 (no output left behind)\n");
    try {  // before any message: `2>> SCENE` or `--config m.toml >> m.toml` would append it to an input
        check_streams_before_parsing(argc, argv, output_option_names(app));
    } catch (const UserError &e) {
        std::fprintf(stderr, "%s: %s\n", program, printable(e.what()).c_str());
        return e.exit_code();
    }
    std::string empty = empty_value_option(app, argc, argv);
    if (!empty.empty()) {
        std::fprintf(stderr, "%s: %s: an empty value\nRun with --help for more information.\n", program, empty.c_str());
        return 2;
    }
    std::string missing = missing_value_option(app, argc, argv);
    if (!missing.empty()) {
        size_t space = missing.find(' ');
        std::fprintf(stderr,
                     "%s: %s: missing its value (the next word, %s, is an option)\nRun with --help for more "
                     "information.\n",
                     program, missing.substr(0, space).c_str(), printable(missing.substr(space + 1)).c_str());
        return 2;
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError &e) {
        if (e.get_exit_code() == 0) return print_help_or_version(program, app, e);
        std::string what = with_suggestion(app, e, reworded(e.what()));
        const CLI::Option *config = app.get_config_ptr();  // name the --config file its errors come from
        if (dynamic_cast<const CLI::ConfigError *>(&e) && config != nullptr && config->count() > 0) {
            const std::string unknown = "INI was not able to parse ";  // CLI11's words for an unknown key
            if (what.rfind(unknown, 0) == 0) what = what.substr(unknown.size()) + ": not a machine option";
            bool at_line = dynamic_cast<const MachineFileError *>(&e) != nullptr;  // "LINE: ..."
            what = shown_text(config->as<std::string>()) + (at_line ? ":" : ": ") + what;
        }
        std::fprintf(stderr, "%s: %s\nRun with --help for more information.\n", program, printable(what).c_str());
        return 2;
    }
    int status = 1;
    try {
        status = body();
    } catch (const UserError &e) {
        std::fprintf(stderr, "%s: %s\n", program, printable(e.what()).c_str());
        status = e.exit_code();
    } catch (const std::bad_alloc &) {
        report_out_of_memory(program, "the system refused an allocation");
    } catch (const std::system_error &e) {
        // A thread's stack or a mapping the system could not give: memory too.
        bool memory = e.code() == std::errc::not_enough_memory || e.code() == std::errc::resource_unavailable_try_again;
        if (memory) report_out_of_memory(program, e.what());
        else std::fprintf(stderr, "%s: %s\n", program, printable(e.what()).c_str());
    } catch (const std::exception &e) {
        std::fprintf(stderr, "%s: %s\n", program, printable(e.what()).c_str());
    }
    return check_standard_output(program, status);
}

}  // namespace torusrt
