"""The backend package (experiments/backend) without a cluster: point lists are read and refused
with the file and line, logs are named after the done files, and the Slurm side's sbatch lines,
squeue parsing and task body do what the runs rely on."""
import os
import shlex
import subprocess
import sys
import tempfile
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(REPO, "experiments"))

from backend import points, slurm, task  # noqa: E402


def write(path, text):
    with open(path, "w") as f:
        f.write(text)


class PointLists(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp()

    def tearDown(self):
        subprocess.run(["rm", "-rf", self.dir])

    def test_read_and_done(self):
        done = os.path.join(self.dir, "a", "p.json")
        write(os.path.join(self.dir, "l"), "# a comment\n\n%s\techo hi\n" % done)
        (p,) = points.read(os.path.join(self.dir, "l"))
        self.assertEqual((p.done, p.command), (done, "echo hi"))
        self.assertFalse(p.is_done())
        os.makedirs(os.path.dirname(done))
        write(done, "")
        self.assertFalse(p.is_done(), "an empty file is not a result")
        write(done, "{}")
        self.assertTrue(p.is_done())

    def test_bad_lines_name_file_and_line(self):
        path = os.path.join(self.dir, "l")
        for text, message in (("/x.json\techo\nno tab here\n", ":2: expected DONE-FILE<TAB>COMMAND"),
                              ("x.json\techo\n", ":1: the done file must be an absolute path")):
            write(path, text)
            with self.assertRaises(ValueError) as e:
                points.read(path)
            self.assertIn(path + message, str(e.exception))

    def test_logs_follow_done_files_and_twice_is_refused(self):
        a = points.Point("/r/calibrated/t1/image1.json", "true", "l:1")
        b = points.Point("/r/literal/t1/image1.json", "true", "l:2")
        points.assign_logs([[a], [b]], "/s/logs")
        self.assertEqual(a.log, "/s/logs/calibrated__t1__image1.json.log")
        self.assertNotEqual(a.log, b.log)
        self.assertEqual(a.wrapped(), "( true ) 3>&1 >/s/logs/calibrated__t1__image1.json.log 2>&1")
        with self.assertRaises(ValueError):
            points.assign_logs([[a, points.Point(a.done, "true", "l:3")]], "/s/logs")


class Slurm(unittest.TestCase):
    def test_squeue_task_counts(self):
        self.assertEqual(slurm.count_tasks("12_3"), 1)
        self.assertEqual(slurm.count_tasks("12"), 1)
        self.assertEqual(slurm.count_tasks("12_[1-4,7]"), 5)
        self.assertEqual(slurm.count_tasks("12_[5-10%2]"), 6)

    def test_sbatch_line(self):
        cmd = slurm.sbatch_command("/s/phase2.todo", 7, 4, 3, "--partition=short --time=0:10:00", "sweep-phase2",
                                   "41", "/s/slurm")
        self.assertIn("--array", cmd)
        self.assertEqual(cmd[cmd.index("--array") + 1], "1-7%3")
        self.assertIn("--dependency=afterany:41", cmd)
        self.assertIn("--partition=short", cmd)
        self.assertIn("--time=0:10:00", cmd)
        self.assertEqual(cmd[cmd.index("--output") + 1], "/s/slurm/%A_%a.out")
        wrap = shlex.split(cmd[cmd.index("--wrap") + 1])
        self.assertEqual(wrap[2:], ["task", "/s/phase2.todo", "4", "/s/phase2.todo.rc"])

    def test_task_runs_its_lines_and_records_them(self):
        d = tempfile.mkdtemp()
        try:
            todo = os.path.join(d, "todo")
            write(todo, "".join("echo %d >>%s/ran\n" % (i, d) for i in range(1, 6)) + "exit 4\n")
            os.makedirs(todo + ".rc")
            os.environ["SLURM_ARRAY_TASK_ID"] = "2"
            with open(os.devnull, "w") as null:
                saved, sys.stdout = sys.stdout, null
                try:
                    self.assertEqual(task.run(todo, 2, todo + ".rc"), 0)  # lines 3 and 4
                    os.environ["SLURM_ARRAY_TASK_ID"] = "3"
                    self.assertEqual(task.run(todo, 2, todo + ".rc"), 1)  # lines 5 and 6 (exit 4)
                finally:
                    sys.stdout = saved
            self.assertEqual(open(os.path.join(d, "ran")).read().split(), ["3", "4", "5"])
            record = [line.split("\t") for line in open(os.path.join(todo + ".rc", "3")).read().splitlines()]
            self.assertEqual([r[:2] for r in record], [["5", "0"], ["6", "4"]])
            self.assertTrue(all(float(r[2]) >= 0 for r in record), "each point's CPU seconds")
            pts = [points.Point("/p%d.json" % i, "true", "l") for i in range(1, 7)]
            failed, cpu = slurm.point_status([(todo, pts)])
            self.assertEqual(failed, {pts[5]: "exit 4"})
            self.assertGreaterEqual(cpu, 0)
        finally:
            os.environ.pop("SLURM_ARRAY_TASK_ID", None)
            subprocess.run(["rm", "-rf", d])


if __name__ == "__main__":
    unittest.main()

