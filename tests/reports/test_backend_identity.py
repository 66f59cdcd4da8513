"""A point of the backend (experiments/backend run) is done when its result is there and was
made by the same command line from the same input files (its identity, recorded beside the
result as DONE.id when the point succeeds): a point whose input file changed, whose command
changed, or whose result has no record runs again, and the backend says why; a point of a later
phase that reads the result of one that runs again runs again too; an unchanged point does not."""
import os
import shlex
import shutil
import subprocess
import sys
import tempfile
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BACKEND = os.path.join(REPO, "experiments", "backend")


def write(path, text):
    with open(path, "w") as f:
        f.write(text)


def read(path):
    with open(path) as f:
        return f.read()


@unittest.skipUnless(shutil.which("parallel"), "GNU parallel is not installed")
class PointIdentity(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp()
        d = self.dir
        self.input, self.t1, self.point = (os.path.join(d, n) for n in ("in.timing", "t1.json", "p.json"))
        write(self.input, "test_hit 1750\n")
        # phase 1 copies the input; phase 2 reads phase 1's result and the input
        write(os.path.join(d, "phase1.list"), "%s\tcp %s %s\n" % (self.t1, shlex.quote(self.input),
                                                                  shlex.quote(self.t1)))
        write(os.path.join(d, "phase2.list"), "%s\tcat %s %s > %s\n" % (
            self.point, shlex.quote(self.t1), shlex.quote(self.input), shlex.quote(self.point)))

    def tearDown(self):
        shutil.rmtree(self.dir)

    def backend(self):
        d = self.dir
        done = subprocess.run([sys.executable, BACKEND, "run", "--state", os.path.join(d, "st"), "-j", "1",
                               os.path.join(d, "phase1.list"), os.path.join(d, "phase2.list")],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        self.assertEqual(done.returncode, 0, done.stdout)
        return done.stdout

    def test_a_changed_input_runs_its_points_again_and_says_why(self):
        self.backend()
        self.assertEqual(read(self.point), "test_hit 1750\ntest_hit 1750\n")
        self.assertIn("2 points in 2 phase(s), 2 already done, 0 to run", self.backend())
        write(self.input, "test_hit 3500\n")
        out = self.backend()
        self.assertIn("%s: made by another command or from other inputs (%s changed since it was made); "
                      "running it again" % (self.t1, self.input), out)
        self.assertIn("0 already done, 2 to run", out)
        self.assertEqual(read(self.point), "test_hit 3500\ntest_hit 3500\n")
        self.assertIn("2 already done, 0 to run", self.backend())

    def test_a_point_reading_a_result_that_runs_again_runs_again(self):
        write(os.path.join(self.dir, "phase2.list"), "%s\tcat %s > %s\n" % (
            self.point, shlex.quote(self.t1), shlex.quote(self.point)))  # phase 1's result only
        self.backend()
        write(self.input, "test_hit 3500\n")
        out = self.backend()
        self.assertIn("%s: made by another command or from other inputs (%s changed since it was made)"
                      % (self.point, self.t1), out)
        self.assertIn("0 already done, 2 to run", out)
        self.assertEqual(read(self.point), "test_hit 3500\n")
        self.assertIn("2 already done, 0 to run", self.backend())

    def test_a_result_without_its_record_runs_again(self):
        self.backend()
        os.remove(self.point + ".id")
        out = self.backend()
        self.assertIn("%s: made by another command or from other inputs (no record of what it was made from "
                      "(%s.id))" % (self.point, self.point), out)
        self.assertIn("1 already done, 1 to run", out)

    def test_a_changed_command_runs_again(self):
        self.backend()
        write(os.path.join(self.dir, "phase2.list"), "%s\tcat %s > %s\n" % (
            self.point, shlex.quote(self.input), shlex.quote(self.point)))
        out = self.backend()
        self.assertIn("%s: made by another command or from other inputs (its command line changed)" % self.point, out)
        self.assertEqual(read(self.point), "test_hit 1750\n")


if __name__ == "__main__":
    unittest.main()


@unittest.skipUnless(shutil.which("parallel"), "GNU parallel is not installed")
class ResultsThatAreInputs(unittest.TestCase):
    """A stale result is removed before its point runs again only when the backend made it (its
    record is there): a file without one (a scene the command reads) is left alone; the point list
    as a result is refused (exit 2, naming the list line), and so is a point that reads a file the
    backend writes (a result's identity record, a phase list, a joblog, a log); a machine file's
    named files (timing=) are part of a point's identity."""

    def setUp(self):
        self.dir = tempfile.mkdtemp()

    def tearDown(self):
        shutil.rmtree(self.dir)

    def run_list(self, text):
        lst = os.path.join(self.dir, "points.list")
        write(lst, text)
        return subprocess.run([sys.executable, BACKEND, "run", "--state", os.path.join(self.dir, "st"), "-j", "1",
                               lst], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True), lst

    def test_a_result_without_record_that_its_command_reads_is_kept(self):
        scene = os.path.join(self.dir, "s.nff")
        write(scene, "the scene\n")
        done, _ = self.run_list("%s\tcat %s > %s.copy\n" % (scene, shlex.quote(scene), shlex.quote(scene)))
        self.assertEqual(done.returncode, 0, done.stdout)
        self.assertIn("no record of what it was made from", done.stdout)
        self.assertEqual(read(scene), "the scene\n")

    def test_the_point_list_as_a_result_is_refused_and_kept(self):
        lst = os.path.join(self.dir, "points.list")
        done, _ = self.run_list("%s\ttrue\n" % lst)
        self.assertEqual(done.returncode, 2, done.stdout)
        self.assertIn("is the point list", done.stdout)
        self.assertTrue(os.path.exists(lst))

    def test_a_file_the_backend_writes_as_an_input_is_refused_and_kept(self):
        out = os.path.join(self.dir, "r.json")
        st = os.path.join(self.dir, "st")
        os.makedirs(os.path.join(st, "logs"))
        for own in (out + ".id", os.path.join(st, "phase1.todo"), os.path.join(st, "joblog.phase1"),
                    os.path.join(st, "failed.tsv"), os.path.join(st, "logs", "mine.txt")):
            with self.subTest(own=own):
                write(own, "precious\n")
                done, _ = self.run_list("%s\tcp %s %s\n" % (out, shlex.quote(own), shlex.quote(out)))
                self.assertEqual(done.returncode, 2, done.stdout)
                self.assertIn("reads %s, which is" % own, done.stdout)
                self.assertIn("refused, nothing removed or run", done.stdout)
                self.assertEqual(read(own), "precious\n")
                self.assertFalse(os.path.exists(out))
                os.remove(own)

    def test_the_runs_file_may_be_neither_an_input_nor_a_result(self):
        given = os.path.join(self.dir, "in.txt")
        out = os.path.join(self.dir, "d5")
        write(given, "input data\n")
        lst = os.path.join(self.dir, "points.list")
        write(lst, "%s\tcp %s %s\n" % (out, shlex.quote(given), shlex.quote(out)))
        for runs, why in ((given, "which is the --runs file"), (out, "the done file %s is the --runs file" % out)):
            with self.subTest(runs=runs):
                done = subprocess.run([sys.executable, BACKEND, "run", "--state", os.path.join(self.dir, "st"),
                                       "--runs", runs, lst], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
                self.assertEqual(done.returncode, 2, done.stdout)
                self.assertIn(why, done.stdout)
                self.assertEqual(read(given), "input data\n")
                self.assertFalse(os.path.exists(out))

    def test_a_machine_files_timing_file_is_an_input(self):
        timing = os.path.join(self.dir, "t.timing")
        machine = os.path.join(self.dir, "m.toml")
        out = os.path.join(self.dir, "p.json")
        write(timing, "test_hit 1750\n")
        write(machine, '[timing]\ntiming="%s"\n' % timing)
        text = "%s\ttrue --config %s && cp %s %s\n" % (out, shlex.quote(machine), shlex.quote(timing), shlex.quote(out))
        self.assertEqual(self.run_list(text)[0].returncode, 0)
        write(timing, "test_hit 3500\n")
        done, _ = self.run_list(text)
        self.assertIn("%s changed since it was made" % timing, done.stdout)
        self.assertEqual(read(out), "test_hit 3500\n")
