#!/usr/bin/env python3
"""check_doc_links.py - README.md stays an entry point and the documentation's links resolve.

Usage: python3 scripts/check_doc_links.py [--max-readme-lines N] ROOT

Checks ROOT/README.md has at most N lines (250), and that every relative Markdown link
[text](target) in ROOT/README.md and ROOT/docs/*.md names an existing file or folder and, with
#anchor, a heading of that Markdown file (GitHub's anchors: lower case, punctuation dropped,
spaces as dashes). Links inside code spans and fenced blocks are not links. Prints each broken
link as FILE:LINE: message and exits 1 if there is one.
"""
import argparse
import os
import re
import sys

LINK = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")


def prose_lines(text):
    """(line number, line with code spans blanked) outside fenced blocks."""
    fenced = False
    for number, line in enumerate(text.split("\n"), 1):
        if line.lstrip().startswith("```"):
            fenced = not fenced
            continue
        if fenced or line.startswith("    "):
            continue
        yield number, re.sub(r"`[^`]*`", "``", line)


def anchor(heading):
    """GitHub's anchor of a heading's text."""
    text = re.sub(r"[^\w\- ]", "", heading.strip().lower())
    return text.replace(" ", "-")


def anchors(path):
    found, seen = set(), {}
    with open(path, encoding="utf-8") as f:
        text = f.read()
    fenced = False
    for line in text.split("\n"):
        if line.lstrip().startswith("```"):
            fenced = not fenced
        m = None if fenced else re.match(r"#{1,6}\s+(.*)", line)
        if m:
            base = anchor(m.group(1))
            n = seen.get(base, 0)
            seen[base] = n + 1
            found.add(base if n == 0 else "%s-%d" % (base, n))
    return found


def broken_links(page):
    """Messages for the page's relative links that do not resolve."""
    with open(page, encoding="utf-8") as f:
        text = f.read()
    for number, line in prose_lines(text):
        for target in LINK.findall(line):
            if re.match(r"[a-z][a-z0-9+.-]*:", target):
                continue  # http:, https:, mailto:
            path, _, frag = target.partition("#")
            full = os.path.normpath(os.path.join(os.path.dirname(page), path)) if path else page
            if not os.path.exists(full):
                yield number, "%s: no such file" % target
            elif frag and full.endswith(".md") and frag not in anchors(full):
                yield number, "%s: no heading #%s in %s" % (target, frag, os.path.basename(full))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--max-readme-lines", type=int, default=250)
    parser.add_argument("root")
    args = parser.parse_args()
    readme = os.path.join(args.root, "README.md")
    docs = os.path.join(args.root, "docs")
    pages = [readme] + sorted(os.path.join(docs, n) for n in os.listdir(docs) if n.endswith(".md"))
    bad = 0
    with open(readme, encoding="utf-8") as f:
        lines = f.read().count("\n")
    if lines > args.max_readme_lines:
        print("README.md: %d lines, more than %d" % (lines, args.max_readme_lines))
        bad += 1
    for page in pages:
        for number, message in broken_links(page):
            print("%s:%d: %s" % (os.path.relpath(page, args.root), number, message))
            bad += 1
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
