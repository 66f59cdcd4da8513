"""The generic sweep (experiments/sweep): the points of a cartesian product over torusrt-sim
options, and after the runs one CSV row per point and a plot (experiments/plots/sweep.gp)."""
import csv
import itertools
import json
import os
import re
import shlex
import subprocess
import sys

from .plots import gnuplot, write_dat

DEFAULT_COLUMNS = ["sim_time_s", "efficiency_t1", "efficiency_busy", "packets.created.total",
                   "packets.forwarded", "links.utilisation.mean", "wall_s"]
PLAN = "points.tsv"


def parse_axis(text):
    """'ips=1,2,4x2x2' -> ('ips', ['1', '2', '4x2x2'])."""
    name, sep, values = text.partition("=")
    name = name.lstrip("-")
    items = [v for v in values.split(",") if v != ""]
    if not sep or not re.fullmatch(r"[a-z0-9][a-z0-9-]*", name) or not items:
        raise ValueError("--axis '%s': expected OPTION=v1,v2,... (an option of torusrt-sim without its dashes)" % text)
    return name, items


def point_name(names, values):
    return "-".join("%s_%s" % (n, re.sub(r"[^A-Za-z0-9.]+", "_", v)) for n, v in zip(names, values))


def dry_run(sim, scene, names, values, fixed):
    """Checks the first point's command line with torusrt-sim --dump-config (nothing is run), so
    that a misspelt axis or fixed option stops the sweep before any point runs."""
    args = [sim, scene, "--dump-config"] + list(fixed)
    for n, v in zip(names, values):
        args += ["--" + n, v]
    done = subprocess.run(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        raise ValueError("the first point's options do not check out (no point was run): %s"
                         % done.stderr.strip())


def plan(out, sim, scene, axes, fixed):
    """Writes OUT/points.tsv (name and axis values per point) and prints the point list
    (experiments/backend): the point's JSON, a tab and its shell command line; a point whose JSON
    exists is skipped, so a re-run resumes. A deadlocked point (exit 3) keeps its JSON (status
    deadlock); a failed one leaves none."""
    names = [n for n, _ in axes]
    combos = list(itertools.product(*(v for _, v in axes)))
    dry_run(sim, scene, names, combos[0], fixed)
    points = os.path.join(out, "points")
    os.makedirs(points, exist_ok=True)
    with open(os.path.join(out, PLAN), "w", newline="") as f:
        table = csv.writer(f, delimiter="\t", lineterminator="\n")
        table.writerow(["name"] + names)
        for k, values in enumerate(combos, 1):
            name = point_name(names, values)
            table.writerow([name] + list(values))
            base = os.path.join(points, name)
            args = [sim, scene, "-o", base + ".png", "--stats", base + ".json.tmp", "-q"] + list(fixed)
            for n, v in zip(names, values):
                args += ["--" + n, v]
            run = " ".join(shlex.quote(a) for a in args)
            j, t = shlex.quote(base + ".json"), shlex.quote(base + ".json.tmp")
            progress = "echo >&3 %s" % shlex.quote("sweep: [%d/%d] %s" % (k, len(combos), name))
            print(base + ".json\t" +
                  "[ -s {j} ] && {p}: done before || {{ {run} >{log} 2>&1; rc=$?; "
                  "if [ $rc -eq 0 ] || {{ [ $rc -eq 3 ] && [ -s {t} ]; }}; then mv {t} {j}; {p}: "
                  "$([ $rc -eq 0 ] && echo ok || echo deadlock); else rm -f {t}; {p}: failed; exit $rc; fi; }}".format(
                      j=j, t=t, run=run, log=shlex.quote(base + ".log"), p=progress))


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
    flat, failed = [], []
    for row in points:
        path = os.path.join(out, "points", row[0] + ".json")
        if os.path.exists(path) and os.path.getsize(path) > 0:
            with open(path) as f:
                flat.append(flatten(json.load(f)))
        else:
            flat.append(None)
            failed.append(row[0])
    if columns == ["all"]:
        columns = sorted({k for f in flat if f for k in f} - {"status"})  # the CSV has its own
    elif y not in columns:
        columns = columns + [y]  # the plotted field is in the CSV too
    present = [f for f in flat if f]
    unknown = [c for c in columns + [y] if present and all(c not in f for f in present)]
    if unknown:
        raise ValueError("no such JSON field in the reports: %s (scalars by dotted name, e.g. links.utilisation.mean)"
                         % ", ".join(unknown))
    with open(os.path.join(out, "sweep.csv.tmp"), "w", newline="") as f:
        table = csv.writer(f, lineterminator="\n")
        table.writerow(names + ["status"] + columns)
        for row, report in zip(points, flat):
            status = report.get("status", "ok") if report else "failed"
            table.writerow(row[1:] + [status] + [text((report or {}).get(c)) for c in columns])
    os.replace(os.path.join(out, "sweep.csv.tmp"), os.path.join(out, "sweep.csv"))
    if any(flat):
        plot(out, names, points, flat, y)
    return failed


def numeric(values):
    try:
        [float(v) for v in values]
        return True
    except ValueError:
        return False


def plot(out, names, points, flat, y):
    """OUT/sweep.png: the first axis on x, one line per combination of the other axes."""
    dat = os.path.join(out, "plot-data")
    os.makedirs(dat, exist_ok=True)
    xs = list(dict.fromkeys(row[1] for row in points))
    is_numeric = numeric(xs)
    series = {}
    for row, report in zip(points, flat):
        if report and report.get(y) is not None:
            series.setdefault(tuple(row[2:]), []).append((xs.index(row[1]), row[1], report[y]))
    ys = [v for rows in series.values() for _, _, v in rows]
    titles = []
    for i, (combo, rows) in enumerate(sorted(series.items()), 1):
        write_dat(os.path.join(dat, "series-%d.dat" % i), rows)
        titles.append(",".join("%s=%s" % (n, v) for n, v in zip(names[1:], combo)) or y)
    gnuplot("sweep.gp", {"dat": dat, "out": os.path.join(out, "sweep.png"), "nseries": len(titles),
                         "titles": " ".join(t.replace(" ", "_") for t in titles), "numeric": int(is_numeric),
                         "xname": names[0], "yname": y,
                         "ymin0": int(all(isinstance(v, (int, float)) and v >= 0 for v in ys))})


def report_deadlocked(out):
    """Lists the points that deadlocked (status deadlock: their JSON holds the figures)."""
    names, points = read_points(out)
    for row in points:
        path = os.path.join(out, "points", row[0] + ".json")
        if os.path.exists(path) and os.path.getsize(path) > 0:
            with open(path) as f:
                report = json.load(f)
            if report.get("status") == "deadlock":
                print("sweep: point %s deadlocked at %.6g s simulated (status deadlock in the CSV)"
                      % (row[0], report["deadlock"]["time_s"]), file=sys.stderr)


def report_failed(out, failed):
    for name in failed:
        log = os.path.join(out, "points", name + ".log")
        tail = ""
        if os.path.exists(log):
            with open(log) as f:
                lines = f.read().strip().splitlines()
            tail = lines[0] if lines else ""
        print("sweep: FAILED point %s: %s (log %s)" % (name, tail, log), file=sys.stderr)
