"""command_words - what the Python tools of experiments/ read in a command line: the output
options of torusrt-sim and torusrt-render among a command's words (-o, --stats=FILE, -oFILE),
the options that make every point fail (--help, --dump-config, an animation's), and the rules
for the tools' own values (an empty value refused, never taken as the default; comma lists).
output_files.py gives these names too.
"""


# The output options of torusrt-sim and torusrt-render: a tool that runs several commands with
# the same fixed options would write each of them into one file from every command.
OUTPUT_OPTIONS = ("-o", "--output", "--stats", "--stats-series", "--vcd", "--write-map", "--load-map",
                  "--frames-csv", "--cost-image")


def _short_output(word):
    """The value of -o in a word of short options (-o, -oFILE, -qoFILE: CLI11 reads -o glued to
    its value, after flags): '' when the value is the next word, None when WORD has no -o."""
    if not word.startswith("-") or word.startswith("--") or len(word) < 2:
        return None
    cluster = word[1:]
    flags = cluster.partition("o")[0]
    if "o" not in cluster or any(c not in "qh" for c in flags):
        return None
    return cluster[len(flags) + 1:]


def output_values(words):
    """(option, file) of each output option among WORDS (OPTION FILE, OPTION=FILE, or -o glued
    to its file as -oFILE), in order; FILE is None when OPTION is the last word."""
    found = []
    for i, word in enumerate(words):
        option, eq, value = word.partition("=")
        glued = _short_output(word)
        if glued is not None:
            option, eq, value = "-o", glued, glued
        elif option not in OUTPUT_OPTIONS or not word.startswith("--"):
            continue
        if eq:
            found.append((option, value))
        else:
            found.append((option, words[i + 1] if i + 1 < len(words) else None))
    return found


def output_options(words):
    """The output options among WORDS (OPTION, OPTION=FILE or -oFILE), in order."""
    return [option for option, _ in output_values(words)]


# Options after which a command runs nothing a point can use: it prints and ends (help, version,
# the machine file), so every point of a sweep or compare-mappings would fail alike.
NO_RUN_OPTIONS = ("--help", "--version", "--dump-config")
# Options that make a run an animation: its -o is a frame pattern and its report per frame, which
# the sweep's and compare-mappings' one image per run cannot hold.
ANIMATION_OPTIONS = ("--frames", "--orbit", "--camera-path", "--motion")


def unusable_option(words, refused=NO_RUN_OPTIONS):
    """The first of REFUSED (or -h, --help's short form, also among other short flags) among
    WORDS as OPTION or OPTION=VALUE; None when there is none."""
    for word in words:
        option = word.partition("=")[0]
        if option in refused and word.startswith("--"):
            return option
        if "--help" in refused and word.startswith("-") and not word.startswith("--"):
            flags = word[1:].partition("o")[0]
            if "h" in flags and all(c in "qh" for c in flags):
                return "-h"
    return None


def nonempty(text):
    """An argparse type: TEXT, refused (exit 2, the option named by argparse) when it is empty,
    as the executables refuse an empty value."""
    if text == "":
        import argparse
        raise argparse.ArgumentTypeError("an empty value")
    return text


def refuse_empty_values(parser):
    """Gives every option and argument of PARSER (and of its subcommands) that takes a value, and
    has no default of its own, nonempty() as its check: an empty value ('') is refused (exit 2,
    the option named), never taken as the default. Options whose default is '' (nothing) keep
    it; a REMAINDER (the fixed options passed on) is the executables' to check."""
    import argparse
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for sub in set(action.choices.values()):
                refuse_empty_values(sub)
            continue
        if action.nargs in (0, argparse.REMAINDER, argparse.PARSER) or action.default == "":
            continue
        if action.type is None:
            action.type = nonempty
        elif action.type is not nonempty:
            action.type = _nonempty_then(action.type)


def refuse_repeated_options(parser):
    """Gives every option of PARSER (and of its subcommands) that stores one value a check that
    it is given once: `--out a --out b` is refused (exit 2, the option named), as the executables
    refuse it (`--output: given 2 times; give it once`), instead of the last one winning."""
    import argparse

    class StoreOnce(argparse._StoreAction):
        def __call__(self, parser, namespace, values, option_string=None):
            given = namespace.__dict__.setdefault("_given_options", set())
            if self.dest in given:
                raise argparse.ArgumentError(self, "given 2 times; give it once")
            given.add(self.dest)
            super().__call__(parser, namespace, values, option_string)

    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for sub in set(action.choices.values()):
                refuse_repeated_options(sub)
        elif type(action) is argparse._StoreAction and action.option_strings:
            action.__class__ = StoreOnce


def help_on_stdout(parser, name=None):
    """Gives PARSER (and its subcommands) a --help that is a write like any other: a text that
    cannot reach standard output (a full disk, a closed pipe, standard output closed) ends the
    tool with `NAME: standard output: cannot write: REASON` (NAME: PARSER's prog), exit 1, where
    argparse would say nothing and exit 0, or print the help on standard error."""
    import argparse
    import os
    import sys
    name = name or parser.prog

    class NamedHelp(argparse._HelpAction):
        def __call__(self, parser, namespace, values, option_string=None):
            data = parser.format_help().encode(errors="surrogateescape")
            try:
                if sys.stdout is None:  # started with standard output closed (>&-)
                    raise OSError(9, os.strerror(9))
                sys.stdout.flush()
                while data:
                    data = data[os.write(1, data):]
            except OSError as e:
                try:
                    os.write(2, ("%s: standard output: cannot write: %s\n" % (name, e.strerror)).encode(
                        errors="surrogateescape"))
                except OSError:
                    pass
                parser.exit(1)
            parser.exit(0)

    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for sub in set(action.choices.values()):
                help_on_stdout(sub, name)
        elif type(action) is argparse._HelpAction:
            action.__class__ = NamedHelp


def _nonempty_then(convert):
    """An argparse type: nonempty(), then CONVERT; named as CONVERT for argparse's messages."""
    def check(text):
        return convert(nonempty(text))
    check.__name__ = getattr(convert, "__name__", "value")
    return check


def list_values(option, text, given=None):
    """The comma-separated values of OPTION's TEXT ('block,cyclic'); ValueError naming OPTION and
    what was GIVEN (default TEXT) when TEXT is empty, a value is empty (',,' or a trailing comma)
    or has blanks around it ('block, cyclic'), or a value is given twice."""
    from output_files import shown
    what = "%s '%s'" % (option, shown(text if given is None else given))
    items = text.split(",")
    if "" in items:
        raise ValueError("%s: an empty value (value %d); write each value once, between commas"
                         % (what, items.index("") + 1))
    for i, item in enumerate(items):
        if item != item.strip():  # ' cyclic' would reach the run as a value with a blank in it
            raise ValueError("%s: '%s' has blanks around it (value %d); write the values between commas, "
                             "without blanks" % (what, shown(item), i + 1))
        if item in items[:i]:
            raise ValueError("%s: '%s' is given twice; write each value once" % (what, shown(item)))
    return items
