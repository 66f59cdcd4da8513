"""The source size checker on hand-made sources whose function lengths are counted by hand."""
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import check_source_size as css  # noqa: E402


def body(n):
    """n statement lines."""
    return "".join("    x += %d;\n" % i for i in range(n))


CPP = ("// a } in a comment, \"{\" in a string\n"                         # 1
       "#include <x>\n"                                                   # 2
       "namespace a {\n"                                                  # 3
       "static const int table[] = {1, 2, 3};\n"                         # 4
       "struct S {\n"                                                     # 5
       "    int m;\n"                                                     # 6
       "    S(int v) : m{v}, n{'}'}\n"                                    # 7
       "    {\n"                                                          # 8
       "        const char *s = \"}}{\";\n"                               # 9
       "    }\n"                                                          # 10
       "    int get() const { return m; }\n"                              # 11
       "};\n"                                                             # 12
       "int f(int x)\n"                                                   # 13
       "{\n" + body(3) +                                                  # 14-17
       "    return x;\n"                                                  # 18
       "}\n"                                                              # 19
       "}  // namespace a\n")


class CFunctions(unittest.TestCase):
    def test_functions_and_their_lines(self):
        found = css.c_functions(css.blank_c(CPP))
        self.assertEqual(found, [("S", 7, 10), ("get", 11, 11), ("f", 13, 19)])

    def test_lambdas_and_inner_blocks_belong_to_the_function(self):
        text = "void g()\n{\n    auto h = [](int y) { return y; };\n    if (1) {\n    }\n}\n"
        self.assertEqual(css.c_functions(css.blank_c(text)), [("g", 1, 6)])

    def test_extern_c_and_c_struct_return(self):
        text = 'extern "C" {\nstatic struct s *make(void)\n{\n    return 0;\n}\n}\n'
        self.assertEqual(css.c_functions(css.blank_c(text)), [("make", 2, 5)])


class Audit(unittest.TestCase):
    def write(self, name, text):
        path = os.path.join(self.dir.name, name)
        with open(path, "w") as f:
            f.write(text)
        return path

    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.dir.cleanup()

    def test_eighty_lines_pass_eighty_one_fail(self):
        # signature + { + body + } = body + 3 lines
        self.write("ok.cpp", "int ok()\n{\n" + body(77) + "}\n")
        self.write("long.c", "int too_long(void)\n{\n" + body(78) + "}\n")
        count, problems, _ = css.audit([self.dir.name], 80, 600)
        self.assertEqual(count, 2)
        self.assertEqual(len(problems), 1)
        self.assertIn("function too_long has 81 lines", problems[0])

    def test_file_length_and_python_functions(self):
        self.write("big.h", "int x;\n" * 601)
        self.write("p.py", "def f():\n" + "    x = 1\n" * 81)
        _, problems, _ = css.audit([self.dir.name], 80, 600)
        self.assertEqual(sorted(p.split(": ", 1)[1] for p in problems),
                         ["601 lines (at most 600 per file)", "function f has 82 lines (at most 80)"])

    def test_allowed_function_is_listed_apart(self):
        path = self.write("long.c", "int too_long(void)\n{\n" + body(78) + "}\n")
        _, problems, allowed = css.audit([self.dir.name], 80, 600, {os.path.normpath(path) + ":too_long"})
        self.assertEqual((len(problems), len(allowed)), (0, 1))


if __name__ == "__main__":
    unittest.main()
