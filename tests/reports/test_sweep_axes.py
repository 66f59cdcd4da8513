"""The generic sweep's plot (experiments/report/sweep.py with experiments/plots/sweep.gp): the y
axis starts at 0 when no plotted value is negative, and follows the data when one is; the
unbounded --queue 0 is drawn apart, right of the other values and not on their line; an axis
whose values span more than 10x is logarithmic; the labels carry units and the title the scene
and the fixed options. Axis ranges are checked on what the real gnuplot drew."""
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


def drawn_ranges(variables):
    """Runs sweep.gp with the variables the report chose, then prints the y and x axes gnuplot
    drew: (y min, y max, x min, x max)."""
    out = os.path.join(variables["dat"], "range.txt")
    assigns = ["%s=%s" % (k, v if isinstance(v, (int, float)) else "'%s'" % v) for k, v in variables.items()]
    script = "; ".join(assigns + ["load '%s'" % os.path.join(plots.PLOT_DIR, "sweep.gp"), "set print '%s'" % out,
                                  "print GPVAL_Y_MIN, GPVAL_Y_MAX, GPVAL_X_MIN, GPVAL_X_MAX"])
    subprocess.run(["gnuplot", "-e", script], check=True)
    with open(out) as f:
        return tuple(float(v) for v in f.read().split())


def drawn_y_range(variables):
    return drawn_ranges(variables)[:2]


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
            sweep.plot(self.out, names, points, flat, "sim_time_s", {})
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



@unittest.skipUnless(shutil.which("gnuplot"), "gnuplot is not installed")
class SweepXAxis(unittest.TestCase):
    def setUp(self):
        self.out = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, self.out)

    def draw(self, name, xs, facts=None):
        points = [["p%d" % i, x, "cyclic"] for i, x in enumerate(xs)]
        flat = [{"sim_time_s": 2.0 + i} for i in range(len(xs))]
        seen = {}
        with mock.patch.object(sweep, "gnuplot", lambda script, variables: seen.update(variables)):
            sweep.plot(self.out, [name, "map"], points, flat, "sim_time_s", facts or {})
        return seen, drawn_ranges(seen)

    def test_unbounded_queue_drawn_apart_on_a_log_axis(self):
        seen, (_, _, xlo, xhi) = self.draw("queue", ["0", "50", "500", "5000"])
        self.assertEqual(seen["logx"], 1, "50 to 5000 spans 100x: a log axis")
        self.assertGreater(xlo, 0, "nothing is drawn at x = 0")
        with open(os.path.join(seen["dat"], "series-1.dat")) as f:
            line_xs = [row.split()[1] for row in f]
        self.assertEqual(line_xs, ["50", "500", "5000"], "the line joins the bounded values only")
        with open(os.path.join(seen["dat"], "apart.dat")) as f:
            (series, x, y), = [row.split() for row in f]
        self.assertEqual((series, y), ("1", "2.0"), "the unbounded point, drawn alone")
        self.assertGreater(float(x), 5000)
        self.assertGreaterEqual(xhi, float(x))
        self.assertIn('"unbounded"', seen["xtics"])

    def test_values_outside_the_strict_syntax_are_named_ticks(self):
        # float() takes these; torusrt-sim does not, and gnuplot must not get them as numbers.
        for odd in ("1_0", "inf", "nan", "\u0661"):
            with self.subTest(value=odd):
                seen, _ = self.draw("queue", ["1", odd])  # gnuplot draws it (check=True)
                self.assertEqual((seen["numeric"], seen["logx"], seen["xtics"]), (0, 0, ""))

    def test_a_narrow_span_stays_linear(self):
        seen, _ = self.draw("link-us", ["50", "100", "200"])
        self.assertEqual(seen["logx"], 0)
        self.assertEqual(seen["logy"], 0)

    def test_labels_carry_units_and_the_title_the_run(self):
        seen, _ = self.draw("queue", ["2", "4"], {"scene": "/a/scenes/paper-image1.nff", "fixed": ["--size", "72x72"]})
        self.assertEqual(seen["xlabel"], "--queue (packets per buffer)")
        self.assertEqual(seen["ylabel"], "image time (s, simulated)")
        self.assertIn("paper-image1.nff", seen["title"])
        self.assertIn("--size 72x72", seen["title"])


if __name__ == "__main__":
    unittest.main()
