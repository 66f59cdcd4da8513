"""The collection step (experiments/report collect.py) on a made-up results folder: one point
with a report, one that failed (its log exists), one never run; fields by name, the derived
columns, the paper's numbers, the sort order and the image check."""
import csv
import json
import os
import sys
import tempfile
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(REPO, "experiments"))

from report import collect  # noqa: E402

REPORT = {
    "sim_time_s": 50.0, "t1_s": 400.0, "ips": 16, "efficiency_t1": 0.5, "efficiency_busy": 0.9,
    "memory": {"max_per_ip_bytes": 1000, "total_bytes": 16000, "pixel_partitioned_bytes": 96000,
               "whole_scene_bytes": 6000, "ratio_to_pixel_partitioned": 0.1666},
    "preprocess": {"units_serial": 9000, "units_parallel": 700},
    "packets": {"created": {"total": 123}, "forwarded": 45, "conserved": True},
    "links": {"packets": 45, "utilisation": {"mean": 0.0}},
    "load": {"busy_s": {"max": 40.5, "mean": 30.25}}, "wall_s": 1.5,
    "config": {"timing": {"bus_cycle": 0.5, "bus_width_bytes": 2}},
}


class Collect(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        res = self.res = self.tmp.name
        os.makedirs(os.path.join(res, "fig5_6"))
        os.makedirs(os.path.join(res, "t1"))
        points = []
        for name, n, mapping in (("image1-cyclic-n16", 16, "cyclic"), ("image1-block-n16", 16, "block"),
                                 ("image1-block-n2", 2, "block")):
            points.append(["fig5_6", name, "image1", mapping, str(n), "4x2x2", "1", "replicated",
                           os.path.join(res, "fig5_6", name + ".json"), "cmd"])
        with open(os.path.join(res, "points.tsv"), "w", newline="") as f:
            csv.writer(f, delimiter="\t", lineterminator="\n").writerows(points)
        with open(points[0][8], "w") as f:
            json.dump(REPORT, f)
        for path, data in ((os.path.join(res, "t1", "image1.png"), b"png"), (points[0][8][:-5] + ".png", b"png"),
                           (points[1][8][:-5] + ".log", b"torusrt-sim: bad\n")):
            with open(path, "wb") as f:
                f.write(data)

    def tearDown(self):
        self.tmp.cleanup()

    def table(self, name):
        with open(os.path.join(self.res, name + ".csv"), newline="") as f:
            return list(csv.DictReader(f))

    def test_rows_statuses_and_fields(self):
        self.assertEqual(collect.collect(self.res), (3, 2, 0))
        rows = self.table("fig5_6")
        self.assertEqual([(r["mapping"], r["n"], r["status"]) for r in rows],
                         [("block", "2", "missing"), ("block", "16", "failed"), ("cyclic", "16", "ok")])
        ok = rows[2]
        self.assertEqual((ok["sim_time_s"], ok["speedup"], ok["busy_mean_s"], ok["packets_conserved"]),
                         ("50", "8", "30.25", "true"))
        self.assertEqual((ok["link_util_mean"], ok["image_identical"]), ("0", "yes"))
        self.assertEqual(rows[1]["sim_time_s"], "")

    def test_memory_and_preprocessing_columns(self):
        collect.collect(self.res)
        memory = self.table("fig7")[2]
        self.assertEqual((memory["max_per_ip_bytes"], memory["pixel_partitioned_over_total"]), ("1000", "6"))
        pre = self.table("fig8")
        self.assertEqual([r["n"] for r in pre], ["2", "16"])  # block-mapping points only
        self.assertEqual((pre[1]["paper_units"], pre[1]["paper_speedup"], pre[1]["speedup"]), ("738", "12.7886", ""))

    def test_an_image_that_differs_is_flagged(self):
        with open(os.path.join(self.res, "fig5_6", "image1-cyclic-n16.png"), "wb") as f:
            f.write(b"other")
        self.assertEqual(collect.collect(self.res)[2], 1)
        self.assertEqual(self.table("fig5_6")[2]["image_identical"], "no")

    def test_a_sweep_folder_is_named_not_a_key_error(self):
        with open(os.path.join(self.res, "points.tsv"), "w") as f:
            f.write("name\tips\nips_1\t1\n")  # experiments/sweep's table
        with self.assertRaisesRegex(ValueError, r"points.tsv:1: 2 columns, not the 9 or more"):
            collect.collect(self.res)

    def test_a_point_json_that_is_not_an_object_is_named(self):
        path = os.path.join(self.res, "fig5_6", "image1-cyclic-n16.json")
        with open(path, "w") as f:
            f.write("[1]")
        with self.assertRaisesRegex(ValueError, "%s: not a JSON report \\(a list" % path):
            collect.collect(self.res)

    def test_a_point_json_or_image_that_is_a_fifo_is_named_never_opened(self):
        path = os.path.join(self.res, "fig5_6", "image1-cyclic-n16.json")
        os.remove(path)
        os.mkfifo(path)
        with self.assertRaisesRegex(OSError, "point JSON '%s': is a FIFO, not a regular file" % path):
            collect.collect(self.res)
        os.remove(path)
        with open(path, "w") as f:
            json.dump(REPORT, f)
        png = path[:-5] + ".png"
        os.remove(png)
        os.mkfifo(png)  # an image that is no file is not the 1-processor image (and is never opened)
        collect.collect(self.res)
        self.assertEqual(self.table("fig5_6")[2]["image_identical"], "no")

    def test_a_figure_csv_that_links_to_an_input_is_refused_and_the_input_kept(self):
        json_path = os.path.join(self.res, "fig5_6", "image1-cyclic-n16.json")
        for name, target in (("fig10_12.csv", "points.tsv"), ("fig7.csv", json_path)):
            with self.subTest(name=name):
                link = os.path.join(self.res, name)
                os.symlink(target, link)
                with open(os.path.join(self.res, target), "rb") as f:
                    before = f.read()
                with self.assertRaisesRegex(ValueError, "is the (points table|point JSON) file"):
                    collect.collect(self.res)
                with open(os.path.join(self.res, target), "rb") as f:
                    self.assertEqual(f.read(), before)
                os.remove(link)

    def test_number_spelling(self):
        self.assertEqual(collect.json_text(2.0), "2")
        self.assertEqual(collect.json_text(0.1), "0.1")
        self.assertEqual(collect.json_text(False), "false")
        self.assertEqual(collect.number_text(439.12252 / 84.42176), "5.20153")


if __name__ == "__main__":
    unittest.main()
