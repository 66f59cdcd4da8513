#!/usr/bin/env python3
"""Format audit: every C and C++ source below the given folders is as clang-format makes it
under the tree's .clang-format.

usage: scripts/check_format.py [--clang-format PROGRAM] ROOT FOLDER...

Runs `clang-format --dry-run -Werror` on each .c, .h and .cpp file below ROOT/FOLDER, prints one
line per file that differs (with clang-format's first complaint) and exits 1 if there is any,
0 otherwise; `clang-format -i FILE` reformats one. Exits 2 if clang-format cannot be run.
"""
import argparse
import os
import subprocess
import sys

EXTENSIONS = (".c", ".h", ".cpp")


def sources(root, folders):
    for folder in folders:
        for base, dirs, files in os.walk(os.path.join(root, folder)):
            dirs.sort()
            for name in sorted(files):
                if name.endswith(EXTENSIONS):
                    yield os.path.join(base, name)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--clang-format", default="clang-format")
    parser.add_argument("root")
    parser.add_argument("folders", nargs="+")
    args = parser.parse_args()
    files = list(sources(args.root, args.folders))
    offenders = 0
    for path in files:
        try:
            run = subprocess.run([args.clang_format, "--dry-run", "-Werror", path],
                                 cwd=args.root, capture_output=True, text=True)
        except OSError as err:
            print(f"check_format: cannot run {args.clang_format}: {err}", file=sys.stderr)
            return 2
        if run.returncode != 0:
            offenders += 1
            first = (run.stderr.strip().splitlines() or ["differs"])[0]
            print(f"{os.path.relpath(path, args.root)}: not formatted ({first})")
    print(f"check_format: {len(files) - offenders} of {len(files)} sources formatted")
    return 1 if offenders else 0


if __name__ == "__main__":
    sys.exit(main())
