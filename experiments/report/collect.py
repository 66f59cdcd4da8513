"""The collection step of the reproduction sweep: the points' JSON reports (listed in
RESULTS/points.tsv by experiments/points.sh) into one CSV per figure, by field name.

A point without a JSON is still a row, with status "failed" (its .log exists) or "missing" and
empty figures: nothing is dropped silently. Every image is compared byte for byte with the
one-processor image of its scene (image_identical)."""
import csv
import io
import json
import os

from output_files import OutputSet, atomic, read_text

from . import paper
from .results import FACTS_FILE, save_facts

POINT_COLUMNS = ["fig", "name", "scene", "mapping", "n", "torus", "m", "data", "json"]

# JSON fields of a point by name: (our name, path, ...alternatives).
FIELDS = {
    "sim_time_s": ["sim_time_s"], "t1_s": ["t1_s"], "efficiency": ["efficiency", "efficiency_t1"],
    "load_balance": ["load_balance", "efficiency_busy"], "timing_profile": ["config.timing_profile"],
    "max_per_ip_bytes": ["memory.max_per_ip_bytes", "memory.max_per_processor_bytes"],
    "total_bytes": ["memory.total_bytes"], "pixel_partitioned_bytes": ["memory.pixel_partitioned_bytes"],
    "whole_scene_bytes": ["memory.whole_scene_bytes"], "ratio_to_pixel_partitioned": ["memory.ratio_to_pixel_partitioned"],
    "units_serial": ["preprocess.units_serial"], "units_parallel": ["preprocess.units_parallel"],
    "packets_created": ["packets.created.total"], "packets_forwarded": ["packets.forwarded"],
    "packets_conserved": ["packets.conserved"], "link_packets": ["links.packets"],
    "link_util_mean": ["links.utilisation.mean"], "bus_util_mean": ["bus.utilisation.mean"],
    "bus_util_max": ["bus.utilisation.max"], "bus_wait_mean_us": ["bus.grant_wait_us.mean"],
    "bus_object_reads": ["bus.object_reads"], "busy_max_s": ["load.busy_s.max"], "busy_mean_s": ["load.busy_s.mean"],
    "wall_s": ["wall_s"], "cell_list_bytes_per_processor": ["memory.shared_cell_list_bytes"],
    "bus_object_bytes": ["bus.object_bytes"], "bus_packet_transfers": ["bus.packet_transfers"],
    "bus_cycle_us": ["config.timing.bus_cycle"], "bus_width_bytes": ["config.timing.bus_width_bytes"],
    "cell_steps": ["ops.cell_steps"],
}

CSVS = {
    "fig5_6": ["scene", "mapping", "n", "torus", "timing_profile", "status", "sim_time_s", "t1_s", "speedup", "efficiency",
               "load_balance", "busy_max_s", "busy_mean_s", "packets_created", "packets_forwarded",
               "packets_conserved", "link_packets", "link_util_mean", "image_identical", "wall_s", "cell_steps"],
    "fig7": ["scene", "mapping", "n", "status", "max_per_ip_bytes", "total_bytes", "pixel_partitioned_bytes",
             "whole_scene_bytes", "ratio_to_pixel_partitioned", "pixel_partitioned_over_total"],
    "fig8": ["scene", "n", "status", "units_serial", "units_parallel", "speedup", "paper_units", "paper_speedup"],
    "fig10_12": ["scene", "data", "m", "processors", "torus", "timing_profile", "status", "sim_time_s", "t1_s", "speedup",
                 "efficiency", "load_balance", "max_per_processor_bytes", "total_bytes",
                 "pixel_partitioned_bytes", "ratio_to_pixel_partitioned", "bus_util_mean", "bus_util_max",
                 "bus_wait_mean_us", "bus_object_reads", "image_identical", "wall_s", "paper_time_s",
                 "cell_list_bytes_per_processor", "bus_object_bytes", "bus_packet_transfers", "bus_cycle_us",
                 "bus_width_bytes", "packets_forwarded", "cell_steps"],
}


def json_text(value):
    """A JSON value as jq -r prints it (numbers shortest, integral ones without a point)."""
    if value is None:
        return ""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float) and value.is_integer() and abs(value) < 1e17:
        return str(int(value))
    return str(value)


def number_text(x):
    """A computed number as awk prints it: integral values whole, others with %.6g."""
    if x == int(x) and abs(x) < 1e16:
        return str(int(x))
    return "%.6g" % x


def lookup(report, path):
    value = report
    for key in path.split("."):
        if not isinstance(value, dict) or key not in value:
            return None
        value = value[key]
    return value


def point_row(res, point):
    """The point's fields by name (all empty when it has no report)."""
    row = dict(point, processors=point["n"])  # n: every processor of the run (16 m for clusters)
    path, base = point["json"], os.path.splitext(point["json"])[0]
    # A FIFO or a device is read_text's to refuse, naming it; not a point without a report.
    if os.path.exists(path) and (not os.path.isfile(path) or os.path.getsize(path) > 0):
        try:
            report = json.loads(read_text(path, "point JSON"))
        except ValueError as e:
            raise ValueError("%s: not a JSON report (%s)" % (path, e)) from None
        except RecursionError:  # a hand-made file nested thousands deep
            raise ValueError("%s: not a JSON report (nested too deeply)" % path) from None
        if not isinstance(report, dict):
            raise ValueError("%s: not a JSON report (a %s, not an object)" % (path, type(report).__name__))
        row["status"] = "ok"
        for name, paths in FIELDS.items():
            row[name] = next((json_text(v) for v in (lookup(report, p) for p in paths) if v is not None), "")
        ref = os.path.join(res, "t1", point["scene"] + ".png")
        row["image_identical"] = "yes" if _same_file(ref, base + ".png") else "no"
    else:
        row["status"] = "failed" if os.path.exists(base + ".log") and os.path.getsize(base + ".log") else "missing"
        row.update({name: "" for name in FIELDS}, image_identical="")
    return row


def _same_file(a, b):
    if not os.path.isfile(a) or not os.path.isfile(b):  # a FIFO would never open, a device never end
        return False
    with open(a, "rb") as fa, open(b, "rb") as fb:
        return fa.read() == fb.read()


def derived(row):
    """speedup, the inverse memory ratio and the paper's numbers of one point."""
    ok = row["status"] == "ok"
    t, t1 = row["sim_time_s"], row["t1_s"]
    row["speedup"] = number_text(float(t1) / float(t)) if ok and t and float(t) > 0 else ""
    total, pp = row["total_bytes"], row["pixel_partitioned_bytes"]
    row["pixel_partitioned_over_total"] = number_text(float(pp) / float(total)) if ok and total and float(total) > 0 else ""
    n = int(row["n"])
    units = paper.PREPROCESS_UNITS.get(n) if row["scene"] == "image1" else None
    row["paper_units"] = str(units) if units else ""
    row["paper_speedup"] = number_text(paper.PREPROCESS_UNITS[1] / units) if units else ""
    t_paper = paper.cluster_time(row["scene"], row["data"]) if int(row["m"]) == paper.CLUSTER_M else None
    row["paper_time_s"] = "%g" % t_paper if t_paper else ""
    row["max_per_processor_bytes"] = row["max_per_ip_bytes"]
    return row


def preprocess_row(row):
    """fig8's speed-up is serial over parallel units (not T(1) over T(n))."""
    out = dict(row)
    serial, parallel = row["units_serial"], row["units_parallel"]
    out["speedup"] = (number_text(float(serial) / float(parallel))
                      if row["status"] == "ok" and parallel and float(parallel) > 0 else "")
    return out


def write_csv(path, columns, rows, key):
    with atomic(path, newline="") as f:
        out = csv.writer(f, lineterminator="\n")
        out.writerow(columns)
        for row in sorted(rows, key=key):
            out.writerow([row[c] for c in columns])


def collect(res):
    """Writes RES/fig5_6.csv, fig7.csv, fig8.csv and fig10_12.csv; returns (points, not ok,
    images differing from the one-processor image)."""
    table = os.path.join(res, "points.tsv")
    points = []
    for number, line in enumerate(csv.reader(io.StringIO(read_text(table, "points table"), newline=""),
                                             delimiter="\t"), 1):
        if len(line) < len(POINT_COLUMNS):  # a sweep's table (name, axes) is not the reproduction's
            raise ValueError("%s:%d: %d columns, not the %d or more of the reproduction's point table (%s); "
                             "experiments/sweep's folders are collected by the sweep itself"
                             % (table, number, len(line), len(POINT_COLUMNS), ",".join(POINT_COLUMNS)))
        points.append(dict(zip(POINT_COLUMNS, line)))
    outs = OutputSet()  # no CSV written over points.tsv or a point's report, also through a link
    outs.add_input("points table", table)
    for p in points:
        outs.add_input("point JSON", p["json"])
        outs.add_input("point image", os.path.splitext(p["json"])[0] + ".png")
    for name in ("fig5_6.csv", "fig7.csv", "fig8.csv", "fig10_12.csv", FACTS_FILE):
        outs.add("results", os.path.join(res, name))
    outs.check()
    rows = [derived(point_row(res, p)) for p in points]
    flat = [r for r in rows if r["fig"] == "fig5_6"]
    clusters = [r for r in rows if r["fig"] == "fig10_12"]
    by_map = lambda r: (r["scene"], r["mapping"], float(r["n"]))
    write_csv(os.path.join(res, "fig5_6.csv"), CSVS["fig5_6"], flat, by_map)
    write_csv(os.path.join(res, "fig7.csv"), CSVS["fig7"], flat, by_map)
    write_csv(os.path.join(res, "fig8.csv"), CSVS["fig8"], [preprocess_row(r) for r in flat if r["mapping"] == "block"],
              lambda r: (r["scene"], float(r["n"])))
    write_csv(os.path.join(res, "fig10_12.csv"), CSVS["fig10_12"], clusters,
              lambda r: (r["scene"], r["data"], float(r["m"])))
    save_facts(res, points)  # from these points only, never another JSON lying in RES
    bad = sum(1 for r in rows if r["status"] != "ok")
    differ = sum(1 for r in rows if r["status"] == "ok" and r["image_identical"] != "yes")
    return len(rows), bad, differ
