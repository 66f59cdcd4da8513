"""The machine file of a report (experiments/report machine): written, read back and compared."""
import json
import os
import subprocess
import sys
import tempfile
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(REPO, "experiments"))

from report import machine_file as mf  # noqa: E402

REPORT = {"config": {"ips": [2, 2, 1], "options": {"ips": "2x2x1", "map": "cyclic", "timing": 'a"b.timing'}}}


class MachineFile(unittest.TestCase):
    def test_written_file_reads_back(self):
        pairs = mf.from_report(REPORT)
        text = mf.toml_text(pairs)
        self.assertIn('ips="2x2x1"\n', text)
        self.assertIn('timing="a\\"b.timing"\n', text)  # a double quote is escaped
        self.assertEqual(mf.read_machine_file(text), dict(pairs))

    def test_written_in_the_reports_option_order(self):
        report = {"config": {"options": {"ips": "2", "map": "cost", "cluster": "4"},
                             "option_order": ["map", "cluster", "ips"]}}
        self.assertEqual([k for k, _ in mf.from_report(report)], ["map", "cluster", "ips"])

    def test_differences_name_every_key(self):
        pairs = mf.from_report(REPORT)
        other = {"ips": "4x1x1", "map": "cyclic", "cluster": "2"}
        self.assertEqual(mf.differences(pairs, other),
                         ["cluster: report (none), file '2'", "ips: report '2x2x1', file '4x1x1'",
                          "timing: report 'a\"b.timing', file (none)"])
        self.assertEqual(mf.differences(pairs, dict(pairs)), [])

    def test_an_option_order_that_is_not_a_list_of_names_is_named(self):
        for order in (None, 3, "ips", [["ips"]], {"ips": 0}):
            report = {"config": {"options": {"ips": "2"}, "option_order": order}}
            with self.assertRaisesRegex(ValueError, "^config.option_order: .*not a list of option names"):
                mf.from_report(report)

    def test_bad_input(self):
        with self.assertRaises(ValueError):
            mf.from_report({"config": {"ips": [1, 1, 1]}})
        with self.assertRaisesRegex(ValueError, "m.toml:2:5: Invalid value"):
            mf.read_machine_file('ips="1"\nmap=cyclic\n', "m.toml")

    def test_read_as_torusrt_sim_reads(self):
        # As torusrt-sim --config: '#' outside quotes is a comment, inside a path it is kept.
        text = 'ips="2x2x1" # four nodes\ntiming="run #2.timing"\n'
        self.assertEqual(mf.read_machine_file(text), {"ips": "2x2x1", "timing": "run #2.timing"})
        with self.assertRaisesRegex(ValueError, "m.toml:3:8: Cannot overwrite a value"):
            mf.read_machine_file('ips="1"\nmap="cyclic"\nips="2"\n', "m.toml")

    def test_bad_report_is_named(self):
        import tempfile
        import types
        from report import cli
        with tempfile.TemporaryDirectory() as tmp:
            for name, text in (("cut.json", "{"), ("old.json", '{"config": {}}')):
                path = os.path.join(tmp, name)
                with open(path, "w") as f:
                    f.write(text)
                with self.assertRaisesRegex(ValueError, "^" + path + ": "):
                    cli.machine(types.SimpleNamespace(report=path, compare=None))


    def test_a_value_that_is_not_a_string_or_an_unknown_key_is_refused(self):
        with self.assertRaisesRegex(ValueError, r"config.options.map: null, not a value"):
            mf.from_report({"config": {"options": {"ips": "2", "map": None}}})
        with self.assertRaisesRegex(ValueError, r"config.options.ips: \[2, 2\], not a value"):
            mf.from_report({"config": {"options": {"ips": [2, 2]}}})
        with self.assertRaisesRegex(ValueError, "config.options.frob: not a machine option"):
            mf.from_report({"config": {"options": {"ips": "2", "frob": "1"}, "option_order": ["ips"]}})

    def test_grouped_file_as_dump_config_writes_it(self):
        report = {"config": {"options": {"ips": "2x1x1", "queue": "8", "timing": "t.timing", "map": "block"},
                             "option_order": ["ips", "queue", "timing", "map"],
                             "option_tables": {"ips": "network", "queue": "network", "timing": "timing",
                                               "map": "mapping"}}}
        text = mf.toml_text(mf.from_report(report), mf.tables_from_report(report))
        self.assertEqual(text, '[network]\nips="2x1x1"\nqueue="8"\n\n[timing]\ntiming="t.timing"\n'
                               '\n[mapping]\nmap="block"\n')
        self.assertEqual(mf.read_machine_file(text), report["config"]["options"])
        self.assertEqual(mf.tables_from_dump(text), report["config"]["option_tables"])
        # A report without tables (older) gives a flat file, which reads too.
        del report["config"]["option_tables"]
        self.assertEqual(mf.toml_text(mf.from_report(report), mf.tables_from_report(report)),
                         'ips="2x1x1"\nqueue="8"\ntiming="t.timing"\nmap="block"\n')
        with self.assertRaisesRegex(ValueError, "map: no table"):
            mf.toml_text([("ips", "2"), ("map", "block")], {"ips": "network"})

    def test_flat_and_grouped_mix_and_a_key_given_twice_is_named(self):
        text = 'ips="2" # flat\n[network]\nqueue = "4"\n[timing]\nstyle = "lt"\n'
        self.assertEqual(mf.read_machine_file(text), {"ips": "2", "queue": "4", "style": "lt"})
        with self.assertRaisesRegex(ValueError, r"m.toml:3:1: ips given twice \(at the top and in \[network\]\)"):
            mf.read_machine_file('ips="2"\n[network]\nips="3"\n', "m.toml")
        with self.assertRaisesRegex(ValueError, r"m.toml:4:1: ips given twice \(in \[network\] and in \[timing\]\)"):
            mf.read_machine_file('[network]\nips="2"\n[timing]\nips="3"\n', "m.toml")
        with self.assertRaisesRegex(ValueError, r"m.toml: \[network.inner\]: a machine file's tables hold no tables"):
            mf.read_machine_file('[network.inner]\nips="2"\n', "m.toml")

    def test_numbers_keep_their_source_text(self):
        # As torusrt-sim reads them: the option's parser judges the text (0x10 is refused there).
        text = '[network]\nqueue = 0x10 # hex\ncells = 1_000\n[mapping]\nreplicate = inf\n'
        self.assertEqual(mf.read_machine_file(text), {"queue": "0x10", "cells": "1_000", "replicate": "inf"})
        self.assertEqual(mf.read_machine_file('network.queue = 8\nips = "2"\n'), {"queue": "8", "ips": "2"})
        with self.assertRaisesRegex(ValueError, r"m.toml:2:1: ips: an array"):
            mf.read_machine_file('[network]\nips = ["2", "2"]\n', "m.toml")
        with self.assertRaisesRegex(ValueError, r"m.toml:2:9: Illegal character"):
            mf.read_machine_file('ips="2"\nmap = "a\x01"\n', "m.toml")

    def test_tables_of_a_dump(self):
        import tempfile
        with tempfile.TemporaryDirectory() as tmp:
            sim = os.path.join(tmp, "torusrt-sim")
            with open(sim, "w") as f:
                f.write('#!/bin/sh\nprintf \'[network]\\nips="1x1x1"\\n\\n[cluster]\\ncluster="1"\\n\'\n')
            os.chmod(sim, 0o755)
            self.assertEqual(mf.option_tables(sim), {"ips": "network", "cluster": "cluster"})
            with open(sim, "w") as f:
                f.write("#!/bin/sh\necho no >&2; exit 2\n")
            with self.assertRaisesRegex(ValueError, "--dump-config: exit 2: no"):
                mf.option_tables(sim)


class MachineCommand(unittest.TestCase):
    def test_a_report_that_is_not_json_is_named_with_line_and_column(self):
        report = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))),
                              "experiments", "report")
        with tempfile.TemporaryDirectory() as d:
            toml = os.path.join(d, "m.toml")
            with open(toml, "w") as f:
                f.write('ips = "4x2x2"\n')
            done = subprocess.run([sys.executable, report, "machine", toml], stdin=subprocess.DEVNULL,
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        self.assertEqual((done.returncode, done.stdout), (1, ""), done.stderr)
        self.assertIn("%s: line 1 column 1: not a JSON run report (torusrt-sim --stats writes one)" % toml,
                      done.stderr)
        self.assertNotIn("Traceback", done.stderr)

    def test_a_key_or_value_no_machine_file_holds_is_named(self):
        # An option name that is no TOML bare key, a table name likewise, and a value with U+FFFD
        # (the report's stand-in for a byte that is not UTF-8): refused naming the report and the
        # key, nothing on standard output; the same report with a plain value is written.
        report = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))),
                              "experiments", "report")
        cases = ((("q\nx", "1", "network"), 'config.options: "q\\nx": not an option name'),
                 (("a b", "1", "network"), 'config.options: "a b": not an option name'),
                 (("", "1", "network"), 'config.options: "": not an option name'),
                 (("timing", "t\ufffd.timing", "timing"), "config.options.timing: \"t\\ufffd.timing\" holds U+FFFD"),
                 (("timing", "t.timing", "a]\n["), 'config.option_tables.timing: "a]\\n[": not a table name'),
                 (("timing", "t\ud800", "timing"), 'config.options.timing: "t\\ud800" holds a lone surrogate'),
                 (("timing", "t.timing", "timing"), None))
        for (key, value, table), why in cases:
            with self.subTest(key=key, value=value, table=table), tempfile.TemporaryDirectory() as d:
                path = os.path.join(d, "r.json")
                with open(path, "w") as f:
                    json.dump({"config": {"options": {key: value}, "option_order": [key],
                                          "option_tables": {key: table}}}, f)
                done = subprocess.run([sys.executable, report, "machine", path], stdin=subprocess.DEVNULL,
                                      stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
                if why is None:
                    self.assertEqual((done.returncode, done.stdout), (0, '[timing]\ntiming="t.timing"\n'), done.stderr)
                    continue
                self.assertEqual((done.returncode, done.stdout), (1, ""), done.stderr)
                self.assertIn("experiments/report: %s: %s" % (path, why), done.stderr)


if __name__ == "__main__":
    unittest.main()
