"""The machine file of a report (experiments/report machine): written, read back and compared."""
import os
import sys
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

    def test_bad_input(self):
        with self.assertRaises(ValueError):
            mf.from_report({"config": {"ips": [1, 1, 1]}})
        with self.assertRaisesRegex(ValueError, "m.toml:2:"):
            mf.read_machine_file('ips="1"\nmap=cyclic\n', "m.toml")

    def test_read_as_torusrt_sim_reads(self):
        # As torusrt-sim --config: '#' outside quotes is a comment, inside a path it is kept.
        text = 'ips="2x2x1" # four nodes\ntiming="run #2.timing"\n'
        self.assertEqual(mf.read_machine_file(text), {"ips": "2x2x1", "timing": "run #2.timing"})
        with self.assertRaisesRegex(ValueError, "m.toml:3: ips given twice"):
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


if __name__ == "__main__":
    unittest.main()
