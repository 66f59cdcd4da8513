"""The facts of a reproduction sweep's run (experiments/report/results.py, run_facts.csv) come
only from the points the figure CSVs are made from: the collection step writes them from the
points of points.tsv; `report plots` and `report reproduction` read them and change nothing, so
a stale point JSON lying in the results folder (an earlier sweep's, under another reading)
changes neither the facts nor the file."""
import csv
import json
import os
import shutil
import sys
import tempfile
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(REPO, "experiments"))

from report import collect, results  # noqa: E402

FIXTURE = os.path.join(REPO, "tests", "reports", "fixtures", "sweep", "calibrated")


def report(ips, mapping, ties, scene="paper-image1.nff", width=144):
    return {"status": "ok", "sim_time_s": 10.0, "t1_s": 100.0, "width": width, "height": width,
            "cells": [24, 24, 24], "scene": scene,
            "config": {"timing_profile": "calibrated", "options": {"map": mapping, "ips": ips, "route-ties": ties},
                       "timing": {"handover_send": 1000, "handover_receive": 1180, "cell_step_packet": 580}}}


def write_json(path, value):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        json.dump(value, f)


def facts_file(res):
    with open(os.path.join(res, results.FACTS_FILE), newline="") as f:
        return {row["key"]: row["value"] for row in csv.DictReader(f)}


class RunFacts(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.res = os.path.join(self.tmp.name, "calibrated")

    def tearDown(self):
        self.tmp.cleanup()

    def test_a_stale_point_beside_the_csvs_changes_neither_the_facts_nor_the_file(self):
        shutil.copytree(FIXTURE, self.res)
        with open(os.path.join(self.res, results.FACTS_FILE), "rb") as f:
            before = f.read()
        write_json(os.path.join(self.res, "fig5_6", "image1-cyclic-n1.json"), report("1x1x1", "block-cyclic:3", "plus"))
        write_json(os.path.join(self.res, "fig5_6", "image1-cyclic-n16.json"), report("4x2x2", "block-cyclic:3", "plus"))
        write_json(os.path.join(self.res, "t1", "image1.json"), report("1x1x1", "cyclic", "plus", width=48))
        facts = results.Results(self.res).facts
        self.assertEqual((facts.image_size, facts.lb_map, facts.route_ties, facts.shape16),
                         ("144x144", "?", "?", "4x2x2"))
        with open(os.path.join(self.res, results.FACTS_FILE), "rb") as f:
            self.assertEqual(f.read(), before)

    def test_collect_takes_the_facts_from_the_listed_points_only(self):
        listed = [["t1", "image1", "image1", "cyclic", "1", "1x1x1", "1", "replicated",
                   os.path.join(self.res, "t1", "image1.json"), "cmd"]]
        for n, ips in ((2, "2x1x1"), (16, "16x1x1")):
            listed.append(["fig5_6", "image1-cyclic-n%d" % n, "image1", "cyclic", str(n), ips, "1", "replicated",
                           os.path.join(self.res, "fig5_6", "image1-cyclic-n%d.json" % n), "cmd"])
        write_json(listed[0][8], report("1x1x1", "cyclic", "split"))
        for row in listed[1:]:
            write_json(row[8], report(row[5], "cyclic", "split"))
        # stale: sorted before the listed ones, from another reading
        write_json(os.path.join(self.res, "fig5_6", "image1-cyclic-n1.json"), report("1x1x1", "block-cyclic:3", "plus"))
        write_json(os.path.join(self.res, "t1", "image0.json"), report("1x1x1", "cyclic", "plus", width=48))
        with open(os.path.join(self.res, "points.tsv"), "w", newline="") as f:
            csv.writer(f, delimiter="\t", lineterminator="\n").writerows(listed)
        collect.collect(self.res)
        saved = facts_file(self.res)
        self.assertEqual((saved["image_size"], saved["t1_runs"], saved["lb_map"], saved["route_ties"],
                          saved["shape16"], saved["cell_step_us"]),
                         ("144x144", "1", "cyclic", "split", "16x1x1", "580"))
        self.assertEqual(results.Facts(self.res).lb_map, "cyclic")


if __name__ == "__main__":
    unittest.main()
