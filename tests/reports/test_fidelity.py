"""The fidelity study, round two (experiments/report/fidelity*.py): the score's ordering, excesses
and ties, the hand-overs a per-step cost allows, the T(1) identity, the stages read back from
their runs, the claims' roles and three counts, and the machine files it writes."""
import argparse
import io
import json
import os
import sys
import tempfile
import unittest
from contextlib import redirect_stdout

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(REPO, "experiments"))

from report import fidelity  # noqa: E402
from report import fidelity_score as fs  # noqa: E402
from report import fidelity_means as fm  # noqa: E402
from report import fidelity_stages as st  # noqa: E402


def write_json(path, data):
    with open(path, "w") as f:
        json.dump(data, f)


def write_rows(path, rows):
    with open(path, "w") as f:
        f.write("".join("\t".join(map(str, r)) + "\n" for r in rows))


class Excess(unittest.TestCase):
    def test_inside_below_above(self):
        self.assertEqual(fs.excess(1.2, 1.05, 1.5), 0)
        self.assertEqual(fs.excess(1.05, 1.05, 1.5), 0, "the band's ends are inside")
        self.assertAlmostEqual(fs.excess(0.84, 1.05, 1.5), (1.05 - 0.84) / 1.05)
        self.assertAlmostEqual(fs.excess(1.8, 1.05, 1.5), (1.8 - 1.5) / 1.5)

    def test_bands_of_the_protocol(self):
        t = fs.TARGETS
        self.assertEqual((t["t1_image1"]["lo"], t["t1_image1"]["hi"]), (508, 635))
        self.assertEqual((t["t1_image2"]["lo"], t["t1_image2"]["hi"]), (1098, 1372))
        self.assertAlmostEqual(t["t1_image1"]["point"], 571.392)
        self.assertAlmostEqual(t["time_image2"]["lo"], 0.8 * 1.34)
        self.assertAlmostEqual(t["units_32"]["hi"], 1.05 * 432)
        self.assertEqual((t["memory_image1"]["lo"], t["memory_image1"]["hi"], t["memory_image1"]["point"]), (6, 7, 6.5))
        self.assertAlmostEqual(t["penalty_image1"]["point"], 0.75 / 0.62)


class Score(unittest.TestCase):
    def test_the_largest_excess_first(self):
        # One unmet target cannot hide behind met ones: 0.3 loses to 0.2 + 0.2 + 0.2.
        one_big = {"penalty_image1": 1.5 * 1.3, "penalty_image2": 1.2}
        many_small = {"penalty_image1": 1.5 * 1.2, "penalty_image2": 1.05 * 0.8}
        self.assertLess(fs.score(fs.excesses(many_small)), fs.score(fs.excesses(one_big)))
        self.assertEqual(fs.best([(0, one_big, 0, "a"), (1, many_small, 2, "b")])[3], "b")

    def test_then_the_next_excess(self):
        a = {"penalty_image1": 1.5 * 1.2, "penalty_image2": 1.5 * 1.1}
        b = {"penalty_image1": 1.5 * 1.2, "penalty_image2": 1.5 * 1.05}
        self.assertEqual(fs.best([(0, a, 0, "a"), (1, b, 1, "b")])[3], "b")

    def test_ties_fewer_moved_then_residual_then_order(self):
        near = {"penalty_image1": 1.22, "penalty_image2": 1.26}
        far = {"penalty_image1": 1.4, "penalty_image2": 1.45}
        self.assertEqual(fs.best([(0, near, 2, "near"), (1, far, 1, "far")])[3], "far", "fewer unknowns moved")
        self.assertEqual(fs.best([(0, far, 1, "far"), (1, near, 1, "near")])[3], "near", "the smaller residual")
        self.assertEqual(fs.best([(0, near, 1, "first"), (1, dict(near), 1, "second")])[3], "first")

    def test_moved(self):
        self.assertEqual(fs.moved({"bus": "2", "memory": "0.5"}, {"bus": "0.5", "memory": "0.5"}), 1)


class CellStep(unittest.TestCase):
    def test_allowed_handovers(self):
        self.assertEqual(fs.allowed_handovers(0), (0, 580, 2180))
        self.assertEqual(fs.allowed_handovers("580"), (0, 1600), "analysis per step: creation may remain")
        self.assertEqual(fs.allowed_handovers(1600), (0, 580), "creation per step: analysis may remain")
        self.assertEqual(fs.allowed_handovers(2180), (0,))
        self.assertRaises(ValueError, fs.allowed_handovers, 100)
        self.assertEqual(fs.HANDOVER_KEYS[1600], (1600, 0))

    def test_identity(self):
        self.assertAlmostEqual(fs.t1_with_cost(280.0, 1065, 332000), 280.0 + 353.58)
        self.assertTrue(fs.identity_holds(600.0, 600.5))
        self.assertFalse(fs.identity_holds(600.0, 601.0))


class ClaimRoles(unittest.TestCase):
    def test_three_counts_split_fit_targets_from_validation(self):
        from report.verdict import FAILS, HOLDS
        verdicts = [FAILS] * 17
        for i in (4, 6, 7, 8, 12, 16):
            verdicts[i - 1] = HOLDS
        (a, n), (f, nf), (v, nv) = fidelity.counts(verdicts)
        self.assertEqual((a, n), (6, 17))
        self.assertEqual((f, nf), (4, 8), "6, 7, 8, 12 of 6, 7, 8, 9, 10, 11, 12, 17")
        self.assertEqual((v, nv), (2, 9), "4 and 16 of 1, 2, 3, 4, 5, 13, 14, 15, 16")
        lines = fidelity.counts_lines(verdicts)
        self.assertIn("Claims holding: 6 of 17", lines[0])
        self.assertIn("Fit targets holding: 4 of 8", lines[1])
        self.assertIn("Validation claims holding: 2 of 9", lines[2])

    def test_roles(self):
        self.assertIn("fit target", fidelity.role(12))
        self.assertIn("F0", fidelity.role(12))
        self.assertIn("F4", fidelity.role(17))
        self.assertIn("derived", fidelity.role(8))
        self.assertEqual(fidelity.role(1), "validation")
        self.assertIn("any space partition", fidelity.role(16))


class Stages(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.res = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def path(self, name, data):
        p = os.path.join(self.res, name + ".json")
        write_json(p, data)
        return p

    def test_a_stage_without_runs_is_named(self):
        # A results folder whose stage has not run: a message naming its table, not an IndexError.
        for stage, table in ((st.stage2, "stage2.tsv"), (st.stage3, "stage3.tsv"), (st.stage4, "stage4.tsv")):
            with self.assertRaisesRegex(ValueError, "%s: no runs" % table):
                stage(self.res)

    def test_stage1_picks_the_cost_that_puts_t1_in_the_window(self):
        # Smoke lists: image 1 planar / planar-z, rules sequential / per-plane, one image 2 variant.
        units = []
        for layout in ("planar", "planar-z"):
            for rule in ("sequential", "per-plane"):
                u = (9438, 738, 432) if (layout, rule) == ("planar-z", "per-plane") else (17000, 1300, 800)
                p = self.path("u-%s-%s" % (layout, rule), {"preprocess": {"units_parallel_by_p":
                                                                          {"1": u[0], "16": u[1], "32": u[2]}}})
                units.append((layout, "1", rule, p))
        write_rows(os.path.join(self.res, "units.tsv"), units)
        s1, s2 = st.specs(st.SMOKE["IMAGE1"]), st.specs(st.SMOKE["IMAGE2"])
        # T(1)|0 = 300 s with 150 000 cell steps: c = 1600 gives 540 s (in [508, 635]); image 2
        # 600 s + 0.3e6 steps x 1600 us = 1080 s (below 1098) and x 2180 us = 1254 s (inside).
        t1 = [("image1", s, 0, self.path("t1-%d" % i, {"sim_time_s": 300.0, "ops": {"cell_steps": 150000}}))
              for i, s in enumerate(s1)]
        t1 += [("image2", s2[0], 0, self.path("t1-2", {"sim_time_s": 600.0, "ops": {"cell_steps": 300000}}))]
        write_rows(os.path.join(self.res, "t1.tsv"), t1)
        choice, ranked, _ = st.stage1(self.res, smoke=True)
        self.assertEqual(choice["spec1"], s1[1])
        self.assertEqual(choice["rule"], "per-plane")
        # c = 2180: image 1 at 627 s (inside) and image 2 inside; c = 1600 leaves image 2 below.
        self.assertEqual(choice["cell_step"], 2180)
        self.assertEqual(max(fs.excesses(ranked[0][1]).values()), 0)
        out = io.StringIO()
        with redirect_stdout(out):
            fidelity.fit1(argparse.Namespace(results=self.res, smoke=True))
        self.assertEqual(out.getvalue().split("\t")[-1].strip(), "2180")

    def test_identity_command(self):
        write_rows(os.path.join(self.res, "t1.tsv"),
                   [("image1", "x", 0, self.path("z", {"sim_time_s": 300.0, "ops": {"cell_steps": 100000}}))])
        write_rows(os.path.join(self.res, "identity.tsv"),
                   [("image1", "x", 580, self.path("m", {"sim_time_s": 358.0}))])
        with redirect_stdout(io.StringIO()):
            self.assertEqual(fidelity.identity(argparse.Namespace(results=self.res)), 0)
            write_rows(os.path.join(self.res, "identity.tsv"),
                       [("image1", "x", 580, self.path("m", {"sim_time_s": 359.0}))])
            self.assertEqual(fidelity.identity(argparse.Namespace(results=self.res)), 1)

    def test_stage2_scores_the_mean_of_the_runs(self):
        rows = []
        # bus 0.5: shared as fast as replicated (penalty 1.0, below the band); bus 2: shared runs
        # of 1.2 and 1.3 s, a penalty of 1.25 on their mean.
        for bus, shared in (("0.5", (1.0, 1.0)), ("2", (1.2, 1.3))):
            for img in ("image1", "image2"):
                for a, s in zip(("0.245", "0.255"), shared):
                    for data, v in (("replicated", 1.0), ("shared", s)):
                        p = self.path("%s-%s-%s-%s" % (bus, img, data, a), {"sim_time_s": v})
                        rows.append(("4x2x2", 0, bus, "1", img, data, a, p))
        write_rows(os.path.join(self.res, "stage2.tsv"), rows)
        choice, ranked = st.stage2(self.res)
        self.assertEqual(choice, {"bus": "2", "memory": "1"})
        self.assertAlmostEqual(ranked[0][1]["penalty_image1"], 1.25)
        self.assertEqual(ranked[0][4][("image1", "shared")]["spread"], (1.2, 1.3))

    def test_stage4_memory_ratio(self):
        rows = []
        for h, ratio in (("4", 5.0), ("0", 6.4)):
            for img in ("image1", "image2"):
                p = self.path("m-%s-%s" % (h, img), {"memory": {"pixel_partitioned_bytes": ratio * 1000,
                                                                "total_bytes": 1000}})
                rows.append((h, "4", "0", img, p))
        write_rows(os.path.join(self.res, "stage4.tsv"), rows)
        self.assertEqual(st.stage4(self.res)[0], {"header": "0", "entry": "4", "record": "0"})

    def test_machine_files(self):
        out = os.path.join(self.res, "machines")
        sim = os.path.join(self.res, "torusrt-sim")  # its --dump-config: each key's table, in its order
        with open(sim, "w") as f:
            f.write("#!/bin/sh\ncat <<'EOF'\n[network]\nips=\"1x1x1\"\nroute-ties=\"split\"\n"
                    "preprocess-count=\"sequential\"\n\n[timing]\ntiming-profile=\"calibrated\"\ntiming=\"\"\n"
                    "\n[cluster]\ncluster=\"1\"\ndata=\"replicated\"\ncell-header-bytes=\"4\"\n"
                    "list-entry-bytes=\"4\"\nobject-record-bytes=\"0\"\n\n[mapping]\nmap=\"cyclic\"\nEOF\n")
        os.chmod(sim, 0o755)
        fidelity.machines(argparse.Namespace(results=self.res, out=out, rule="per-plane", bus="2", memory="1",
                                             shape="4x4", handover="1600", cell_step="580", header="2", entry="2",
                                             record="36", sim=sim))
        with open(os.path.join(out, "paper-1024-shared.toml")) as f:
            text = f.read()
        self.assertTrue(text.startswith("# paper-1024-shared.toml - "))
        body = text[text.index("[network]"):]
        self.assertEqual(body, '[network]\nips="4x4"\nroute-ties="split"\npreprocess-count="per-plane"\n\n'
                               '[timing]\ntiming-profile="calibrated"\ntiming="timing/fitted.timing"\n\n'
                               '[cluster]\ncluster="64"\ndata="shared"\ncell-header-bytes="2"\nlist-entry-bytes="2"\n'
                               'object-record-bytes="36"\n\n[mapping]\nmap="cyclic"\n')
        from report import machine_file as mf
        self.assertEqual(mf.read_machine_file(text)["cluster"], "64")
        with open(os.path.join(out, "timing", "fitted.timing")) as f:
            keys = dict(line.split() for line in f if line.strip() and not line.startswith("#"))
        self.assertEqual((keys["bus_cycle"], keys["memory_access"], keys["cell_step_packet"]), ("2", "1", "580"))
        self.assertEqual((keys["handover_send"], keys["handover_receive"]), ("1600", "0"))
        self.assertEqual(keys["shading"], "4600")  # the rest is the calibrated profile's


class MeanOfFive(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.res = self.tmp.name
        os.makedirs(os.path.join(self.res, "fig10_12"))
        os.makedirs(os.path.join(self.res, "fig5_6"))

    def tearDown(self):
        self.tmp.cleanup()

    def test_cluster_points_run_once_per_arbitration_and_the_point_is_their_mean(self):
        c = os.path.join(self.res, "fig10_12", "image1-shared-m64.json")
        f = os.path.join(self.res, "fig5_6", "image1-cyclic-n16.json")
        phase2 = os.path.join(self.res, "points.phase2")
        write_rows(phase2, [(c, "run_point.sh %s --t1-from t1.json -- sim scene.nff --cluster 64" % c),
                            (f, "run_point.sh %s -- sim scene.nff --ips 4x2x2" % f)])
        flat, reps = os.path.join(self.res, "flat"), os.path.join(self.res, "reps")
        fm.split_lists(phase2, flat, reps, ["0.240", "0.260"])
        with open(flat) as fh:
            self.assertEqual([line.split("\t")[0] for line in fh], [f])
        with open(reps) as fh:
            lines = [line.rstrip("\n").split("\t") for line in fh]
        self.assertEqual([x[0] for x in lines], [fm.replica(c, "0.240"), fm.replica(c, "0.260")])
        self.assertTrue(lines[1][1].endswith("--cluster 64 --timing-values bus_arbitration=0.260"))
        self.assertIn(fm.replica(c, "0.240") + " --t1-from", lines[0][1])
        self.assertFalse(fm.mean_point(c, ["0.240", "0.260"]), "a missing run writes nothing")
        self.assertFalse(os.path.exists(c))
        for a, t, e in (("0.240", 1.0, 0.8), ("0.260", 1.2, 0.6)):
            write_json(fm.replica(c, a), {"sim_time_s": t, "efficiency": e, "load_balance": e, "bus": a})
        self.assertTrue(fm.mean_point(c, ["0.240", "0.260"]))
        with open(c) as fh:
            j = json.load(fh)
        self.assertAlmostEqual(j["sim_time_s"], 1.1)
        self.assertAlmostEqual(j["efficiency"], 0.7)
        self.assertEqual(j["arbitration_runs"]["sim_time_s"], [1.0, 1.2])
        # Again: the mean of the runs, not of the mean.
        self.assertTrue(fm.mean_point(c, ["0.240", "0.260"]))
        self.assertEqual(fm.spreads(self.res)["image1-shared-m64"], (1.1, 1.0, 1.2, 2))


if __name__ == "__main__":
    unittest.main()
