"""A reproduction sweep's results folder: the four CSVs and the facts of the run."""
import csv
import json
import os

from output_files import atomic, input_file

from .csvdata import Table

FIGURES = ("fig5_6", "fig7", "fig8", "fig10_12")
FACTS_FILE = "run_facts.csv"
# The readings a sweep runs (experiments/lib.sh READINGS), the default first: each has its
# results folder RESULTS/READING.
PROFILES = ("fitted", "calibrated", "literal", "round-one")


def profile_results(res):
    """Results of each profile folder of the sweep's results folder present, default first."""
    found = [Results(os.path.join(res, p)) for p in PROFILES if os.path.isdir(os.path.join(res, p))]
    if not found:
        raise FileNotFoundError("%s has none of the profile folders %s" % (res, ", ".join(PROFILES)))
    return found


def _own_or_parent(res, name):
    """RES/NAME, else the sweep's RES/../NAME (a profile's folder inside the results folder)."""
    own = os.path.join(res, name)
    return own if os.path.exists(own) else os.path.join(os.path.dirname(res), name)


class Facts:
    """What the CSVs do not hold: image size, cells, hand-over cost, the reading's timing profile,
    image 1 scene file and load-balancing mapping, one-processor runs, the joblog. Read from
    run_facts.csv, which the collection step writes (save_facts) from the very points the figure
    CSVs are made from: a point JSON that lies in the folder without being one of them (a stale
    one of an earlier sweep) changes neither."""

    KEYS = ("image_size", "cells", "hop_us", "t1_runs", "joblog_points", "joblog_span_s", "timing_profile",
            "image1_scene", "lb_map", "cell_step_us", "cell_header_bytes", "list_entry_bytes",
            "object_record_bytes", "image2_scene", "shape16", "route_ties")

    def __init__(self, res):
        values = saved_facts(res)
        self.image_size = values["image_size"] or "?"
        self.cells = int(values["cells"] or 13824)
        self.hop_us = values["hop_us"] or "2180"
        self.t1_runs = int(values["t1_runs"] or 0)
        self.joblog_points = values["joblog_points"]
        self.joblog_span_s = values["joblog_span_s"]
        self.timing_profile = values["timing_profile"] or "?"
        self.image1_scene = values["image1_scene"] or "?"
        self.lb_map = values["lb_map"] or "?"
        self.image2_scene = values["image2_scene"] or "?"
        self.shape16 = values["shape16"] or "4x2x2"  # the arrangement of 16 nodes, flat and clustered
        self.route_ties = values["route_ties"] or "?"
        self.cell_step_us = values["cell_step_us"] or "0"  # a table without the key charged nothing
        # The memory accounting the points ran under (docs/memory.md; a record of 0 is the natural size).
        self.cell_header_bytes = int(values["cell_header_bytes"] or 4)
        self.list_entry_bytes = int(values["list_entry_bytes"] or 4)
        self.object_record_bytes = int(values["object_record_bytes"] or 0)


def saved_facts(res):
    """Every key of Facts.KEYS from RES/run_facts.csv ("" for one it lacks, or no file)."""
    path = os.path.join(res, FACTS_FILE)
    saved = {}
    if os.path.exists(path):
        with open(path, newline="") as f:
            saved = {row["key"]: row["value"] for row in csv.DictReader(f)}
    return {k: saved.get(k, "") for k in Facts.KEYS}


def save_facts(res, points):
    """RES/run_facts.csv from POINTS, the rows of points.tsv the figure CSVs are made from (their
    one-processor runs, fig "t1", and load-balancing points, fig5_6 mapping cyclic, whose JSON is
    there), and the sweep's joblog; a fact they do not give keeps its saved value. Nothing is
    written when they give none."""
    found = _from_points(res, points)
    if not found:
        return
    values = saved_facts(res)
    values.update(found)
    with atomic(os.path.join(res, FACTS_FILE), newline="") as f:
        out = csv.writer(f, lineterminator="\n")
        out.writerow(["key", "value"])
        out.writerows((k, values[k]) for k in Facts.KEYS)


def _reports(points, fig, **match):
    """The JSON paths of POINTS of FIG (and the MATCH columns) that hold a report, sorted."""
    return sorted(p["json"] for p in points
                  if p["fig"] == fig and all(p[k] == v for k, v in match.items())
                  and os.path.exists(p["json"]) and os.path.getsize(p["json"]) > 0)


def _from_points(res, points):
    found = {}
    t1 = _reports(points, "t1")
    if t1:
        with open(t1[0]) as f:
            report = json.load(f)
        found["image_size"] = "%dx%d" % (report["width"], report["height"])
        cells = report["cells"]
        found["cells"] = str(cells[0] * cells[1] * cells[2])
        timing = report["config"]["timing"]
        hand_over = ("handover_send", "handover_receive") if "handover_send" in timing else (
            "packet_creation", "packet_analysis")
        found["hop_us"] = "%g" % sum(timing[k] for k in hand_over)
        found["cell_step_us"] = "%g" % timing.get("cell_step_packet", 0)
        found["t1_runs"] = str(len(t1))
        found["timing_profile"] = report["config"]["timing_profile"]
    for path in t1:
        name = os.path.basename(path)
        if name in ("image1.json", "image2.json"):
            with open(path) as f:
                found[name[:-5] + "_scene"] = os.path.basename(json.load(f)["scene"])
    lb = _reports(points, "fig5_6", mapping="cyclic")
    if lb:
        with open(lb[0]) as f:
            options = json.load(f).get("config", {}).get("options", {})
        if "map" in options:
            found["lb_map"] = options["map"]
        for key in ("cell_header_bytes", "list_entry_bytes", "object_record_bytes", "route_ties"):
            if key.replace("_", "-") in options:
                found[key] = options[key.replace("_", "-")]
    n16 = _reports(points, "fig5_6", mapping="cyclic", n="16")
    if n16:
        with open(n16[0]) as f:
            found["shape16"] = json.load(f).get("config", {}).get("options", {}).get("ips", "")
    joblog = _own_or_parent(res, "joblog")
    if os.path.exists(joblog) and os.path.getsize(joblog) > 0:
        with open(joblog, newline="") as f:
            rows = list(csv.DictReader(f, delimiter="\t"))
        if rows:
            starts = [float(row["Starttime"]) for row in rows]
            ends = [float(row["Starttime"]) + float(row["JobRuntime"]) for row in rows]
            found["joblog_points"] = str(len(rows))
            found["joblog_span_s"] = "%.1f" % (max(ends) - min(starts))
    return found


class Results:
    """The tables of one sweep and what the claims need to know about them."""

    def __init__(self, res):
        self.dir = res
        self.profile = os.path.basename(res)
        for name in FIGURES:
            path = os.path.join(res, name + ".csv")
            if os.path.exists(path):
                input_file(path, "figure table")  # a FIFO or a device: refused naming it
            if not os.path.exists(path) or os.path.getsize(path) == 0:
                raise FileNotFoundError("%s missing (run the sweep's collect step first)" % path)
        self.f56, self.f7, self.f8, self.f10 = (Table.load(os.path.join(res, n + ".csv")) for n in FIGURES)
        self.facts = Facts(res)
        self.runs = self._runs()
        self.scenes = self.f56.distinct("scene")
        self.cscenes = self.f10.distinct("scene")
        self.nmax = max((int(row["n"]) for row in self.f56.where()), default=0)
        mode_file = os.path.join(res, "mode")
        if os.path.exists(mode_file):
            with open(mode_file) as f:
                self.mode = f.read().strip()
        else:
            self.mode = self.runs.get("mode", "unknown")

    def _runs(self):
        """The row of runs.tsv that computed the most points (the latest among equals)."""
        path = _own_or_parent(self.dir, "runs.tsv")
        best = {}
        if os.path.exists(path):
            with open(path, newline="") as f:
                for row in csv.DictReader(f, delimiter="\t"):
                    if not best or int(row["points_run"]) >= int(best["points_run"]):
                        best = row
        return best
