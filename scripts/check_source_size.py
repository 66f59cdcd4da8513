#!/usr/bin/env python3
"""Source size audit: no function over 80 lines and no source file over 600 lines.

usage: scripts/check_source_size.py [--max-function N] [--max-file N] [--allow FILE:FUNCTION]... PATH...

Reads C and C++ files (.c .h .cpp .hpp) and Python files below each PATH. A C/C++ function
is found by matching braces after comments, strings and preprocessor lines are blanked: a
brace at file, namespace, class or extern "C" level that follows a closing parenthesis opens a
function body (constructor initialiser braces are part of it); a function's length runs from
the first line of its signature to its closing brace. Python functions come from the ast.
Prints one line per offender and exits 1 if there is any, 0 otherwise; a function named with
--allow (path as found, e.g. model/x.cpp:build) is listed as allowed and does not fail.
"""
import argparse
import ast
import os
import re
import sys

C_EXTENSIONS = (".c", ".h", ".cpp", ".hpp", ".cc")
CONTAINER = re.compile(r"\b(namespace|class|struct|union|enum)\b|\bextern\s*\"\s*\"")
INIT_LIST = re.compile(r"\)\s*(?:const\s*|noexcept\s*|override\s*|final\s*)*:(?!:)")


def blank_c(text):
    """The text with comments, string and character literals and preprocessor lines turned to
    spaces (newlines kept, so that line numbers hold)."""
    out = []
    i, n = 0, len(text)
    line_start = True
    while i < n:
        c = text[i]
        if line_start and c == "#":  # a preprocessor line, with its continuations
            while i < n and text[i] != "\n":
                if text[i] == "\\" and i + 1 < n and text[i + 1] == "\n":
                    out.append(" \n")
                    i += 2
                    continue
                out.append(" ")
                i += 1
            continue
        if c == "\n":
            line_start = True
            out.append(c)
            i += 1
            continue
        if not c.isspace():
            line_start = False
        if text.startswith("//", i):
            while i < n and text[i] != "\n":
                out.append(" ")
                i += 1
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            out.append(re.sub(r"[^\n]", " ", text[i:end]))
            i = end
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(c + " " * (min(j, n) - i - 1) + (c if j < n else ""))
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def matching_brace(text, i):
    """The index of the brace closing the one at i."""
    depth = 0
    for j in range(i, len(text)):
        if text[j] == "{":
            depth += 1
        elif text[j] == "}":
            depth -= 1
            if depth == 0:
                return j
    return len(text) - 1


def c_functions(text):
    """(name, first line, last line) of every function body in blanked C/C++ text."""
    found = []
    line_of = lambda pos: text.count("\n", 0, pos) + 1

    def scan(start, end):
        stmt_start = start  # where the current declaration began
        i = start
        while i < end:
            c = text[i]
            if c == ";":
                stmt_start = i + 1
            elif c == "}":
                stmt_start = i + 1
            elif c == "{":
                stmt = text[stmt_start:i]
                close = matching_brace(text, i)
                if INIT_LIST.search(stmt) and re.search(r"[\w>]\s*$", stmt):
                    i = close + 1  # a member's brace initialiser: the constructor goes on
                    continue
                if ")" in stmt and not stmt.rstrip().endswith("="):
                    head = stmt.lstrip()
                    first = line_of(stmt_start + len(stmt) - len(head))
                    name = re.findall(r"([~\w:]+)\s*\(", head)
                    found.append((name[0] if name else "?", first, line_of(close)))
                elif CONTAINER.search(stmt) and not stmt.rstrip().endswith("="):
                    scan(i + 1, close)
                i = close + 1
                stmt_start = i
                continue
            i += 1

    scan(0, len(text))
    return found


def python_functions(text, path):
    tree = ast.parse(text, path)
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            first = min([node.lineno] + [d.lineno for d in node.decorator_list])
            yield node.name, first, node.end_lineno


def source_files(paths):
    for path in paths:
        if os.path.isfile(path):
            yield path
            continue
        for root, dirs, files in os.walk(path):
            dirs[:] = sorted(d for d in dirs if not d.startswith(".") and d != "__pycache__")
            for name in sorted(files):
                if name.endswith(C_EXTENSIONS) or name.endswith(".py"):
                    yield os.path.join(root, name)


def audit(paths, max_function, max_file, allowed=()):
    problems, allowances = [], []
    count = 0
    for path in source_files(paths):
        count += 1
        with open(path, encoding="utf-8", errors="replace") as f:
            text = f.read()
        lines = text.count("\n") + (0 if text.endswith("\n") or not text else 1)
        if lines > max_file:
            problems.append("%s: %d lines (at most %d per file)" % (path, lines, max_file))
        functions = python_functions(text, path) if path.endswith(".py") else c_functions(blank_c(text))
        for name, first, last in functions:
            if last - first + 1 > max_function:
                line = "%s:%d: function %s has %d lines (at most %d)" % (path, first, name, last - first + 1,
                                                                         max_function)
                (allowances if "%s:%s" % (os.path.normpath(path), name) in allowed else problems).append(line)
    return count, problems, allowances


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--max-function", type=int, default=80)
    parser.add_argument("--max-file", type=int, default=600)
    parser.add_argument("--allow", action="append", default=[], metavar="FILE:FUNCTION")
    parser.add_argument("paths", nargs="+")
    args = parser.parse_args(argv)
    allowed = {os.path.normpath(a.rsplit(":", 1)[0]) + ":" + a.rsplit(":", 1)[-1] for a in args.allow}
    count, problems, allowances = audit(args.paths, args.max_function, args.max_file, allowed)
    for p in problems:
        print(p)
    for p in allowances:
        print("allowed: " + p)
    print("check_source_size: %d files, %d over the limits (function %d, file %d lines)"
          % (count, len(problems), args.max_function, args.max_file))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
