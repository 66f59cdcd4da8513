"""A machine file (torusrt-sim --config) from a JSON report, and the two compared key by key.

The report's config.options holds the machine as torusrt-sim --dump-config writes it: the
option names without dashes and their values as the options take them. A machine file is
key="value" lines (the subset of TOML that --dump-config writes).
"""


def from_report(report):
    """The (key, value) pairs of a report's machine, in the report's order."""
    options = report.get("config", {}).get("options")
    if not isinstance(options, dict):
        raise ValueError("the report has no config.options (written by torusrt-sim 0.1.0 and later)")
    return [(str(k), str(v)) for k, v in options.items()]


def toml_text(pairs):
    """key="value" lines, as --dump-config writes them."""
    lines = []
    for key, value in pairs:
        quote = "'" if '"' in value else '"'
        lines.append("%s=%s%s%s\n" % (key, quote, value, quote))
    return "".join(lines)


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
        key, sep, value = line.partition("=")
        key, value = key.strip(), value.strip()
        if not sep or len(value) < 2 or value[0] not in "\"'" or value[-1] != value[0]:
            raise ValueError("%s:%d: expected key=\"value\"" % (name, number))
        if key in values:
            raise ValueError("%s:%d: %s given twice" % (name, number, key))
        values[key] = value[1:-1]
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
