"""A Python tool's standard output appended to a file of experiments/ (its own code, a plot
script) is refused before anything is written, exit 2, the file unchanged; the same for a study
script through lib.sh."""
import os
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
EXP = os.path.join(ROOT, "experiments")


class StreamIntoTools(unittest.TestCase):
    def setUp(self):
        # A file of the tools' folder made for the test (never one of its real files).
        fd, self.code = tempfile.mkstemp(dir=os.path.join(EXP, "report"), prefix=".stream-test-", suffix=".py")
        os.write(fd, b"# code\n")
        os.close(fd)
        self.out = tempfile.mkdtemp()

    def tearDown(self):
        os.remove(self.code)
        os.rmdir(self.out) if os.path.isdir(self.out) and not os.listdir(self.out) else None

    def check_refused(self, argv):
        with open(self.code, "a") as f:
            done = subprocess.run(argv, stdout=f, stderr=subprocess.PIPE, text=True)
        self.assertEqual(done.returncode, 2, done.stderr)
        self.assertIn("standard output is redirected to %s" % self.code, done.stderr)
        with open(self.code) as f:
            self.assertEqual(f.read(), "# code\n")

    def test_a_report_command(self):
        self.check_refused([sys.executable, os.path.join(EXP, "report"), "sweep-collect", "--out",
                            os.path.join(self.out, "R")])

    def test_a_study_script(self):
        self.check_refused(["bash", os.path.join(EXP, "buffers", "study.sh"), "--help"])


if __name__ == "__main__":
    unittest.main()
