// model_test.h - GoogleTest for the SystemC model tests (tests/model/*.cpp, one executable each).
//
// A process elaborates SystemC modules only before its first sc_start, and only once, so each
// test file follows one pattern:
//   - one function elaborates the scenario (modules, bindings), runs sc_start and returns what
//     the TESTs check (times, counts) in a plain struct; a function-local static holds it,
//         static Outcome simulate();
//         static const Outcome &run() { static const Outcome r = simulate(); return r; }
//     so the scenario is simulated once per process, on the first TEST that calls run(), and
//     never by `--gtest_list_tests`;
//   - each TEST(Module, WhatItChecks) calls run() and EXPECTs on the recorded times and counts,
//     with the expected values worked out by hand in comments; every TEST can run alone
//     (CTest runs each in its own process with --gtest_filter);
//   - no assertion inside a SystemC process: record there, check in a TEST.
// sc_main (tests/model/main/gtest_sc_main.cpp, linked into every model test) runs the TESTs;
// tests/CMakeLists.txt registers each TEST as CTest `model.SUITE.NAME`, label `model`.
#pragma once

#include <gtest/gtest.h>
#include <systemc>

namespace model_test {

inline sc_core::sc_time us(double v) { return sc_core::sc_time(v, sc_core::SC_US); }
inline sc_core::sc_time ns(double v) { return sc_core::sc_time(v, sc_core::SC_NS); }

}  // namespace model_test
