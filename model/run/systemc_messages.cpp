// systemc_messages.cpp - a report handler that prints on stderr instead of stdout.
#include "systemc_messages.h"

#include <cstdio>
#include <cstring>
#include <systemc>

namespace torusrt {

namespace {

bool g_quiet = false;
bool g_stack_failed = false;
bool g_out_of_memory = false;

void to_stderr(const sc_core::sc_report &report, const sc_core::sc_actions &actions)
{
    // A process's stack the system refused (E518) is memory running out: the run's own message
    // says so (systemc_stack_failed), not SystemC's.
    if (report.get_severity() >= sc_core::SC_ERROR && std::strcmp(report.get_msg_type(), "stack setup failed") == 0) {
        g_stack_failed = true;
        sc_core::sc_report_handler::default_handler(report, actions & ~sc_core::SC_DISPLAY);
        return;
    }
    // An allocation refused inside a process (E549 wrapping std::bad_alloc): the run's own
    // out-of-memory message says so, once.
    if (report.get_severity() >= sc_core::SC_ERROR &&
        std::strcmp(report.get_msg_type(), sc_core::SC_ID_SIMULATION_UNCAUGHT_EXCEPTION_) == 0 &&
        std::strstr(report.get_msg(), "bad_alloc") != nullptr) {
        g_out_of_memory = true;
        sc_core::sc_report_handler::default_handler(report, actions & ~sc_core::SC_DISPLAY);
        return;
    }
    if (actions & sc_core::SC_DISPLAY) {
        bool minor = report.get_severity() < sc_core::SC_ERROR;
        if (!(g_quiet && minor)) std::fprintf(stderr, "%s\n", sc_core::sc_report_compose_message(report).c_str());
    }
    // Everything but the display (throwing, stopping, aborting) stays SystemC's own.
    sc_core::sc_report_handler::default_handler(report, actions & ~sc_core::SC_DISPLAY);
}

}  // namespace

bool systemc_stack_failed() { return g_stack_failed; }

bool systemc_out_of_memory() { return g_out_of_memory; }

void route_systemc_messages(bool quiet)
{
    g_quiet = quiet;
    sc_core::sc_report_handler::set_handler(to_stderr);
}

}  // namespace torusrt
