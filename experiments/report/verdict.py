"""The one rule that turns counted checks into a verdict."""

HOLDS = "holds"
ONE_IMAGE = "holds for one image"
MOSTLY = "mostly"
DIRECTION = "direction only"
FAILS = "does not hold"
NOT_RUN = "not run"

# Order and plural wording of the summary line.
SUMMARY = [(HOLDS, "hold"), (ONE_IMAGE, "hold for one image only"), (MOSTLY, "hold mostly"),
           (DIRECTION, "hold in direction only"), (FAILS, "do not hold"), (NOT_RUN, "were not run")]


def verdict(passed, total, partial=ONE_IMAGE, failing=FAILS, need_all=True):
    """NOT_RUN without checks; HOLDS when every check passed (any one, with need_all False);
    `partial` when some passed; `failing` when none did."""
    if total == 0:
        return NOT_RUN
    if passed == total or (passed > 0 and not need_all):
        return HOLDS
    if passed > 0:
        return partial
    return failing


def summary(verdicts):
    """'17 claims: 9 hold, 1 hold for one image only, ...' for a list of verdicts."""
    parts = []
    for key, words in SUMMARY:
        count = sum(1 for v in verdicts if v == key)
        if count:
            parts.append("%d %s" % (count, words))
    return "%d claims: %s." % (len(verdicts), ", ".join(parts))
