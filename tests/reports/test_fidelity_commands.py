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

    def test_identity_without_runs_fails(self):
        with tempfile.TemporaryDirectory() as empty:
            for folder, why in ((empty, "run stage 1 first"), (os.path.join(empty, "none"), "no such results folder")):
                with self.subTest(folder=folder):
                    done = fidelity("identity", folder)
                    self.assertEqual(done.returncode, 1)
                    self.assertIn("identity.tsv: no identity runs to check (%s)" % why, done.stderr)


if __name__ == "__main__":
    unittest.main()
