"""output_files - every file the Python tools of experiments/ write (a sweep, a study, the
backend, compare-mappings, report) goes through here, under the rules of the executables'
outputs (support/output_files.cpp; docs/cli.md, "Input and output files"):

- a file is written to a temporary `.NAME.XXXXXX` in its own folder and renamed onto its name
  only when it is complete; on any error, or an interrupt (Ctrl-C; SIGTERM and SIGHUP after
  exit_on_signals()), the temporary is removed and the old file stays as it was;
- a name that is a symbolic link is followed to the file it names (the temporary goes beside
  that file and is renamed onto it), so the link itself is never replaced;
- a folder, a FIFO, a device or a socket is refused as an output, before anything is written,
  with a message naming the option and the file;
- OutputSet checks a command's outputs before it runs: none may be one of its inputs nor the
  file of another output, also through another spelling of the name or a hard link.

A refusal is an OutputError (a ValueError): a command-line error, exit status 2. A failed write
is an OSError naming the file: `PATH: cannot write: REASON`.

    outs = OutputSet()
    outs.add_input("the scene", scene)
    png = outs.add("--out", args.out)
    outs.check()                       # OutputError when --out is the scene
    with staged(png, "--out") as tmp:  # for another program (gnuplot) to write
        run_gnuplot(tmp)
    write_text(csv_path, text, "--out")
"""
import contextlib
import os
import stat
import tempfile


class OutputError(ValueError):
    """An output refused before anything was written: its message names the option and the file."""


def _kind(mode):
    """What a file that is not a regular one is, for a message."""
    for test, name in ((stat.S_ISFIFO, "FIFO"), (stat.S_ISCHR, "character device"),
                       (stat.S_ISBLK, "block device"), (stat.S_ISSOCK, "socket")):
        if test(mode):
            return name
    return "special file"


def _stat(path):
    try:
        return os.stat(path)
    except FileNotFoundError:
        return None


def target(option, path):
    """The file PATH writes, a link followed to what it names; OutputError (naming OPTION) when
    it is empty, a folder, a FIFO, a device or a socket, or its folder does not exist."""
    what = "%s '%s'" % (option, path)
    if not path:
        raise OutputError("%s: an empty file name" % option)
    real = os.path.realpath(path)
    try:
        st = _stat(real)
    except OSError as e:  # a loop of links, a folder on the way that is a file
        raise OutputError("%s: %s" % (what, e.strerror))
    if st is not None:
        if stat.S_ISDIR(st.st_mode):
            raise OutputError("%s: is a folder" % what)
        if not stat.S_ISREG(st.st_mode):
            raise OutputError("%s: is a %s, not a regular file" % (what, _kind(st.st_mode)))
    elif not os.path.isdir(os.path.dirname(real)):
        shown = os.path.dirname(real) if os.path.islink(path) else os.path.dirname(path) or "."
        raise OutputError("%s: folder '%s' does not exist" % (what, shown))
    return real


def _new_file_mode():
    """The mode open() gives a new file (mkstemp makes 0600)."""
    mask = os.umask(0)
    os.umask(mask)
    return 0o666 & ~mask


def _temporary(real):
    """A new empty temporary beside REAL, its name cut to fit the 255-byte name limit."""
    folder, base = os.path.split(real)
    fd, tmp = tempfile.mkstemp(dir=folder, prefix="." + base[:240] + ".")
    os.fchmod(fd, _new_file_mode())
    return fd, tmp


def _cannot_write(shown, e):
    """`SHOWN: cannot write: REASON`, the executables' form (no errno number in front)."""
    return OSError("%s: cannot write: %s" % (shown, e.strerror or e))


def _replace(tmp, real, shown):
    try:
        os.replace(tmp, real)
    except OSError as e:
        raise _cannot_write(shown, e) from None


class _Named:
    """A file whose failed writes and flushes name the file the user asked for."""

    def __init__(self, f, shown):
        self._f, self._shown = f, shown

    def write(self, data):
        try:
            return self._f.write(data)
        except OSError as e:
            raise _cannot_write(self._shown, e) from None

    def flush(self):
        try:
            self._f.flush()
        except OSError as e:
            raise _cannot_write(self._shown, e) from None

    def __getattr__(self, name):
        return getattr(self._f, name)


@contextlib.contextmanager
def atomic(path, option="output", mode="w", newline=None):
    """Opens a temporary for PATH (text, or binary with mode "wb"); renames it onto PATH (the file
    a link names) when the block ends, removes it when the block raises."""
    real = target(option, path)
    try:
        fd, tmp = _temporary(real)
    except OSError as e:
        raise _cannot_write(path, e) from None
    try:
        with os.fdopen(fd, mode, newline=newline) as f:
            named = _Named(f, path)
            yield named
            named.flush()
        _replace(tmp, real, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise


@contextlib.contextmanager
def staged(path, option="output"):
    """A temporary name beside PATH (the file a link names) for another program to write;
    renamed onto PATH when the block ends, removed when the block raises. The temporary ends in
    PATH's extension, for programs that choose a format by it."""
    real = target(option, path)
    folder, base = os.path.split(real)
    ext = os.path.splitext(base)[1][:16]
    try:
        fd, tmp = tempfile.mkstemp(dir=folder, prefix="." + base[:220] + ".", suffix=ext)
        os.fchmod(fd, _new_file_mode())
        os.close(fd)
    except OSError as e:
        raise _cannot_write(path, e) from None
    try:
        yield tmp
        if os.path.getsize(tmp) == 0:
            raise OSError("%s: cannot write: the program wrote nothing" % path)
        _replace(tmp, real, path)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise


def write_text(path, text, option="output", newline=None):
    """PATH holds TEXT, written through a temporary."""
    with atomic(path, option, newline=newline) as f:
        f.write(text)


def write_lines(path, lines, option="output"):
    """PATH holds LINES, each ended by a newline."""
    write_text(path, "".join(line + "\n" for line in lines), option)


def append_text(path, text, option="output"):
    """PATH holds what it held and TEXT after it, written through a temporary like any output."""
    real = target(option, path)
    before = ""
    if os.path.exists(real):
        with open(real) as f:
            before = f.read()
    write_text(path, before + text, option)


def copy_file(source, path, option="output"):
    """PATH holds a copy of SOURCE's bytes."""
    with open(source, "rb") as src, atomic(path, option, mode="wb") as f:
        while True:
            chunk = src.read(1 << 20)
            if not chunk:
                break
            f.write(chunk)


def _identity(path):
    """(device, inode) of an existing regular file, else None."""
    try:
        st = os.stat(path)
    except OSError:
        return None
    return (st.st_dev, st.st_ino) if stat.S_ISREG(st.st_mode) else None


class OutputSet:
    """A command's outputs and inputs, checked together before anything runs."""

    def __init__(self):
        self.inputs = []   # (option, path)
        self.outputs = []  # (option, path, the file it writes)

    def add_input(self, option, path):
        if path:
            self.inputs.append((option, path))

    def add(self, option, path):
        """Checks one output (target()) and returns the file it writes."""
        real = target(option, path)
        self.outputs.append((option, path, real))
        return real

    def check(self):
        """OutputError when an output is one of the inputs or the file of another output."""
        inputs = {}
        for option, path in self.inputs:
            key = _identity(path)
            if key is not None:
                inputs.setdefault(key, "%s file %s" % (option, path))
        names, files = {}, {}
        for option, path, real in self.outputs:
            what = "%s '%s'" % (option, path)
            key = _identity(real)
            if key in inputs:
                raise OutputError("%s: is the %s, an input" % (what, inputs[key]))
            other = names.get(real) or (files.get(key) if key else None)
            if other:
                raise OutputError("%s: is also the file of %s" % (what, other))
            names[real] = what
            if key:
                files[key] = what


def named_files(words):
    """(option, path) of each word of a command line that names an existing regular file, the
    option being the word before it (or OPTION of OPTION=PATH; "the argument" for a word after
    no option): the inputs a command's outputs are checked against."""
    found = []
    for i, word in enumerate(words):
        option, eq, value = word.partition("=")
        if word.startswith("--") and eq and _identity(value) is not None:
            found.append((option, value))
        elif _identity(word) is not None:
            before = words[i - 1] if i > 0 else ""
            found.append((before if before.startswith("-") else "argument", word))
    return found


def exit_on_signals():
    """SIGTERM and SIGHUP end the program as SystemExit(128 + the signal), so that an unfinished
    file's temporary is removed on the way out as on Ctrl-C; a signal the program was started
    ignoring (nohup) stays ignored."""
    import signal

    def leave(signum, frame):
        raise SystemExit(128 + signum)
    for sig in (signal.SIGTERM, signal.SIGHUP):
        if signal.getsignal(sig) != signal.SIG_IGN:
            signal.signal(sig, leave)


def main(argv):
    """`python3 output_files.py FILE [OPTION]`: standard input into FILE under these rules, for
    the shell scripts (exit 2 when FILE is refused, naming OPTION; 1 when the write fails)."""
    import sys
    if len(argv) not in (1, 2):
        print("usage: output_files.py FILE [OPTION] < TEXT", file=sys.stderr)
        return 2
    try:
        with atomic(argv[0], argv[1] if len(argv) == 2 else "output", mode="wb") as f:
            while True:
                chunk = sys.stdin.buffer.read(1 << 20)
                if not chunk:
                    break
                f.write(chunk)
    except OutputError as e:
        print(e, file=sys.stderr)
        return 2
    except OSError as e:
        print(e, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    import sys
    exit_on_signals()
    sys.exit(main(sys.argv[1:]))
