"""docs/error-vs-runtime.md: the timing-style and pruning studies from quantum.csv and pruning.csv,
with their plots (experiments/plots/error-quantum.gp, error-pruning.gp)."""
import os

from output_files import atomic

from . import before_fit, pruning, quantum
from .csvdata import Table
from .plots import gnuplot

INTRO = """docs/design.md section 8 asks for two studies, each a table and a plot: the loosely-timed (LT) style
at growing quanta against the approximately-timed (AT) reference, and shade-tree pruning
(max-depth, min-weight) against the full-depth image. Produced by

    {command}

(`experiments/error_vs_runtime/study.sh --help` lists the options; `--build DIR` or
`TORUSRT_BUILD` picks the build folder). The raw numbers are in
`experiments/error_vs_runtime/results/quantum.csv` and `pruning.csv`; the columns are described
at the top of `quantum.sh` and `pruning.sh`. Wall-clock times are the fastest of repeated
runs on the machine that ran the study (other load only adds time, but can still add some
10-20 % to a point); simulated times and errors are deterministic.

## 1. Timing style: loosely timed against approximately timed

Each configuration (paper scene at 144x144, torus 4x2x2 = 16 IPs, 4x4x4 = 64 IPs or 8x8x8 = 512
IPs) is run once
in AT (`--style at`, the reference) and then in LT (`--style lt --quantum Q`) at quanta 0, 10 us,
100 us and then in 1-2-5 steps from 1 ms, until the error of `sim_time_s` passes 20 % (or the
largest quantum, 100 s, is reached). Every run gets `--t1` from a first AT run, so no run pays
for the internal one-processor run. The error is signed, (LT - AT) / AT: negative means the LT
run reports a shorter image time (a higher efficiency) than AT. `efficiency_busy` is busy time
over n T(n), and the busy time (the sum of the step costs) is the same in both styles, so its
error is exactly AT/LT - 1 of the image time: the two columns carry the same information with
opposite sign. Speed-up is the AT wall time over the LT wall time (whole process, scene loading
included); "simulation only" uses `sim_wall_s`. Events are steps + link hops + injections.

"""

WHY = """
Why, from the model's design (model/time_keeper.cpp, intersection_processor.cpp,
toroidal_link.cpp, comm_unit.cpp, host.cpp):

- *Where the error comes from.* Every packet carries its send time (`TimedPacket.stamp`), a link
  adds its transfer time, and a receiver advances its local time to the stamp before starting
  the packet, so no packet is ever started before it arrived and every IP and link still serves
  one packet at a time. What LT changes is the *order* of service. A sender that has run ahead
  by up to a quantum hands over packets stamped in its future, and they are routed at once
  along their whole route within the quantum. An IP's queue is in stamp order, and a link books
  each crossing into the earliest gap at its stamp, but an IP can only choose among the packets
  present: when it takes up one, an earlier one that another sender hands over later then waits
  behind it. The schedule stays causal but is no longer first-come-first-served by arrival
  time, so the image time (the latest consumption) moves (docs/model.md, Timing styles).
- *Small quanta are free of error.* The step costs are milliseconds (a step is 1-20 ms of
  simulated time, a link hop 50 us), so a quantum below the smallest delay still makes every
  process synchronise after every step: up to 100 us nothing changes at all, and up to some
  hundred milliseconds only a few packets are reordered.
- *Either sign.* Serving a later-arriving packet first can lengthen or shorten the critical path
  through the shade trees, so the error has no fixed sign at small quanta; at large quanta it is
  consistently positive: a receiver runs through its whole queue without yielding and
  senders' packets pile up behind it.
- *Saturation and non-monotonicity.* Once the quantum is longer than the image time no process
  ever reaches its quantum: a process synchronises only when its input queue runs empty (the
  `sync()` before the blocking pop). From there on the schedule no longer depends on the
  quantum, and between neighbouring large quanta the order in which processes happen to run
  dry decides the result, so the error can fall again as the quantum grows.
- *Idle processes stay close to AT.* A process that finds its queue empty synchronises and
  blocks; its quantum keeper keeps the synchronisation point computed before the wait, which
  simulation time has usually passed when the next packet comes, so the first delay after an
  idle wait synchronises at once: the process waits until the packet's stamp, as in AT. Lightly
  loaded IPs therefore run nearly AT-timed until the quantum approaches the image time. This
  costs process activations but keeps the
  error small: recomputing the synchronisation point after the wait (the usual
  `tlm_quantumkeeper::reset()` after an explicit wait) cuts the delta cycles by a quarter to
  a half at quanta of 10 ms to 1 s, and raises the error two- to fourfold there (measured
  on paper-image2 with a patched copy of the model; not part of the model).
- *Speed-up is bounded.* LT saves SystemC process activations and delta cycles (in AT one per
  step and one per hop; in LT a packet's whole route within the quantum is one call chain, and
  an IP runs step after step in one activation); it cannot save the packet steps themselves
  (the kernel's intersection and shading work) nor the model's per-step and per-hop
  bookkeeping (queues, pool, links, statistics), which are the same in both styles. Once the
  delta cycles have collapsed (see `delta_cycles` in the CSV) the wall time stops falling
  (bench/README.md, Where the time goes, has the profile), and the quanta past that point only
  add error: the quanta that give that speed-up are the ones past the 1-5 % bounds."""

PRUNING_INTRO = """## 2. Shade-tree pruning

Images at `--max-depth` 0..8 (min-weight at its default 1/512) and `--min-weight` 1/512..1/8
(max-depth at its default 8), compared with the default-settings image of the reference
renderer (`torusrt-render`, max-depth 8, min-weight 1/512: the full-depth image). PSNR is over
the 8-bit R, G, B samples (inf = identical), "max abs diff" the largest difference of one
sample in levels, "pixels off > 2" the pixels with a sample more than 2 levels off. The image
time is the renderer's T(1) (one processor, the timing table applied to its operation counts)
and `sim_time_s` of `torusrt-sim` (AT) on each torus; wall times are the fastest of repeated runs.
The last row per scene ("beyond": max-depth 32, min-weight 1/65536) compares a much deeper tree
with the default image, to show what the defaults themselves leave out.

"""


def plots(qt, pt, img_dir, work):
    os.makedirs(work, exist_ok=True)
    os.makedirs(img_dir, exist_ok=True)
    variables = quantum.plot_data(qt, work)
    gnuplot("error-quantum.gp", dict(variables, dat=work, out=os.path.join(img_dir, "error-quantum.png"),
                                     out_q=os.path.join(img_dir, "error-quantum-q.png")))
    gnuplot("error-pareto.gp", dict(variables, dat=work, out=os.path.join(img_dir, "error-pareto.png")))
    gnuplot("error-pruning.gp", dict(pruning.plot_data(pt, work), dat=work, out=os.path.join(img_dir, "error-pruning.png")))


def quantum_section(qt, rel_img, command):
    f = quantum.findings(qt)
    out = [INTRO.replace("{command}", command).rstrip("\n"), "",
           "![error against wall time and speed-up](%s/error-quantum.png)" % rel_img, "",
           "![error against the quantum](%s/error-quantum-q.png)" % rel_img, "",
           "### The trade", "",
           "Per configuration, the runs no other run beats on both wall time and |error of `sim_time_s`|",
           "(the Pareto front, fastest first; AT is the front's error-free end):", "",
           "![wall time against error, the Pareto front of each configuration](%s/error-pareto.png)" % rel_img, ""]
    out += ["- %s" % line for line in quantum.front_text(qt)]
    out += ["",
           "### Recommended quantum", "",
           "The largest quantum tried whose error, and that of every smaller quantum tried (both",
           "`sim_time_s` and `efficiency_busy`), is within the bound:", "", quantum.recommend_table(qt), "",
           "For all configurations at once: **%s for 1 %% error, %s for 5 %% error** (the smallest of"
           % (quantum.overall(qt, 1), quantum.overall(qt, 5)),
           "the per-configuration values). The bound is a property of the tried grid: the true limit lies",
           "between that quantum and the next one tried.", "", "### Tables", "", quantum.tables(qt), ""]
    if f["slower"] or f["negatives"] or f["nonmono"]:
        out += ["### Observations", ""]
    if f["slower"]:
        out.append("- LT not faster than AT (speed-up < 1) at: %s. Below a few milliseconds LT does the same process "
                   "activations as AT (compare delta cycles), so there it is AT plus the time keeper's bookkeeping, within "
                   "the timing noise." % f["slower"])
    if f["negatives"]:
        out.append("- LT image time *below* AT (negative error) at: %s." % f["negatives"])
    if f["nonmono"]:
        out.append("- The error is not monotonic in the quantum; |error of sim_time_s| falls as the quantum grows at: %s."
                   % f["nonmono"])
    return out + ["", WHY.strip("\n")]


def pruning_section(pt, rel_img):
    return ["", PRUNING_INTRO.rstrip("\n"), "", "![PSNR against image time and wall time](%s/error-pruning.png)" % rel_img,
            "", pruning.tables(pt)]


def findings(qt, pt):
    """The page's opening: what each study shows, before the set-up and the tables."""
    f, g = quantum.findings(qt), pruning.findings(pt)
    return ["## Findings", "",
            "Timing style (LT at growing quanta against AT):", "",
            "- Every LT image equals its AT image byte for byte: **%s**. Every repetition of a run gave the" % f["all_equal"],
            "  same `sim_time_s`: **%s**." % f["all_det"],
            "- Quantum 0 gives exactly the AT image time and efficiency: **%s** (the LT time keeper waits at" % f["q0_zero"],
            "  every delay when the quantum is 0, as AT does).",
            "- The quantum to pick: **%s for 1 %% error, %s for 5 %%** (the largest that keeps every" % (
                quantum.overall(qt, 1), quantum.overall(qt, 5)),
            "  configuration, 16 to 512 IPs, within the bound; section 1, Recommended quantum).",
            "- Highest speed-up per configuration: %s." % f["maxspd"],
            "", "Shade-tree pruning (max-depth, min-weight) against the full-depth image:", "",
            "- Every torusrt-sim image equals the renderer's image at the same settings: **%s**." % g["all_sim_equal"],
            "- PSNR never falls as max-depth rises: **%s** (a deeper tree only adds rays, whose" % g["monotone"],
            "  contributions are non-negative, so every sample moves toward the reference).", pruning.facts(pt), ""]


def write(quantum_csv, pruning_csv, doc, img_dir, command):
    """Draws the three plots into img_dir and writes the page to doc (atomically)."""
    qt, pt = Table.load(quantum_csv), Table.load(pruning_csv)
    if not qt.rows or not pt.rows:
        raise ValueError("%s or %s has no rows" % (quantum_csv, pruning_csv))
    doc_dir = os.path.dirname(os.path.realpath(doc))
    rel_img = os.path.relpath(os.path.abspath(img_dir), doc_dir)
    head = ["# Error against run time", "",
            "<!-- Generated by experiments/report (python3 experiments/report error-vs-runtime) from "
            "experiments/error_vs_runtime/results/*.csv: do not edit by hand. -->", ""]
    try:  # the page's text first: a table without the studies' columns stops before any plot is drawn
        lines = head + findings(qt, pt) + before_fit.section(os.path.dirname(os.path.abspath(quantum_csv))) + \
            ["## How it was made", ""] + quantum_section(qt, rel_img, command) \
            + pruning_section(pt, rel_img)
    except KeyError as e:
        raise ValueError("%s, %s: no column %s (the columns quantum.sh and pruning.sh write; see their headers)"
                         % (quantum_csv, pruning_csv, e)) from None
    plots(qt, pt, img_dir, os.path.join(os.path.dirname(os.path.abspath(quantum_csv)), "plot-data"))
    with atomic(doc) as out:
        out.write("\n".join(lines) + "\n")
