"""The fidelity study, round two (experiments/fidelity/study.sh, docs/fidelity-protocol.md): the
commands study.sh calls between its stages (the candidate lists, each stage's choice, the T(1)
identity's check, the fitted machine's files) and the claims' roles and three counts. The scores
are fidelity_score's, the stages' tables fidelity_stages', the page fidelity_page's."""
import os
import re
import sys

import decimal_number
from output_files import atomic

from . import fidelity_score as fs
from . import fidelity_stages as st
from .verdict import HOLDS

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))

# Each claim's role in the protocol's fit (section 3): the fit targets (F0-F4), the claims
# derived from them (8 from F1's own numbers, 10 the product of 9 and 11), and the validation
# claims no stage used; 4 and 16 hold for any division of the object space.
FIT_TARGETS = (6, 7, 9, 11, 12, 17)
DERIVED = {8: "F1's own numbers", 10: "claims 9 and 11"}
ANY_PARTITION = (4, 16)
THROUGH = {6: "F4", 7: "F1", 9: "F2 and F0", 11: "F3", 12: "F0", 17: "F4"}


def role(i):
    """The claim's role, as the page's tables print it."""
    if i in FIT_TARGETS:
        return "fit target (%s)" % THROUGH[i]
    if i in DERIVED:
        return "fit target (derived: %s)" % DERIVED[i]
    return "validation" + (" (holds for any space partition)" if i in ANY_PARTITION else "")


def counts(verdicts):
    """(held, of), (fit targets held, of), (validation claims held, of) for verdicts 1..17."""
    fit = [i for i in range(1, len(verdicts) + 1) if i in FIT_TARGETS or i in DERIVED]
    val = [i for i in range(1, len(verdicts) + 1) if i not in fit]

    def held(ids):
        return sum(1 for i in ids if verdicts[i - 1] == HOLDS), len(ids)
    return held(range(1, len(verdicts) + 1)), held(fit), held(val)


def counts_lines(verdicts):
    """The three counts, one line each, as the page's first lines."""
    (a, n), (f, nf), (v, nv) = counts(verdicts)
    fit = sorted(FIT_TARGETS + tuple(DERIVED))
    val = [i for i in range(1, n + 1) if i not in fit]
    return ["- **Claims holding: %d of %d.**" % (a, n),
            "- **Fit targets holding: %d of %d** (claims %s; %s derived)." % (
                f, nf, ", ".join(map(str, fit)), " and ".join(map(str, DERIVED))),
            "- **Validation claims holding: %d of %d** (claims %s, which no stage of the fit used; %s hold "
            "for any space partition)." % (v, nv, ", ".join(map(str, val)), " and ".join(map(str, ANY_PARTITION)))]


# ---- the commands study.sh calls ------------------------------------------------------------

def _bash_list(name, values):
    return "%s=(%s)" % (name, " ".join("'%s'" % v for v in values))


def lists_cmd(args):
    """The candidate lists as bash arrays (study.sh sources them)."""
    ls = st.lists(args.smoke)
    out = [_bash_list("image1_specs", st.specs(ls["IMAGE1"])), _bash_list("image2_specs", st.specs(ls["IMAGE2"])),
           _bash_list("layouts", dict(ls["IMAGE1"])["layout"]), _bash_list("scales", dict(ls["IMAGE1"])["scale"]),
           _bash_list("image1_lights", dict(ls["IMAGE1"])["lights"]),
           _bash_list("image1_margins", dict(ls["IMAGE1"])["margin"]),
           _bash_list("image2_planes", dict(ls["IMAGE2"])["plane"]), _bash_list("image2_radii", dict(ls["IMAGE2"])["radius"]),
           _bash_list("image2_lights", dict(ls["IMAGE2"])["lights"]),
           _bash_list("image2_margins", dict(ls["IMAGE2"])["margin"]),
           _bash_list("rules", ls["RULES"]), _bash_list("shapes", ls["SHAPES"]),
           _bash_list("bus_pairs", ["%s/%s" % p for p in ls["BUS_PAIRS"]]),
           _bash_list("accountings", ["%s/%s/%s" % a for a in ls["ACCOUNTING"]]),
           _bash_list("arbitrations", ls["ARBITRATIONS"]), _bash_list("cell_steps", fs.CELL_STEP_COSTS),
           "m_fit=%d" % ls["M_FIT"]]
    print("\n".join(out))
    return 0


def fit1(args):
    choice = st.stage1(args.results, args.smoke)[0]
    print("\t".join([choice["spec1"], choice["rule"], choice["spec2"], str(choice["cell_step"])]))
    return 0


def fit2(args):
    choice = st.stage2(args.results, args.table)[0]
    print(choice["bus"], choice["memory"])
    return 0


def fit3(args):
    choice = st.stage3(args.results, args.table)[0]
    print(choice["shape"], choice["handover"])
    return 0


def fit4(args):
    choice = st.stage4(args.results)[0]
    print(choice["header"], choice["entry"], choice["record"])
    return 0


def allowed(args):
    print(" ".join(map(str, fs.allowed_handovers(args.cell_step))))
    return 0


def identity(args):
    """Exit 0 when every real run at c > 0 (identity.tsv: image, spec, c, JSON) is within 0.1 %
    of T(1)|0 + c x cell_steps; 1, naming the run, when one is not."""
    table = os.path.join(args.results, "identity.tsv")
    if not os.path.isfile(table) or not st.rows(args.results, "identity.tsv"):
        raise ValueError("%s: no identity runs to check (%s)" % (
            table, "no such results folder" if not os.path.isdir(args.results) else "run stage 1 first"))
    zero, _ = st.t1_table(args.results)
    ok = True
    for image, spec, cost, path in st.rows(args.results, "identity.tsv"):
        measured = st.load(path)["sim_time_s"]
        t0, steps = zero[(image, spec)]
        predicted = fs.t1_with_cost(t0, int(cost), steps)
        held = fs.identity_holds(predicted, measured)
        ok &= held
        print("identity %s %s c=%s: predicted %.6f s, measured %.6f s (%s)" % (
            image, spec, cost, predicted, measured, "within 0.1 %" if held else "differs by more than 0.1 %"))
    return 0 if ok else 1


def handover_lines(h):
    send, receive = fs.HANDOVER_KEYS[int(h)]
    return ["handover_send %d" % send, "handover_receive %d" % receive]


# The largest timing value a run accepts (support/timing_limits.h, kMaxTimingUs), in us.
TIMING_MAX = 1e6


def timing_cmd(args):
    """A timing file on stdout: the calibrated table with the given keys replaced (every key, so
    the file stands on its own)."""
    values = {}
    for word in args.set:
        key, eq, value = word.partition("=")
        if not eq or not key:
            print("fidelity timing: %s: not KEY=VALUE" % word, file=sys.stderr)
            return 2
        if key in values:
            print("fidelity timing: %s: the key '%s' is given twice" % (word, key), file=sys.stderr)
            return 2
        if key == "handover" and value not in [str(h) for h in fs.HANDOVER_KEYS]:
            print("fidelity timing: %s: the hand-over is one of %s" % (word, ", ".join(map(str, fs.HANDOVER_KEYS))),
                  file=sys.stderr)
            return 2
        why = decimal_number.fault(value)
        if not why and float(value) > TIMING_MAX:
            why = "is more than %g, the largest value of a timing file" % TIMING_MAX
        if why or value.startswith("-"):
            print("fidelity timing: %s: not a time in microseconds (a decimal number, 0 or more)%s" % (
                word, ": '%s' %s" % (value, why) if why else ""), file=sys.stderr)
            return 2
        values[key] = value
    if "handover" in values:
        for line in handover_lines(values.pop("handover")):
            k, v = line.split()
            values[k] = v
    table = []  # printed once every key is known: a refused command writes nothing
    with open(os.path.join(REPO, "timing", "calibrated.timing")) as f:
        for line in f:
            words = line.split()
            if words and not words[0].startswith("#"):
                table.append("%s %s" % (words[0], values.pop(words[0], words[1])))
    if values:
        print("fidelity timing: no such timing key: %s" % ", ".join(sorted(values)), file=sys.stderr)
        return 2
    print("\n".join(table))
    return 0


MACHINES = {
    "paper-16": ("the flat torus of 16 IPs, load-balancing mapping", 1, "replicated"),
    "paper-1024-replicated": ("16 clusters of 64 (1024 processors), object data replicated", 64, "replicated"),
    "paper-1024-shared": ("16 clusters of 64 (1024 processors), object data shared over the bus", 64, "shared"),
    "paper-192-replicated": ("16 clusters of 12 (m = 12, 192 processors), object data replicated", 12, "replicated"),
    "paper-192-shared": ("16 clusters of 12 (m = 12, 192 processors), object data shared over the bus", 12, "shared"),
}


def _checked(convert, name):
    """An argparse type: CONVERT(text), its ValueError as argparse's refusal (exit 2, the option
    named, before anything is read or written); the text itself is kept."""
    def check(text):
        try:
            convert(text)
        except ValueError as e:
            import argparse
            raise argparse.ArgumentTypeError(str(e)) from None
        return text
    check.__name__ = name
    return check


def _time_us(text):
    """A timing value: the strict decimal syntax, 0 to TIMING_MAX us (a timing file's range)."""
    value = decimal_number.real(text)
    if value < 0 or value > TIMING_MAX:
        raise ValueError("'%s' is not a time in microseconds from 0 to %d" % (text, TIMING_MAX))


def _bytes_in(low, high):
    """A byte count of the memory accounting: a whole number from LOW to HIGH (docs/cli.md)."""
    def check(text):
        value = decimal_number.whole(text)
        if not low <= value <= high:
            raise ValueError("'%s' is not a number of bytes from %d to %d" % (text, low, high))
    return check


def _one_of(values):
    def check(text):
        if text not in values:
            raise ValueError("'%s' is not one of %s" % (text, ", ".join(values)))
    return check


def _shape(text):
    """An --ips value: up to three sizes, each a whole number of 1 or more (16, 4x4, 4x2x2)."""
    sizes = text.split("x")
    if len(sizes) > 3 or not all(re.fullmatch(r"[1-9][0-9]*", s) for s in sizes):
        raise ValueError("'%s' is not a machine shape (up to three sizes of 1 or more: 16, 4x4, 4x2x2)" % text)


def _table_name(text):
    """An argparse type: the name of a table in the results folder, never a path (it is read as
    RESULTS/NAME)."""
    if "/" in text or text in ("", ".", ".."):
        import argparse
        raise argparse.ArgumentTypeError("'%s': the name of a table in the results folder (stage2b.tsv), not a path"
                                         % text)
    return text


# The options of `fidelity machines`, each checked as a run would check it, so that no machine or
# timing file the command writes is refused by the runs that read it.
MACHINE_OPTIONS = (
    ("rule", _checked(_one_of(st.RULES), "rule")), ("bus", _checked(_time_us, "time")),
    ("memory", _checked(_time_us, "time")), ("shape", _checked(_shape, "shape")),
    ("handover", _checked(_one_of([str(h) for h in fs.HANDOVER_KEYS]), "handover")),
    ("cell-step", _checked(_time_us, "time")),
    ("header", _checked(_bytes_in(0, 4096), "bytes")), ("entry", _checked(_bytes_in(1, 4096), "bytes")),
    ("record", _checked(_bytes_in(0, 4096), "bytes")))


def machines(args):
    """OUT/timing/fitted.timing (every key) and OUT/paper-*.toml: the fitted reading."""
    from . import machine_file as mf
    tables = mf.option_tables(args.sim)  # each key in its table, as torusrt-sim groups them
    out = args.out
    os.makedirs(os.path.join(out, "timing"), exist_ok=True)
    keys = {"bus_cycle": args.bus, "memory_access": args.memory, "cell_step_packet": args.cell_step}
    for line in handover_lines(args.handover):
        k, v = line.split()
        keys[k] = v
    lines = ["# fitted.timing - the timing of the fitted reading (docs/fidelity.md), written by",
             "# experiments/fidelity/study.sh: the paper's operation table, with the bus and memory",
             "# timing fitted on the shared-data penalty, the packet cost per cell step on the work",
             "# window and the units, and the hand-over on the 1024-processor times. Every key."]
    with open(os.path.join(REPO, "timing", "calibrated.timing")) as f:
        for line in f:
            words = line.split()
            if words and not words[0].startswith("#"):
                lines.append("%s %s" % (words[0], keys.get(words[0], words[1])))
    with atomic(os.path.join(out, "timing", "fitted.timing")) as f:
        f.write("\n".join(lines) + "\n")
    for name, (what, m, data) in MACHINES.items():
        text = ["# %s.toml - the paper's machine under the fitted reading (docs/fidelity.md):" % name,
                "# %s. Written by experiments/fidelity/study.sh." % what,
                "# Run: torusrt-sim SCENE -o OUT.png --config machines/%s.toml" % name]
        pairs = [("ips", args.shape), ("map", "cyclic"), ("route-ties", "split"), ("preprocess-count", args.rule),
                 ("timing-profile", "calibrated"), ("timing", "timing/fitted.timing"), ("cluster", str(m)),
                 ("data", data), ("cell-header-bytes", args.header), ("list-entry-bytes", args.entry),
                 ("object-record-bytes", args.record)]
        rank = {key: i for i, key in enumerate(tables)}  # --dump-config's order
        pairs.sort(key=lambda kv: rank.get(kv[0], len(rank)))
        with atomic(os.path.join(out, name + ".toml")) as f:
            f.write("\n".join(text) + "\n" + mf.toml_text(pairs, tables))
    return 0


def means_lists(args):
    from . import fidelity_means
    fidelity_means.split_lists(args.phase2, args.flat, args.replicas, args.arbitrations)
    return 0


def means(args):
    from . import fidelity_means
    done, missing = fidelity_means.mean_all(args.phase2, args.arbitrations)
    print("fidelity means: %d cluster points written as their mean, %d with a run missing" % (done, missing))
    return 1 if missing else 0


def page(args):
    from . import fidelity_page
    return fidelity_page.write(args.results, args.doc, args.smoke)


def add_commands(sub):
    """The `fidelity` subcommands of experiments/report."""
    p = sub.add_parser("fidelity", help="the fidelity study's fits, machine files and page")
    fsub = p.add_subparsers(dest="step", required=True)
    q = fsub.add_parser("lists")
    q.add_argument("--smoke", action="store_true")
    q.set_defaults(run=lists_cmd)
    for name, fn, table in (("fit1", fit1, None), ("fit2", fit2, "stage2.tsv"), ("fit3", fit3, "stage3.tsv"),
                            ("fit4", fit4, None), ("identity", identity, None)):
        q = fsub.add_parser(name)
        q.add_argument("results")
        q.add_argument("--smoke", action="store_true")
        if table:
            q.add_argument("--table", default=table, type=_table_name,
                           help="the stage's table in RESULTS (its name, default %s)" % table)
        q.set_defaults(run=fn)
    q = fsub.add_parser("allowed")
    q.add_argument("cell_step")
    q.set_defaults(run=allowed)
    q = fsub.add_parser("timing")
    q.add_argument("set", nargs="*", metavar="KEY=VALUE")
    q.set_defaults(run=timing_cmd)
    q = fsub.add_parser("machines")
    q.add_argument("results")
    q.add_argument("out")
    for opt, check in MACHINE_OPTIONS:
        q.add_argument("--" + opt, required=True, type=check)
    q.add_argument("--sim", required=True, help="the torusrt-sim whose --dump-config gives each key's table")
    q.set_defaults(run=machines)
    q = fsub.add_parser("means-lists", help="the cluster points once per bus_arbitration value")
    for a in ("phase2", "flat", "replicas"):
        q.add_argument(a)
    q.add_argument("arbitrations", nargs="+")
    q.set_defaults(run=means_lists)
    q = fsub.add_parser("means", help="each cluster point's JSON as the mean of its runs")
    q.add_argument("phase2")
    q.add_argument("arbitrations", nargs="+")
    q.set_defaults(run=means)
    q = fsub.add_parser("page")
    q.add_argument("results")
    q.add_argument("doc")
    q.add_argument("--smoke", action="store_true")
    q.set_defaults(run=page)
