"""The generic sweep's plot (experiments/report/sweep.py with experiments/plots/sweep.gp): the y
axis starts at 0 when no plotted value is negative, and follows the data when one is; both
checked on the axis range the real gnuplot drew."""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest
from unittest import mock

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(REPO, "experiments"))

from report import plots, sweep  # noqa: E402


def drawn_y_range(variables):
    """Runs sweep.gp with the variables the report chose, then prints the y axis gnuplot drew."""
    out = os.path.join(variables["dat"], "range.txt")
    assigns = ["%s=%s" % (k, v if isinstance(v, (int, float)) else "'%s'" % v) for k, v in variables.items()]
    script = "; ".join(assigns + ["load '%s'" % os.path.join(plots.PLOT_DIR, "sweep.gp"),
                                  "set print '%s'" % out, "print GPVAL_Y_MIN, GPVAL_Y_MAX"])
    subprocess.run(["gnuplot", "-e", script], check=True)
    with open(out) as f:
        lo, hi = f.read().split()
    return float(lo), float(hi)


@unittest.skipUnless(shutil.which("gnuplot"), "gnuplot is not installed")
class SweepYAxis(unittest.TestCase):
    def setUp(self):
        self.out = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, self.out)

    def draw(self, ys):
        names = ["ips", "map"]
        points = [["p%d" % i, str(i + 1), "cyclic"] for i in range(len(ys))]
        flat = [{"sim_time_s": y} for y in ys]
        seen = {}
        with mock.patch.object(sweep, "gnuplot", lambda script, variables: seen.update(variables)):
            sweep.plot(self.out, names, points, flat, "sim_time_s")
        self.assertTrue(seen, "the sweep did not draw its plot")
        return seen, drawn_y_range(seen)

    def test_positive_values_start_at_zero(self):
        seen, (lo, hi) = self.draw([90.0, 95.0, 100.0])
        self.assertEqual(seen["ymin0"], 1)
        self.assertEqual(lo, 0.0)
        self.assertGreaterEqual(hi, 100.0)

    def test_a_negative_value_is_shown(self):
        seen, (lo, hi) = self.draw([-5.0, 3.0, 8.0])
        self.assertEqual(seen["ymin0"], 0)
        self.assertLessEqual(lo, -5.0)
        self.assertGreaterEqual(hi, 8.0)


if __name__ == "__main__":
    unittest.main()
