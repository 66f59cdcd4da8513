"""The pages `report reproduction` and `report error-vs-runtime` write, and their pictures, keep
the output rules: a picture that is a symbolic link is written through (the link stays), an
earlier sweep's picture of a figure this one did not draw is removed but a link is left alone, a
page reached through a link gets its img/ folder beside the file the link names, a run that fails
or is refused leaves no folder it made, and a table without the studies' columns is named before
any plot is drawn; `report plots` refuses a picture that is one of the CSVs it plots, and `report sweep-collect` a
sweep.csv or sweep.png that is one of the sweep's points or its plan."""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
REPORT = os.path.join(REPO, "experiments", "report")
FIXTURE = os.path.join(REPO, "tests", "reports", "fixtures", "sweep")


def report(*args):
    return subprocess.run([sys.executable, REPORT] + list(args), stdin=subprocess.DEVNULL,
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def write(path, text):
    with open(path, "w") as f:
        f.write(text)


def read(path):
    with open(path) as f:
        return f.read()


class ReportPages(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name
        self.res = os.path.join(self.dir, "sweep")
        shutil.copytree(FIXTURE, self.res)
        os.makedirs(os.path.join(self.res, "plots"))
        write(os.path.join(self.res, "plots", "fig7.png"), "fig7 of this sweep")

    def tearDown(self):
        self.tmp.cleanup()

    def path(self, *parts):
        return os.path.join(self.dir, *parts)

    def test_pictures_that_are_links_are_written_through_and_kept(self):
        os.makedirs(self.path("page", "img"))
        write(self.path("mine7.png"), "old")
        write(self.path("mine6.png"), "keep")
        os.symlink(self.path("mine7.png"), self.path("page", "img", "reproduction-fig7.png"))
        os.symlink(self.path("mine6.png"), self.path("page", "img", "reproduction-fig6.png"))
        write(self.path("page", "img", "reproduction-fig5.png"), "an earlier sweep's")
        done = report("reproduction", self.res, "--doc", self.path("page", "x.md"))
        self.assertEqual(done.returncode, 0, done.stderr)
        self.assertTrue(os.path.islink(self.path("page", "img", "reproduction-fig7.png")))
        self.assertEqual(read(self.path("mine7.png")), "fig7 of this sweep")
        self.assertTrue(os.path.islink(self.path("page", "img", "reproduction-fig6.png")))
        self.assertEqual(read(self.path("mine6.png")), "keep")
        self.assertFalse(os.path.exists(self.path("page", "img", "reproduction-fig5.png")))

    def test_a_page_through_a_link_has_its_pictures_beside_the_file_it_names(self):
        os.makedirs(self.path("a"))
        os.makedirs(self.path("b"))
        os.symlink(self.path("b", "real.md"), self.path("a", "x.md"))
        done = report("reproduction", self.res, "--doc", self.path("a", "x.md"))
        self.assertEqual(done.returncode, 0, done.stderr)
        self.assertEqual(read(self.path("b", "img", "reproduction-fig7.png")), "fig7 of this sweep")
        self.assertIn("](img/reproduction-fig7.png)", read(self.path("b", "real.md")))
        self.assertEqual(os.listdir(self.path("a")), ["x.md"])

    def test_a_failed_reproduction_leaves_no_folder(self):
        os.makedirs(self.path("empty"))
        done = report("reproduction", self.path("empty"), "--doc", self.path("new", "x.md"))
        self.assertEqual(done.returncode, 1, done.stderr)
        self.assertIn("has none of the profile folders", done.stderr)
        self.assertFalse(os.path.exists(self.path("new")))

    def test_plots_refuse_a_picture_that_is_an_input(self):
        link = os.path.join(self.res, "plots", "fig7.png")
        os.remove(link)
        os.symlink(os.path.join("..", "calibrated", "fig7.csv"), link)
        before = read(os.path.join(self.res, "calibrated", "fig7.csv"))
        done = report("plots", self.res)
        self.assertEqual(done.returncode, 2, done.stderr)
        self.assertIn("is the results file %s, an input" % os.path.join(self.res, "calibrated", "fig7.csv"),
                      done.stderr)
        self.assertEqual(read(os.path.join(self.res, "calibrated", "fig7.csv")), before)

    def test_sweep_collect_refuses_an_output_that_is_a_points_file(self):
        out = self.path("sw")
        os.makedirs(os.path.join(out, "points"))
        write(os.path.join(out, "points.tsv"), "name\tqueue\nqueue_0\t0\n")
        point = os.path.join(out, "points", "queue_0.json")
        write(point, '{"status": "ok", "sim_time_s": 1.5, "config": {}}')
        for name, target in (("sweep.csv", point), ("sweep.png", os.path.join(out, "points.tsv"))):
            with self.subTest(name=name):
                os.symlink(target, os.path.join(out, name))
                before = read(target)
                done = report("sweep-collect", "--out", out)
                self.assertEqual(done.returncode, 2, done.stderr)
                self.assertIn("an input", done.stderr)
                self.assertEqual(read(target), before)
                os.remove(os.path.join(out, name))

    def test_error_vs_runtime_names_a_missing_column_before_any_plot(self):
        os.makedirs(self.path("ev"))
        for name in ("q.csv", "p.csv"):
            write(self.path("ev", name), "a,b\n1,2\n")
        args = ["error-vs-runtime", "--quantum", self.path("ev", "q.csv"), "--pruning", self.path("ev", "p.csv"),
                "--doc", self.path("ev", "out", "x.md")]
        done = report(*args, "--img-dir", self.path("ev", "img"))
        self.assertEqual(done.returncode, 1, done.stderr)
        self.assertIn("no column", done.stderr)
        self.assertNotIn("Traceback", done.stderr)
        self.assertEqual(sorted(os.listdir(self.path("ev"))), ["p.csv", "q.csv"])
        done = report(*args, "--img-dir", self.path("ev", "q.csv"))
        self.assertEqual(done.returncode, 2, done.stderr)
        self.assertIn("--img-dir: the folder '%s' it writes into is a file, not a folder" % self.path("ev", "q.csv"),
                      done.stderr)
        self.assertEqual(sorted(os.listdir(self.path("ev"))), ["p.csv", "q.csv"])


if __name__ == "__main__":
    unittest.main()
