"""busy_share.py - the share of busy processors over time, from a torusrt-sim VCD trace.

Usage: python3 -m report.busy_share TRACE.vcd BINS LABEL
Prints one line per time bin: LABEL, the bin's start in seconds and the share (0 to 1) of the
processors' time in it they were busy. A processor is a `busy` wire of a scope named ip_K
(docs/traces.md); the trace's timescale and the image time (the last time stamp) set the bins.
"""
import sys

UNITS = {"s": 1.0, "ms": 1e-3, "us": 1e-6, "ns": 1e-9, "ps": 1e-12, "fs": 1e-15}


def timescale_s(text):
    """Seconds per VCD time unit, from a $timescale body such as '1 ps' or '10ns'."""
    text = text.replace(" ", "")
    digits = "".join(c for c in text if c.isdigit())
    return int(digits or "1") * UNITS[text[len(digits):]]


def busy_share(path, bins):
    """[(bin start s, share busy)] over `bins` equal bins from 0 to the end of the last busy span."""
    busy_ids, scope, scale, in_scale = {}, None, 1e-12, False
    intervals, since, now, scale_text = [], {}, 0, ""
    with open(path) as f:
        for line in f:
            if in_scale:
                if line.startswith("$end"):
                    scale, in_scale = timescale_s(scale_text), False
                else:
                    scale_text += line.strip()
                continue
            if line.startswith("$timescale"):
                in_scale, scale_text = True, line[len("$timescale"):].replace("$end", "").strip()
                if "$end" in line:
                    scale, in_scale = timescale_s(scale_text), False
            elif line.startswith("$scope"):
                name = line.split()[2]
                scope = name if name.startswith("ip_") else None
            elif line.startswith("$var") and scope:
                words = line.split()
                if words[4] == "busy":
                    busy_ids[words[3]] = scope
            elif line.startswith("#"):
                now = int(line[1:])
            elif line[:1] in "01" and line[1:].strip() in busy_ids:
                key = line[1:].strip()
                if line[0] == "1":
                    since[key] = now
                elif key in since:
                    intervals.append((since.pop(key), now))
    intervals += [(a, now) for a in since.values()]  # still busy where the trace ends
    # The last processor's work ends the image; a link's use may still be written after it.
    end = max([b for _, b in intervals], default=0)
    if not busy_ids or end == 0:
        raise ValueError(f"{path}: no processor busy signal")
    width = -(-end // bins)  # whole time units, so that a bin's end is exact
    busy = [0] * bins
    for a, b in intervals:
        while a < b:
            k = a // width  # a < (k + 1) x width: every pass moves a on
            edge = min(b, (k + 1) * width)
            busy[k] += edge - a
            a = edge
    return [(k * width * scale, busy[k] / (width * len(busy_ids))) for k in range(bins)]


def main(argv):
    if len(argv) != 4 or not argv[2].isdigit() or int(argv[2]) < 1:
        sys.exit("usage: python3 -m report.busy_share TRACE.vcd BINS LABEL (BINS a whole number, at least 1)")
    path, bins, label = argv[1], int(argv[2]), argv[3]
    try:
        shares = busy_share(path, bins)
    except (OSError, ValueError, KeyError, IndexError) as e:
        sys.exit(f"busy_share: {path}: {e}")
    for start, share in shares:
        print(f"{label}\t{start:.6g}\t{share:.4f}")


if __name__ == "__main__":
    main(sys.argv)
