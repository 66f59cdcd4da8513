"""The sweep comparison (experiments/report compare.py) on the checked-in reproduction CSVs: a
sweep equals itself, and a changed simulated time, a changed image verdict or a missing point is
found, while a changed wall time is not."""
import csv
import os
import shutil
import sys
import tempfile
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(REPO, "experiments"))

from report import compare  # noqa: E402

RESULTS = os.path.join(REPO, "experiments", "results")
FIG = os.path.join("calibrated", "fig5_6.csv")


def edit(path, change):
    """Rewrites a CSV with `change(rows)` applied to its rows (dicts)."""
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        columns, rows = reader.fieldnames, list(reader)
    rows = change(rows)
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns, lineterminator="\n")
        w.writeheader()
        w.writerows(rows)


class Compare(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.new = os.path.join(self.tmp.name, "results")
        shutil.copytree(RESULTS, self.new)

    def tearDown(self):
        self.tmp.cleanup()

    def test_identical(self):
        rows, diffs = compare.compare(RESULTS, self.new)
        self.assertGreater(rows, 100)
        self.assertEqual(diffs, [])

    def test_sim_time_change_found(self):
        def change(rows):
            rows[3]["sim_time_s"] = str(float(rows[3]["sim_time_s"]) * (1 + 1e-12))
            return rows
        edit(os.path.join(self.new, FIG), change)
        _, diffs = compare.compare(RESULTS, self.new)
        self.assertEqual(len(diffs), 1)
        self.assertIn("sim_time_s", diffs[0])

    def test_image_change_found(self):
        def change(rows):
            rows[0]["image_identical"] = "no"
            return rows
        edit(os.path.join(self.new, FIG), change)
        _, diffs = compare.compare(RESULTS, self.new)
        self.assertEqual(len(diffs), 1)
        self.assertIn("image_identical", diffs[0])

    def test_missing_point_found(self):
        edit(os.path.join(self.new, FIG), lambda rows: rows[1:])
        _, diffs = compare.compare(RESULTS, self.new)
        self.assertEqual(len(diffs), 1)
        self.assertIn("missing", diffs[0])

    def test_wall_time_ignored(self):
        def change(rows):
            for r in rows:
                r["wall_s"] = "99"
            return rows
        edit(os.path.join(self.new, FIG), change)
        self.assertEqual(compare.compare(RESULTS, self.new)[1], [])

    def test_a_csv_on_either_side_only_is_a_difference(self):
        os.remove(os.path.join(self.new, FIG))
        for old, new in ((RESULTS, self.new), (self.new, RESULTS)):
            _, diffs = compare.compare(old, new)
            self.assertEqual(diffs, ["%s: not in %s" % (FIG, self.new)])

    def test_a_missing_folder_is_an_error(self):
        missing = os.path.join(self.tmp.name, "nonexistent")
        for old, new in ((missing, RESULTS), (RESULTS, missing)):
            with self.assertRaisesRegex(ValueError, "%s: no such results folder" % missing):
                compare.compare(old, new)

    def test_a_point_twice_is_an_error_naming_the_file_and_the_point(self):
        # A second row of a changed point would hide the change: neither side may hold one twice.
        def change(rows):
            twin = dict(rows[0])
            twin["sim_time_s"] = str(float(twin["sim_time_s"]) * 2)
            return rows + [twin]
        edit(os.path.join(self.new, FIG), change)
        for old, new in ((RESULTS, self.new), (self.new, RESULTS)):
            with self.assertRaisesRegex(ValueError, r"%s: line \d+: the point .*=.* is also on line 2"
                                        % os.path.join(self.new, FIG)):
                compare.compare(old, new)

    def test_an_unknown_column_is_an_error_naming_it(self):
        with self.assertRaisesRegex(ValueError, "--columns: no such column .*: nosuch$"):
            compare.compare(RESULTS, self.new, ["sim_time_s", "nosuch"])
        self.assertEqual(compare.compare(RESULTS, self.new, ["sim_time_s"])[1], [])

    def test_a_column_only_in_the_new_csv_is_compared(self):
        def change(rows):
            for r in rows:
                r["extra"] = "1"
            return rows
        path = os.path.join(self.new, FIG)
        with open(path, newline="") as f:
            columns = next(csv.reader(f))
        with open(path, newline="") as f:
            rows = change(list(csv.DictReader(f)))
        with open(path, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=columns + ["extra"], lineterminator="\n")
            w.writeheader()
            w.writerows(rows)
        _, diffs = compare.compare(RESULTS, self.new, ["extra"])
        self.assertTrue(diffs and all("extra None -> 1" in d for d in diffs), diffs[:2])

    def test_a_csv_that_is_not_utf8_is_named(self):
        path = os.path.join(self.new, FIG)
        with open(path, "ab") as f:
            f.write(b"\xff\xfe,\n")
        for old, new in ((RESULTS, self.new), (self.new, RESULTS)):
            with self.assertRaisesRegex(ValueError, "'%s': not UTF-8 text" % path):
                compare.compare(old, new)


if __name__ == "__main__":
    unittest.main()
