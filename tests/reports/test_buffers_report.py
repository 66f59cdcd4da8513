"""The buffer study's page from runs that did not all finish: a machine whose unbounded run failed
is named as having nothing to compare with (no traceback), and a failed capacity-1 run shows its
status where its time would be."""
import csv
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
RUNS = os.path.join(ROOT, "experiments", "buffers", "results", "runs.tsv")


@unittest.skipUnless(shutil.which("gnuplot"), "gnuplot is not installed")
class FailedRuns(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp()

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def test_failed_unbounded_and_capacity_one(self):
        with open(RUNS, newline="") as f:
            rows = list(csv.DictReader(f, delimiter="\t"))
        first = (rows[0]["scene"], rows[0]["machine"])
        second = None
        for r in rows:
            key = (r["scene"], r["machine"])
            if r["flow"] != "classes":
                continue
            if key == first and r["capacity"] == "0":
                r["status"], r["sim_time_s"] = "failed", ""
            elif key != first and r["capacity"] == "1" and second in (None, key):
                second = key
                r["status"], r["sim_time_s"] = "deadlock", ""
        runs = os.path.join(self.tmp, "runs.tsv")
        with open(runs, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()), delimiter="\t")
            w.writeheader()
            w.writerows(rows)
        doc = os.path.join(self.tmp, "buffers.md")
        done = subprocess.run([sys.executable, os.path.join(ROOT, "experiments", "report", "buffers.py"), runs, doc,
                               os.path.join(self.tmp, "pics"), os.path.join(ROOT, "experiments", "plots", "buffers.gp"),
                               "--size", "8x8", "--wall", "1", "--jobs", "1"], capture_output=True, text=True)
        self.assertEqual(done.returncode, 0, done.stderr)
        self.assertNotIn("Traceback", done.stderr)
        with open(doc) as f:
            page = f.read()
        self.assertIn("have no comparison", page)
        self.assertIn("did not finish (failed): nothing to compare with", page)
        row = next(line for line in page.splitlines() if line.startswith("| %s | %s |" % second))
        self.assertIn("| deadlock |", row)


if __name__ == "__main__":
    unittest.main()
