"""A machine file (torusrt-sim --config) from a JSON report, and the two compared key by key.

The report's config.options holds the machine as torusrt-sim --dump-config writes it: the
option names without dashes and their values as the options take them. A machine file is
key="value" lines (the subset of TOML that --dump-config writes), in --dump-config's order,
which the report gives as config.option_order.
"""
import json
import tomllib


def from_report(report):
    """The (key, value) pairs of a report's machine, in --dump-config's order (config.option_order;
    keys it does not list after them, in the report's order)."""
    options = report.get("config", {}).get("options")
    if not isinstance(options, dict):
        raise ValueError("the report has no config.options (written by torusrt-sim 0.1.0 and later)")
    order = report["config"].get("option_order", [])
    rank = {key: i for i, key in enumerate(order)}
    keys = sorted(options, key=lambda k: rank.get(k, len(order)))
    for key in keys:  # torusrt-sim writes every value as a string, every key in option_order
        if order and key not in rank:
            raise ValueError("config.options.%s: not a machine option (not in config.option_order)" % key)
        if not isinstance(options[key], str):
            raise ValueError("config.options.%s: %s, not a value torusrt-sim writes (a string)"
                             % (key, json.dumps(options[key])))
    return [(str(k), options[k]) for k in keys]


def toml_string(value):
    """A TOML basic string, escaped as --dump-config escapes it."""
    out = []
    for c in value:
        if c in '"\\':
            out.append("\\" + c)
        elif ord(c) < 0x20 or ord(c) == 0x7f:
            out.append("\\u%04X" % ord(c))
        else:
            out.append(c)
    return '"' + "".join(out) + '"'


def toml_text(pairs):
    """key="value" lines, as --dump-config writes them."""
    return "".join("%s=%s\n" % (key, toml_string(value)) for key, value in pairs)


def without_comment(line):
    """The line up to a '#' outside quotes (a path may hold '#'), as torusrt-sim reads it."""
    quote = None
    for i, c in enumerate(line):
        if quote:
            quote = None if c == quote else quote
        elif c in "\"'":
            quote = c
        elif c == "#":
            return line[:i]
    return line


def read_machine_file(text, name="machine file"):
    """{key: value} of key="value" lines; blank lines and # comments are skipped."""
    values = {}
    for number, line in enumerate(text.splitlines(), 1):
        line = without_comment(line).strip()
        if not line:
            continue
        try:  # each line is a TOML document of one key (escapes as TOML has them)
            pair = tomllib.loads(line)
        except tomllib.TOMLDecodeError:
            pair = None
        if not pair or len(pair) != 1 or not isinstance(next(iter(pair.values())), str):
            raise ValueError("%s:%d: expected key=\"value\"" % (name, number))
        key, value = next(iter(pair.items()))
        if key in values:
            raise ValueError("%s:%d: %s given twice" % (name, number, key))
        values[key] = value
    return values


def differences(report_pairs, file_values):
    """Lines naming every key whose value differs, or that only one side has."""
    report_values = dict(report_pairs)
    out = []
    for key in sorted(set(report_values) | set(file_values)):
        a, b = report_values.get(key), file_values.get(key)
        if a != b:
            out.append("%s: report %s, file %s" % (key, "(none)" if a is None else repr(a),
                                                  "(none)" if b is None else repr(b)))
    return out
