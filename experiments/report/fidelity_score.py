"""The score of the fidelity study, round two (docs/fidelity-protocol.md section 4): each fit
target's band and point value, a candidate's excesses, the sorted-excess score and its tie
rules, the hand-over costs a per-step packet cost leaves allowed, and the T(1) identity."""
import decimal_number

from . import paper

# The F0 window: claim 12's 80 % at 1024 processors over claim 9's times, taken as exact.
T1_WINDOW = {s: (0.8 * 1024 * paper.cluster_time(s, "replicated"), 1024 * paper.cluster_time(s, "replicated"))
             for s in ("image1", "image2")}
UNITS_TOL, TIMES_TOL = 0.05, 0.20
PENALTY_BAND = (1.05, 1.5)
MEMORY_BAND = paper.MEMORY_RATIO_AT_16


def _band(lo, hi, point):
    return {"lo": lo, "hi": hi, "point": point}


def targets():
    """{target name: band and point value}: F0 t1_image1/2, F1 units_1/16/32, F2 time_image1/2,
    F3 penalty_image1/2, F4 memory_image1/2."""
    t = {}
    for s in ("image1", "image2"):
        lo, hi = T1_WINDOW[s]
        # The window's ends rounded to whole seconds, as the protocol writes them.
        t["t1_" + s] = _band(round(lo), round(hi), 0.9 * 1024 * paper.cluster_time(s, "replicated"))
        rep = paper.cluster_time(s, "replicated")
        t["time_" + s] = _band((1 - TIMES_TOL) * rep, (1 + TIMES_TOL) * rep, rep)
        pen = paper.cluster_time(s, "shared") / rep
        t["penalty_" + s] = _band(PENALTY_BAND[0], PENALTY_BAND[1], pen)
        t["memory_" + s] = _band(MEMORY_BAND[0], MEMORY_BAND[1], sum(MEMORY_BAND) / 2)
    for n, u in paper.PREPROCESS_UNITS.items():
        t["units_%d" % n] = _band((1 - UNITS_TOL) * u, (1 + UNITS_TOL) * u, u)
    return t


TARGETS = targets()


def excess(x, lo, hi):
    """The relative distance of x outside [lo, hi]: 0 inside, (lo - x) / lo below, (x - hi) / hi above."""
    if x < lo:
        return (lo - x) / lo
    if x > hi:
        return (x - hi) / hi
    return 0.0


def excesses(figures):
    """{target: excess} of a candidate's measured figures {target: value}."""
    return {k: excess(v, TARGETS[k]["lo"], TARGETS[k]["hi"]) for k, v in figures.items()}


def residual(figures):
    """The largest |x / point - 1| over the figures: the secondary score."""
    return max(abs(v / TARGETS[k]["point"] - 1) for k, v in figures.items())


def score(exc):
    """The excesses sorted from largest to smallest: compared element by element, the largest
    first, so one unmet target cannot hide the others. Rounded so that equal sums tie."""
    return tuple(round(e, 12) for e in sorted(exc.values(), reverse=True))


def rank(index, figures, moved):
    """The sort key of a candidate: its score, then fewer unknowns moved from the unfitted
    reading, then the smaller largest residual against the point values, then the listed order."""
    return (score(excesses(figures)), moved, round(residual(figures), 12), index)


def best(candidates):
    """The chosen one of [(index, figures, moved, payload)]: the smallest rank."""
    return min(candidates, key=lambda c: rank(c[0], c[1], c[2]))


def moved(choice, unfitted):
    """How many of the choice's unknowns differ from the unfitted reading's values."""
    return sum(1 for k, v in choice.items() if k in unfitted and str(v) != str(unfitted[k]))


# U15 (packet cost per cell step) against U6 (hand-over at an IP crossing): an operation every step
# already pays is not charged again at a crossing (creation 1600 + analysis 580).
CELL_STEP_COSTS = (0, 580, 1600, 2180)
HANDOVERS = (0, 580, 2180)
HANDOVER_KEYS = {0: (0, 0), 580: (0, 580), 1600: (1600, 0), 2180: (1600, 580)}


def allowed_handovers(cell_step):
    """The hand-over costs (us) allowed beside a per-step cost: none {0, 580, 2180}, analysis
    {0, 1600}, creation {0, 580}, both {0}."""
    try:
        c = cell_step if isinstance(cell_step, int) else decimal_number.whole(cell_step)
    except ValueError as e:  # 0580, 1e999, 1.5, x: no cost of the study
        raise ValueError("cell_step_packet %s: one of %s" % (e, CELL_STEP_COSTS)) from None
    if c not in CELL_STEP_COSTS:
        raise ValueError("cell_step_packet %r is not one of %s" % (cell_step, CELL_STEP_COSTS))
    return {0: (0, 580, 2180), 580: (0, 1600), 1600: (0, 580), 2180: (0,)}[c]


def t1_with_cost(t1_zero_s, cell_step_us, cell_steps):
    """T(1)|c = T(1)|0 + c x cell_steps: T(1) is a sum of operation costs."""
    return t1_zero_s + float(cell_step_us) * 1e-6 * cell_steps


IDENTITY_TOL = 0.001


def identity_holds(predicted_s, measured_s):
    """Whether a real run's T(1) is within 0.1 % of the identity's."""
    return abs(measured_s / predicted_s - 1) <= IDENTITY_TOL
