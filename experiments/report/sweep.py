"""The generic sweep (experiments/sweep): the points of a cartesian product over torusrt-sim
options, and after the runs one CSV row per point and a plot (experiments/plots/sweep.gp)."""
import csv
import hashlib
import io
import itertools
import json
import math
import os
import re
import shlex
import subprocess
import sys

import decimal_number
from output_files import (ANIMATION_OPTIONS, NO_RUN_OPTIONS, OUTPUT_OPTIONS, OutputSet, atomic, list_values,
                          named_files, output_options, read_text, unusable_option, write_lines, write_text)
from stop_signals import run_child

from .plots import gnuplot, write_dat

DEFAULT_COLUMNS = ["sim_time_s", "efficiency_t1", "efficiency_busy", "packets.created.total",
                   "packets.forwarded", "links.utilisation.mean", "wall_s"]
PLAN = "points.tsv"
FACTS = "sweep-facts.json"  # the scene and fixed options, for the plot's title

# An option's value that means "no bound" (torusrt-sim --help): drawn apart, never at x = 0.
UNBOUNDED = {"queue": ("0", "unbounded"), "memory-budget": ("0", "no limit")}
# The unit of an option's bare number (torusrt-sim --help), for the plot's x label.
OPTION_UNITS = {"queue": "packets per buffer", "link-us": "us per packet", "link-bytes-per-us": "bytes/us",
                "packet-bytes": "bytes", "cluster": "processors per node", "quantum": "s", "cells": "per axis",
                "ips": "nodes", "replicate": "fraction of a node's data", "max-depth": "levels",
                "memory-budget": "bytes"}
# The words for a JSON field on the plot's y axis (docs/report.md); other fields by their name,
# with the unit their name ends in.
FIELD_LABELS = {"sim_time_s": "image time (s, simulated)", "wall_s": "wall time (s)",
                "efficiency_t1": "efficiency T(1)/(n T(n))", "efficiency_busy": "load balance busy/(n T(n))",
                "t1_s": "T(1) (s, simulated)", "packets.created.total": "packets created",
                "packets.forwarded": "packets handed between nodes",
                "links.utilisation.mean": "mean link utilisation (fraction of the time)",
                "links.utilisation.max": "busiest link's utilisation (fraction of the time)"}
UNIT_SUFFIXES = (("_us", "us"), ("_s", "s"), ("_bytes", "bytes"))


def parse_axis(text):
    """'ips=1,2,4x2x2' -> ('ips', ['1', '2', '4x2x2'])."""
    name, sep, values = text.partition("=")
    name = name.lstrip("-")
    if not sep or not re.fullmatch(r"[a-z0-9][a-z0-9-]*", name) or not values:
        raise ValueError("--axis '%s': expected OPTION=v1,v2,... (an option of torusrt-sim without its dashes)" % text)
    items = list_values("--axis", values, text)
    if "--" + name in OUTPUT_OPTIONS:
        raise ValueError("--axis '%s': --%s is an output; the sweep writes each point's files itself" % (text, name))
    if "--" + name in NO_RUN_OPTIONS + ANIMATION_OPTIONS:
        raise ValueError("--axis '%s': %s" % (text, UNSWEPT % ("--" + name)))
    return name, items


def point_name(names, values):
    return "-".join("%s_%s" % (n, re.sub(r"[^A-Za-z0-9.]+", "_", v)) for n, v in zip(names, values))


def dry_run(sim, scene, names, values, fixed):
    """Checks the first point's command line with torusrt-sim --dump-config (nothing is run), so
    that a misspelt axis or fixed option stops the sweep before any point runs."""
    args = [sim, scene, "--dump-config"] + list(fixed)
    for n, v in zip(names, values):
        args += ["--" + n, v]
    # a name's bytes that are not UTF-8 kept as they came (the message shows them as \xNN)
    done = run_child(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                     errors="surrogateescape")
    if done.returncode != 0:
        raise ValueError("the first point's options do not check out (no point was run): %s"
                         % done.stderr.strip())


def without_size(words):
    """WORDS without their --size option (--size WxH or --size=WxH)."""
    out, skip = [], False
    for word in words:
        if skip:
            skip = False
        elif word == "--size":
            skip = True
        elif not word.startswith("--size="):
            out.append(word)
    return out


def check_fields(sim, scene, names, combos, fixed, columns, y):
    """Checks the fields of --columns and --y against the reports of the points run at 1x1
    pixels, one point after the other until each field is found, so that a misspelt field stops
    the sweep before any point runs (nothing to run for the default columns, in every report)."""
    if y == "status":  # the CSV's own column: ok, deadlock or failed
        raise ValueError("--y status: the points' status is text, not a number to plot")
    wanted = [] if columns == ["all"] else [c for c in columns if c not in DEFAULT_COLUMNS]
    wanted += [y] if y not in DEFAULT_COLUMNS + wanted else []
    if not wanted:
        return
    import tempfile
    with tempfile.TemporaryDirectory(prefix="sweep-fields.") as work:
        stats = os.path.join(work, "r.json")
        for values in combos:
            args = [sim, scene, "-q", "-o", os.path.join(work, "r.png"), "--stats", stats]
            args += without_size(list(fixed))
            for n, v in zip(names, values):
                args += ["--" + n, v] if n != "size" else []
            done = run_child(args + ["--size", "1x1"], stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                             stderr=subprocess.PIPE, text=True, errors="surrogateescape")
            if done.returncode == 0:
                fields = flatten(read_report(stats))
                if y in wanted and y in fields and not is_number(fields[y]):
                    raise ValueError("--y %s: %s in the points' reports, not a number to plot"
                                     % (y, json.dumps(fields[y])[:40]))
                wanted = [c for c in wanted if c not in fields]
            if not wanted:
                return
    raise ValueError("no such JSON field in the points' reports (each point run at 1x1 pixels, no point of the "
                     "sweep was run): %s (scalars by dotted name, e.g. links.utilisation.mean)" % ", ".join(wanted))


def is_number(value):
    """A JSON number (true and false are not)."""
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def file_hash(path, cache):
    """The SHA-256 of a file's content (once per file and sweep)."""
    if path not in cache:
        digest = hashlib.sha256()
        with open(path, "rb") as f:
            for chunk in iter(lambda: f.read(1 << 20), b""):
                digest.update(chunk)
        cache[path] = digest.hexdigest()
    return cache[path]


def identity(sim, args, cache):
    """What makes a point: the executable's and every input file's content (the scene, and any
    argument naming a file) and the whole command line but its output files, the executable's
    path included, as the backend's record holds it (so that a point the sweep counts as done is
    one the backend does not run again). Two points with the same identity report the same
    figures."""
    made = {"executable": file_hash(sim, cache), "command": [sim] + list(args),
            "inputs": [[option, file_hash(path, cache)] for option, path in named_files(args)]}
    return hashlib.sha256(json.dumps(made, sort_keys=True).encode()).hexdigest()


REPORT_KEYS = {"status": str, "sim_time_s": (int, float), "config": dict}


def _refuse_constant(name):
    raise ValueError("%s is not a number a report holds" % name)


def _not_finite(value):
    """The first number of a JSON value that is not finite (1e999 reads as inf), else None."""
    if isinstance(value, float) and not math.isfinite(value):
        return value
    items = value.values() if isinstance(value, dict) else value if isinstance(value, list) else ()
    for item in items:
        bad = _not_finite(item)
        if bad is not None:
            return bad
    return None


def read_report(path):
    """A point's JSON report; ValueError naming PATH when it is not one (not a regular file, not
    JSON, nested deeper than Python's recursion limit, not an object, a number that is not
    finite, or without the keys every report has)."""
    try:
        return _read_report(path)
    except RecursionError:  # a hand-made file nested thousands deep: no report's shape
        raise ValueError("%s: not a JSON report (nested too deeply)" % path) from None


def _read_report(path):
    try:
        report = json.loads(read_text(path, "point JSON"), parse_constant=_refuse_constant)
    except OSError as e:
        raise ValueError("%s: not a JSON report (%s)" % (path, e))
    except ValueError as e:
        raise ValueError("%s: not a JSON report (%s)" % (path, e))
    if _not_finite(report) is not None:
        raise ValueError("%s: not a JSON report (a number that is not finite: %r)" % (path, _not_finite(report)))
    if not isinstance(report, dict):
        raise ValueError("%s: not a JSON report (a %s, not an object)" % (path, type(report).__name__))
    missing = [k for k, kind in REPORT_KEYS.items()
               if not isinstance(report.get(k), kind) or isinstance(report.get(k), bool)]
    if missing:
        raise ValueError("%s: not a JSON report (no %s)" % (path, ", ".join(missing)))
    return report


# The longest file name a point's NAME makes (its series' temporary, HOST the machine's short
# name, then a process number of up to 7 digits), and the file systems' limit on one name.
LONGEST_SUFFIX = ".series.csv.tmp.%s.4194304"
NAME_MAX = 255


def _host():
    """The short host name the point's shell puts in its temporaries' names (hostname -s)."""
    import socket
    return socket.gethostname().split(".")[0] or "host"


def point_files(out, name):
    """The files of one point: its JSON report, image, log and identity."""
    base = os.path.join(out, "points", name)
    files = {ext: base + "." + ext for ext in ("json", "png", "log", "id")}
    files["series"] = base + ".series.csv"  # with --stats-interval
    return files


def is_done(files, ident, series=False):
    """True when the point's JSON is a report made by this identity and, unless it deadlocked
    (a deadlock writes only the JSON), its image (and its series, with SERIES) is there; a JSON
    that is not a report, was made by another executable, scene, input or command line, or lost
    its image or series, is removed (with a message) so that the point runs again."""
    if not os.path.exists(files["json"]):
        return False
    why = None
    try:
        report = read_report(files["json"])
        with open(files["id"]) as f:
            made = f.read().split()
        kept = [files["png"]] + ([files["series"]] if series else [])
        gone = [path for path in kept if not os.path.exists(path)] if report["status"] != "deadlock" else []
        if made[:1] != [ident]:
            why = "%s: made by another executable, scene, input file or command line" % files["json"]
        elif made[1:] != [file_hash(files["json"], {})]:
            why = "%s: not the JSON its run wrote (changed since)" % files["json"]
        elif gone:
            why = "%s: its run's %s is gone" % (files["json"], gone[0])
    except FileNotFoundError:
        why = "%s: made by another command (no identity file %s)" % (files["json"], files["id"])
    except ValueError as e:
        why = str(e)
    if why is None:
        return True
    print("sweep: %s; running the point again" % why, file=sys.stderr)
    for ext in ("json", "png", "id"):
        if os.path.lexists(files[ext]):
            os.remove(files[ext])
    return False


def has_series(args):
    """True when a point's command line asks for a time series (--stats-interval)."""
    return any(w.partition("=")[0] == "--stats-interval" for w in args)


# Why an option of NO_RUN_OPTIONS or ANIMATION_OPTIONS cannot be given to every point.
UNSWEPT = ("%s: every point would fail (help, the version and --dump-config print and run nothing; an "
           "animation's -o is a frame pattern, and a sweep point is one image)")


def check_fixed(fixed):
    """ValueError naming the first output option among the fixed options (-o, -oFILE, --stats,
    --stats-series, --vcd, ...): every point would write it into one file; or an option that
    makes every point fail (--help, --version, --dump-config, an animation's)."""
    written = output_options(fixed)
    if written:
        raise ValueError("%s among the fixed options: every point would write it into one file; the sweep "
                         "writes each point's image, JSON and series itself (DIR/points/)" % written[0])
    unusable = unusable_option(fixed, NO_RUN_OPTIONS + ANIMATION_OPTIONS)
    if unusable:
        raise ValueError("%s among the fixed options: %s" % (unusable, UNSWEPT % unusable))


def plan(out, sim, scene, axes, fixed, listing, columns=(), y=DEFAULT_COLUMNS[0]):
    """Writes OUT/points.tsv (name and axis values per point) and the point list LISTING
    (experiments/backend): the point's JSON, a tab and its shell command line. A point is done
    when its JSON is a report and its identity file (NAME.id) holds this command's identity()
    for it; any other point is listed and runs. A deadlocked point (exit 3) keeps its JSON
    (status deadlock); a failed one leaves none. Every output is checked first (output_files)."""
    names = [n for n, _ in axes]
    combos = list(itertools.product(*(v for _, v in axes)))
    check_fixed(fixed)
    seen = {}
    longest = NAME_MAX - len(LONGEST_SUFFIX % _host())
    for values in combos:
        name = point_name(names, values)
        if len(name.encode()) > longest:
            raise ValueError("--axis: the point %s: its name is %d bytes, and its files' (NAME%s) may have %d at "
                             "most, the file system's %d less the suffix; shorten the axis values (a --config "
                             "machine file's name, say); nothing was written"
                             % (name[:120] + "...", len(name.encode()), LONGEST_SUFFIX % "HOST", longest, NAME_MAX))
        if name in seen:
            raise ValueError("--axis: the points %s and %s have one name, %s (a point's name keeps letters, "
                             "digits and dots of its values); nothing was written"
                             % (",".join(seen[name]), ",".join(values), name))
        seen[name] = values
    outs = OutputSet()
    outs.add_input("scene", scene)
    words = list(fixed) + [w for n, vs in axes for v in vs for w in ("--" + n, v)]
    for option, path in named_files(words):
        outs.add_input(option, path)
    files = [point_files(out, point_name(names, values)) for values in combos]
    points = os.path.join(out, "points")
    if os.path.isdir(out):  # a new folder holds nothing to check, and is made after the checks
        for name in (PLAN, "points.list", "sweep.csv", "sweep.png", FACTS):
            outs.add("--out", os.path.join(out, name))
    outs.add_folder("--out", os.path.join(out, "plot-data"))
    if os.path.isdir(points):
        for f in files:
            for ext in ("json", "png", "log", "id", "series"):
                f[ext] = outs.add("--out", f[ext])
    outs.check()
    dry_run(sim, scene, names, combos[0], fixed)
    check_fields(sim, scene, names, combos, fixed, list(columns), y)
    os.makedirs(points, exist_ok=True)
    write_text(os.path.join(out, FACTS), json.dumps({"scene": scene, "fixed": list(fixed)}) + "\n", "--out")
    cache, rows, lines, done = {}, [["name"] + names], [], 0
    for k, (values, f) in enumerate(zip(combos, files), 1):
        name = point_name(names, values)
        rows.append([name] + list(values))
        args = [scene] + list(fixed)
        for n, v in zip(names, values):
            args += ["--" + n, v]
        ident = identity(sim, args, cache)
        if is_done(f, ident, has_series(args)):
            done += 1
        # The temporaries end in .tmp.HOST.PID ($u, set by the point's shell): two sweeps into
        # one --out, or a point run twice at once, never share one.
        u = '"$u"'
        t = shlex.quote(f["json"] + ".tmp") + u
        # A series torusrt-sim would name from --stats gets the point's own name instead (its
        # temporary renamed with the JSON), never one made from the temporary JSON's.
        st, sf = shlex.quote(f["series"] + ".tmp") + u, shlex.quote(f["series"])
        series = " --stats-series " + st if has_series(args) else ""
        run = shlex.join([sim] + args + ["-o", f["png"]]) + " --stats " + t + series + " -q"
        j, i = shlex.quote(f["json"]), shlex.quote(f["id"])
        it = shlex.quote(f["id"] + ".tmp") + u
        keep = "{ [ ! -e %s ] || mv %s %s; } && " % (st, st, sf) if series else ""
        drop = " " + st if series else ""
        progress = "echo >&3 %s" % shlex.quote("sweep: [%d/%d] %s" % (k, len(combos), name))
        lines.append(f["json"] + "\t" +
                     "u=.$(hostname -s 2>/dev/null || echo host).$$; "
                     "{run} >{log} 2>&1; rc=$?; "
                     "if [ $rc -eq 0 ] || {{ [ $rc -eq 3 ] && [ -s {t} ]; }}; then "
                     "echo {ident} $(sha256sum <{t} | cut -d' ' -f1) >{it} && mv {it} {i} && {keep}mv {t} {j}; {p}: "
                     "$([ $rc -eq 0 ] && echo ok || echo deadlock); else rm -f {t}{drop}; {p}: failed; exit $rc; fi".format(
                         j=j, t=t, i=i, it=it, ident=ident, run=run, log=shlex.quote(f["log"]), p=progress,
                         keep=keep, drop=drop))
    table = io.StringIO()
    csv.writer(table, delimiter="\t", lineterminator="\n").writerows(rows)
    write_text(os.path.join(out, PLAN), table.getvalue(), "--out")
    write_lines(listing, lines, "--out")
    return len(combos), done


def flatten(report, prefix=""):
    """Every scalar of a JSON object by dotted name (arrays left out)."""
    out = {}
    for key, value in report.items():
        name = prefix + key
        if isinstance(value, dict):
            out.update(flatten(value, name + "."))
        elif not isinstance(value, list):
            out[name] = value
    return out


def text(value):
    """A CSV cell: numbers with 6 significant digits."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return "%.6g" % value
    return "" if value is None else str(value)


def read_points(out):
    with open(os.path.join(out, PLAN), newline="") as f:
        rows = list(csv.reader(f, delimiter="\t"))
    return rows[0][1:], rows[1:]


def collect(out, columns, y):
    """Writes OUT/sweep.csv and OUT/sweep.png; returns the names of the points that failed."""
    names, points = read_points(out)
    outs = OutputSet()  # neither over the plan nor over a point's files, also through a link
    outs.add_input("points table", os.path.join(out, PLAN))
    for row in points:
        for what, path in point_files(out, row[0]).items():
            outs.add_input("point " + what, path)
    for name in ("sweep.csv", "sweep.png"):
        outs.add("--out", os.path.join(out, name))
    outs.add_folder("--out", os.path.join(out, "plot-data"))
    outs.check()
    flat, failed = [], []
    for row in points:
        path = os.path.join(out, "points", row[0] + ".json")
        try:
            flat.append(flatten(read_report(path)) if os.path.exists(path) else None)
        except ValueError as e:  # a report gone bad after its run: the point failed
            print("sweep: %s" % e, file=sys.stderr)
            flat.append(None)
        if flat[-1] is None:
            failed.append(row[0])
    if columns == ["all"]:
        columns = sorted({k for f in flat if f for k in f} - {"status"})  # the CSV has its own
    elif y not in columns:
        columns = columns + [y]  # the plotted field is in the CSV too
    present = [f for f in flat if f]
    unknown = [c for c in dict.fromkeys(columns + [y]) if present and all(c not in f for f in present)]
    if unknown:
        raise ValueError("no such JSON field in the reports: %s (scalars by dotted name, e.g. links.utilisation.mean)"
                         % ", ".join(unknown))
    with atomic(os.path.join(out, "sweep.csv"), "--out", newline="") as f:
        table = csv.writer(f, lineterminator="\n")
        table.writerow(names + ["status"] + columns)
        for row, report in zip(points, flat):
            status = report.get("status", "ok") if report else "failed"
            table.writerow(row[1:] + [status] + [text((report or {}).get(c)) for c in columns])
    if any(flat):
        plot(out, names, points, flat, y, read_facts(out))
    return failed


def read_facts(out):
    """The scene and fixed options plan() kept ({} for a folder without them)."""
    try:
        with open(os.path.join(out, FACTS)) as f:
            return json.load(f)
    except (OSError, ValueError):
        return {}


def option_label(name):
    """The x label: the option and the unit of its values."""
    unit = OPTION_UNITS.get(name)
    return "--%s (%s)" % (name, unit) if unit else "--" + name


def field_label(field):
    """The y label: the field in words, with its unit."""
    if field in FIELD_LABELS:
        return FIELD_LABELS[field]
    for suffix, unit in UNIT_SUFFIXES:
        if field.endswith(suffix):
            return "%s (%s)" % (field, unit)
    return field


def plot_title(facts, y, x):
    """The scene and the fixed options (those every point shares), then what is drawn."""
    scene = os.path.basename(facts.get("scene", "")) or "?"
    fixed = " ".join(facts.get("fixed", []))
    return "%s%s: %s against --%s" % (scene, ", " + fixed if fixed else "", FIELD_LABELS.get(y, y), x)


def tics(values, free, free_x, free_label):
    """gnuplot's tick list: each value of the axis at itself, and the unbounded one at free_x."""
    marks = ['"%s" %s' % (v, v) for v in values] + (['"%s" %r' % (free_label, free_x)] if free else [])
    return "(%s)" % ", ".join(marks)


def spans_decade(values):
    """Positive values whose largest is more than 10 times the smallest: a log axis."""
    return bool(values) and min(values) > 0 and max(values) > 10 * min(values)


def numeric(values):
    """Whether every value is a number of the executables' strict syntax (decimal_number): `1_0`,
    `inf`, `nan` or a digit of another script are named values, one tick each, never numbers
    gnuplot would be given bare."""
    return all(not decimal_number.fault(v) for v in values)


def plot(out, names, points, flat, y, facts):
    """OUT/sweep.png: the first axis on x, one line per combination of the other axes. A value
    that means "no bound" (--queue 0) is drawn apart, right of the others and not joined to them;
    an axis whose positive values span more than 10x is logarithmic."""
    dat = os.path.join(out, "plot-data")
    os.makedirs(dat, exist_ok=True)
    xs = list(dict.fromkeys(row[1] for row in points))
    free, free_label = UNBOUNDED.get(names[0], (None, None))
    bounded = [x for x in xs if x != free]
    is_numeric = numeric(bounded)
    if not is_numeric:  # named values: one tick each, in order, the unbounded one among them
        free, bounded = None, xs
    logx = is_numeric and spans_decade([float(x) for x in bounded])
    # where the unbounded value is drawn: a step beyond the largest value
    if is_numeric and free in xs:
        top = max([float(x) for x in bounded] or [1.0])
        free_x = top * 4 if logx else top + max(1.0, (top - min([float(x) for x in bounded] or [0.0])) / 4)
    else:
        free_x = 0
    series, apart = {}, {}
    for row, report in zip(points, flat):
        if report and report.get(y) is not None:
            combo, x = tuple(row[2:]), row[1]
            if x == free:
                apart[combo] = (xs.index(x), free_x, report[y])
            else:
                series.setdefault(combo, []).append((xs.index(x), x, report[y]))
    ys = [v for rows in series.values() for _, _, v in rows] + [v for _, _, v in apart.values()]
    titles, apart_rows = [], []
    for i, combo in enumerate(sorted(set(series) | set(apart)), 1):
        write_dat(os.path.join(dat, "series-%d.dat" % i), series.get(combo, []))
        if combo in apart:
            apart_rows.append((i,) + apart[combo][1:])
        titles.append(",".join("%s=%s" % (n, v) for n, v in zip(names[1:], combo)) or y)
    write_dat(os.path.join(dat, "apart.dat"), apart_rows)  # series number, x, y
    numbers = [v for v in ys if isinstance(v, (int, float)) and not isinstance(v, bool)]
    gnuplot("sweep.gp", {"dat": dat, "out": os.path.join(out, "sweep.png"), "nseries": len(titles),
                         "titles": " ".join(t.replace(" ", "_") for t in titles), "numeric": int(is_numeric),
                         "xlabel": option_label(names[0]), "ylabel": field_label(y),
                         "title": plot_title(facts, y, names[0]).replace("'", ""),
                         "logx": int(logx), "logy": int(spans_decade(numbers) and len(numbers) == len(ys)),
                         "free": int(free in xs), "xtics": tics(bounded, free in xs, free_x, free_label) if is_numeric else "",
                         "ymin0": int(all(isinstance(v, (int, float)) and v >= 0 for v in ys))})


def report_deadlocked(out):
    """Lists the points that deadlocked (status deadlock: their JSON holds the figures)."""
    names, points = read_points(out)
    for row in points:
        path = os.path.join(out, "points", row[0] + ".json")
        try:
            report = read_report(path)
        except (OSError, ValueError):  # missing or not a report: listed as failed
            continue
        if report.get("status") == "deadlock":
            print("sweep: point %s deadlocked at %.6g s simulated (status deadlock in the CSV)"
                  % (row[0], report["sim_time_s"]), file=sys.stderr)


def report_failed(out, failed):
    for name in failed:
        log = os.path.join(out, "points", name + ".log")
        tail = ""
        if os.path.exists(log):
            with open(log) as f:
                lines = f.read().strip().splitlines()
            tail = lines[0] if lines else ""
        print("sweep: FAILED point %s: %s (log %s)" % (name, tail, log), file=sys.stderr)
