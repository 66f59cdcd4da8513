#!/usr/bin/env python3
"""Writes docs/cli.md's generated option tables from `torusrt-sim --option-tables`.

Usage: python3 scripts/write_option_docs.py [BUILD_DIR] [--check]

Each block the program prints replaces the lines of docs/cli.md between the same
"<!-- BEGIN generated: NAME" and "<!-- END generated: NAME -->" lines. With --check nothing is
written: exit 1 naming each block that differs (or is missing), 0 when all agree.
"""
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOC = os.path.join(ROOT, "docs", "cli.md")
BLOCK = re.compile(r"<!-- BEGIN generated: (.*?) \(.*?-->\n.*?<!-- END generated: \1 -->\n", re.S)


def main(argv):
    check = "--check" in argv
    args = [a for a in argv if a != "--check"]
    build = args[0] if args else os.path.join(ROOT, "build")
    generated = subprocess.run([os.path.join(build, "torusrt-sim"), "--option-tables"], check=True,
                               stdout=subprocess.PIPE, universal_newlines=True).stdout
    with open(DOC, encoding="utf-8") as f:
        text = f.read()
    problems = []
    for block in BLOCK.finditer(generated):
        name, want = block.group(1), block.group(0)
        found = [m for m in BLOCK.finditer(text) if m.group(1) == name]
        if len(found) != 1:
            problems.append("docs/cli.md: the block '%s' is there %d times, not once" % (name, len(found)))
            continue
        if found[0].group(0) != want:
            problems.append("docs/cli.md: the block '%s' differs from torusrt-sim --option-tables" % name)
            text = text.replace(found[0].group(0), want)
    if check:
        for p in problems:
            print(p, file=sys.stderr)
        if problems:
            print("write them with: python3 scripts/write_option_docs.py BUILD_DIR", file=sys.stderr)
        return 1 if problems else 0
    with open(DOC, "w", encoding="utf-8") as f:
        f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
