"""output_rules - the body of output_files.py, which the tools import and run: every file the
Python tools of experiments/ write (a sweep, a study, the backend, compare-mappings, report)
goes through here, under the rules of the executables' outputs (support/output_files.cpp; docs/cli.md, "Input and output files"):

- a file is written to a temporary `.NAME.XXXXXX` in its own folder and renamed onto its name
  only when it is complete; on any error, or a stopping signal after exit_on_signals()
  (Ctrl-C, SIGTERM, SIGHUP, ...), the temporary is removed and the old file stays as it was;
- a name that is a symbolic link is followed to the file it names (the temporary goes beside
  that file and is renamed onto it), so the link itself is never replaced;
- a folder, a FIFO, a device or a socket is refused as an output, before anything is written,
  with a message naming the option and the file; so is a name that reaches its file through
  /proc or /dev/fd (/dev/stdout, /dev/stderr: a stream the shell opened, which a rename would
  replace instead of writing at the stream's position);
- an input (read_text, read_bytes) must be a regular file: a FIFO or a device is refused before
  anything is read, and a text that is not UTF-8 is refused, each naming the file;
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
import signal
import stat
import sys
import tempfile

from command_words import (ANIMATION_OPTIONS, NO_RUN_OPTIONS, OUTPUT_OPTIONS, help_on_stdout,  # noqa: F401
                           list_values, nonempty, output_options, output_values, refuse_empty_values, refuse_repeated_options,
                           unusable_option)
from stop_signals import STOP_SIGNALS, exit_on_signals  # noqa: F401  (the tools take it from here, with the rest)


class OutputError(ValueError):
    """An output refused before anything was written: its message names the option and the file."""


def shown(text, backslash=True):
    """TEXT for a message, as the executables show a file name (rt_escape_bytes): a control
    character, DEL or a byte that is not UTF-8 as \\xNN, a backslash as \\\\, so that no name
    sends raw control bytes to a terminal or breaks a message's line. backslash=False leaves
    backslashes: for a whole message whose names may be shown already."""
    out = []
    for ch in str(text):
        code = ord(ch)
        if ch == "\\" and backslash:
            out.append("\\\\")
        elif code < 0x20 or code == 0x7f:
            out.append("\\x%02x" % code)
        elif 0xdc80 <= code <= 0xdcff:  # a byte os.fsdecode could not decode
            out.append("\\x%02x" % (code - 0xdc00))
        else:
            out.append(ch)
    return "".join(out)


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


def _through_stream(path, depth=0):
    """True when PATH, its links followed one by one, passes through /proc or /dev/fd: a file a
    process holds open (standard output, a pipe), not a name in a folder."""
    parts = os.path.normpath(os.path.abspath(path)).split(os.sep)[1:]
    here = os.sep
    for i, part in enumerate(parts):
        here = os.path.join(here, part)
        if here in ("/proc", "/dev/fd") or here.startswith(("/proc/", "/dev/fd/")):
            return True
        if depth < 40 and os.path.islink(here):
            rest = os.sep.join(parts[i + 1:])
            return _through_stream(os.path.join(os.path.dirname(here), os.readlink(here), rest), depth + 1)
    return False


def target(option, path):
    """The file PATH writes, a link followed to what it names; OutputError (naming OPTION) when
    it is empty, a folder, a FIFO, a device or a socket, or its folder does not exist."""
    what = "%s '%s'" % (option, shown(path))
    if not path:
        raise OutputError("%s: an empty file name" % option)
    if _through_stream(path):
        raise OutputError("%s: is a stream or a file another process holds open (through /proc or /dev/fd), "
                          "not a file these tools can replace; name a file" % what)
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
        folder = os.path.dirname(real) if os.path.islink(path) else os.path.dirname(path) or "."
        raise OutputError("%s: folder '%s' does not exist" % (what, shown(folder)))
    return real


def _new_file_mode():
    """The mode open() gives a new file (mkstemp makes 0600)."""
    mask = os.umask(0)
    os.umask(mask)
    return 0o666 & ~mask


@contextlib.contextmanager
def _signals_held():
    """The stopping signals held back for the block: a signal that comes while a temporary is
    being made is handled when the block ends, once the caller knows the temporary's name and
    can remove it, instead of between its making and the caller's `try`."""
    held = {getattr(signal, name) for name in STOP_SIGNALS}
    old = signal.pthread_sigmask(signal.SIG_BLOCK, held)
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, old)


def _temporary(real, suffix=""):
    """A new empty temporary beside REAL, its name cut to fit the 255-byte name limit. Call it
    with the signals held (_signals_held) and keep its name where the clean-up sees it."""
    folder, base = os.path.split(real)
    fd, tmp = tempfile.mkstemp(dir=folder, prefix="." + base[:240 - len(suffix)] + ".", suffix=suffix)
    try:
        os.fchmod(fd, _new_file_mode())
    except OSError:
        os.close(fd)
        os.unlink(tmp)
        raise
    return fd, tmp


class WriteError(OSError):
    """A write that failed (a full disk, a closed pipe): `FILE: cannot write: REASON`, exit 1."""


def os_message(e):
    """An OSError as `FILE: REASON` (no errno number), as the executables name a file."""
    if isinstance(e, OSError) and e.strerror and str(e).startswith("["):
        return "%s: %s" % (shown(os.fsdecode(e.filename)), e.strerror) if e.filename is not None else e.strerror
    return str(e)


def _cannot_write(shown, e):
    """`SHOWN: cannot write: REASON`, the executables' form (no errno number in front)."""
    return WriteError("%s: cannot write: %s" % (shown, e.strerror or e))


def _replace(tmp, real, shown):
    try:
        os.replace(tmp, real)
    except OSError as e:
        raise _cannot_write(shown, e) from None


class _Named:
    """A file whose failed writes and flushes name the file the user asked for."""

    def __init__(self, f, shown):
        self._f, self._shown = f, shown

    def _failed(self, e):
        return _cannot_write(self._shown, e)

    def write(self, data):
        try:
            return self._f.write(data)
        except OSError as e:
            raise self._failed(e) from None

    def flush(self):
        try:
            self._f.flush()
        except OSError as e:
            raise self._failed(e) from None

    def __getattr__(self, name):
        return getattr(self._f, name)


@contextlib.contextmanager
def atomic(path, option="output", mode="w", newline=None):
    """Opens a temporary for PATH (text, or binary with mode "wb"); renames it onto PATH (the file
    a link names) when the block ends, removes it when the block raises."""
    real = target(option, path)
    tmp = None
    try:
        with _signals_held():
            try:
                fd, tmp = _temporary(real)
            except OSError as e:
                raise _cannot_write(path, e) from None
        with os.fdopen(fd, mode, newline=newline) as f:
            named = _Named(f, path)
            yield named
            named.flush()
        _replace(tmp, real, path)
    except BaseException:
        if tmp is not None:
            with contextlib.suppress(OSError):
                os.unlink(tmp)
        raise


@contextlib.contextmanager
def staged(path, option="output"):
    """A temporary name beside PATH (the file a link names) for another program to write;
    renamed onto PATH when the block ends, removed when the block raises. The temporary ends in
    PATH's extension, for programs that choose a format by it."""
    real = target(option, path)
    ext = os.path.splitext(os.path.basename(real))[1][:16]
    tmp = None
    try:
        with _signals_held():
            try:
                fd, tmp = _temporary(real, ext)
                os.close(fd)
            except OSError as e:
                raise _cannot_write(path, e) from None
        yield tmp
        if os.path.getsize(tmp) == 0:
            raise WriteError("%s: cannot write: the program wrote nothing" % path)
        _replace(tmp, real, path)
    except BaseException:
        if tmp is not None:
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
        self.folders = []  # (option, folder whose files the command writes as it likes)

    def add_input(self, option, path):
        if path:
            self.inputs.append((option, path))

    def add(self, option, path):
        """Checks one output (target()) and returns the file it writes."""
        real = target(option, path)
        self.outputs.append((option, path, real))
        return real

    def add_folder(self, option, folder):
        """A folder whose files the command writes under names it chooses (plot data): no input
        may lie in it."""
        self.folders.append((option, folder))

    def check(self):
        """OutputError when an output is one of the inputs or the file of another output, or an
        input lies in a folder the command writes."""
        for option, folder in self.folders:
            top = os.path.realpath(folder) + os.sep
            for what, path in self.inputs:
                if _identity(path) is not None and os.path.realpath(path).startswith(top):
                    raise OutputError("%s: its folder %s, which the command writes, holds the %s file %s, an input"
                                      % (option, shown(folder), what, shown(path)))
        inputs = {}
        for option, path in self.inputs:
            key = _identity(path)
            if key is not None:
                inputs.setdefault(key, "%s file %s" % (option, shown(path)))
        names, files = {}, {}
        for option, path, real in self.outputs:
            what = "%s '%s'" % (option, shown(path))
            key = _identity(real)
            if key in inputs:
                raise OutputError("%s: is the %s, an input" % (what, inputs[key]))
            other = names.get(real) or (files.get(key) if key else None)
            if other:
                raise OutputError("%s: is also the file of %s" % (what, other))
            names[real] = what
            if key:
                files[key] = what


def input_file(path, what):
    """Refuses (OSError naming WHAT and PATH) an input that is missing, a folder, a FIFO or a
    device, before anything is read: a device may never end, a FIFO may never open."""
    try:
        st = os.stat(path)
    except OSError as e:
        raise OSError("%s '%s': %s" % (what, shown(path), e.strerror)) from None
    if stat.S_ISDIR(st.st_mode):
        raise OSError("%s '%s': is a folder, not a file" % (what, shown(path)))
    if not stat.S_ISREG(st.st_mode):
        raise OSError("%s '%s': is a %s, not a regular file" % (what, shown(path), _kind(st.st_mode)))


def read_text(path, what="input"):
    """The UTF-8 text of the regular file PATH; OSError or ValueError naming WHAT and PATH."""
    input_file(path, what)
    with open(path, "rb") as f:
        data = f.read()
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as e:
        raise ValueError("%s '%s': not UTF-8 text (byte %d)" % (what, shown(path), e.start)) from None


def out_folder(option, path, inputs=()):
    """Checks the folder PATH a command writes into (made if it does not exist) before anything is
    made: OutputError naming OPTION when PATH is empty, or exists and is not a folder (naming
    the input of INPUTS, (option, path) pairs, that it is)."""
    if not path:
        raise OutputError("%s: an empty value (name a folder)" % option)
    if os.path.exists(path) and not os.path.isdir(path):
        key = _identity(path)
        for what, input_path in inputs:
            if key is not None and _identity(input_path) == key:
                raise OutputError("%s '%s': is the %s file %s, an input, not a folder"
                                  % (option, shown(path), what, shown(input_path)))
        raise OutputError("%s '%s': is a file, not a folder" % (option, shown(path)))
    if not os.path.exists(path):  # to be made: refused now if it cannot be, not at the mkdir
        above = os.path.abspath(path)
        while not os.path.exists(above) and above != os.path.dirname(above):
            if os.path.lexists(above):
                raise OutputError("%s '%s': '%s' is a link that names no folder (its target is missing, or the "
                                  "links loop)" % (option, shown(path), shown(above)))
            above = os.path.dirname(above)
        if not os.path.isdir(above):
            raise OutputError("%s '%s': cannot be made: '%s' is a file, not a folder"
                              % (option, shown(path), shown(above)))
    return os.path.abspath(path)


class _Stdout(_Named):
    """Standard output whose failed writes raise `standard output: cannot write: REASON`; after
    one, further output goes to /dev/null, so that the exit flush adds no second report."""

    def __init__(self, f):
        super().__init__(f, "standard output")

    def _failed(self, e):
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, self._f.fileno())
        os.close(devnull)
        return _cannot_write(self._shown, e)


def named_stdout():
    """Makes sys.stdout report a failed write (a full disk, a closed pipe, a closed descriptor)
    as an OSError `standard output: cannot write: REASON`; call finish_stdout() before the exit
    status is chosen so that a failure at the last flush is reported too."""
    import sys
    if sys.stdout is None:  # started with standard output closed (>&-): refused before anything is made
        import errno
        raise WriteError("standard output: cannot write: %s" % os.strerror(errno.EBADF))
    if not isinstance(sys.stdout, _Stdout):
        sys.stdout = _Stdout(sys.stdout)


def finish_stdout():
    import sys
    sys.stdout.flush()


def machine_file_inputs(path):
    """(key, path) of every value of the machine file PATH (torusrt-sim --config) that names an
    existing regular file (timing, map-file, ...), a relative one taken from the machine file's
    folder as torusrt-sim takes it. A file this reader cannot read as TOML gives every quoted
    string in it that names a file: a reader that parses less than torusrt-sim must not hide an
    input from the checks (torusrt-sim names the file's own errors)."""
    import re
    from report.machine_file import read_machine_file
    try:
        text = read_text(path, "--config")
    except (OSError, ValueError):
        return []
    try:
        values = read_machine_file(text, path)
    except ValueError:
        values = {"value %d" % i: v for i, v in enumerate(
            v for q in re.findall(r'"((?:[^"\\\n]|\\.)*)"|\'([^\'\n]*)\'', text) for v in q if v)}
    folder = os.path.dirname(os.path.abspath(path))
    found = []
    for key, value in values.items():
        named = os.path.join(folder, value) if value else ""
        if named and _identity(named) is not None:
            found.append(("--config %s's %s" % (path, key), named))
    return found


def named_files(words):
    """(option, path) of each word of a command line that names an existing regular file, the
    option being the word before it (or OPTION of OPTION=PATH; "the argument" for a word after
    no option), and of every file a --config machine file names: the inputs a command's outputs
    are checked against, and what makes a sweep point besides its command line."""
    found = []
    for i, word in enumerate(words):
        option, eq, value = word.partition("=")
        if word.startswith("--") and eq and _identity(value) is not None:
            found.append((option, value))
        elif _identity(word) is not None:
            before = words[i - 1] if i > 0 else ""
            option, value = (before if before.startswith("-") else "argument"), word
            found.append((option, value))
        else:
            continue
        if option == "--config":
            found += machine_file_inputs(value)
    return found


# The outputs run_point.sh gives each command itself.
POINT_OPTIONS = ("-o", "--output", "--stats")


def check_point_command(outs, command):
    """OutputError naming the option when COMMAND (run_point.sh's) gives -o or --stats, which
    run_point.sh gives it, or an output option naming one of OUTS (the point's JSON, image, log
    and series): the run would write over the point's own files."""
    mine = {os.path.realpath(path): path for path in outs}
    unusable = unusable_option(command)
    if unusable:
        raise OutputError("%s in the command: torusrt-sim would print and end without a run, and the point "
                          "would fail" % unusable)
    for option, value in output_values(command):
        value = value or ""
        if option in POINT_OPTIONS:
            raise OutputError("%s '%s': run_point.sh gives each point's -o and --stats itself "
                              "(OUT.json, OUT.png)" % (option, value))
        real = os.path.realpath(value) if value else ""
        if real in mine:
            raise OutputError("%s '%s': is the point's own file %s, which run_point.sh writes"
                              % (option, value, mine[real]))
        if option == "--vcd" and value:  # and the GTKWave save file torusrt-sim writes beside it
            save = (value[:-4] if value.endswith(".vcd") and len(value) > 4 else value) + ".gtkw"
            if os.path.realpath(save) in mine:
                raise OutputError("--vcd '%s': its GTKWave save file %s is the point's own file %s, which "
                                  "run_point.sh writes" % (value, save, mine[os.path.realpath(save)]))


def check_outputs(argv):
    """`output_files.py --check-outputs OUT... -- COMMAND...`: exit 2, naming both, when an OUT is
    a file COMMAND names (named_files) or the file of another OUT, or when COMMAND's output
    options name an OUT or are run_point.sh's own (check_point_command); 0 otherwise."""
    import sys
    split = argv.index("--") if "--" in argv else len(argv)
    outs = OutputSet()
    for option, path in named_files(argv[split + 1:]):
        outs.add_input(option, path)
    try:
        check_point_command(argv[:split], argv[split + 1:])
        for path in argv[:split]:
            outs.add("output", path)
        outs.check()
    except OutputError as e:
        print("run_point: %s" % e, file=sys.stderr)
        return 2
    return 0


def copy_to_stdout(prog):
    """`output_files.py --stdout PROG`: standard input onto standard output, for the shell tools'
    --help: exit 1 with `PROG: standard output: cannot write: REASON` when it cannot be written."""
    import sys
    try:
        named_stdout()
        sys.stdout.write(sys.stdin.read())
        finish_stdout()
    except OSError as e:
        print("%s: %s" % (prog, e), file=sys.stderr)
        return 1
    return 0


def main(argv):
    """`python3 output_files.py FILE [OPTION]`: standard input into FILE under these rules, for
    the shell scripts (exit 2 when FILE is refused, naming OPTION; 1 when the write fails);
    --check-outputs and --stdout: see check_outputs() and copy_to_stdout();
    `--check-streams PROG [--folders DIR...] [--own FILE...] -- WORDS...`: see check_streams()
    (exit 2 or 0); `--check-places`: see output_places.check_places()."""
    import sys
    if argv[:1] == ["--check-outputs"]:
        return check_outputs(argv[1:])
    if argv[:1] == ["--check-streams"] and len(argv) >= 3 and "--" in argv[2:]:
        from stream_checks import check_streams
        split = argv.index("--", 2)
        extra, kind = {"--folders": [], "--own": []}, None
        for word in argv[2:split]:
            if word in extra:
                kind = word
            elif kind is not None:
                extra[kind].append(word)
        check_streams(argv[1], argv[split + 1:], extra["--folders"], extra["--own"])
        return 0
    if argv[:1] == ["--check-places"] and len(argv) >= 3:
        from output_places import check_places
        return check_places(argv[1], argv[2], argv[3:])
    if argv[:1] == ["--stdout"] and len(argv) == 2:
        return copy_to_stdout(argv[1])
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

