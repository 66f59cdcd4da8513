"""A machine file (torusrt-sim --config) from a JSON report, and the two compared key by key.

The report's config.options holds the machine as torusrt-sim --dump-config writes it: the
option names without dashes and their values as the options take them. A machine file is TOML:
key="value" lines grouped in tables ([network], [timing], [cluster], [mapping]; the report gives
each key's table as config.option_tables), in --dump-config's order, which the report gives as
config.option_order. A file of key="value" lines without tables (flat) reads too.
"""
import json
import re
import subprocess
import tomllib

from stop_signals import run_child


# A machine option's name as a machine file holds it: a TOML bare key (torusrt-sim's option names
# are lower-case words joined by '-'); a table's name too.
OPTION_NAME = re.compile(r"[A-Za-z0-9_-]+")


def from_report(report):
    """The (key, value) pairs of a report's machine, in --dump-config's order (config.option_order;
    keys it does not list after them, in the report's order)."""
    config = report.get("config", {})
    if not isinstance(config, dict):
        raise ValueError("config: %s, not an object" % json.dumps(config))
    options = config.get("options")
    if not isinstance(options, dict):
        raise ValueError("the report has no config.options (written by torusrt-sim 0.1.0 and later)")
    order = report["config"].get("option_order", [])
    if not isinstance(order, list) or not all(isinstance(key, str) for key in order):
        raise ValueError("config.option_order: %s, not a list of option names" % json.dumps(order)[:80])
    rank = {key: i for i, key in enumerate(order)}
    keys = sorted(options, key=lambda k: rank.get(k, len(order)))
    for key in keys:  # torusrt-sim writes every value as a string, every key in option_order
        if not OPTION_NAME.fullmatch(key):
            raise ValueError("config.options: %s: not an option name (letters, digits, '-' and '_'), "
                             "which a machine file cannot hold as a key" % json.dumps(key))
        if order and key not in rank:
            raise ValueError("config.options.%s: not a machine option (not in config.option_order)" % key)
        if not isinstance(options[key], str):
            raise ValueError("config.options.%s: %s, not a value torusrt-sim writes (a string)"
                             % (key, json.dumps(options[key])))
        try:
            options[key].encode()
        except UnicodeEncodeError:  # "\ud800" in the JSON: a lone surrogate, no text a file can hold
            raise ValueError("config.options.%s: %s holds a lone surrogate, not text a machine file can hold"
                             % (key, json.dumps(options[key])[:200])) from None
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


def tables_from_report(report):
    """{key: table} of a report's machine (config.option_tables); {} for a report without it."""
    config = report.get("config", {})
    if not isinstance(config, dict):
        raise ValueError("config: %s, not an object" % json.dumps(config))
    tables = config.get("option_tables", {})
    if not isinstance(tables, dict) or not all(isinstance(t, str) for t in tables.values()):
        raise ValueError("config.option_tables: not an object of table names")
    for key, table in tables.items():
        if not OPTION_NAME.fullmatch(table):
            raise ValueError("config.option_tables.%s: %s: not a table name (letters, digits, '-' and '_')"
                             % (key, json.dumps(table)))
    return tables


def unknown_bytes(pairs):
    """ValueError naming the first key whose value holds U+FFFD: the report writes it for a byte
    of the run's value that is not UTF-8, so the value the run was given cannot be known, and a
    machine file may hold UTF-8 only (torusrt-sim --dump-config refuses such a value alike)."""
    for key, value in pairs:
        if "\ufffd" in value:
            raise ValueError("config.options.%s: %s holds U+FFFD, which the report writes for a byte that is not "
                             "UTF-8: the run's value is not known, and a machine file holds UTF-8 only"
                             % (key, json.dumps(value)[:200]))


def toml_text(pairs, tables=None):
    """The machine file as --dump-config writes it: each key's [table] (TABLES: {key: table}),
    the tables in the order of their first key, a blank line between them; without TABLES,
    key="value" lines without tables."""
    if not tables:
        return "".join("%s=%s\n" % (key, toml_string(value)) for key, value in pairs)
    for key, _ in pairs:
        if key not in tables:
            raise ValueError("%s: no table for this key (config.option_tables)" % key)
    order = []
    for key, _ in pairs:
        if tables[key] not in order:
            order.append(tables[key])
    out = []
    for table in order:
        out.append(("\n" if out else "") + "[%s]\n" % table)
        out += ["%s=%s\n" % (key, toml_string(value)) for key, value in pairs if tables[key] == table]
    return "".join(out)


def tables_from_dump(text):
    """{key: table} of a grouped machine file, e.g. `torusrt-sim --dump-config`'s."""
    return {key: table for table, values in tomllib.loads(text).items() if isinstance(values, dict)
            for key in values}


def option_tables(sim):
    """{key: table} of every machine option, from `SIM --dump-config` (torusrt-sim's option table)."""
    done = run_child([sim, "--dump-config"], stdin=subprocess.DEVNULL, capture_output=True, text=True,
                     errors="replace")
    if done.returncode != 0:
        raise ValueError("%s --dump-config: exit %d: %s" % (sim, done.returncode, done.stderr.strip()))
    return tables_from_dump(done.stdout)


def key_position(text, table, key):
    """(line, column) of KEY's line in TABLE ("" for the top) of TEXT, as far as a plain scan of
    its `[table]`, `key =` and `table.key =` lines finds it; (0, 0) if it does not."""
    quoted = r"""(%s|"%s"|'%s')""" % ((re.escape(key),) * 3)
    in_table = re.compile(quoted + r"\s*=")
    dotted = re.compile(re.escape(table) + r"\s*\.\s*" + quoted + r"\s*=")
    current = ""
    for number, line in enumerate(text.splitlines(), 1):
        stripped = line.strip()
        header = re.match(r"\[\s*([A-Za-z0-9_-]+)\s*\]\s*(#.*)?$", stripped)
        if header:
            current = header.group(1)
        elif (current == table and in_table.match(stripped)) or (table and not current and dotted.match(stripped)):
            return number, len(line) - len(line.lstrip()) + 1
    return 0, 0


def scalar_text(value, text, table, key, name):
    """A value as torusrt-sim hands it to the option: a string as it is, a boolean as true or
    false, a number as its source text (torusrt-sim's number parser judges it: 0x10 is refused)."""
    if isinstance(value, str):
        return value
    line, column = key_position(text, table, key)
    where = "%s:%d:%d" % (name, line, column) if line else name
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)) and line:
        raw = text.splitlines()[line - 1].split("=", 1)[1]
        return re.split(r"[\s#]", raw.strip(), maxsplit=1)[0]
    kind = "a table" if isinstance(value, dict) else "an array" if isinstance(value, list) else "not a string"
    raise ValueError("%s: %s: %s; a machine option takes one value, e.g. %s=\"...\"" % (where, key, kind, key))


def read_machine_file(text, name="machine file"):
    """{key: value} of a machine file, flat or in tables; TOML's errors name the line and column,
    and so does a key given twice (once at the top and once in a table). A byte-order mark at the
    start is skipped, as torusrt-sim skips it."""
    text = text[1:] if text.startswith("\ufeff") else text
    try:
        doc = tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        at = re.search(r"\(at line (\d+), column (\d+)\)$", str(e))
        what = str(e)[:at.start()].strip() if at else str(e)
        raise ValueError("%s:%s: %s" % (name, "%s:%s" % at.groups() if at else "?", what)) from None
    values, where = {}, {}
    for top, item in doc.items():
        inner = item.items() if isinstance(item, dict) else [(top, item)]
        table = top if isinstance(item, dict) else ""
        for key, value in inner:
            if isinstance(value, dict) and table:
                raise ValueError("%s: [%s.%s]: a machine file's tables hold no tables" % (name, table, key))
            if key in values:
                line, column = key_position(text, table, key)
                first = "in [%s]" % where[key] if where[key] else "at the top"
                raise ValueError("%s:%d:%d: %s given twice (%s and in [%s])" % (name, line, column, key, first, table))
            values[key] = scalar_text(value, text, table, key, name)
            where[key] = table
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
