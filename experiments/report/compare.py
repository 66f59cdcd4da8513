"""Two sweeps' CSVs side by side: the same points (matched by the columns before `status`) must
have the same measured values. Used to show that a change of the code left every simulated time
and every image as it was."""
import os

from .csvdata import Table

# Wall-clock figures differ from run to run; everything else a point reports is simulated.
NOT_COMPARED = ("wall_s",)


def key_columns(table):
    """The columns naming a point: every column before `status` (the sweep's axes)."""
    if "status" not in table.columns:
        raise ValueError("%s: no status column" % table.path)
    return table.columns[:table.columns.index("status")]


def point_index(table, keys):
    """The table's rows by point (their KEYS columns); ValueError naming the file, the point and
    both lines when a point is there twice: one of the two rows would hide the other."""
    index, lines = {}, {}
    for line, row in enumerate(table.rows, 2):  # line 1 is the header
        point = tuple(row[k] for k in keys)
        if point in index:
            raise ValueError("%s: line %d: the point %s is also on line %d (a figure CSV holds each point once)"
                             % (table.path, line, ",".join("%s=%s" % kv for kv in zip(keys, point)),
                                lines[point]))
        index[point], lines[point] = row, line
    return index


def compare_tables(old, new, columns=None):
    """Differences between two tables of the same figure, as text lines (empty: identical)."""
    keys = key_columns(old)
    if key_columns(new) != keys:
        return ["%s: point columns differ from %s" % (new.path, old.path)]
    wanted = columns or [c for c in old.columns if c not in keys and c not in NOT_COMPARED]
    point_index(old, keys)
    index = point_index(new, keys)
    out = []
    for row in old.rows:
        point = tuple(row[k] for k in keys)
        other = index.pop(point, None)
        name = ",".join("%s=%s" % kv for kv in zip(keys, point))
        if other is None:
            out.append("%s: %s missing in the new sweep" % (os.path.basename(old.path), name))
            continue
        for c in wanted:
            if (c in row or c in other) and row.get(c) != other.get(c):
                out.append("%s: %s: %s %s -> %s" % (os.path.basename(old.path), name, c, row.get(c),
                                                     other.get(c)))
    for point in index:
        out.append("%s: %s only in the new sweep" % (os.path.basename(new.path), ",".join(point)))
    return out


def figure_csvs(results):
    """(relative path, absolute path) of every figure CSV under a results folder."""
    found = []
    for root, _dirs, files in os.walk(results):
        for f in sorted(files):
            if f.startswith("fig") and f.endswith(".csv"):
                path = os.path.join(root, f)
                found.append((os.path.relpath(path, results), path))
    return sorted(found)


def compare(old_dir, new_dir, columns=None):
    """(rows compared, difference lines) over every figure CSV of either folder: a CSV that only
    one folder holds is a difference; a folder that does not exist is an error (ValueError)."""
    for folder in (old_dir, new_dir):
        if not os.path.isdir(folder):
            raise ValueError("%s: no such results folder" % folder)
    rows, diffs, seen = 0, [], set()
    new_csvs = dict(figure_csvs(new_dir))
    for rel, path in figure_csvs(old_dir):
        other = new_csvs.pop(rel, None)
        if other is None:
            diffs.append("%s: not in %s" % (rel, new_dir))
            continue
        old, new = Table.load(path), Table.load(other)
        seen.update(old.columns, new.columns)
        rows += len(old.rows)
        diffs += compare_tables(old, new, columns)
    for rel in sorted(new_csvs):
        diffs.append("%s: not in %s" % (rel, old_dir))
    unknown = [c for c in columns or [] if c not in seen]
    if unknown:  # a misspelt column would compare nothing and pass
        raise ValueError("--columns: no such column in the figure CSVs of %s or %s: %s"
                         % (old_dir, new_dir, ", ".join(unknown)))
    return rows, diffs
