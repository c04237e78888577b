#!/usr/bin/env python3
"""Mutation qualification of the fault campaign (docs/mutants.md).

Every mutant (a firmware patch from tests/mutants/firmware/*.patch, a
hand-written RTL patch from tests/mutants/rtl-targeted/*.patch, or an RTL
module file made by tests/mutants/rtl/generate) gets its own source tree,
build-mutants/trees/<id>/src (the working tree's files as they are now,
tracked and untracked-not-ignored, deleted ones skipped, then the mutation),
and its own build tree build-mutants/trees/<id>/src/build (Ninja,
RelWithDebInfo, ccache with the source copy as CCACHE_BASEDIR). The build
tree sits where the main build sits (the Makefile's build/, built with the
repository as CCACHE_BASEDIR), so every compile line is the main build's
and only the mutated file recompiles, even in the first tree of a run.
Only what the mutant's checks need is built: a firmware mutant's dsp tests
and its reference-firmware plugin (libstereosim_fw_reference.so; the
unmutated stereosim of the main build runs it, docs/firmware-abi.md), an RTL
mutant's rtl tests and then stereosim; a mutant that does not compile is
`stillborn`.

First a baseline: the unmutated tree, built and checked the same way (skip
with --no-baseline); campaign rows and tests that fail there are never
counted as kills, and make the run exit 1.

Kill checks, stopping at the first that kills:
  firmware: (--whole) the smoke campaign of its plugin (`stereosim faults
            --campaign smoke --firmware PLUGIN --stop-on-violation`, exit 1 =
            killed, by the rows that broke the contract before it stopped),
            then `ctest -L dsp` only if the campaign did not kill (column
            campaign_kills: the campaign alone killed it); by default first
            the tests tests/mutants/firmware-killers.tsv says killed it last
            time, and the campaign after `ctest -L dsp --stop-on-failure` for
            a mutant the record gives to tests (known_killers.py);
  rtl:      `ctest -L rtl` first (fast), then the smoke campaign.
A crash or timeout of a simulation counts as killed ("crash: ..."), noted.
Campaign exit 2, or anything else the harness cannot judge, is an `error`.
A survivor listed in tests/mutants/equivalent.txt is `equivalent`.

Reports in --out DIR (default build-mutants/results): mutants.json,
mutants.csv, mutants.txt (the table, also printed, and a summary line with
mutation score = killed / (total - equivalent - stillborn)); per mutant
DIR/<id>/ holds build.log, campaign.log, campaign/ and ctest.log.
Exit 0: no unlisted survivor, no error, a clean baseline; 1 otherwise; 2 bad
usage.
"""

import argparse
import concurrent.futures
import csv
import dataclasses
import fcntl
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

import known_killers

REPO = Path(__file__).resolve().parents[2]
MUTANTS_DIR = REPO / "tests" / "mutants"
FIRMWARE_DIR = MUTANTS_DIR / "firmware"
TARGETED_RTL_DIR = MUTANTS_DIR / "rtl-targeted"
EQUIVALENT_FILE = MUTANTS_DIR / "equivalent.txt"
KILLERS_FILE = MUTANTS_DIR / "firmware-killers.tsv"
RTL_GENERATOR = MUTANTS_DIR / "rtl" / "generate"
WORK_DIR = REPO / "build-mutants"
# The main build's spelling of the path (CMakeLists.txt's default for a
# checkout): a compile definition, so the same text keeps ccache's hits.
SHARED_DATA = f"{REPO}/../shared/data"  # tests/support/data_path.h

CAMPAIGN_TIMEOUT_S = 15 * 60
# A safety net only: each test has its own timeout (tests/CMakeLists.txt),
# and one that runs out fails as that test. The dsp label alone takes 6 min
# on 2 idle cores and 12 with one (docs/ci.md): at 10 min a mutant run with
# --build-jobs 1 was counted killed by a slow suite, not by a test.
CTEST_TIMEOUT_S = 45 * 60
BUILD_TIMEOUT_S = 60 * 60
GENERATOR_TIMEOUT_S = 10 * 60

COLUMNS = ["id", "kind", "file", "description", "status", "killed_by", "campaign_kills",
           "wall_s", "build_s", "campaign_s", "ctest_s", "note"]

print_lock = threading.Lock()
running_lock = threading.Lock()
running_processes = set()  # the steps under way, each its own process group


def log(message):
    with print_lock:
        print(message, flush=True)


# ---- the catalogue -------------------------------------------------------------------------

@dataclasses.dataclass
class Mutant:
    id: str
    kind: str         # firmware | rtl
    file: str         # the repository file it mutates
    description: str
    source: Path      # the .patch, or the mutated module file

    def is_patch(self):
        return self.source.suffix == ".patch"


@dataclasses.dataclass
class Result:
    id: str
    kind: str
    file: str
    description: str
    status: str = "error"    # killed | survived | equivalent | stillborn | error | unjudged
    killed_by: list = dataclasses.field(default_factory=list)
    campaign_kills: object = None  # True / False, None when the campaign did not run
    wall_s: float = 0.0
    build_s: float = 0.0
    campaign_s: float = 0.0
    ctest_s: float = 0.0
    note: str = ""


def patch_targets(patch_text):
    """The repository paths a unified diff changes (its '+++ b/...' lines)."""
    paths = []
    for line in patch_text.splitlines():
        if line.startswith("+++ "):
            name = line[4:].split("\t")[0].strip()
            paths.append(name[2:] if name.startswith("b/") else name)
    return paths


def patch_mutants(directory, kind):
    """One Mutant of `kind` per <id>.patch in directory, described by its first line."""
    mutants = []
    for patch in sorted(directory.glob("*.patch")):
        text = patch.read_text()
        header = text.splitlines()[0] if text else ""
        description = header[1:].strip() if header.startswith("#") else ""
        targets = patch_targets(text)
        mutants.append(Mutant(patch.stem, kind, ",".join(targets), description, patch))
    return mutants


def firmware_mutants(directory=FIRMWARE_DIR):
    """The firmware catalogue."""
    return patch_mutants(directory, "firmware")


def targeted_rtl_mutants(directory=TARGETED_RTL_DIR):
    """The hand-written RTL mutants (judged like the generator's)."""
    return patch_mutants(directory, "rtl")


def read_rtl_catalogue(rtl_dir):
    """OUTDIR/rtl-mutants.tsv of the generator: header line, then id, module,
    file, mutate command, source location, description (tab separated); the
    mutated file is OUTDIR/<id>/<basename of file>."""
    lines = (Path(rtl_dir) / "rtl-mutants.tsv").read_text().splitlines()
    mutants = []
    for line in lines[1:]:
        if not line.strip() or line.startswith("#"):
            continue
        cells = line.split("\t")
        ident, module, file = cells[0].strip(), cells[1].strip(), cells[2].strip()
        where = cells[4].strip() if len(cells) > 4 else ""
        text = cells[5].strip() if len(cells) > 5 else ""
        description = f"{module}: {text}" + (f" ({where})" if where else "")
        basename = Path(file).name
        mutants.append(Mutant(ident, "rtl", f"rtl/{basename}", description,
                              Path(rtl_dir) / ident / basename))
    return mutants


def generate_rtl_mutants(rtl_dir, count, seed):
    """Runs the generator into rtl_dir; False (with a message) if it is not there."""
    if not RTL_GENERATOR.exists():
        log(f"rtl: {RTL_GENERATOR.relative_to(REPO)} does not exist yet: RTL mutants skipped")
        return False
    Path(rtl_dir).mkdir(parents=True, exist_ok=True)
    command = [str(RTL_GENERATOR), str(rtl_dir)]
    if count is not None:
        command += ["--count", str(count)]
    if seed is not None:
        command += ["--seed", str(seed)]
    done = subprocess.run(command, cwd=REPO, capture_output=True, text=True,
                          timeout=GENERATOR_TIMEOUT_S)
    if done.returncode != 0:
        raise RuntimeError(f"rtl generator failed ({done.returncode}): {done.stderr.strip()}")
    return True


def read_equivalents(path=EQUIVALENT_FILE):
    """`<id> <reason>` per line, # comments: id -> reason."""
    equivalents = {}
    if not path.exists():
        return equivalents
    for line in path.read_text().splitlines():
        line = line.split("#", 1)[0].strip()
        if line:
            ident, _, reason = line.partition(" ")
            equivalents[ident] = reason.strip()
    return equivalents


# ---- the mutant's source tree --------------------------------------------------------------

def working_tree_files(repo=REPO):
    """Tracked and untracked-not-ignored files of the working tree as they are
    now (what the main build globs), without deleted ones."""
    listing = subprocess.run(
        ["git", "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
        cwd=repo, check=True, capture_output=True).stdout.decode()
    files = sorted({name for name in listing.split("\0") if name})
    return [name for name in files if (repo / name).is_file()]


def snapshot_working_tree(repo=REPO):
    """{path: (bytes, executable)} of working_tree_files, read once, so every
    mutant of a run starts from the same sources even while others edit."""
    snapshot = {}
    for name in working_tree_files(repo):
        path = repo / name
        snapshot[name] = (path.read_bytes(), os.access(path, os.X_OK))
    return snapshot


def mutated_contents(mutant, snapshot):
    """{repository path: new bytes} of the files the mutation changes. A
    firmware patch is applied with `patch -p1` to copies of its files in a
    scratch directory, without fuzz (a patch whose context drifted could
    mutate the wrong line); an error there is an error of the catalogue."""
    if not mutant.is_patch():
        if not mutant.source.is_file():
            raise RuntimeError(f"mutated file {mutant.source} missing")
        return {mutant.file: mutant.source.read_bytes()}
    targets = patch_targets(mutant.source.read_text())
    with tempfile.TemporaryDirectory(prefix="mutant-") as scratch:
        for target in targets:
            if target not in snapshot:
                raise RuntimeError(f"patch targets {target}, not in the working tree")
            (Path(scratch) / target).parent.mkdir(parents=True, exist_ok=True)
            (Path(scratch) / target).write_bytes(snapshot[target][0])
        done = subprocess.run(["patch", "-p1", "--batch", "--forward", "--fuzz=0",
                               "--no-backup-if-mismatch", "-i", str(mutant.source)],
                              cwd=scratch, capture_output=True, text=True)
        if done.returncode != 0:
            raise RuntimeError("patch does not apply: " +
                               (done.stdout + done.stderr).strip().replace("\n", " / "))
        return {target: (Path(scratch) / target).read_bytes() for target in targets}


def sync_tree(src_dir, snapshot, overrides):
    """Makes src_dir hold exactly the snapshot's files, `overrides` replacing
    their content; rewrites only files whose content differs, so that an
    unchanged file keeps its time stamp and Ninja does not rebuild it. The
    build tree inside it (build/) is left alone."""
    for name, (content, executable) in sorted(snapshot.items()):
        content = overrides.get(name, content)
        dest = src_dir / name
        if dest.is_file() and dest.read_bytes() == content:
            continue
        dest.parent.mkdir(parents=True, exist_ok=True)
        dest.write_bytes(content)
        dest.chmod(0o755 if executable else 0o644)
    for path in sorted(src_dir.rglob("*"), reverse=True):
        name = path.relative_to(src_dir).as_posix()
        if name == "build" or name.startswith("build/"):
            continue
        if path.is_file() and name not in snapshot:
            path.unlink()
        elif path.is_dir() and not any(path.iterdir()):
            path.rmdir()


# ---- steps ---------------------------------------------------------------------------------

def run_step(command, cwd, log_path, timeout, env=None):
    """Runs one step in its own process group, output to log_path. Returns
    (exit code, or None on timeout; seconds)."""
    start = time.monotonic()
    with open(log_path, "w") as out:
        out.write("$ " + " ".join(str(c) for c in command) + "\n")
        out.flush()
        process = subprocess.Popen([str(c) for c in command], cwd=cwd, stdout=out,
                                   stderr=subprocess.STDOUT, env=env, start_new_session=True)
        with running_lock:
            running_processes.add(process)
        try:
            code = process.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()
            code = None
            out.write(f"\n[run_mutants] timed out after {timeout} s: killed\n")
        finally:
            with running_lock:
                running_processes.discard(process)
    return code, time.monotonic() - start


def stop_on_signal(signum, _frame):
    """SIGTERM / SIGINT: kill the steps under way (their own process groups,
    which would otherwise outlive the runner) and leave; the reports hold
    every mutant finished so far."""
    with running_lock:
        processes = list(running_processes)
    for process in processes:
        try:
            os.killpg(process.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    # No log(): the main thread may hold print_lock right now.
    os.write(2, f"run_mutants: stopped by signal {signum}; {len(processes)} step(s) "
                f"killed\n".encode())
    os._exit(128 + signum)


def lock_work_dir(work_dir=WORK_DIR):
    """An exclusive lock on build-mutants/ for this run (two runs would share
    the mutant trees): the open lock file, or None if another run holds it."""
    work_dir.mkdir(parents=True, exist_ok=True)
    handle = open(work_dir / "run_mutants.lock", "a+")
    try:
        fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        handle.close()
        return None
    handle.seek(0)
    handle.truncate()
    handle.write(f"{os.getpid()}\n")
    handle.flush()
    return handle


def tree_build_dir(tree_dir):
    """build-mutants/trees/<id>/src/build: the main build's place in its tree."""
    return tree_dir / "src" / "build"


def build_env(tree_dir):
    env = dict(os.environ)
    # Paths relative to the source copy, as the main build's are to the
    # repository (Makefile), so both trees' compile lines hash alike.
    env["CCACHE_BASEDIR"] = str(tree_dir / "src")
    env["CCACHE_NOHASHDIR"] = "1"
    return env


def label_targets(src_dir, label):
    """The test executables of a CTest label (tests/<label>/test_*.cpp, as
    tests/CMakeLists.txt names them: <label>_test_<name>)."""
    return sorted(f"{label}_{p.stem}" for p in (src_dir / "tests" / label).glob("test_*.cpp"))


def build_tree(tree_dir, labels, jobs, log_path, with_stereosim=True, extra_targets=()):
    """Configures (once) and builds the labels' tests, stereosim unless
    with_stereosim is false, and extra_targets. Returns (ok, seconds)."""
    src, build = tree_dir / "src", tree_build_dir(tree_dir)
    env = build_env(tree_dir)
    seconds = 0.0
    # The real test data sits beside the repository, not beside the copy.
    shared_data = f"STEREOSIM_SHARED_DATA:PATH={SHARED_DATA}"
    cache = build / "CMakeCache.txt"
    if not cache.exists() or shared_data not in cache.read_text(errors="replace"):
        configure_log = log_path.with_name("configure.log")
        code, seconds = run_step(["cmake", "-S", src, "-B", build, "-G", "Ninja",
                                  "-DCMAKE_BUILD_TYPE=RelWithDebInfo", "-D" + shared_data],
                                 tree_dir, configure_log, BUILD_TIMEOUT_S, env)
        if code != 0:
            shutil.copyfile(configure_log, log_path)
            return False, seconds
    targets = (["stereosim"] if with_stereosim else []) + list(extra_targets) + \
        [t for label in labels for t in label_targets(src, label)]
    command = ["cmake", "--build", build, "-j", str(jobs), "--target", *targets]
    code, build_s = run_step(command, tree_dir, log_path, BUILD_TIMEOUT_S, env)
    if code != 0 and build_interrupted(code, log_path):
        # A signal from outside (a shared machine), not the mutant: once more.
        log(f"[{tree_dir.name}] build interrupted by a signal: retrying once")
        shutil.copyfile(log_path, log_path.with_name("build-interrupted.log"))
        code, retry_s = run_step(command, tree_dir, log_path, BUILD_TIMEOUT_S, env)
        build_s += retry_s
    return code == 0, seconds + build_s


def build_interrupted(code, log_path):
    """The build died of a signal (ninja: 'interrupted by user') rather than
    of a compile error."""
    if code is None:  # a timeout
        return False
    if code < 0:
        return True
    return "interrupted by user" in log_path.read_text(errors="replace")


def failure_in_mutated_file(log_text, mutated_files):
    """Whether a failed build names a mutated file (comma-separated list) in
    an error line (else the tree itself is broken, not the mutant)."""
    stems = [Path(f).stem for f in mutated_files.split(",") if f]
    for line in log_text.splitlines():
        if not (line.startswith("FAILED:") or "error" in line.lower()):
            continue
        if any(f"/{stem}." in line or line.startswith(f"{stem}.") for stem in stems):
            return True
    return False


def first_error_line(log_text):
    """The first compiler error of a build log, trimmed, or ''."""
    for line in log_text.splitlines():
        if ": error:" in line:
            return line.strip()[:200]
    return ""


def campaign_rows_broken(campaign_json):
    """The rows that broke the contract: [(row key, killed_by entry)], the
    entry 'campaign:<fault>: <first violation>', or 'crash:campaign:...' for
    a row that did not run."""
    broken = []
    for row in json.loads(Path(campaign_json).read_text()).get("rows", []):
        if row.get("contract_ok", False):
            continue
        fault = row.get("fault", "?")
        key = f"{row.get('index')}:{fault}:{row.get('seed')}"
        if fault == "clean":
            fault = f"clean(seed={row.get('seed')})"
        if not row.get("ran", True):
            broken.append((key, f"crash:campaign:{fault}: {row.get('error', 'did not run')}"))
            continue
        violations = row.get("violations") or ["(no violation text)"]
        broken.append((key, f"campaign:{fault}: {violations[0]}"))
    return broken


def run_campaign(build, out_dir, campaign_jobs, plugin=None, binary=None, stop=False):
    """The smoke campaign: (exit code or None on timeout, seconds, broken
    rows). With a firmware plugin, `binary` (an unmutated stereosim) runs
    it; `stop`: the campaign ends at its first broken row."""
    campaign_dir = out_dir / "campaign"
    shutil.rmtree(campaign_dir, ignore_errors=True)
    command = [binary or build / "stereosim", "faults", "--campaign", "smoke", "--jobs",
               str(campaign_jobs), "--out", campaign_dir]
    if plugin:
        command += ["--firmware", plugin]
    if stop:
        command.append("--stop-on-violation")
    code, seconds = run_step(command, build, out_dir / "campaign.log", CAMPAIGN_TIMEOUT_S)
    json_path = campaign_dir / "campaign.json"
    broken = campaign_rows_broken(json_path) if code == 1 and json_path.exists() else []
    return code, seconds, broken


# A firmware mutant is the reference firmware's plugin built in its tree,
# run by an unmutated stereosim: only dsp/ and the plugin are rebuilt.
PLUGIN_TARGET = "stereosim_fw_reference"
PLUGIN_PATH = Path("dsp") / "libstereosim_fw_reference.so"


def platform_binary():
    """The unmutated stereosim that runs the firmware mutants' plugins: the
    main build's, or the baseline tree's."""
    for candidate in (REPO / "build" / "stereosim",
                      WORK_DIR / "trees" / "baseline" / "src" / "build" / "stereosim"):
        if candidate.exists():
            return candidate
    raise RuntimeError("no unmutated stereosim to run the firmware plugins: build it first "
                       "(make build) or run with the baseline")


def check_campaign(result, build, out_dir, campaign_jobs, baseline, plugin=None):
    """The smoke campaign. Returns True when it killed the mutant: exit 1 with
    a broken row the unmutated baseline keeps, a crash, or a timeout. A
    plugin's campaign stops at its first broken row; if that row is one the
    baseline breaks too, it runs again whole."""
    binary = platform_binary() if plugin else None
    code, result.campaign_s, broken = run_campaign(build, out_dir, campaign_jobs, plugin, binary,
                                                   stop=plugin is not None)
    if plugin and code == 1 and broken and all(k in baseline.broken_rows for k, _ in broken):
        code, seconds, broken = run_campaign(build, out_dir, campaign_jobs, plugin, binary)
        result.campaign_s += seconds
    if code is None:
        result.killed_by = [f"crash: campaign timed out after {CAMPAIGN_TIMEOUT_S} s"]
        add_note(result, "campaign timeout")
        return True
    if code < 0:
        result.killed_by = [f"crash: stereosim faults died of signal {-code}"]
        add_note(result, "campaign crash")
        return True
    if code == 0:
        return False
    if code != 1:
        raise RuntimeError(f"campaign exit {code} (see {out_dir / 'campaign.log'})")
    if not broken:
        result.killed_by = ["crash: campaign exit 1 without a broken row in campaign.json"]
        add_note(result, "campaign crash")
        return True
    kills = [entry for key, entry in broken if key not in baseline.broken_rows]
    crashes = sum(entry.startswith("crash:") for entry in kills)
    if crashes:
        add_note(result, f"{crashes} simulation run(s) crashed")
    if not kills:
        add_note(result, "campaign broke only rows the baseline breaks too")
        return False
    result.killed_by = kills
    return True


def failed_tests(ctest_output):
    """Names in ctest's 'The following tests FAILED:' list, with the reason:
    [(name, 'ctest:<name> (<reason>)')]."""
    names, in_list = [], False
    for line in ctest_output.splitlines():
        if line.startswith("The following tests FAILED"):
            in_list = True
            continue
        # A parameterized test's name is followed by "# GetParam() = ...";
        # the reason is the last parenthesized word of the line.
        match = re.match(r"\s*\d+\s+-\s+(\S+).*\((\w[^()]*)\)\s*$", line) if in_list else None
        if match:
            names.append((match.group(1), f"ctest:{match.group(1)} ({match.group(2)})"))
        elif in_list and line.strip() and not line.startswith(("\t", " ")):
            in_list = False
    return names


def run_ctest(build, log_path, label, jobs, stop=False, include=None, exclude=None):
    """`ctest -L <label>` (every label if label is None), with
    --stop-on-failure if stop, -R include and -E exclude (regexes) if given:
    (exit code or None on timeout, seconds, failed tests)."""
    command = ["ctest"] + (["-L", label] if label else []) + \
        ["--output-on-failure", "-j", str(jobs)]
    command += ["--stop-on-failure"] if stop else []
    command += ["-R", include] if include else []
    command += ["-E", exclude] if exclude else []
    code, seconds = run_step(command, build, log_path, CTEST_TIMEOUT_S)
    what = ctest_text(label)
    if code is not None and code < 0:
        raise RuntimeError(f"{what} died of signal {-code} (see {log_path})")
    failed = failed_tests(log_path.read_text(errors="replace")) if code else []
    if code and not failed:
        raise RuntimeError(f"{what} exit {code} with no failed test listed (see {log_path})")
    return code, seconds, failed


def ctest_text(label):
    return f"ctest -L {label}" if label else "ctest -R <known killers>"


# Tests of how the build is put together, not of what the card or firmware
# does: an RTL mutant that adds a trigger puts the island on Verilator's own
# eval (tb/platform/arrangements/fast/card_eval.h), which this test reports.
# Its failure is noted, never a kill.
SHAPE_TESTS = {"rtl.CardEval.TheShippedCardTakesTheLeanPath"}


def check_ctest(result, build, out_dir, label, jobs, baseline, stop=False, include=None,
                exclude=None, log_name="ctest.log"):
    """`ctest -L <label>` (run_ctest's filters) in the mutant's build tree.
    Returns True when it killed: a test failed that passes on the baseline,
    or a timeout."""
    code, seconds, failed = run_ctest(build, out_dir / log_name, label, jobs, stop, include,
                                      exclude)
    result.ctest_s += seconds
    if code is None:
        result.killed_by = [f"crash: {ctest_text(label)} timed out after {CTEST_TIMEOUT_S} s"]
        add_note(result, "ctest timeout")
        return True
    if any(name in SHAPE_TESTS for name, _ in failed):
        add_note(result, "the card takes Verilator's eval (another trigger count)")
    failed = [(name, entry) for name, entry in failed if name not in SHAPE_TESTS]
    kills = [entry for name, entry in failed if name not in baseline.failed_tests]
    if failed and not kills:
        add_note(result, f"{ctest_text(label)}: only tests the baseline fails too")
    result.killed_by = kills
    return bool(kills)


def add_note(result, text):
    result.note = f"{result.note}; {text}" if result.note else text


# ---- the baseline --------------------------------------------------------------------------

@dataclasses.dataclass
class Baseline:
    """What the unmutated working tree breaks: a mutant is only killed by
    campaign rows / tests the baseline keeps."""
    broken_rows: set = dataclasses.field(default_factory=set)
    failed_tests: set = dataclasses.field(default_factory=set)
    summary: str = "not run (--no-baseline)"
    built: bool = False  # the unmutated tree built: a mutant's build failure is its own


def run_baseline(settings, labels):
    """Builds the unmutated tree (trees/baseline) and runs the campaign and
    ctest -L <label> for each label there. Raises if it does not build or
    does not run."""
    tree, out_dir = settings.trees_dir / "baseline", settings.out_dir / "baseline"
    out_dir.mkdir(parents=True, exist_ok=True)
    (tree / "src").mkdir(parents=True, exist_ok=True)
    log("[baseline] tree + build (the unmutated working tree)")
    sync_tree(tree / "src", settings.snapshot, {})
    built, build_s = build_tree(tree, labels, settings.build_jobs, out_dir / "build.log")
    if not built:
        raise RuntimeError(f"the unmutated tree does not build (see {out_dir / 'build.log'})")
    baseline = Baseline(built=True)
    log("[baseline] smoke campaign")
    code, campaign_s, broken = run_campaign(tree_build_dir(tree), out_dir, settings.campaign_jobs)
    if code not in (0, 1):
        raise RuntimeError(f"baseline campaign exit {code} (see {out_dir / 'campaign.log'})")
    baseline.broken_rows = {key for key, _ in broken}
    parts = [f"build {build_s:.0f} s", f"campaign {campaign_s:.0f} s, {len(broken)} row(s) "
             "break the contract" + "".join(f"\n  baseline {entry}" for _, entry in broken)]
    for label in labels:
        log(f"[baseline] ctest -L {label}")
        code, ctest_s, failed = run_ctest(tree_build_dir(tree), out_dir / f"ctest-{label}.log",
                                          label, settings.build_jobs)
        if code is None:
            raise RuntimeError(f"baseline ctest -L {label} timed out")
        baseline.failed_tests |= {name for name, _ in failed}
        parts.append(f"ctest -L {label} {ctest_s:.0f} s, {len(failed)} failed" +
                     "".join(f"\n  baseline {entry}" for _, entry in failed))
    baseline.summary = "; ".join(parts)
    log(f"[baseline] {baseline.summary}")
    return baseline


# ---- one mutant ----------------------------------------------------------------------------

@dataclasses.dataclass
class Settings:
    out_dir: Path
    trees_dir: Path
    campaign_jobs: int
    build_jobs: int
    clean: bool
    snapshot: dict
    # known_killers' record and {ctest name: executable} of the main build;
    # None: every mutant goes the whole way (--whole)
    killers: object = None
    test_executables: dict = dataclasses.field(default_factory=dict)
    neighbours: dict = dataclasses.field(default_factory=dict)  # {file: [mutant id, ...]}
    known_only: bool = False  # a firmware mutant its known killers leave is `unjudged`
    killers_file: Path = KILLERS_FILE


def run_mutant(mutant, settings, baseline):
    """Tree, build, kill checks; never raises (an exception is an `error`)."""
    result = Result(mutant.id, mutant.kind, mutant.file, mutant.description)
    start = time.monotonic()
    tree = settings.trees_dir / mutant.id
    out_dir = settings.out_dir / mutant.id
    out_dir.mkdir(parents=True, exist_ok=True)
    try:
        judge_mutant(mutant, result, tree, out_dir, settings, baseline)
    except Exception as error:  # noqa: BLE001 - every failure is reported, not raised
        result.status = "error"
        add_note(result, str(error))
    finally:
        if settings.clean:
            shutil.rmtree(tree_build_dir(tree), ignore_errors=True)
    result.wall_s = round(time.monotonic() - start, 1)
    for name in ("build_s", "campaign_s", "ctest_s"):
        setattr(result, name, round(getattr(result, name), 1))
    log(f"[{mutant.id}] {result.status} in {result.wall_s:.0f} s "
        f"(build {result.build_s:.0f} s, campaign {result.campaign_s:.0f} s, "
        f"ctest {result.ctest_s:.0f} s) {first(result.killed_by)} {result.note}".rstrip())
    return result


def label_of(kind):
    return "dsp" if kind == "firmware" else "rtl"


def judge_mutant(mutant, result, tree, out_dir, settings, baseline):
    log(f"[{mutant.id}] tree + build")
    (tree / "src").mkdir(parents=True, exist_ok=True)
    sync_tree(tree / "src", settings.snapshot, mutated_contents(mutant, settings.snapshot))
    label = label_of(mutant.kind)
    passed = []  # the known killers that passed: not run again
    if mutant.kind == "firmware" and known_killers_kill(mutant, result, tree, out_dir,
                                                        settings, baseline, passed):
        result.status = "killed"
        return
    if mutant.kind == "firmware" and settings.known_only and campaign_later(mutant, settings):
        result.status = "unjudged"
        add_note(result, "--known-only: not judged the whole way")
        return
    # An RTL mutant's tests come first: they need no stereosim, whose fast
    # card evaluation may not fit a mutated netlist (below).
    firmware = mutant.kind == "firmware"
    built, seconds = build_tree(tree, [label], settings.build_jobs, out_dir / "build.log",
                                with_stereosim=False,
                                extra_targets=[PLUGIN_TARGET] if firmware else [])
    result.build_s += seconds
    if not built:
        log_text = (out_dir / "build.log").read_text(errors="replace")
        in_mutated = failure_in_mutated_file(log_text, mutant.file)
        if not in_mutated and not baseline.built:
            raise RuntimeError(f"build failed outside {mutant.file}: is the working tree "
                               f"broken? (see {out_dir / 'build.log'})")
        # Where the baseline built, a failure elsewhere is the mutation's too.
        result.status = "stillborn"
        if not in_mutated:
            add_note(result, "does not build where the baseline did: " +
                     first_error_line(log_text))
        return
    build, jobs = tree_build_dir(tree), settings.build_jobs
    if firmware:
        killed = judge_firmware(mutant, result, build, out_dir, settings, baseline, passed)
    else:
        log(f"[{mutant.id}] ctest -L rtl")
        killed = check_ctest(result, build, out_dir, "rtl", jobs, baseline)
        if not killed and not build_stereosim(mutant, result, tree, out_dir, settings,
                                              baseline):
            return
        if not killed:
            log(f"[{mutant.id}] smoke campaign")
            result.campaign_kills = check_campaign(result, build, out_dir,
                                                   settings.campaign_jobs, baseline)
            killed = result.campaign_kills
    result.status = "killed" if killed else "survived"
    if not killed and firmware and settings.known_only:
        result.status = "unjudged"  # the campaign, its known killer, did not kill
        add_note(result, "--known-only: not judged the whole way")


def campaign_later(mutant, settings):
    """Whether the tests go before the campaign for a firmware mutant."""
    return settings.killers is not None and known_killers.tests_first(
        mutant.id, settings.killers, settings.neighbours.get(mutant.file, ()))


def judge_firmware(mutant, result, build, out_dir, settings, baseline, passed=()):
    """The smoke campaign, then `ctest -L dsp`. With a record (not --whole)
    ctest stops at its first failure, and for a mutant the record does not
    give to the campaign it comes first, the campaign only if it left the
    mutant alive (a box mutant is hardly ever the campaign's)."""
    tests_first = campaign_later(mutant, settings)
    steps = ("ctest", "campaign") if tests_first else ("campaign", "ctest")
    # --known-only: a mutant here is the campaign's, and the campaign its known killer.
    for step in steps[:1] if settings.known_only else steps:
        if step == "campaign":
            log(f"[{mutant.id}] smoke campaign (its plugin, stopping at the first broken row)")
            result.campaign_kills = check_campaign(result, build, out_dir,
                                                   settings.campaign_jobs, baseline,
                                                   plugin=build / PLUGIN_PATH)
            if result.campaign_kills:
                return True
        elif ctest_kills(mutant, result, build, out_dir, settings, baseline,
                         settings.killers is not None and not baseline.failed_tests, passed):
            return True
    return False


# The box cases: 367 of the dsp label's 590 tests (31 disabled) and most of its time
# (2.7 s each with one job), so a ctest that stops at its first failure
# runs the label's quick unit tests before them.
SLOW_TESTS = "BoxOnMotion"


def ctest_kills(mutant, result, build, out_dir, settings, baseline, stop, passed):
    """`ctest -L dsp` without the tests already passed; when stopping at
    the first failure (a baseline test failing would stop it without a
    verdict), the quick tests first, then the box cases (ctest-slow.log)."""
    log(f"[{mutant.id}] ctest -L dsp" + (" (stopping at the first failure)" if stop else ""))
    return any(check_ctest(result, build, out_dir, "dsp", settings.build_jobs, baseline,
                           stop=stop, include=include, exclude=exclude, log_name=log_name)
               for log_name, include, exclude in ctest_parts(stop, passed))


def ctest_parts(stop, passed):
    """[(log name, -R regex, -E regex)] of the ctest runs after the known
    killers: together the label less the tests passed."""
    tried = known_killers.ctest_regex(passed) if passed else None
    if not stop:
        return [("ctest.log", None, tried)]
    return [("ctest.log", None, SLOW_TESTS + (f"|{tried}" if tried else "")),
            ("ctest-slow.log", SLOW_TESTS, tried)]


def known_killers_kill(mutant, result, tree, out_dir, settings, baseline, passed):
    """Builds the executables of the tests the record names for this mutant
    (or its most frequent killers) and runs those tests, stopping at the
    first failure. True when one the baseline passes failed; False sends
    the mutant the whole way (its tree then builds the rest), and when
    they all ran and passed, their names are put in passed."""
    if not campaign_later(mutant, settings):
        return False  # --whole, or the campaign's mutant: the campaign comes first
    names, why = known_killers.tests_to_try(mutant.id, settings.killers,
                                            settings.neighbours.get(mutant.file, ()))
    names = [n for n in names if n in settings.test_executables
             and n not in baseline.failed_tests and n not in SHAPE_TESTS]
    if not names:
        return False
    targets = sorted({settings.test_executables[n] for n in names})
    log(f"[{mutant.id}] known killers first ({why}): {len(names)} test(s) of "
        f"{', '.join(targets)}")
    # A cli test runs the tree's stereosim with its reference firmware plugin.
    cli = known_killers.needs_stereosim(names)
    built, seconds = build_tree(tree, [], settings.build_jobs, out_dir / "build-known.log",
                                with_stereosim=cli,
                                extra_targets=targets + ([PLUGIN_TARGET] if cli else []))
    result.build_s += seconds
    if not built:
        return False  # the whole build tells stillborn from broken
    # The names hold no baseline failure: a pass that did not kill passed them all.
    if not check_ctest(result, tree_build_dir(tree), out_dir, None, settings.build_jobs,
                       baseline, stop=True, include=known_killers.ctest_regex(names),
                       log_name="ctest-known.log"):
        passed.extend(names)
        add_note(result, f"known killers ({why}) did not kill")
        return False
    add_note(result, f"killed by known killers ({why}); campaign not run")
    return True


def build_stereosim(mutant, result, tree, out_dir, settings, baseline):
    """Builds stereosim for an RTL mutant the tests left alive. A build that
    fails where the baseline built is the mutation's doing (e.g. a netlist
    whose evaluation no longer has the shape the fast arrangement's
    card_eval.h requires): `stillborn`, with the first error as its note.
    False when there is no stereosim to run the campaign with."""
    log_path = out_dir / "build-stereosim.log"
    built, seconds = build_tree(tree, ["rtl"], settings.build_jobs, log_path)
    result.build_s += seconds
    if built:
        return True
    text = log_path.read_text(errors="replace")
    if not baseline.built and not failure_in_mutated_file(text, mutant.file):
        raise RuntimeError(f"stereosim failed to build outside {mutant.file} and there is no "
                           f"baseline to tell (see {log_path})")
    result.status = "stillborn"
    add_note(result, "survived the rtl tests; stereosim does not build with it: " +
             first_error_line(text))
    return False


def first(items):
    return items[0] if items else ""


# ---- reports -------------------------------------------------------------------------------

def apply_equivalents(results, equivalents):
    for result in results:
        if result.status == "survived" and result.id in equivalents:
            result.status = "equivalent"
            add_note(result, "equivalent: " + equivalents[result.id])


def summary(results, wall_s):
    count = {s: sum(r.status == s for r in results)
             for s in ("killed", "survived", "equivalent", "stillborn", "error", "unjudged")}
    judged = len(results) - count["equivalent"] - count["stillborn"] - count["unjudged"]
    score = 100.0 * count["killed"] / judged if judged else 0.0
    firmware = [r for r in results if r.kind == "firmware" and r.campaign_kills is not None
                and r.status != "equivalent"]
    by_campaign = sum(bool(r.campaign_kills) for r in firmware)
    return (f"mutants: {len(results)} total, {count['killed']} killed, {count['survived']} "
            f"survived, {count['equivalent']} equivalent, {count['stillborn']} stillborn, "
            f"{count['error']} error" +
            (f", {count['unjudged']} unjudged (--known-only)" if count["unjudged"] else "") +
            f"; mutation score {score:.1f} % "
            f"({count['killed']}/{judged}); the smoke campaign alone kills {by_campaign} of "
            f"{len(firmware)} firmware mutants; wall {wall_s:.1f} s")


def campaign_kills_text(value):
    return "-" if value is None else ("yes" if value else "no")


def table(results, wall_s):
    width = max([len(r.id) for r in results] + [2])
    lines = [f"{'id':<{width}}  {'kind':<8} {'status':<10} {'campaign':<8} {'wall_s':>7} "
             f"{'build_s':>7} {'camp_s':>7}  killed_by / note"]
    for r in results:
        reason = first(r.killed_by) or r.note
        if len(r.killed_by) > 1:
            reason += f" (+{len(r.killed_by) - 1} more)"
        lines.append(f"{r.id:<{width}}  {r.kind:<8} {r.status:<10} "
                     f"{campaign_kills_text(r.campaign_kills):<8} {r.wall_s:>7.1f} "
                     f"{r.build_s:>7.1f} {r.campaign_s:>7.1f}  {reason[:150]}")
    lines.append("")
    lines.append(summary(results, wall_s))
    return "\n".join(lines) + "\n"


def write_reports(results, out_dir, wall_s, baseline=None):
    out_dir.mkdir(parents=True, exist_ok=True)
    rows = [dataclasses.asdict(r) for r in results]
    (out_dir / "mutants.json").write_text(json.dumps(rows, indent=2) + "\n")
    with open(out_dir / "mutants.csv", "w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=COLUMNS)
        writer.writeheader()
        for row in rows:
            row = dict(row, killed_by=" | ".join(row["killed_by"]),
                       campaign_kills=campaign_kills_text(row["campaign_kills"]))
            writer.writerow(row)
    text = table(results, wall_s)
    if baseline is not None:
        text += f"baseline (unmutated tree): {baseline.summary}\n"
    (out_dir / "mutants.txt").write_text(text)
    return text


def write_killers(results, settings):
    """DIR/killers.tsv: the record as this run leaves it (copy it over
    tests/mutants/firmware-killers.tsv to keep it)."""
    record = known_killers.read_killers(settings.killers_file) if settings.killers is None \
        else settings.killers
    record = known_killers.merged_record(record, results)
    known_killers.write_record(settings.out_dir / "killers.tsv", record)
    if settings.killers is not None:
        settings.killers = record  # the mutants still to run learn from these


def exit_code(results, baseline=None):
    """1 if a mutant survived unlisted, is an error or was not judged, or
    the unmutated tree itself breaks the contract or a test; else 0."""
    bad = [r for r in results if r.status in ("survived", "error", "unjudged")]
    baseline_broken = baseline is not None and (baseline.broken_rows or baseline.failed_tests)
    return 1 if bad or baseline_broken else 0


# ---- command line --------------------------------------------------------------------------

def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--kind", choices=["firmware", "rtl", "all"], default="all")
    parser.add_argument("--only", default="", help="comma-separated mutant ids")
    parser.add_argument("--jobs", type=int, default=int(os.environ.get("MUTANT_JOBS") or 1),
                        help="mutants at a time (default $MUTANT_JOBS or 1)")
    parser.add_argument("--campaign-jobs", type=int, default=None,
                        help="the campaign's --jobs (default 2 if --jobs is 1, else 1)")
    parser.add_argument("--build-jobs", type=int, default=None,
                        help="ninja / ctest -j per mutant (default cores / --jobs)")
    parser.add_argument("--out", type=Path, default=WORK_DIR / "results")
    parser.add_argument("--rtl-dir", type=Path, default=None,
                        help="an existing generator OUTDIR (default: run the generator "
                             "into build-mutants/rtl)")
    parser.add_argument("--rtl-count", type=int, default=None)
    parser.add_argument("--rtl-seed", type=int, default=None)
    parser.add_argument("--clean", action="store_true",
                        help="remove each mutant's build tree after its run")
    parser.add_argument("--killers", type=Path, default=KILLERS_FILE,
                        help="the record of known killers (default "
                             "tests/mutants/firmware-killers.tsv)")
    parser.add_argument("--known-only", action="store_true",
                        help="judge firmware mutants by their known killers only: one they "
                             "leave alive is `unjudged` (a quick re-check of the record)")
    parser.add_argument("--whole", action="store_true",
                        help="every firmware mutant the whole way (campaign, then ctest -L "
                             "dsp), not its known killers first")
    parser.add_argument("--no-baseline", action="store_true",
                        help="skip the unmutated baseline tree (its campaign rows and tests "
                             "that fail are otherwise not counted as kills)")
    args = parser.parse_args(argv)
    if args.jobs < 1:
        parser.error("--jobs must be >= 1")
    if args.campaign_jobs is None:
        args.campaign_jobs = 2 if args.jobs == 1 else 1
    if args.build_jobs is None:
        args.build_jobs = max(1, (os.cpu_count() or 1) // args.jobs)
    return args


def select_mutants(args):
    mutants = []
    if args.kind in ("firmware", "all"):
        mutants += firmware_mutants()
    if args.kind in ("rtl", "all"):
        mutants += targeted_rtl_mutants()
        rtl_dir = args.rtl_dir
        if rtl_dir is None:
            rtl_dir = WORK_DIR / "rtl"
            if not generate_rtl_mutants(rtl_dir, args.rtl_count, args.rtl_seed):
                rtl_dir = None
        if rtl_dir is not None:
            mutants += read_rtl_catalogue(rtl_dir)
    if args.only:
        wanted = [i.strip() for i in args.only.split(",") if i.strip()]
        known = {m.id for m in mutants}
        missing = [i for i in wanted if i not in known]
        if missing:
            raise RuntimeError(f"unknown mutant id(s): {', '.join(missing)}")
        mutants = [m for m in mutants if m.id in wanted]
    return mutants


def run_all(mutants, settings, baseline, jobs, start):
    """N mutants at a time; the reports are rewritten after each one, so an
    interrupted run keeps what it finished. Returns the results in order."""
    done = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = {pool.submit(run_mutant, m, settings, baseline): i
                   for i, m in enumerate(mutants)}
        for future in concurrent.futures.as_completed(futures):
            done[futures[future]] = future.result()
            partial = [done[i] for i in sorted(done)]
            write_reports(partial, settings.out_dir, time.monotonic() - start, baseline)
            write_killers(partial, settings)
    return [done[i] for i in range(len(mutants))]


def load_known_killers(settings, whole, path=KILLERS_FILE):
    """The record and the main build's test executables, unless --whole or
    there is no main build to map the tests (then every mutant goes the
    whole way, said once)."""
    settings.killers_file = path
    if whole:
        return
    record = known_killers.read_killers(path)
    main_build = REPO / "build"
    if not (main_build / "CTestTestfile.cmake").exists():
        log(f"run_mutants: no configured {main_build}: every mutant goes the whole way")
        return
    settings.killers = record
    # The cli and system labels' too: a firmware mutant the box cases miss may
    # still break a co-simulated scenario or the default scenario's cycle golden
    # (the record names those by hand, docs/mutants.md).
    settings.test_executables = {name: program for label in ("dsp", "cli", "system")
                                 for name, program in
                                 known_killers.test_executables(main_build, label).items()}
    for mutant in firmware_mutants():
        settings.neighbours.setdefault(mutant.file, []).append(mutant.id)


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    start = time.monotonic()
    lock = lock_work_dir()
    if lock is None:
        print(f"run_mutants: another run holds {WORK_DIR / 'run_mutants.lock'}: wait for it "
              "(two runs would share the mutant trees)", file=sys.stderr)
        return 2
    signal.signal(signal.SIGTERM, stop_on_signal)
    signal.signal(signal.SIGINT, stop_on_signal)
    try:
        mutants = select_mutants(args)
    except (RuntimeError, OSError, subprocess.TimeoutExpired) as error:
        print(f"run_mutants: {error}", file=sys.stderr)
        return 2
    if not mutants:
        print("run_mutants: no mutant selected", file=sys.stderr)
        return 2
    settings = Settings(args.out.resolve(), WORK_DIR / "trees", args.campaign_jobs,
                        args.build_jobs, args.clean, snapshot_working_tree())
    try:
        load_known_killers(settings, args.whole, args.killers)
        settings.known_only = args.known_only and settings.killers is not None
    except (ValueError, OSError, subprocess.SubprocessError) as error:
        print(f"run_mutants: known killers: {error}", file=sys.stderr)
        return 2
    log(f"run_mutants: {len(mutants)} mutant(s), {args.jobs} at a time, campaign --jobs "
        f"{args.campaign_jobs}, build -j {args.build_jobs}; results in {settings.out_dir}")
    baseline = Baseline()
    if not args.no_baseline:
        labels = sorted({label_of(m.kind) for m in mutants})
        try:
            baseline = run_baseline(settings, labels)
        except (RuntimeError, OSError) as error:
            print(f"run_mutants: baseline: {error}", file=sys.stderr)
            return 1
        finally:
            if args.clean:
                shutil.rmtree(tree_build_dir(settings.trees_dir / "baseline"), ignore_errors=True)
    results = run_all(mutants, settings, baseline, args.jobs, start)
    apply_equivalents(results, read_equivalents())
    text = write_reports(results, settings.out_dir, time.monotonic() - start, baseline)
    write_killers(results, settings)
    print("\n" + text, end="")
    return exit_code(results, baseline)


if __name__ == "__main__":
    sys.exit(main())
