"""Memory the system refuses a Python tool of experiments/ (a small ulimit -v), wherever it is
refused: each tool ends with `PROGRAM: out of memory: ...` and exit 1, never a traceback, when
loading any of its modules fails as the loader and the system fail then (MemoryError, OSError
ENOMEM, ImportError of an extension module the loader could not map), the first one included.
The refusal is made where it is wanted by a module finder that fails for one module's name."""
import os
import subprocess
import sys
import tempfile
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EXP = os.path.join(REPO, "experiments")

# Runs the tool FILE (argv[3:] its arguments) as python3 runs it, loading the module NAME failing
# with the error KIND.
REFUSING = """import os, runpy, sys
kind, name, path = sys.argv[1:4]
errors = {"MemoryError": MemoryError(),
          "ENOMEM": OSError(12, "Cannot allocate memory", os.path.dirname(path)),
          "map": ImportError("/usr/lib/python3/lib-dynload/%s.so: failed to map segment from shared object" % name)}


class Refuse:
    def find_spec(self, fullname, path=None, target=None):
        if fullname == name:
            raise errors[kind]
        return None


sys.meta_path.insert(0, Refuse())
sys.argv = [path] + sys.argv[4:]
runpy.run_path(path, run_name="__main__")
"""

MESSAGE = "%s: out of memory: the system refused the memory the tool asked for (ulimit -v?)\n"

# (program as its message names it, the file python3 runs, its arguments, modules it loads)
TOOLS = [
    ("experiments/report", "report/__main__.py", ["compare", "a", "b"],
     ["memory_exit", "stop_signals", "_hashlib", "report.cli", "argparse", "_csv"]),
    ("sweep", "report/__main__.py", ["sweep-plan", "--out", "o"], ["memory_exit", "stop_signals", "_hashlib"]),
    ("experiments/backend", "backend/__main__.py", ["run", "--state", "st", "x.list"],
     ["memory_exit", "stop_signals", "backend.cli", "argparse"]),
    ("compare-mappings", "compare-mappings", ["s.nff"],
     ["memory_exit", "stop_signals", "compare_mappings", "subprocess", "_posixsubprocess", "output_files"]),
    # a script's check: the script is named (the sweep, a study), never the helper it runs
    ("sweep", "output_files.py", ["--check-streams", "sweep", "--"],
     ["memory_exit", "output_rules", "command_words", "tempfile", "stream_checks"]),
    ("output_files.py", "output_files.py", ["out.txt"], ["memory_exit", "output_rules", "tempfile"]),
    ("experiments/report/buffers.py", "report/buffers.py", ["r.tsv", "d.md", "p", "b.gp"],
     ["memory_exit", "_csv", "output_files", "argparse"]),
    ("experiments/report/animation.py", "report/animation.py", ["r", "d.md", "p", "g", "1", "1"],
     ["memory_exit", "_csv", "stop_signals"]),
    ("experiments/mapping/report.py", "mapping/report.py", ["r.tsv", "d.md", "p", "s"], ["memory_exit", "_csv"]),
    ("experiments/calibration/report.py", "calibration/report.py", ["r.tsv", "d.md", "p", "g"],
     ["memory_exit", "_csv"]),
    ("experiments/motion/report.py", "motion/report.py", ["r", "d.md", "p", "s", "1", "1"],
     ["memory_exit", "_csv", "report.plots"]),
    ("experiments/scaling/report.py", "scaling/report.py", ["r", "d.md", "p", "s", "1", "1"],
     ["memory_exit", "_csv", "report.plots"]),
]


class MemoryRefused(unittest.TestCase):
    def test_each_tool_names_refused_memory_wherever_a_module_fails_to_load(self):
        with tempfile.TemporaryDirectory() as work:
            for program, path, args, modules in TOOLS:
                for name in modules:
                    for kind in ("MemoryError", "ENOMEM", "map"):
                        with self.subTest(program=program, module=name, kind=kind):
                            done = subprocess.run([sys.executable, "-c", REFUSING, kind, name,
                                                   os.path.join(EXP, path)] + args, cwd=work,
                                                  stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                                  stderr=subprocess.PIPE, text=True)
                            self.assertEqual((done.returncode, done.stderr), (1, MESSAGE % program))

    def test_another_import_error_stays_a_traceback(self):
        """Only the refusals: a module missing for another reason is not called memory."""
        done = subprocess.run([sys.executable, "-c", REFUSING.replace("failed to map segment", "no such file"),
                               "map", "stop_signals", os.path.join(EXP, "report/__main__.py")],
                              stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        self.assertEqual(done.returncode, 1)
        self.assertIn("Traceback", done.stderr)


if __name__ == "__main__":
    unittest.main()
