"""The mean of five of the fidelity study's validation (docs/fidelity-protocol.md section 3): each
cluster point of the reproduction runs once at every bus_arbitration value, and the point's JSON,
which the collect step reads, is the mean of those runs. Under the round-robin dispatcher one
run's shared / replicated ratio moves by a few per cent with the order packets reach it."""
import json
import os
import shlex
import shutil

from output_files import atomic

MEANED = ("sim_time_s", "efficiency", "load_balance")


def replica(json_path, arbitration):
    """Where the run of a cluster point at one bus_arbitration value goes."""
    d, name = os.path.split(json_path)
    return os.path.join(d, "arb", "%s-a%s.json" % (name[:-len(".json")], arbitration))


def split_lists(phase2, out2, out3, arbitrations):
    """PHASE2's point list (JSON, tab, command) as OUT2, its flat points, and OUT3, every cluster
    point (under fig10_12/) once per arbitration value, --timing-values bus_arbitration=A added."""
    flat, runs = [], []
    with open(phase2) as f:
        for line in f:
            if not line.strip():
                continue
            done, cmd = line.rstrip("\n").split("\t", 1)
            if os.sep + "fig10_12" + os.sep not in done:
                flat.append(line.rstrip("\n"))
                continue
            words = shlex.split(cmd)
            for a in arbitrations:
                out = replica(done, a)
                os.makedirs(os.path.dirname(out), exist_ok=True)
                w = [words[0], out] + words[2:] + ["--timing-values", "bus_arbitration=%s" % a]
                runs.append("%s\t%s" % (out, " ".join(shlex.quote(x) for x in w)))
    for path, lines in ((out2, flat), (out3, runs)):
        with atomic(path) as f:
            f.write("".join(x + "\n" for x in lines))


def mean_point(json_path, arbitrations):
    """JSON_PATH written as the mean of its runs at every arbitration value (the figures MEANED;
    the others, and the image, those of the middle value's run), with each run's time kept under
    arbitration_runs. Nothing is written when a run is missing."""
    runs = []
    for a in arbitrations:
        path = replica(json_path, a)
        if not os.path.exists(path):
            return False
        with open(path) as f:
            runs.append(json.load(f))
    mid = len(runs) // 2
    out = dict(runs[mid])
    for key in MEANED:
        vals = [r[key] for r in runs if r.get(key) is not None]
        if len(vals) == len(runs):
            out[key] = sum(vals) / len(vals)
    out["arbitration_runs"] = {"bus_arbitration_us": [float(a) for a in arbitrations],
                               "sim_time_s": [r["sim_time_s"] for r in runs]}
    png = replica(json_path, arbitrations[mid])[:-len(".json")] + ".png"
    if os.path.exists(png):
        shutil.copyfile(png, json_path[:-len(".json")] + ".png")
    with atomic(json_path) as f:
        json.dump(out, f, indent=1)
    return True


def mean_all(phase2, arbitrations):
    """Every cluster point of PHASE2 written as its mean; returns (written, missing)."""
    done, missing = 0, 0
    with open(phase2) as f:
        for line in f:
            path = line.split("\t", 1)[0]
            if os.sep + "fig10_12" + os.sep in path:
                if mean_point(path, arbitrations):
                    done += 1
                else:
                    missing += 1
    return done, missing


def spreads(sweep_dir):
    """{point name: (mean, min, max, runs)} of the cluster points written as means."""
    out = {}
    d = os.path.join(sweep_dir, "fig10_12")
    if not os.path.isdir(d):
        return out
    for name in sorted(os.listdir(d)):
        if not name.endswith(".json"):
            continue
        with open(os.path.join(d, name)) as f:
            j = json.load(f)
        runs = j.get("arbitration_runs", {}).get("sim_time_s")
        if runs:
            out[name[:-len(".json")]] = (j["sim_time_s"], min(runs), max(runs), len(runs))
    return out
