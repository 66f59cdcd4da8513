#!/usr/bin/env python3
"""check_includes.py - the import rule of docs/design.md ("Layout"): includes run
testbench -> model/run -> model -> support -> kernel, never back, and CLI11 and SystemC's
kernel internals stay where they belong.

Usage: check_includes.py [ROOT]   (default: the source tree this script is in)
Prints each offence as FILE:LINE: what and why, and exits 1 if there is one.
Standard library only.
"""
import os
import re
import sys

# Folder -> layer, and what each layer may include (its own layer and the ones below it).
LAYERS = [("include", "kernel"), ("src", "kernel"), ("support", "support"), ("model/run", "model/run"),
          ("model", "model"), ("testbench", "testbench")]
ALLOWED = {
    "kernel": {"kernel"},
    "support": {"kernel", "support"},
    "model": {"kernel", "support", "model"},
    "model/run": {"kernel", "support", "model", "model/run"},
    "testbench": {"kernel", "support", "model", "model/run", "testbench"},
}
SOURCE = (".c", ".h", ".cpp", ".hpp")
QUOTED = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
CLI11 = re.compile(r'^\s*#\s*include\s+<CLI/')
# Calls into the Accellera kernel's elaboration, outside IEEE 1666.
INTERNALS = re.compile(r"prepare_to_simulate|sc_get_curr_simcontext\(\)\s*->\s*elaborate")


def layer_of(rel):
    """The layer of a path relative to the root (the longest matching folder), or None."""
    for folder, layer in LAYERS:
        if rel == folder or rel.startswith(folder + "/"):
            return layer
    return None


def sources(root):
    for folder, _ in LAYERS:
        top = os.path.join(root, folder)
        for dirpath, _, files in os.walk(top):
            for name in sorted(files):
                if name.endswith(SOURCE):
                    yield os.path.relpath(os.path.join(dirpath, name), root)


def header_layers(root):
    """{header file name: set of layers that hold a header of that name}."""
    out = {}
    for rel in sources(root):
        if rel.endswith((".h", ".hpp")):
            out.setdefault(os.path.basename(rel), set()).add(layer_of(rel))
    return out


def offences(root):
    headers = header_layers(root)
    out = []
    for rel in sorted(set(sources(root))):
        layer = layer_of(rel)
        with open(os.path.join(root, rel), errors="replace") as f:
            lines = f.read().split("\n")
        for number, line in enumerate(lines, 1):
            where = "%s:%d" % (rel, number)
            m = QUOTED.match(line)
            if m:
                name = m.group(1)
                beside = os.path.isfile(os.path.join(root, os.path.dirname(rel), name))
                held = {layer} if beside else headers.get(os.path.basename(name), set())
                if ".." in name.split("/"):
                    out.append('%s: includes "%s" by a relative path out of its folder' % (where, name))
                elif held and not held & ALLOWED[layer]:
                    out.append('%s: %s includes "%s" from %s, which it may not (it may include %s)' % (
                        where, layer, name, "/".join(sorted(held)), ", ".join(sorted(ALLOWED[layer]))))
            if CLI11.match(line) and layer != "testbench":
                out.append("%s: CLI11 outside testbench/ (the command line stays in the executables)" % where)
            if INTERNALS.search(line) and not line.lstrip().startswith("//"):
                out.append("%s: calls the SystemC kernel's elaboration directly, outside IEEE 1666" % where)
    return out


def main(argv):
    root = argv[1] if len(argv) > 1 else os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    found = offences(root)
    for line in found:
        print(line)
    print("check_includes: %d offence(s)" % len(found))
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
