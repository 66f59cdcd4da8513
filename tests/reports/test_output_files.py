"""experiments/output_files.py, the one way the Python tools write files: through a temporary
renamed into place, links followed, folders, FIFOs and devices refused naming the option, an
output never an input nor another output's file. Also the sweep's point identity and report
check (experiments/report/sweep.py) and the backend's -j (experiments/backend/cli.py)."""
import contextlib
import io
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import unittest
from unittest import mock

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(REPO, "experiments"))

import output_files as of  # noqa: E402
from backend import cli as backend_cli  # noqa: E402
from report import sweep  # noqa: E402


def read(path):
    with open(path) as f:
        return f.read()


def write(path, text):
    with open(path, "w") as f:
        f.write(text)


class Base(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, self.dir)

    def path(self, *names):
        return os.path.join(self.dir, *names)

    def listing(self):
        return sorted(os.listdir(self.dir))


class Writing(Base):
    def test_written_whole_and_no_temporary_left(self):
        of.write_text(self.path("a.csv"), "x,y\n")
        self.assertEqual(read(self.path("a.csv")), "x,y\n")
        self.assertEqual(self.listing(), ["a.csv"])

    def test_new_file_mode_follows_umask(self):
        old = os.umask(0o022)
        self.addCleanup(os.umask, old)
        of.write_text(self.path("a"), "1")
        self.assertEqual(os.stat(self.path("a")).st_mode & 0o777, 0o644)

    def test_error_in_the_middle_keeps_the_old_file(self):
        write(self.path("a.csv"), "old\n")
        with self.assertRaises(RuntimeError):
            with of.atomic(self.path("a.csv")) as f:
                f.write("half")
                raise RuntimeError("stop")
        self.assertEqual(read(self.path("a.csv")), "old\n")
        self.assertEqual(self.listing(), ["a.csv"])

    def test_interrupt_removes_the_temporary(self):
        with self.assertRaises(KeyboardInterrupt):
            with of.atomic(self.path("a.csv")) as f:
                f.write("half")
                raise KeyboardInterrupt
        self.assertEqual(self.listing(), [])

    def test_a_failed_write_names_the_file_and_leaves_nothing(self):
        class Full:
            def __init__(self, f):
                self.f = f

            def write(self, data):
                raise OSError(28, "No space left on device")

            def __getattr__(self, name):
                return getattr(self.f, name)

            def __enter__(self):
                return self

            def __exit__(self, *exc):
                self.f.close()
        real_fdopen = os.fdopen
        with mock.patch.object(of.os, "fdopen", lambda *a, **k: Full(real_fdopen(*a, **k))):
            with self.assertRaisesRegex(OSError, "^%s: cannot write: No space left on device$" % self.path("a.csv")):
                of.write_text(self.path("a.csv"), "x")
        self.assertEqual(self.listing(), [])

    def test_sigterm_removes_the_temporary(self):
        code = ("import os, signal, sys; sys.path.insert(0, %r); import output_files as of; of.exit_on_signals()\n"
                "with of.atomic(%r) as f:\n    f.write('half'); f.flush(); os.kill(os.getpid(), signal.SIGTERM)\n"
                % (os.path.join(REPO, "experiments"), self.path("a.csv")))
        done = subprocess.run([sys.executable, "-c", code])
        self.assertEqual(done.returncode, 128 + signal.SIGTERM)
        self.assertEqual(self.listing(), [])

    def test_a_link_is_followed_and_kept(self):
        write(self.path("real.csv"), "old\n")
        os.symlink("real.csv", self.path("link.csv"))
        of.write_text(self.path("link.csv"), "new\n")
        self.assertTrue(os.path.islink(self.path("link.csv")))
        self.assertEqual(read(self.path("real.csv")), "new\n")
        self.assertEqual(self.listing(), ["link.csv", "real.csv"])

    def test_a_dangling_link_makes_its_target(self):
        os.mkdir(self.path("sub"))
        os.symlink(os.path.join("sub", "t.csv"), self.path("link.csv"))
        of.write_text(self.path("link.csv"), "new\n")
        self.assertTrue(os.path.islink(self.path("link.csv")))
        self.assertEqual(read(self.path("sub", "t.csv")), "new\n")

    def test_append_keeps_what_was_there(self):
        of.append_text(self.path("r.tsv"), "a\n")
        of.append_text(self.path("r.tsv"), "b\n")
        self.assertEqual(read(self.path("r.tsv")), "a\nb\n")

    def test_copy(self):
        write(self.path("src"), "bytes")
        of.copy_file(self.path("src"), self.path("dst"))
        self.assertEqual(read(self.path("dst")), "bytes")

    def test_staged_for_another_program(self):
        with of.staged(self.path("p.png"), "--out") as tmp:
            self.assertEqual(os.path.dirname(tmp), self.dir)
            self.assertTrue(tmp.endswith(".png"))
            write(tmp, "picture")
        self.assertEqual(read(self.path("p.png")), "picture")
        self.assertEqual(self.listing(), ["p.png"])

    def test_staged_that_wrote_nothing_fails_and_leaves_nothing(self):
        with self.assertRaisesRegex(OSError, "p.png: cannot write"):
            with of.staged(self.path("p.png"), "--out"):
                pass
        self.assertEqual(self.listing(), [])

    def test_staged_that_failed_leaves_the_old_file(self):
        write(self.path("p.png"), "old")
        with self.assertRaises(RuntimeError):
            with of.staged(self.path("p.png")) as tmp:
                write(tmp, "half")
                raise RuntimeError("gnuplot failed")
        self.assertEqual(read(self.path("p.png")), "old")
        self.assertEqual(self.listing(), ["p.png"])


class Refused(Base):
    def assert_refused(self, path, pattern):
        with self.assertRaisesRegex(of.OutputError, pattern):
            of.write_text(path, "x", "--out")

    def test_folder(self):
        os.mkdir(self.path("d"))
        self.assert_refused(self.path("d"), r"^--out '.*d': is a folder$")

    def test_link_to_a_folder(self):
        os.mkdir(self.path("d"))
        os.symlink("d", self.path("l"))
        self.assert_refused(self.path("l"), "is a folder")

    def test_fifo_refused_without_waiting_for_a_reader(self):
        os.mkfifo(self.path("f"))
        self.assert_refused(self.path("f"), r"^--out '.*f': is a FIFO, not a regular file$")

    def test_device(self):
        self.assert_refused("/dev/null", "^--out '/dev/null': is a character device, not a regular file$")

    def test_missing_folder(self):
        self.assert_refused(self.path("no", "a.csv"), "folder '.*no' does not exist")

    def test_empty_name(self):
        self.assert_refused("", "^--out: an empty file name$")

    def test_link_loop(self):
        os.symlink("b", self.path("a"))
        os.symlink("a", self.path("b"))
        with self.assertRaises(of.OutputError):
            of.write_text(self.path("a"), "x", "--out")

    def test_dangling_link_into_no_folder_names_that_folder(self):
        os.symlink(os.path.join("gone", "t.csv"), self.path("l.csv"))
        self.assert_refused(self.path("l.csv"), "folder '.*gone' does not exist")

    def test_a_stream_through_proc_or_dev_fd(self):
        os.symlink("/proc/self/fd/1", self.path("to_stdout"))
        for name in ("/dev/stdout", "/dev/stderr", "/dev/fd/1", "/proc/self/fd/2", self.path("to_stdout")):
            with self.assertRaisesRegex(of.OutputError, "is a stream or a file another process holds open"):
                of.target("--out", name)

    def test_an_input_must_be_a_regular_utf8_file(self):
        os.mkfifo(self.path("fifo"))
        for name, why in (("/dev/zero", "is a character device"), (self.path("fifo"), "is a FIFO"),
                          (self.dir, "is a folder"), (self.path("none"), "No such file")):
            with self.assertRaisesRegex(OSError, "the list '%s': %s" % (name, why)):
                of.read_text(name, "the list")
        with open(self.path("bin"), "wb") as f:
            f.write(b"ok\xff")
        with self.assertRaisesRegex(ValueError, "the list '%s': not UTF-8 text .byte 2." % self.path("bin")):
            of.read_text(self.path("bin"), "the list")

    def test_output_options_found(self):
        self.assertEqual(of.output_options(["--size", "8x8", "--vcd=v.vcd", "-o", "a.png", "--stats", "s"]),
                         ["--vcd", "-o", "--stats"])
        self.assertEqual(of.output_options(["--size", "8x8", "--map-file", "m"]), [])

    def test_glued_short_output_found(self):
        # CLI11 reads -oFILE and -qoFILE as -o FILE: a refusal must see them too.
        self.assertEqual(of.output_values(["-ox.png", "-qoy.png", "--stats=s.json", "-q", "--quantum", "1"]),
                         [("-o", "x.png"), ("-o", "y.png"), ("--stats", "s.json")])
        self.assertEqual(of.output_values(["--size", "8x8", "-o"]), [("-o", None)])

    def test_options_that_run_nothing_found(self):
        self.assertEqual(of.unusable_option(["--size", "8x8", "--dump-config"]), "--dump-config")
        self.assertEqual(of.unusable_option(["--version=1"]), "--version")
        self.assertEqual(of.unusable_option(["-qh"]), "-h")
        self.assertIsNone(of.unusable_option(["-q", "--ips", "2", "--frames", "2"]))
        self.assertEqual(of.unusable_option(["--frames", "2"], of.ANIMATION_OPTIONS), "--frames")

    def test_list_values_checked(self):
        self.assertEqual(of.list_values("--map", "block,cyclic"), ["block", "cyclic"])
        for text, pattern in (("block,", "an empty value"), ("", "an empty value"), ("a,,b", "value 2"),
                              ("block,block", "'block' is given twice")):
            with self.assertRaisesRegex(ValueError, "--map '%s': .*%s" % (text, pattern)):
                of.list_values("--map", text)

    def test_empty_value_refused_by_argparse(self):
        import argparse
        parser = argparse.ArgumentParser()
        parser.add_argument("--state", type=of.nonempty)
        with contextlib.redirect_stderr(io.StringIO()) as err, self.assertRaises(SystemExit) as done:
            parser.parse_args(["--state", ""])
        self.assertEqual(done.exception.code, 2)
        self.assertIn("--state: an empty value", err.getvalue())

    def test_out_folder_that_is_a_file_refused(self):
        scene = self.path("s.nff")
        of.write_text(scene, "x")
        with self.assertRaisesRegex(of.OutputError, "--out '.*s.nff': is the scene file .*s.nff, an input"):
            of.out_folder("--out", scene, [("scene", scene)])
        with self.assertRaisesRegex(of.OutputError, "is a file, not a folder"):
            of.out_folder("--state", scene)
        with self.assertRaisesRegex(of.OutputError, "an empty value"):
            of.out_folder("--state", "")
        self.assertEqual(of.out_folder("--out", self.path("new")), self.path("new"))
        self.assertFalse(os.path.exists(self.path("new")))  # checked, not made

    def test_standard_output_on_a_full_device_named(self):
        done = subprocess.run([sys.executable, "-c", "import sys; sys.path.insert(0, %r)\n"
                               "import output_files as of\nof.named_stdout()\n"
                               "try:\n    print('x' * 100000)\n    of.finish_stdout()\n"
                               "except OSError as e:\n    print(e, file=sys.stderr); sys.exit(1)"
                               % os.path.join(REPO, "experiments")],
                              stdout=open("/dev/full", "w"), stderr=subprocess.PIPE, text=True)
        self.assertEqual(done.returncode, 1)
        self.assertEqual(done.stderr, "standard output: cannot write: No space left on device\n")

    def test_refused_is_a_value_error(self):
        self.assertTrue(issubclass(of.OutputError, ValueError))


class ShellCommand(Base):
    """`python3 output_files.py FILE [OPTION]`, the shell scripts' write_file."""

    def write_file(self, *args):
        return subprocess.run([sys.executable, os.path.join(REPO, "experiments", "output_files.py")] + list(args),
                              input=b"rows\n", stdout=subprocess.PIPE, stderr=subprocess.PIPE)

    def test_writes_standard_input(self):
        done = self.write_file(self.path("list"), "--results")
        self.assertEqual(done.returncode, 0, done.stderr)
        self.assertEqual(read(self.path("list")), "rows\n")
        self.assertEqual(self.listing(), ["list"])

    def test_refuses_a_fifo_naming_the_option(self):
        os.mkfifo(self.path("list"))
        done = self.write_file(self.path("list"), "--results")
        self.assertEqual(done.returncode, 2)
        self.assertRegex(done.stderr.decode(), "^--results '.*list': is a FIFO")

    def test_usage(self):
        self.assertEqual(self.write_file().returncode, 2)


class Sets(Base):
    def test_output_is_an_input_by_another_spelling(self):
        write(self.path("s.nff"), "scene")
        os.mkdir(self.path("sub"))
        outs = of.OutputSet()
        outs.add_input("scene", self.path("s.nff"))
        outs.add("--out", self.path("sub", "..", "s.nff"))
        with self.assertRaisesRegex(of.OutputError, r"^--out '.*': is the scene file .*s.nff, an input$"):
            outs.check()

    def test_an_input_in_a_folder_the_command_writes_is_refused(self):
        os.mkdir(self.path("plot-data"))
        write(self.path("plot-data", "apart.dat"), "t")
        os.symlink(self.path("plot-data", "apart.dat"), self.path("l.timing"))
        for given in (self.path("plot-data", "apart.dat"), self.path("l.timing")):
            outs = of.OutputSet()
            outs.add_input("--timing", given)
            outs.add_folder("--out", self.path("plot-data"))
            with self.assertRaisesRegex(of.OutputError, "^--out: its folder .*plot-data, which the command writes, "
                                        "holds the --timing file"):
                outs.check()
        outs = of.OutputSet()
        outs.add_input("--timing", self.path("l.timing"))
        outs.add_folder("--out", self.path("other"))
        outs.check()

    def test_output_is_an_input_through_a_hard_link(self):
        write(self.path("t.timing"), "t")
        os.link(self.path("t.timing"), self.path("h.png"))
        outs = of.OutputSet()
        outs.add_input("--timing", self.path("t.timing"))
        outs.add("--out", self.path("h.png"))
        with self.assertRaisesRegex(of.OutputError, "is the --timing file"):
            outs.check()

    def test_output_is_an_input_through_a_link(self):
        write(self.path("s.nff"), "scene")
        os.symlink("s.nff", self.path("l.png"))
        outs = of.OutputSet()
        outs.add_input("scene", self.path("s.nff"))
        outs.add("--out", self.path("l.png"))
        with self.assertRaisesRegex(of.OutputError, "an input"):
            outs.check()

    def test_two_outputs_on_one_file(self):
        write(self.path("points.tsv"), "")
        os.symlink("points.tsv", self.path("sweep.csv"))
        outs = of.OutputSet()
        outs.add("--out", self.path("points.tsv"))
        outs.add("--out", self.path("sweep.csv"))
        with self.assertRaisesRegex(of.OutputError, r"sweep.csv': is also the file of --out '.*points.tsv'"):
            outs.check()

    def test_two_new_outputs_with_one_name(self):
        outs = of.OutputSet()
        outs.add("--a", self.path("x.png"))
        outs.add("--b", self.path(".", "x.png"))
        with self.assertRaisesRegex(of.OutputError, "is also the file of --a"):
            outs.check()

    def test_distinct_files_pass(self):
        write(self.path("s.nff"), "scene")
        outs = of.OutputSet()
        outs.add_input("scene", self.path("s.nff"))
        outs.add("--out", self.path("a.png"))
        outs.add("--csv", self.path("a.csv"))
        outs.check()

    def test_named_files(self):
        write(self.path("t.timing"), "t")
        words = ["--size", "8x8", "--timing", self.path("t.timing"), "--config=" + self.path("t.timing")]
        self.assertEqual(of.named_files(words), [("--timing", self.path("t.timing")),
                                                 ("--config", self.path("t.timing"))])


REPORT = {"status": "ok", "sim_time_s": 1.5, "config": {"ips": "2"}}


class SweepPoints(Base):
    def test_not_a_report_names_the_file(self):
        for text, why in (("garbage", "not a JSON report"), ("[1, 2]", "a list, not an object"),
                          ("{}", "no status, sim_time_s, config"), ('{"status": "ok", "sim_time_s": true, '
                                                                   '"config": {}}', "no sim_time_s")):
            write(self.path("p.json"), text)
            with self.assertRaisesRegex(ValueError, "^%s: .*%s" % (self.path("p.json"), why)):
                sweep.read_report(self.path("p.json"))

    def test_a_report_reads(self):
        write(self.path("p.json"), json.dumps(REPORT))
        self.assertEqual(sweep.read_report(self.path("p.json")), REPORT)

    def test_identity_follows_executable_scene_inputs_and_command(self):
        sim, scene, timing = self.path("sim"), self.path("s.nff"), self.path("t.timing")
        for p in (sim, scene, timing):
            write(p, p)

        def ident(args):
            return sweep.identity(sim, args, {})
        base = ident([scene, "--timing", timing, "--ips", "2"])
        self.assertEqual(base, ident([scene, "--timing", timing, "--ips", "2"]))
        self.assertNotEqual(base, ident([scene, "--timing", timing, "--ips", "4"]), "the command line")
        write(scene, "another scene")
        self.assertNotEqual(base, ident([scene, "--timing", timing, "--ips", "2"]), "the scene's content")
        write(scene, scene)
        write(timing, "another timing")
        self.assertNotEqual(base, ident([scene, "--timing", timing, "--ips", "2"]), "an input file's content")
        write(timing, timing)
        write(sim, "another build")
        self.assertNotEqual(base, ident([scene, "--timing", timing, "--ips", "2"]), "the executable")
        write(sim, sim)
        # The same executable in another folder: another command line, as the backend's record
        # holds it (it runs such a point again, so the sweep may not count it as done).
        copy = self.path("sim2")
        write(copy, sim)
        self.assertEqual(base, ident([scene, "--timing", timing, "--ips", "2"]))
        self.assertNotEqual(base, sweep.identity(copy, [scene, "--timing", timing, "--ips", "2"], {}),
                            "the executable's path")

    def point(self, report_text, ident_text):
        os.makedirs(self.path("points"), exist_ok=True)
        files = sweep.point_files(self.dir, "ips_2")
        write(files["json"], report_text)
        write(files["png"], "png")
        if ident_text is not None:
            write(files["id"], ident_text)
        return files

    def is_done(self, files, ident):
        """sweep.is_done, and what it said on stderr."""
        said = io.StringIO()
        with contextlib.redirect_stderr(said):
            done = sweep.is_done(files, ident)
        return done, said.getvalue()

    def made(self, text):
        """An identity file's text for a JSON holding TEXT: the identity and the JSON's hash."""
        write(self.path("made.json"), text)
        return "abc %s\n" % sweep.file_hash(self.path("made.json"), {})

    def test_done_only_with_a_report_of_the_same_identity(self):
        files = self.point(json.dumps(REPORT), self.made(json.dumps(REPORT)))
        self.assertEqual(self.is_done(files, "abc"), (True, ""))
        self.assertTrue(os.path.exists(files["json"]))

    def test_a_point_whose_image_or_series_is_gone_runs_again(self):
        files = self.point(json.dumps(REPORT), self.made(json.dumps(REPORT)))
        os.remove(files["png"])
        done, said = self.is_done(files, "abc")
        self.assertFalse(done)
        self.assertIn(files["json"] + ": its run's " + files["png"] + " is gone", said)
        self.assertFalse(os.path.exists(files["json"]))
        files = self.point(json.dumps(REPORT), self.made(json.dumps(REPORT)))
        with contextlib.redirect_stderr(io.StringIO()) as said:
            self.assertFalse(sweep.is_done(files, "abc", series=True), "no series.csv")
        self.assertIn(files["series"] + " is gone", said.getvalue())
        stalled = dict(REPORT, status="deadlock")  # a deadlock writes only its JSON
        files = self.point(json.dumps(stalled), self.made(json.dumps(stalled)))
        os.remove(files["png"])
        self.assertEqual(self.is_done(files, "abc"), (True, ""))

    def test_a_json_changed_after_its_run_runs_again(self):
        other = dict(REPORT, sim_time_s=0.97511)  # another point's report copied over this one's
        files = self.point(json.dumps(other), self.made(json.dumps(REPORT)))
        done, said = self.is_done(files, "abc")
        self.assertFalse(done)
        self.assertIn(files["json"] + ": not the JSON its run wrote", said)
        self.assertFalse(os.path.exists(files["json"]))

    def test_a_number_that_is_not_finite_is_not_a_report(self):
        for text in ('{"status":"ok","sim_time_s":1e999,"config":{}}',
                     '{"status":"ok","sim_time_s":NaN,"config":{}}',
                     '{"status":"ok","sim_time_s":1,"config":{},"x":[-Infinity]}'):
            files = self.point(text, self.made(text))
            done, said = self.is_done(files, "abc")
            self.assertFalse(done, text)
            self.assertIn(files["json"] + ": not a JSON report", said)

    def test_a_config_files_inputs_make_the_identity(self):
        sim, scene, timing = self.path("sim"), self.path("s.nff"), self.path("n.timing")
        os.makedirs(self.path("cfg"))
        machine = self.path("cfg", "m.toml")
        for p in (sim, scene, timing):
            write(p, p)
        write(self.path("cfg", "n.timing"), "link 50\n")
        write(machine, 'timing="n.timing"\n')  # from the machine file's folder, not the working one
        args = [scene, "--config", machine]
        base = sweep.identity(sim, args, {})
        write(self.path("cfg", "n.timing"), "link 50000\n")
        self.assertNotEqual(base, sweep.identity(sim, args, {}), "a file the machine file names")
        self.assertIn(("--config %s's timing" % machine, self.path("cfg", "n.timing")), of.named_files(args))

    def test_a_config_file_with_a_byte_order_mark_or_past_this_reader_still_names_its_inputs(self):
        os.makedirs(self.path("cfg"))
        write(self.path("cfg", "n.timing"), "link 50\n")
        for name, text in (("bom.toml", '\ufeff[timing]\ntiming = "n.timing"\n'),
                           ("odd.toml", "[timing]\ntiming = 'n.timing'\nnot toml = = 1\n")):
            machine = self.path("cfg", name)
            with open(machine, "w", encoding="utf-8") as f:
                f.write(text)
            named = [path for _, path in of.named_files([self.path("s.nff"), "--config", machine])]
            self.assertIn(self.path("cfg", "n.timing"), named, name)

    def test_another_identity_runs_again(self):
        files = self.point(json.dumps(REPORT), self.made(json.dumps(REPORT)))
        done, said = self.is_done(files, "def")
        self.assertFalse(done)
        self.assertIn(files["json"] + ": made by another executable", said)
        self.assertFalse(os.path.exists(files["json"]) or os.path.exists(files["png"]))

    def test_no_identity_runs_again(self):
        files = self.point(json.dumps(REPORT), None)
        self.assertFalse(self.is_done(files, "abc")[0])
        self.assertFalse(os.path.exists(files["json"]))

    def test_not_a_report_runs_again(self):
        for text in ("garbage", "[]", "{}"):
            files = self.point(text, "abc\n")
            done, said = self.is_done(files, "abc")
            self.assertFalse(done, text)
            self.assertIn(files["json"] + ": not a JSON report", said)
            self.assertFalse(os.path.exists(files["json"]), text)

    def test_an_empty_axis_value_is_refused(self):
        for text in ("ips=1,,2", "ips=1,", "ips=,1"):
            with self.assertRaisesRegex(ValueError, "an empty value"):
                sweep.parse_axis(text)
        with self.assertRaisesRegex(ValueError, "--vcd is an output"):
            sweep.parse_axis("vcd=a.vcd,b.vcd")

    def test_two_points_of_one_name_or_an_output_option_refused_before_anything(self):
        out = self.path("sw")
        with self.assertRaisesRegex(ValueError, "the points a/t.timing and a_t.timing have one name, "
                                                "timing_a_t.timing"):
            sweep.plan(out, "sim", "s.nff", [("timing", ["a/t.timing", "a_t.timing"])], [], self.path("l"))
        for fixed in (["--vcd", "v.vcd"], ["--size", "8x8", "--write-map=wm.txt"], ["-o", "a.png"]):
            with self.assertRaisesRegex(ValueError, "%s among the fixed options" % fixed[-2 if len(fixed) == 2 else -1]
                                        .partition("=")[0]):
                sweep.plan(out, "sim", "s.nff", [("ips", ["1", "2"])], fixed, self.path("l"))
        self.assertFalse(os.path.exists(out) or os.path.exists(self.path("l")))


class Jobs(unittest.TestCase):
    def test_capped_at_the_points_and_the_maximum(self):
        self.assertEqual(backend_cli.in_flight(99999, "local", 2), 2)
        self.assertEqual(backend_cli.in_flight(99999, "slurm", 5000), backend_cli.MAX_JOBS)
        self.assertEqual(backend_cli.in_flight(3, "local", 10), 3)
        self.assertLessEqual(backend_cli.in_flight(None, "local", 1), 1)
        self.assertIsNone(backend_cli.in_flight(None, "slurm", 10))

    def test_not_a_positive_whole_number(self):
        for text in ("0", "-1", "abc", "1.5", ""):
            with self.assertRaises(Exception, msg=text):
                backend_cli.positive(text)
        self.assertEqual(backend_cli.positive("4"), 4)


if __name__ == "__main__":
    unittest.main()
