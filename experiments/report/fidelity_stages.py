"""The stages of the fidelity study, round two (docs/fidelity-protocol.md section 4): the
candidate lists study.sh runs, and each stage's candidates read back from its runs
(RES/<stage>.tsv, one run a line, its JSON last) and scored by fidelity_score."""
import itertools
import json
import os
from collections import OrderedDict

from output_files import shown

from . import fidelity_score as fs

# The candidates, the unfitted value first (section 2 of the protocol).
IMAGE1 = (("layout", ("planar", "planar-z", "cube", "tree")), ("scale", ("1", "0.8", "1.25")),
          ("lights", ("2", "1", "3")), ("margin", ("1.03", "0.8", "1.25")))
IMAGE2 = (("plane", ("floor", "wall")), ("radius", ("2", "1.5", "2.5")), ("lights", ("2", "1", "3")),
          ("margin", ("1.02", "0.8", "1.25")))
RULES = ("sequential", "per-plane", "bounding-sphere")
SHAPES = ("4x2x2", "2x2x4", "4x4", "16")
BUS_PAIRS = tuple((b, m) for b in ("0.5", "1", "2", "4") for m in ("0.5", "1", "2"))
ACCOUNTING = tuple((h, e, r) for h in ("4", "2", "0") for e in ("4", "2") for r in ("0", "36"))
ARBITRATIONS = ("0.240", "0.245", "0.250", "0.255", "0.260")
M_FIT = 64

# The smoke mode's lists: every stage with a choice to make, in seconds.
SMOKE = {"IMAGE1": (("layout", ("planar", "planar-z")), ("scale", ("1",)), ("lights", ("2",)), ("margin", ("1.03",))),
         "IMAGE2": (("plane", ("floor",)), ("radius", ("2",)), ("lights", ("2",)), ("margin", ("1.02",))),
         "RULES": ("sequential", "per-plane"), "SHAPES": ("4x2x2", "4x4"), "BUS_PAIRS": (("0.5", "0.5"), ("2", "1")),
         "ACCOUNTING": (("4", "4", "0"), ("2", "2", "0")), "ARBITRATIONS": ("0.245", "0.255"), "M_FIT": 4}


def lists(smoke=False):
    """{name: value} of the candidate lists, the smoke mode's when smoke."""
    out = {"IMAGE1": IMAGE1, "IMAGE2": IMAGE2, "RULES": RULES, "SHAPES": SHAPES, "BUS_PAIRS": BUS_PAIRS,
           "ACCOUNTING": ACCOUNTING, "ARBITRATIONS": ARBITRATIONS, "M_FIT": M_FIT}
    if smoke:
        out.update(SMOKE)
    return out


def specs(unknowns):
    """Every variant of an image as torusrt-genscenes KEY=VALUE,... specs, in the listed order."""
    names = [k for k, _ in unknowns]
    return [",".join("%s=%s" % kv for kv in zip(names, vals))
            for vals in itertools.product(*[v for _, v in unknowns])]


def parse_spec(spec):
    return OrderedDict(kv.split("=", 1) for kv in spec.split(","))


def rows(res, name):
    """The tab-separated rows of the table NAME in the results folder RES ([] when there is no
    such table); ValueError when RES is there but no folder (a file, a device)."""
    if os.path.exists(res) and not os.path.isdir(res):
        raise ValueError("%s: not a results folder (a file or a device, not a folder)" % shown(res))
    path = os.path.join(res, name)
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [line.rstrip("\n").split("\t") for line in f if line.strip()]


def load(path):
    with open(path) as f:
        return json.load(f)


def _mean(xs):
    return sum(xs) / len(xs)


# ---- stage 1: scenes and work (F1 + F0) -------------------------------------------------------

def units_table(res):
    """{(layout, scale, rule): {1: u, 16: u, 32: u}} of the renderer's units runs (units.tsv)."""
    out = {}
    for layout, scale, rule, path in rows(res, "units.tsv"):
        by_p = load(path)["preprocess"]["units_parallel_by_p"]
        out[(layout, scale, rule)] = {n: by_p[str(n)] for n in paper_units()}
    return out


def paper_units():
    return (1, 16, 32)


def t1_table(res):
    """{(image, spec): (T(1) at cell_step_packet 0, cell steps)} and {(image, spec, c): T(1)} of
    the one-processor runs measured at c > 0 (the identity's check, or every c when it failed)."""
    zero, measured = {}, {}
    for image, spec, cost, path in rows(res, "t1.tsv"):
        j = load(path)
        if int(cost) == 0:
            zero[(image, spec)] = (j["sim_time_s"], j["ops"]["cell_steps"])
        else:
            measured[(image, spec, int(cost))] = j["sim_time_s"]
    return zero, measured


def t1_of(zero, measured, image, spec, cost, use_measured):
    """T(1)|c of a variant: measured where the study ran it every c, else by the identity."""
    if use_measured and (image, spec, cost) in measured:
        return measured[(image, spec, cost)]
    t0, steps = zero[(image, spec)]
    return fs.t1_with_cost(t0, cost, steps)


def stage1(res, smoke=False):
    """(choice, ranked list of the best candidates, per-part tables) of the joint stage-1 score.
    A choice: layout, scale, rule, spec1 (image 1's variant), spec2, cell_step."""
    ls = lists(smoke)
    units = units_table(res)
    zero, measured = t1_table(res)
    for table, runs in (("units.tsv", units), ("t1.tsv", zero)):
        if not runs:
            raise ValueError("%s: no runs (the stage has not run)" % shown(os.path.join(res, table)))
    try:
        return _stage1(res, ls, units, zero, measured)
    except KeyError as e:  # a candidate the tables lack: the stage did not finish
        raise ValueError("%s: no run of %s (the stage has not finished)" % (
            shown(os.path.join(res, "t1.tsv" if len(e.args[0]) == 2 else "units.tsv")),
            " ".join(map(str, e.args[0])))) from None


def _stage1(res, ls, units, zero, measured):
    """stage1()'s score over tables that hold runs (KeyError: a candidate they lack)."""
    every_c = os.path.exists(os.path.join(res, "identity-failed"))
    s1, s2 = specs(ls["IMAGE1"]), specs(ls["IMAGE2"])
    t1 = {("image1", s, c): t1_of(zero, measured, "image1", s, c, every_c) for s in s1 for c in fs.CELL_STEP_COSTS}
    t1.update({("image2", s, c): t1_of(zero, measured, "image2", s, c, every_c)
               for s in s2 for c in fs.CELL_STEP_COSTS})
    cands = []
    index = 0
    for spec1 in s1:
        v1 = parse_spec(spec1)
        for rule in ls["RULES"]:
            u = units[(v1["layout"], v1["scale"], rule)]
            for spec2 in s2:
                for c in fs.CELL_STEP_COSTS:
                    figures = {"units_%d" % n: u[n] for n in paper_units()}
                    figures["t1_image1"] = t1[("image1", spec1, c)]
                    figures["t1_image2"] = t1[("image2", spec2, c)]
                    moved = (sum(1 for i, (_, vals) in enumerate(ls["IMAGE1"]) if list(v1.values())[i] != vals[0]) +
                             sum(1 for i, (_, vals) in enumerate(ls["IMAGE2"])
                                 if list(parse_spec(spec2).values())[i] != vals[0]) +
                             (rule != ls["RULES"][0]) + (c != 0))
                    cands.append((index, figures, moved, {"spec1": spec1, "rule": rule, "spec2": spec2,
                                                          "cell_step": c}))
                    index += 1
    ranked = sorted(cands, key=lambda x: fs.rank(x[0], x[1], x[2]))
    return ranked[0][3], ranked, {"units": units, "t1": t1}


# ---- stages 2 and 3: the bus (F3) and the 1024 times (F2), each point a mean of five ----------

def _means(res, name, keys):
    """{key tuple: {"time": mean, "spread": (min, max), "e_t1": mean, "e_busy": mean}} of NAME's
    runs grouped by the columns KEYS (every column but the arbitration and the JSON)."""
    groups = OrderedDict()
    for row in rows(res, name):
        key, path = tuple(row[:keys]), row[-1]
        j = load(path)
        groups.setdefault(key, []).append((j["sim_time_s"], j.get("efficiency"), j.get("load_balance")))
    out = OrderedDict()
    for key, runs in groups.items():
        times = [r[0] for r in runs]
        e = [r[1] for r in runs if r[1] is not None]
        b = [r[2] for r in runs if r[2] is not None]
        out[key] = {"time": _mean(times), "spread": (min(times), max(times)), "runs": len(runs),
                    "e_t1": _mean(e) if e else None, "e_busy": _mean(b) if b else None}
    return out


def stage2(res, name="stage2.tsv"):
    """(choice {bus, memory}, [(index, figures, moved, choice, means)]) of the penalty fit; rows:
    shape, handover, bus, memory, image, data, arbitration, JSON."""
    means = _means(res, name, 6)
    cands = []
    pairs = list(OrderedDict.fromkeys((k[2], k[3]) for k in means))
    for i, (bus, mem) in enumerate(pairs):
        m = {(k[4], k[5]): v for k, v in means.items() if (k[2], k[3]) == (bus, mem)}
        figures = {"penalty_" + s: m[(s, "shared")]["time"] / m[(s, "replicated")]["time"] for s in ("image1", "image2")}
        moved = (bus != "0.5") + (mem != "0.5")
        cands.append((i, figures, moved, {"bus": bus, "memory": mem}, m))
    return _best(cands, res, name)


def _best(cands, res, name):
    """(the best candidate's choice, every candidate ranked best first); ValueError naming the
    table when it holds no run (a results folder whose stage did not run)."""
    if not cands:
        raise ValueError("%s: no runs (the stage has not run)" % shown(os.path.join(res, name)))
    ranked = sorted(cands, key=lambda x: fs.rank(x[0], x[1], x[2]))
    return ranked[0][3], ranked


def stage3(res, name="stage3.tsv"):
    """(choice {shape, handover}, ranked candidates) of the 1024-times fit; rows: shape,
    handover, image, arbitration, JSON."""
    means = _means(res, name, 3)
    cands = []
    keys = list(OrderedDict.fromkeys((k[0], k[1]) for k in means))
    for i, (shape, h) in enumerate(keys):
        m = {k[2]: v for k, v in means.items() if (k[0], k[1]) == (shape, h)}
        figures = {"time_" + s: m[s]["time"] for s in ("image1", "image2")}
        moved = (shape != "4x2x2") + (h != "0")
        cands.append((i, figures, moved, {"shape": shape, "handover": h}, m))
    return _best(cands, res, name)


# ---- stage 4: memory accounting (F4) --------------------------------------------------------

def memory_ratio(path):
    """Pixel-partitioned memory over the run's total (the 1/x of claim 6)."""
    mem = load(path)["memory"]
    return mem["pixel_partitioned_bytes"] / mem["total_bytes"]


def stage4(res):
    """(choice {header, entry, record}, ranked candidates); rows: header, entry, record, image, JSON."""
    got = OrderedDict()
    for h, e, r, image, path in rows(res, "stage4.tsv"):
        got.setdefault((h, e, r), {})["memory_" + image] = memory_ratio(path)
    cands = [(i, figures, (k[0] != "4") + (k[1] != "4") + (k[2] != "0"), {"header": k[0], "entry": k[1], "record": k[2]},
              None) for i, (k, figures) in enumerate(got.items())]
    return _best(cands, res, "stage4.tsv")


# ---- stage 5: residuals on the written machine files ----------------------------------------

def residuals(res, units):
    """{target: value} measured on the fitted files (residuals.tsv rows: kind, image,
    arbitration, JSON; kind t1, replicated, shared or memory) with F1's units given."""
    got = {}
    for kind, image, _, path in rows(res, "residuals.tsv"):
        j = load(path)
        if kind == "memory":
            got[("memory", image)] = [memory_ratio(path)]
        else:
            got.setdefault((kind, image), []).append(j["sim_time_s"])
    out = {"units_%d" % n: units[n] for n in paper_units()}
    for s in ("image1", "image2"):
        if ("t1", s) in got:
            out["t1_" + s] = _mean(got[("t1", s)])
        if ("replicated", s) in got:
            out["time_" + s] = _mean(got[("replicated", s)])
            if ("shared", s) in got:
                out["penalty_" + s] = _mean(got[("shared", s)]) / out["time_" + s]
        if ("memory", s) in got:
            out["memory_" + s] = got[("memory", s)][0]
    return out
