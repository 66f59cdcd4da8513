"""scripts/check_format.py on made-up trees: a formatted source passes, a misformatted one is
named and fails the audit."""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
CHECKER = os.path.join(HERE, "..", "..", "scripts", "check_format.py")
STYLE = "BasedOnStyle: LLVM\nIndentWidth: 4\n"


@unittest.skipIf(shutil.which("clang-format") is None, "clang-format is not installed")
class CheckFormat(unittest.TestCase):
    def tree(self, sources):
        root = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, root)
        with open(os.path.join(root, ".clang-format"), "w") as f:
            f.write(STYLE)
        os.mkdir(os.path.join(root, "src"))
        for name, text in sources.items():
            with open(os.path.join(root, "src", name), "w") as f:
                f.write(text)
        return root

    def check(self, root):
        return subprocess.run([sys.executable, CHECKER, root, "src"], capture_output=True, text=True)

    def test_formatted_source_passes(self):
        run = self.check(self.tree({"a.c": "int f(int x) { return x + 1; }\n"}))
        self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
        self.assertIn("1 of 1 sources formatted", run.stdout)

    def test_misformatted_source_is_named(self):
        run = self.check(self.tree({"a.c": "int f(int x) { return x + 1; }\n",
                                    "b.cpp": "int  g( int x ){return x;}\n"}))
        self.assertEqual(run.returncode, 1)
        self.assertIn(os.path.join("src", "b.cpp") + ": not formatted", run.stdout)
        self.assertNotIn("a.c:", run.stdout)


if __name__ == "__main__":
    unittest.main()
