#!/usr/bin/env python3
"""Unit tests of run_mutants.py that need no build: the catalogue (every
patch applies to the working tree), the RTL path with a hand-made generator
OUTDIR (rtl/irq_pulse.v with one operator changed), tree syncing, report
parsing and the score. Run: python3 tests/mutants/test_run_mutants.py"""

import json
import os
import re
import subprocess
import sys
import time
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import known_killers as kk  # noqa: E402
import run_mutants as rm  # noqa: E402


def fake_rtl_outdir(root):
    """A generator OUTDIR by hand: one mutant of rtl/irq_pulse.v."""
    original = (rm.REPO / "rtl" / "irq_pulse.v").read_text()
    old = "if (count_q != '0) begin"
    assert old in original
    (root / "rtl-000").mkdir()
    (root / "rtl-000" / "irq_pulse.v").write_text(
        original.replace(old, "if (count_q == '0) begin"))
    (root / "rtl-mutants.tsv").write_text(
        "id\tmodule\tfile\tmutate\tlocation\tdescription\n"
        "rtl-000\tirq_pulse\trtl/irq_pulse.v\tsed s/!=/==/\tirq_pulse.v:40\t"
        "count compare inverted\n")


SNAPSHOT = rm.snapshot_working_tree()


class Catalogue(unittest.TestCase):
    def test_at_least_16_firmware_mutants_with_descriptions(self):
        mutants = rm.firmware_mutants()
        self.assertGreaterEqual(len(mutants), 16)
        for m in mutants:
            self.assertTrue(m.description, m.id)
            self.assertTrue(m.file.startswith("dsp/"), m.id)

    def test_targeted_rtl_mutants_patch_rtl_files(self):
        mutants = rm.targeted_rtl_mutants()
        self.assertGreaterEqual(len(mutants), 8)
        for m in mutants:
            self.assertEqual(m.kind, "rtl", m.id)
            self.assertTrue(m.description, m.id)
            self.assertTrue(m.file.startswith("rtl/") and m.file.endswith(".v"), m.id)

    def test_every_patch_applies_and_changes_its_file(self):
        for m in rm.firmware_mutants() + rm.targeted_rtl_mutants():
            with self.subTest(mutant=m.id):
                changed = rm.mutated_contents(m, SNAPSHOT)
                for path, content in changed.items():
                    self.assertNotEqual(content, (rm.REPO / path).read_bytes())

    def test_a_patch_that_does_not_apply_is_an_error(self):
        with tempfile.TemporaryDirectory() as tmp:
            bad = Path(tmp) / "fw-99-bad.patch"
            bad.write_text("# broken\n--- a/dsp/controller.cpp\n+++ b/dsp/controller.cpp\n"
                           "@@ -1,1 +1,1 @@\n-no such line\n+other\n")
            mutant = rm.firmware_mutants(Path(tmp))[0]
            with self.assertRaisesRegex(RuntimeError, "does not apply"):
                rm.mutated_contents(mutant, SNAPSHOT)


class RtlPath(unittest.TestCase):
    def test_catalogue_and_tree_from_a_fake_generator_outdir(self):
        with tempfile.TemporaryDirectory() as tmp:
            root = Path(tmp)
            (root / "gen").mkdir()
            fake_rtl_outdir(root / "gen")
            mutants = rm.read_rtl_catalogue(root / "gen")
            self.assertEqual([m.id for m in mutants], ["rtl-000"])
            m = mutants[0]
            self.assertEqual((m.kind, m.file), ("rtl", "rtl/irq_pulse.v"))
            self.assertIn("irq_pulse", m.description)
            files = {k: SNAPSHOT[k] for k in ["rtl/irq_pulse.v", "rtl/oe_control.v"]}
            src = root / "src"
            rm.sync_tree(src, files, rm.mutated_contents(m, SNAPSHOT))
            self.assertIn("count_q == '0", (src / "rtl/irq_pulse.v").read_text())
            self.assertEqual((src / "rtl/oe_control.v").read_bytes(),
                             (rm.REPO / "rtl/oe_control.v").read_bytes())
            self.assertEqual(rm.label_targets(rm.REPO, "rtl")[:1], ["rtl_test_async_fifo"])


class Tree(unittest.TestCase):
    def test_sync_keeps_unchanged_files_and_removes_stale_ones(self):
        with tempfile.TemporaryDirectory() as tmp:
            src = Path(tmp)
            files = {k: SNAPSHOT[k] for k in ["dsp/controller.h", "rtl/irq_pulse.v"]}
            rm.sync_tree(src, files, {})
            stamp = (src / "dsp/controller.h").stat().st_mtime_ns
            (src / "old.txt").write_text("stale")
            rm.sync_tree(src, {"dsp/controller.h": files["dsp/controller.h"]}, {})
            self.assertEqual((src / "dsp/controller.h").stat().st_mtime_ns, stamp)
            self.assertFalse((src / "old.txt").exists())
            self.assertFalse((src / "rtl").exists())

    def test_snapshot_includes_untracked_files_like_this_one(self):
        self.assertIn("tests/mutants/test_run_mutants.py", SNAPSHOT)
        self.assertTrue(SNAPSHOT["tests/mutants/run_mutants.py"][1])  # executable


class Parsing(unittest.TestCase):
    def test_campaign_rows_broken(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = Path(tmp) / "campaign.json"
            path.write_text(json.dumps({"rows": [
                {"fault": "clean", "seed": 3, "contract_ok": True, "ran": True},
                {"fault": "dead:sensor=R", "seed": 3, "contract_ok": False, "ran": True,
                 "violations": ["outcome pending", "second"]},
                {"fault": "clean", "seed": 4, "contract_ok": False, "ran": False,
                 "error": "signal 11"}]}))
            broken = rm.campaign_rows_broken(path)
            self.assertEqual([entry for _, entry in broken],
                             ["campaign:dead:sensor=R: outcome pending",
                              "crash:campaign:clean(seed=4): signal 11"])
            self.assertEqual(len({key for key, _ in broken}), 2)

    def test_failed_tests(self):
        out = ("90% tests passed, 2 tests failed out of 20\n\nTotal Test time (real) = 3 sec\n\n"
               "The following tests FAILED:\n"
               "\t  7 - dsp.ControlProgramCard.RearmsWhenTheCardGivesUp (Failed)\n"
               "\t 12 - dsp.X.Y (Timeout)\nErrors while running CTest\n")
        self.assertEqual(rm.failed_tests(out),
                         [("dsp.ControlProgramCard.RearmsWhenTheCardGivesUp",
                           "ctest:dsp.ControlProgramCard.RearmsWhenTheCardGivesUp (Failed)"),
                          ("dsp.X.Y", "ctest:dsp.X.Y (Timeout)")])

    def test_stillborn_needs_the_mutated_file_in_an_error(self):
        log = "FAILED: dsp/CMakeFiles/dsp.dir/control_program.cpp.o\n"
        self.assertTrue(rm.failure_in_mutated_file(log, "dsp/control_program.cpp"))
        self.assertFalse(rm.failure_in_mutated_file("FAILED: tb/x.cpp.o\n",
                                                    "dsp/control_program.cpp"))

    def test_equivalents(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = Path(tmp) / "eq.txt"
            path.write_text("# header\nfw-01 same code\n\nrtl-3  reason two # note\n")
            self.assertEqual(rm.read_equivalents(path),
                             {"fw-01": "same code", "rtl-3": "reason two"})


class Baseline(unittest.TestCase):
    """A fake `stereosim` that writes a campaign.json with one broken row."""

    def fake_build(self, root, rows):
        build = root / "build"
        build.mkdir()
        rows_json = json.dumps({"rows": rows})
        (build / "stereosim").write_text(
            "#!/bin/sh\n# faults --campaign smoke --jobs J --out DIR\n"
            f"mkdir -p \"$7\"; echo '{rows_json}' > \"$7/campaign.json\"; exit 1\n")
        (build / "stereosim").chmod(0o755)
        return build

    def test_rows_the_baseline_breaks_do_not_kill(self):
        rows = [{"index": 0, "fault": "clean", "seed": 3, "ran": True, "contract_ok": False,
                 "violations": ["v"]}]
        with tempfile.TemporaryDirectory() as tmp:
            build = self.fake_build(Path(tmp), rows)
            result = rm.Result("m", "firmware", "f", "d")
            baseline = rm.Baseline(broken_rows={"0:clean:3"})
            self.assertFalse(rm.check_campaign(result, build, Path(tmp), 1, baseline))
            self.assertIn("baseline breaks too", result.note)
            result = rm.Result("m", "firmware", "f", "d")
            self.assertTrue(rm.check_campaign(result, build, Path(tmp), 1, rm.Baseline()))
            self.assertEqual(result.killed_by, ["campaign:clean(seed=3): v"])
            self.assertEqual(rm.exit_code([], baseline), 1)

    def test_a_firmware_mutant_is_its_plugin_run_by_the_unmutated_stereosim(self):
        """The campaign of a firmware mutant: the platform's stereosim with
        --firmware <the tree's plugin> --stop-on-violation; a stop on a row the
        baseline breaks too runs it again whole."""
        rows = [{"index": 0, "fault": "clean", "seed": 3, "ran": True, "contract_ok": False,
                 "violations": ["v"]}]
        with tempfile.TemporaryDirectory() as tmp:
            root = Path(tmp)
            platform = root / "platform"
            platform.mkdir()
            rows_json = json.dumps({"rows": rows})
            (platform / "stereosim").write_text(
                "#!/bin/sh\n"
                f"echo \"$@\" >> {root}/calls\n"
                f"mkdir -p \"$7\"; echo '{rows_json}' > \"$7/campaign.json\"; exit 1\n")
            (platform / "stereosim").chmod(0o755)
            build = root / "tree"
            build.mkdir()
            saved = rm.platform_binary
            rm.platform_binary = lambda: platform / "stereosim"
            try:
                result = rm.Result("m", "firmware", "f", "d")
                plugin = build / rm.PLUGIN_PATH
                self.assertTrue(rm.check_campaign(result, build, root, 1, rm.Baseline(),
                                                  plugin=plugin))
                calls = (root / "calls").read_text().splitlines()
                self.assertEqual(len(calls), 1)
                self.assertTrue(calls[0].endswith(f"--firmware {plugin} --stop-on-violation"))
                result = rm.Result("m", "firmware", "f", "d")
                baseline = rm.Baseline(broken_rows={"0:clean:3"})
                self.assertFalse(rm.check_campaign(result, build, root, 1, baseline,
                                                   plugin=plugin))
                calls = (root / "calls").read_text().splitlines()
                self.assertEqual(len(calls), 3)
                self.assertTrue(calls[2].endswith(f"--firmware {plugin}"))
            finally:
                rm.platform_binary = saved

    def test_the_eval_shape_test_alone_does_not_kill(self):
        """A fake ctest whose only failure is the lean-eval shape test: noted,
        not a kill; with a behaviour test failing beside it, killed."""
        with tempfile.TemporaryDirectory() as tmp:
            build = Path(tmp)
            fake_bin = build / "bin"
            fake_bin.mkdir()
            shape = next(iter(rm.SHAPE_TESTS))
            for failing, expect_kill in (([shape], False), ([shape, "rtl.CardSync.X"], True)):
                listing = "".join(f"\t  {i + 1} - {name} (Failed)\n"
                                  for i, name in enumerate(failing))
                (fake_bin / "ctest").write_text(
                    "#!/bin/sh\nprintf 'The following tests FAILED:\\n" + listing.replace(
                        "\n", "\\n").replace("\t", "\\t") + "'\nexit 8\n")
                (fake_bin / "ctest").chmod(0o755)
                result = rm.Result("m", "rtl", "f", "d")
                old_path = os.environ["PATH"]
                os.environ["PATH"] = f"{fake_bin}:{old_path}"
                try:
                    killed = rm.check_ctest(result, build, build, "rtl", 1, rm.Baseline())
                finally:
                    os.environ["PATH"] = old_path
                self.assertEqual(killed, expect_kill)
                self.assertIn("Verilator's eval", result.note)


def alive(pid):
    """Running (not gone, not a zombie waiting for its new parent to reap it)."""
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except FileNotFoundError:
        return False
    return stat.rsplit(")", 1)[1].split()[0] != "Z"


class Processes(unittest.TestCase):
    def test_a_second_run_cannot_take_the_lock(self):
        with tempfile.TemporaryDirectory() as tmp:
            first = rm.lock_work_dir(Path(tmp))
            self.assertIsNotNone(first)
            self.assertIsNone(rm.lock_work_dir(Path(tmp)))
            first.close()
            second = rm.lock_work_dir(Path(tmp))
            self.assertIsNotNone(second)
            second.close()

    def test_sigterm_kills_the_steps_under_way(self):
        with tempfile.TemporaryDirectory() as tmp:
            script = (
                "import sys, os, signal, threading, time\n"
                f"sys.path.insert(0, {str(Path(rm.__file__).parent)!r})\n"
                "import run_mutants as rm\n"
                "from pathlib import Path\n"
                "signal.signal(signal.SIGTERM, rm.stop_on_signal)\n"
                f"log = Path({tmp!r}) / 'step.log'\n"
                "threading.Thread(target=rm.run_step, args=(['sh', '-c', 'echo $$ > "
                f"{tmp}/pid; exec sleep 60'], '.', log, 100), daemon=True).start()\n"
                "time.sleep(1)\n"
                "os.kill(os.getpid(), signal.SIGTERM)\n"
                "time.sleep(30)\n")
            import subprocess
            done = subprocess.run([sys.executable, "-c", script], capture_output=True,
                                  text=True, timeout=20)
            self.assertEqual(done.returncode, 128 + 15, done.stderr)
            pid = int((Path(tmp) / "pid").read_text())
            time.sleep(0.2)
            self.assertFalse(alive(pid))


class Reports(unittest.TestCase):
    def test_score_and_exit_code(self):
        results = [rm.Result("a", "firmware", "f", "d", status="killed", campaign_kills=True),
                   rm.Result("b", "firmware", "f", "d", status="survived", campaign_kills=False),
                   rm.Result("c", "rtl", "f", "d", status="stillborn")]
        self.assertIn("mutation score 50.0 % (1/2)", rm.summary(results, 1.0))
        self.assertEqual(rm.exit_code(results), 1)
        rm.apply_equivalents(results, {"b": "why"})
        self.assertEqual(results[1].status, "equivalent")
        self.assertIn("mutation score 100.0 % (1/1)", rm.summary(results, 1.0))
        self.assertEqual(rm.exit_code(results), 0)
        with tempfile.TemporaryDirectory() as tmp:
            text = rm.write_reports(results, Path(tmp), 2.0)
            self.assertIn("equivalent", text)
            rows = json.loads((Path(tmp) / "mutants.json").read_text())
            self.assertEqual(rows[0]["campaign_kills"], True)
            header = (Path(tmp) / "mutants.csv").read_text().splitlines()[0]
            self.assertTrue(header.startswith("id,kind,file,description,status,killed_by,"
                                              "campaign_kills,wall_s,build_s"))


class KnownKillers(unittest.TestCase):
    NAMES = ["dsp.Slow/BoxOnMotion.StaysOnTheObject/pass1", "dsp.Key.Turned"]

    def test_the_record_round_trips_and_a_bad_line_is_named(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = Path(tmp) / "k.tsv"
            record = {"fw-02-b": ["campaign"], "fw-01-a": self.NAMES}
            kk.write_record(path, record)
            self.assertEqual(dict(kk.read_killers(path)), record)
            path.write_text("fw-01-a dsp.Key.Turned\n")
            with self.assertRaisesRegex(ValueError, "k.tsv:1"):
                kk.read_killers(path)
            self.assertEqual(kk.read_killers(Path(tmp) / "none.tsv"), {})

    def test_the_committed_record_names_catalogue_mutants(self):
        ids = {m.id for m in rm.firmware_mutants()}
        record = kk.read_killers(rm.KILLERS_FILE)
        self.assertTrue(record)
        self.assertEqual([i for i in record if i not in ids], [])

    def test_a_cli_killer_maps_to_its_executable_and_runs_without_a_label(self):
        """The cli label's own executables are mapped (a script's test is
        not: no target builds it); a cli name needs stereosim; the known
        killers' ctest selects by -R alone, so a cli killer is run."""
        build = rm.REPO / "build"
        if not (build / "CTestTestfile.cmake").exists():
            self.skipTest("no configured build/")
        table = kk.test_executables(build, "cli")
        self.assertEqual(table.get("cli.MotionScenarios.SlowLargeBall"),
                         "cli_test_motion_scenarios")
        self.assertNotIn("cli.sdk_install_and_outside_build", table)
        self.assertTrue(all(exe.startswith("cli_test_") for exe in table.values()))
        self.assertTrue(kk.needs_stereosim(["dsp.A.B", "cli.MotionScenarios.SlowLargeBall"]))
        self.assertFalse(kk.needs_stereosim(self.NAMES))
        # A mutant's own cli killer is tried; the most frequent killers hold none.
        record = {"fw-a": ["cli.M.S", "dsp.A.B"], "fw-b": ["cli.M.S", "dsp.A.B"]}
        self.assertEqual(kk.likely_killers(record), ["dsp.A.B"])
        self.assertEqual(kk.tests_to_try("fw-a", record)[0], ["cli.M.S", "dsp.A.B"])
        with tempfile.TemporaryDirectory() as tmp:
            fake_bin = Path(tmp) / "bin"
            fake_bin.mkdir()
            (fake_bin / "ctest").write_text(f"#!/bin/sh\necho \"$@\" > {tmp}/args\n")
            (fake_bin / "ctest").chmod(0o755)
            old_path = os.environ["PATH"]
            os.environ["PATH"] = f"{fake_bin}:{old_path}"
            try:
                rm.run_ctest(Path(tmp), Path(tmp) / "log", None, 1, stop=True, include="^(x)")
                args = (Path(tmp) / "args").read_text().split()
                rm.run_ctest(Path(tmp), Path(tmp) / "log", "dsp", 1)
                labelled = (Path(tmp) / "args").read_text().split()
            finally:
                os.environ["PATH"] = old_path
            self.assertNotIn("-L", args)
            self.assertEqual(args[args.index("-R") + 1], "^(x)")
            self.assertEqual(labelled[:2], ["-L", "dsp"])

    def test_the_regex_matches_exactly_the_names(self):
        import re
        regex = re.compile(kk.ctest_regex(self.NAMES))
        self.assertTrue(regex.search(self.NAMES[0] + "  # GetParam() = pass1"))
        self.assertTrue(regex.search(self.NAMES[1]))
        self.assertFalse(regex.search(self.NAMES[0] + "0"))
        self.assertFalse(regex.search("dsp.Slow/BoxOnMotion.StaysOnTheObject/pass"))
        self.assertFalse(regex.search("dsp.KeyXTurned"))

    def test_ctest_selects_exactly_a_mutants_known_killers(self):
        build = rm.REPO / "build"
        if not (build / "CTestTestfile.cmake").exists():
            self.skipTest("no configured build/")
        table = kk.test_executables(build, "dsp")
        names = sorted(table)[:3] + sorted(table)[-2:]
        listed = subprocess.run(["ctest", "-N", "-R", kk.ctest_regex(names)], cwd=build,
                                capture_output=True, text=True, check=True).stdout
        found = re.findall(r"Test\s+#\d+: (\S+)", listed)
        self.assertEqual(sorted(found), sorted(names))
        rest = subprocess.run(["ctest", "-N", "-L", "dsp", "-E", kk.ctest_regex(names)],
                              cwd=build, capture_output=True, text=True, check=True).stdout
        self.assertEqual(sorted(re.findall(r"Test\s+#\d+: (\S+)", rest)),
                         sorted(set(table) - set(names)))

    def test_the_ctest_after_the_known_killers_runs_the_rest_quick_tests_first(self):
        build = rm.REPO / "build"
        if not (build / "CTestTestfile.cmake").exists():
            self.skipTest("no configured build/")
        table = kk.test_executables(build, "dsp")
        passed = [n for n in sorted(table) if rm.SLOW_TESTS in n][:2] + sorted(table)[:1]
        for stop in (False, True):
            runs = []
            for _, include, exclude in rm.ctest_parts(stop, passed):
                command = ["ctest", "-N", "-L", "dsp"] + (["-R", include] if include else []) \
                    + (["-E", exclude] if exclude else [])
                listed = subprocess.run(command, cwd=build, capture_output=True, text=True,
                                        check=True).stdout
                runs.append(re.findall(r"Test\s+#\d+: (\S+)", listed))
            self.assertEqual(sorted(sum(runs, [])), sorted(set(table) - set(passed)))
            if stop:
                self.assertFalse([n for n in runs[0] if rm.SLOW_TESTS in n])
                self.assertTrue(runs[0] and runs[1])

    def test_a_mutant_tries_its_own_killers_else_its_neighbours(self):
        record = {"fw-01-a": ["campaign"], "fw-02-b": ["t1", "t2"], "fw-03-c": ["t3"],
                  "fw-04-d": ["t2", "t3"], "fw-05-e": ["t3", "t4"]}
        self.assertEqual(kk.tests_to_try("fw-01-a", record)[0], [])
        self.assertEqual(kk.tests_to_try("fw-02-b", record)[0], ["t1", "t2", "t3", "t4"])
        self.assertEqual(kk.tests_to_try("fw-09-new", record)[0], ["t3", "t2", "t1", "t4"])
        self.assertEqual(kk.tests_to_try("fw-09-new", record, ["fw-02-b"])[0],
                         ["t1", "t2", "t3", "t4"])

    def test_the_campaign_goes_first_unless_the_record_says_tests(self):
        record = {"fw-01-a": ["campaign"], "fw-02-b": ["t1"], "fw-03-c": ["t2"]}
        self.assertFalse(kk.tests_first("fw-01-a", record))
        self.assertTrue(kk.tests_first("fw-02-b", record))
        self.assertTrue(kk.tests_first("fw-09-new", record))
        self.assertFalse(kk.tests_first("fw-09-new", {"fw-01-a": ["campaign"]}))
        self.assertFalse(kk.tests_first("fw-09-new", {}))
        self.assertTrue(kk.tests_first("fw-09-new", record, ["fw-02-b"]))
        self.assertFalse(kk.tests_first("fw-09-new", record, ["fw-01-a", "fw-02-b"]))
        self.assertTrue(kk.tests_first("fw-09-new", record, ["fw-01-a", "fw-02-b", "fw-03-c"]))

    def test_a_run_replaces_the_lines_of_the_mutants_it_judged(self):
        record = {"fw-01-a": ["t1"], "fw-02-b": ["t2"], "fw-03-c": ["t3"]}
        killed = rm.Result("fw-01-a", "firmware", "dsp/x.cpp", "", status="killed",
                           killed_by=["ctest:t9 (Failed)", "ctest:t8 (Failed)"],
                           campaign_kills=False)
        by_campaign = rm.Result("fw-04-d", "firmware", "dsp/x.cpp", "", status="killed",
                                killed_by=["campaign:row: ..."], campaign_kills=True)
        survived = rm.Result("fw-02-b", "firmware", "dsp/x.cpp", "", status="survived")
        broken = rm.Result("fw-03-c", "firmware", "dsp/x.cpp", "", status="error")
        unjudged = rm.Result("fw-05-e", "firmware", "dsp/x.cpp", "", status="unjudged")
        record["fw-05-e"] = ["t5"]
        merged = kk.merged_record(record, [killed, by_campaign, survived, broken, unjudged])
        self.assertEqual(dict(merged), {"fw-01-a": ["t9", "t8"], "fw-03-c": ["t3"],
                                        "fw-04-d": ["campaign"], "fw-05-e": ["t5"]})

    def test_an_unjudged_mutant_is_not_scored_and_fails_the_run(self):
        results = [rm.Result("fw-01-a", "firmware", "dsp/x.cpp", "", status="killed"),
                   rm.Result("fw-02-b", "firmware", "dsp/x.cpp", "", status="unjudged")]
        text = rm.summary(results, 1.0)
        self.assertIn("1 unjudged", text)
        self.assertIn("100.0 % (1/1)", text)
        self.assertEqual(rm.exit_code(results), 1)
        self.assertEqual(rm.exit_code(results[:1]), 0)


if __name__ == "__main__":
    unittest.main()
