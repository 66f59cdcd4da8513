"""The include checker (scripts/check_includes.py) on made-up trees: each allowed arrow passes,
each backward arrow, CLI11 outside the executables and a kernel-internal call are found."""
import os
import shutil
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import check_includes as ci  # noqa: E402


class IncludeRule(unittest.TestCase):
    def setUp(self):
        self.root = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, self.root)
        # One header per layer.
        self.write("include/rt_k.h", "")
        self.write("support/s.h", '#include "rt_k.h"\n')
        self.write("model/m.h", '#include "s.h"\n#include "rt_k.h"\n')
        self.write("model/run/r.h", '#include "m.h"\n#include "s.h"\n')
        self.write("testbench/common/t.h", '#include "r.h"\n#include <CLI/CLI.hpp>\n')
        self.write("testbench/main.cpp", '#include "t.h"\n#include "r.h"\n#include "m.h"\n')

    def write(self, rel, text):
        path = os.path.join(self.root, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(text)

    def test_the_allowed_arrows_pass(self):
        self.assertEqual(ci.offences(self.root), [])

    def test_model_including_the_run_code_is_found(self):
        self.write("model/bad.cpp", '#include "m.h"\n#include "r.h"\n')
        found = ci.offences(self.root)
        self.assertEqual(len(found), 1, found)
        self.assertTrue(found[0].startswith("model/bad.cpp:2: model includes \"r.h\" from model/run"), found)

    def test_a_sub_folder_of_the_run_code_is_the_run_layer(self):
        # model/run/report/ may include the run code beside it and the model, never the testbench;
        # the hardware may not include it.
        self.write("model/run/report/rep.h", '#include "r.h"\n#include "m.h"\n')
        self.assertEqual(ci.offences(self.root), [])
        self.write("model/run/report/bad.cpp", '#include "rep.h"\n#include "t.h"\n')
        self.write("model/bad2.cpp", '#include "rep.h"\n')
        found = sorted(f.split(":")[0] for f in ci.offences(self.root))
        self.assertEqual(found, ["model/bad2.cpp", "model/run/report/bad.cpp"], found)

    def test_model_including_the_testbench_is_found(self):
        self.write("model/bad.h", '#include "t.h"\n')
        self.assertEqual(len(ci.offences(self.root)), 1)

    def test_support_including_the_model_is_found(self):
        self.write("support/bad.cpp", '#include "s.h"\n#include "m.h"\n')
        found = ci.offences(self.root)
        self.assertEqual([f.split(":")[1] for f in found], ["2"], found)

    def test_the_kernel_including_support_is_found(self):
        self.write("src/bad.c", '#include "s.h"\n')
        self.assertEqual(len(ci.offences(self.root)), 1)

    def test_cli11_outside_the_testbench_is_found(self):
        self.write("model/run/opts.cpp", "#include <CLI/CLI.hpp>\n")
        found = ci.offences(self.root)
        self.assertEqual(len(found), 1)
        self.assertIn("CLI11", found[0])

    def test_a_kernel_internal_call_is_found(self):
        self.write("model/run/run.cpp", "void f() { sc_core::sc_get_curr_simcontext()->elaborate(); }\n")
        self.write("model/run/doc.cpp", "// prepare_to_simulate is not called here\n")
        found = ci.offences(self.root)
        self.assertEqual(len(found), 1, found)
        self.assertIn("run.cpp:1", found[0])

    def test_a_relative_path_out_of_the_folder_is_found(self):
        self.write("model/rel.cpp", '#include "../support/s.h"\n')
        self.assertEqual(len(ci.offences(self.root)), 1)

    def test_main_exits_1_on_an_offence(self):
        self.write("support/bad.h", '#include "t.h"\n')
        with open(os.devnull, "w") as null:
            out, sys.stdout = sys.stdout, null
            try:
                self.assertEqual(ci.main(["check_includes.py", self.root]), 1)
            finally:
                sys.stdout = out


if __name__ == "__main__":
    unittest.main()
