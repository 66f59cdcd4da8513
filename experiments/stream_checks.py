"""stream_checks - a tool's own standard output and standard error checked against its inputs
before it writes anything (docs/experiments.md, the output rules of the Python tools): `>>
s.nff` or `>> RESULTS/fig7.csv` would append to a file the command reads."""
import os
import stat

from output_files import _identity, _through_stream, named_files, shown
from output_places import linked_into

TOOLS = os.path.dirname(os.path.abspath(__file__))  # experiments/


def divert_stderr():
    """Points standard error at the terminal (/dev/tty) when there is one, else at /dev/null: for
    when standard error is an input, so that no message is written into it (as the executables)."""
    try:
        fd = os.open("/dev/tty", os.O_WRONLY | os.O_NOCTTY)
    except OSError:
        fd = os.open(os.devnull, os.O_WRONLY)
    if fd != 2:
        os.dup2(fd, 2)
        os.close(fd)


def check_streams(prog, words, folders=(), own=()):
    """Ends the program (exit 2, before anything is written) when standard output or standard
    error is redirected to a file one of WORDS names (named_files: the scene, a --config and the
    files it names, a report), also through a hard link: `>> s.nff` would append to an input; or
    to a file inside a folder one of WORDS names (a results folder, a sweep's --out), at any
    depth, which the command may read or replace (a point's log among them): `>> RESULTS/fig7.csv`
    would append to it too. FOLDERS are more folders checked so (a study's scenes/, machines/,
    ...), named as themselves, and OWN the files the command writes (run_point.sh's OUT.log). A
    hard link made outside a folder to a file in it is found too (linked_into). The
    message about standard error goes to the terminal (or nowhere), never into the file. Called
    first by every tool, before its command line is parsed (a parse error is a message too)."""
    import sys
    streams = []
    for fd, name in ((2, "standard error"), (1, "standard output")):
        try:
            st = os.fstat(fd)
        except OSError:
            continue
        if stat.S_ISREG(st.st_mode):
            streams.append((fd, name, (st.st_dev, st.st_ino)))
    if not streams:
        return
    try:
        named = named_files(list(words))
    except (OSError, ValueError, RecursionError):
        return
    inputs, mine = {}, {}
    for option, path in named:
        if not _through_stream(path):  # --out /dev/stdout names the stream itself (refused as an output)
            inputs.setdefault(_identity(path), (option, path))
    for path in own:
        if _identity(path) is not None:
            mine.setdefault(_identity(path), path)
    # The tools' own folder too: its code and its results folders (`>> experiments/report/sweep.py`).
    folders = list(folders) + [TOOLS]
    folders = named_folders(list(words)) + [("argument", folder) for folder in folders if os.path.isdir(folder)]
    for fd, name, key in streams:
        if key in mine:
            why = "%s: %s is redirected to %s, a file the command writes\n" % (prog, name, shown(mine[key]))
        elif key in inputs:
            option, path = inputs[key]
            what = "the file %s" % shown(path) if option == "argument" else "the %s file %s" % (option, shown(path))
            why = "%s: %s is redirected to %s, an input\n" % (prog, name, what)
        else:
            inside = _stream_in_folder(fd, folders)
            if inside is None:
                continue
            path, option, folder = inside
            what = "the folder %s" % shown(folder) if option == "argument" else "the %s folder %s" % (option, shown(folder))
            why = "%s: %s is redirected to %s, in %s, whose files the command reads and writes\n" % (
                prog, name, shown(path), what)
        if fd == 2:
            divert_stderr()
        sys.stderr.write(why)
        sys.stderr.flush()
        raise SystemExit(2)


def named_folders(words):
    """(option, path) of each word of a command line that names an existing folder (as
    named_files names files): the folders whose files a command reads (a results folder, a
    sweep's --out, a backend's --state)."""
    found = []
    for i, word in enumerate(words):
        option, eq, value = word.partition("=")
        if word.startswith("--") and eq and os.path.isdir(value):
            found.append((option, value))
        elif os.path.isdir(word) and not word.startswith("-"):
            before = words[i - 1] if i > 0 else ""
            found.append((before if before.startswith("-") else "argument", word))
    return found


def _stream_in_folder(fd, folders):
    """(the stream's path, option, folder) when descriptor FD is a file inside one of FOLDERS
    (at any depth), by its path or, for a file with more than one link, as a hard link to a
    file there; else None."""
    try:
        path = os.readlink("/proc/self/fd/%d" % fd)
    except OSError:
        return None
    if path.startswith(os.sep):
        real = os.path.realpath(path)
        for option, folder in folders:
            top = os.path.realpath(folder)
            if real.startswith(top.rstrip(os.sep) + os.sep):
                return path, option, folder
    try:
        st = os.fstat(fd)
    except OSError:
        return None
    linked = linked_into(st, folders)
    return None if linked is None else (path, linked[0], linked[1])
