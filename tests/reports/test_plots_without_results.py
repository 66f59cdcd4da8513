"""`report plots` on a sweep whose every point failed draws nothing and says why in one line
(exit 1, no traceback, no gnuplot command line), and leaves no picture of an earlier sweep
beside results it does not show; a gnuplot that fails is named by its script and picture."""
import csv
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
REPORT = os.path.join(REPO, "experiments", "report")
FIXTURE = os.path.join(REPO, "tests", "reports", "fixtures", "sweep")
sys.path.insert(0, os.path.join(REPO, "experiments"))

from report import plots  # noqa: E402


def fail_every_point(folder):
    """Every row of the figure CSVs under FOLDER marked failed, as a sweep whose runs all failed."""
    for root, _, names in os.walk(folder):
        for name in names:
            if name.startswith("fig") and name.endswith(".csv"):
                path = os.path.join(root, name)
                with open(path, newline="") as f:
                    rows = list(csv.DictReader(f))
                    fields = list(rows[0].keys()) if rows else []
                with open(path, "w", newline="") as f:
                    out = csv.DictWriter(f, fields, lineterminator="\n")
                    out.writeheader()
                    for row in rows:
                        out.writerow(dict(row, status="failed"))


class PlotsWithoutResults(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.res = os.path.join(self.tmp.name, "sweep")
        shutil.copytree(FIXTURE, self.res)

    def tearDown(self):
        self.tmp.cleanup()

    def test_a_figure_table_that_is_a_fifo_is_named(self):
        csvs = [os.path.join(root, n) for root, _, names in os.walk(self.res) for n in names if n == "fig7.csv"]
        os.remove(csvs[0])
        os.mkfifo(csvs[0])
        done = subprocess.run([sys.executable, REPORT, "plots", self.res], stdin=subprocess.DEVNULL,
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=60)
        self.assertEqual(done.returncode, 1, done.stderr)
        self.assertIn("figure table '%s': is a FIFO, not a regular file" % csvs[0], done.stderr)

    def test_every_point_failed_draws_nothing_and_says_so(self):
        fail_every_point(self.res)
        old = os.path.join(self.res, "plots", "fig5.png")
        os.makedirs(os.path.dirname(old))
        with open(old, "w") as f:
            f.write("an earlier sweep's picture")
        done = subprocess.run([sys.executable, REPORT, "plots", self.res], stdin=subprocess.DEVNULL,
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        self.assertEqual(done.returncode, 1, done.stderr)
        self.assertIn("no point in %s gave a result" % self.res, done.stderr)
        self.assertNotIn("Traceback", done.stderr)
        self.assertNotIn("gnuplot', '-e'", done.stderr)
        self.assertEqual(sorted(n for n in os.listdir(os.path.join(self.res, "plots")) if n.endswith(".png")), [])

    @unittest.skipUnless(shutil.which("gnuplot"), "gnuplot is not installed")
    def test_a_failing_gnuplot_is_named_by_script_and_picture(self):
        png = os.path.join(self.tmp.name, "f.png")
        with self.assertRaises(ValueError) as caught:
            plots.gnuplot("fig5.gp", {"dat": os.path.join(self.tmp.name, "none"), "scenes": "image1", "main": "x",
                                      "other": "x", "lb_main": "?", "lb_other": "?", "maps": "block", "xmax": 2,
                                      "out": png})
        self.assertIn("gnuplot could not draw f.png with fig5.gp", str(caught.exception))
        self.assertEqual(os.listdir(self.tmp.name), ["sweep"])


if __name__ == "__main__":
    unittest.main()
