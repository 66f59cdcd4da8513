"""The fidelity study's small commands refuse what they cannot use, with one message: `report
fidelity allowed` a per-step cost that is no whole number, `report fidelity timing` a value that
is not a finite time of 0 or more in the strict decimal syntax of every torusrt format (`010` and
`0x10` refused, as on the command line) (or a word without '=', a hand-over the study does not know),
exit 2 and nothing on standard output; `report fidelity identity` a folder without identity runs
(missing, or empty), exit 1."""
import os
import subprocess
import sys
import tempfile
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
REPORT = os.path.join(REPO, "experiments", "report")


def fidelity(*args):
    return subprocess.run([sys.executable, REPORT, "fidelity"] + list(args), stdin=subprocess.DEVNULL,
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


class FidelityCommands(unittest.TestCase):
    def test_allowed_names_a_cost_that_is_no_whole_number(self):
        for text, why in (("1e999", "is too large"), ("0580", "has a leading zero"), ("580.0", "is not a whole number"),
                          ("7", "is not one of")):
            with self.subTest(text=text):
                done = fidelity("allowed", text)
                self.assertEqual((done.returncode, done.stdout), (1, ""), done.stderr)
                self.assertIn("cell_step_packet '%s' %s" % (text, why), done.stderr)
                self.assertIn("(0, 580, 1600, 2180)", done.stderr)
                self.assertNotIn("invalid literal", done.stderr)
        done = fidelity("allowed", "580")
        self.assertEqual((done.returncode, done.stdout), (0, "0 1600\n"), done.stderr)

    def test_timing_refuses_a_value_that_is_not_a_time(self):
        for word in ("link=x", "link=1e999", "link=-1", "link=nan", "link", "handover=7", "link=010", "link=0x10",
                     "link=1_000", "link= 5"):
            with self.subTest(word=word):
                done = fidelity("timing", word)
                self.assertEqual((done.returncode, done.stdout), (2, ""), done.stderr)
                self.assertIn("fidelity timing: %s: " % word, done.stderr)
        for words in (("nosuch=5",), ("link=1e7",), ("link=5", "link=6")):  # nothing printed before the refusal
            with self.subTest(words=words):
                done = fidelity("timing", *words)
                self.assertEqual((done.returncode, done.stdout), (2, ""), done.stderr)
                self.assertIn("fidelity timing: ", done.stderr)
        done = fidelity("timing", "link=5", "handover=580")
        self.assertEqual(done.returncode, 0, done.stderr)
        self.assertIn("\nlink 5\n", done.stdout)

    def test_machines_refuses_values_no_run_reads(self):
        good = {"rule": "sequential", "bus": "0.5", "memory": "1", "shape": "4x4", "handover": "580",
                "cell-step": "580", "header": "4", "entry": "4", "record": "36"}
        bad = (("bus", ".5", "is not a number"), ("memory", "inf", "is not a number"), ("bus", "1e7", "from 0 to"),
               ("memory", "-1", "from 0 to"), ("cell-step", "0580", "has a leading zero"), ("shape", "planar", "shape"),
               ("shape", "4x0", "shape"), ("handover", "5", "is not one of"), ("rule", "seq", "is not one of"),
               ("header", "010", "has a leading zero"), ("header", "zz", "is not a number"),
               ("entry", "0", "from 1 to 4096"), ("record", "4.5", "is not a whole number"))
        with tempfile.TemporaryDirectory() as tmp:
            sim = os.path.join(tmp, "torusrt-sim")  # a dump with the tables of the keys written
            with open(sim, "w") as f:
                f.write("#!/bin/sh\ncat <<'EOF'\n[network]\nips=\"1\"\nroute-ties=\"split\"\npreprocess-count=\"sequential\"\n"
                        "[mapping]\nmap=\"block\"\n[timing]\ntiming-profile=\"paper\"\ntiming=\"\"\n[cluster]\n"
                        "cluster=\"1\"\ndata=\"replicated\"\ncell-header-bytes=\"4\"\nlist-entry-bytes=\"4\"\n"
                        "object-record-bytes=\"0\"\nEOF\n")
            os.chmod(sim, 0o755)
            for opt, text, why in bad:
                with self.subTest(opt=opt, text=text):
                    values = dict(good, **{opt: text})
                    out = os.path.join(tmp, "out")
                    words = [w for k, v in values.items() for w in ("--" + k, v)]
                    done = fidelity("machines", tmp, out, "--sim", sim, *words)
                    self.assertEqual((done.returncode, done.stdout), (2, ""), done.stderr)
                    self.assertIn("argument --%s: '%s' " % (opt, text), done.stderr)
                    self.assertIn(why, done.stderr)
                    self.assertFalse(os.path.exists(out))
            words = [w for k, v in good.items() for w in ("--" + k, v)]
            done = fidelity("machines", tmp, os.path.join(tmp, "out"), "--sim", sim, *words)
            self.assertEqual(done.returncode, 0, done.stderr)
            with open(os.path.join(tmp, "out", "paper-16.toml")) as f:
                self.assertIn('ips="4x4"', f.read().replace(" ", ""))

    def test_a_folder_without_the_stage_runs_is_named(self):
        with tempfile.TemporaryDirectory() as empty:
            for args, why in ((("fit1", empty), "%s/units.tsv: no runs (the stage has not run)" % empty),
                              (("page", empty, os.path.join(empty, "p.md")), "%s/units.tsv: no runs" % empty),
                              (("fit1", os.devnull), "%s: not a results folder" % os.devnull)):
                with self.subTest(args=args):
                    done = fidelity(*args)
                    self.assertEqual((done.returncode, done.stdout), (1, ""), done.stderr)
                    self.assertIn(why, done.stderr)
                    self.assertFalse(os.path.exists(os.path.join(empty, "p.md")))
            done = fidelity("fit2", empty, "--table", os.path.join(empty, "x.tsv"))
            self.assertEqual(done.returncode, 2, done.stderr)
            self.assertIn("argument --table: '%s/x.tsv': the name of a table" % empty, done.stderr)

    def test_identity_without_runs_fails(self):
        with tempfile.TemporaryDirectory() as empty:
            for folder, why in ((empty, "run stage 1 first"), (os.path.join(empty, "none"), "no such results folder")):
                with self.subTest(folder=folder):
                    done = fidelity("identity", folder)
                    self.assertEqual(done.returncode, 1)
                    self.assertIn("identity.tsv: no identity runs to check (%s)" % why, done.stderr)


if __name__ == "__main__":
    unittest.main()
