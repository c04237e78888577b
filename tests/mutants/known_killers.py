"""What killed each firmware mutant last time, tried first (docs/mutants.md,
"Known killers first").

A whole catalogue run judges most firmware mutants by `ctest -L dsp`, which
runs every dsp test (about 6 min on 2 cores) whatever fails first. A mutant
that a known test kills is judged as well by that test alone: its tree then
builds only the executables holding its known killers and runs them with
`ctest -R ... --stop-on-failure`; only if none of them kills does it go the
whole way (the plugin, the smoke campaign, `ctest -L dsp`).

The record, tests/mutants/firmware-killers.tsv, has one line per check that
killed a mutant: `<id> TAB campaign` or `<id> TAB <ctest name>`, in the
order the run listed them. Each run writes it anew into its --out DIR as
killers.tsv: the record's lines for mutants it did not judge, and this
run's killers for those it killed.
"""

import collections
import json
import re
import subprocess
from pathlib import Path

CAMPAIGN = "campaign"
# A mutant's tests tried first, at most; and for a mutant with no record,
# the record's most frequent killers tried instead. The tests tried are
# left out of the `ctest -L dsp` after them, so a long list only reorders.
MAX_OWN = 8
MAX_LIKELY = 30


def read_killers(path):
    """{id: [check, ...]} from a record; {} when it does not exist. A line
    that is not `id TAB check` raises ValueError naming it."""
    killers = collections.OrderedDict()
    path = Path(path)
    if not path.exists():
        return killers
    for number, line in enumerate(path.read_text().splitlines(), 1):
        if not line.strip() or line.startswith("#"):
            continue
        parts = line.split("\t")
        if len(parts) != 2 or not parts[0].strip() or not parts[1].strip():
            raise ValueError(f"{path}:{number}: not '<id> TAB <check>': {line!r}")
        checks = killers.setdefault(parts[0].strip(), [])
        if parts[1].strip() not in checks:
            checks.append(parts[1].strip())
    return killers


def checks_of(killed_by, campaign_killed):
    """A killed result's checks as the record spells them: `campaign`, or
    the test names of its `ctest:<name> (<reason>)` entries."""
    if campaign_killed:
        return [CAMPAIGN]
    names = []
    for entry in killed_by:
        match = re.match(r"ctest:(\S+)", entry)
        if match:
            names.append(match.group(1))
    return names


def likely_killers(killers, limit=MAX_LIKELY):
    """The record's tests that killed the most mutants, most first (ties in
    name order): what a mutant with no record of its own tries first. Not
    the cli label's: each would build stereosim into every mutant's tree."""
    count = collections.Counter(c for checks in killers.values() for c in checks
                                if c != CAMPAIGN and not needs_stereosim([c]))
    return [name for name, _ in sorted(count.items(), key=lambda i: (-i[1], i[0]))[:limit]]


def tests_to_try(mutant_id, killers, neighbours=()):
    """The tests a mutant tries before the whole way, and why: ([], reason)
    when the campaign comes first anyway (its record says the campaign).
    With no record of its own: the most frequent killers of its neighbours
    (the mutants of its source file), then of the whole record."""
    own = killers.get(mutant_id, [])
    if CAMPAIGN in own:
        return [], "its record's killer is the campaign"
    near = likely_killers({k: v for k, v in killers.items() if k in set(neighbours)},
                          MAX_LIKELY // 2)
    rest = [n for n in likely_killers(killers, MAX_LIKELY) if n not in near]
    likely = [n for n in (near + rest)[:MAX_LIKELY] if n not in own[:MAX_OWN]]
    if own:
        return own[:MAX_OWN] + likely, "its record, then the record's most frequent killers"
    return likely, "the record's most frequent killers"


def tests_first(mutant_id, killers, neighbours=()):
    """Whether `ctest -L dsp` goes before the smoke campaign: yes for a
    mutant its record gives to tests; for one with no record, when more of
    its neighbours' records are tests than the campaign (the control
    program's mutants are the campaign's, the box's the box cases'), or
    where none has one, more of the whole record's."""
    own = killers.get(mutant_id)
    if own:
        return CAMPAIGN not in own
    near = [killers[n] for n in neighbours if n in killers] or list(killers.values())
    by_campaign = sum(CAMPAIGN in checks for checks in near)
    return len(near) - by_campaign > by_campaign


def ctest_regex(names):
    """A CTest -R regex matching exactly these tests. A parameterized test's
    CTest name goes on with '  # GetParam() = ...', hence the end `( |$)`."""
    special = set("\\^$.|?*+()[]{}")
    escaped = ["".join("\\" + c if c in special else c for c in n) for n in names]
    return "^(" + "|".join(escaped) + ")( |$)"


def test_executables(build_dir, label):
    """{ctest name: executable name} of a configured build's label, from
    `ctest --show-only=json-v1` (names cut at their first space). Only the
    label's own executables (<label>_test_*): a test run by a script has no
    target to build."""
    output = subprocess.run(["ctest", "--show-only=json-v1", "-L", label], cwd=build_dir,
                            capture_output=True, text=True, check=True, timeout=120).stdout
    table = {}
    for test in json.loads(output).get("tests", []):
        command = test.get("command") or []
        if command and Path(command[0]).name.startswith(f"{label}_"):
            table[test["name"].split(" ")[0]] = Path(command[0]).name
    return table


def needs_stereosim(names):
    """Whether these tests run the stereosim program (the cli label's do)."""
    return any(name.startswith("cli.") for name in names)


def merged_record(killers, results):
    """The record after a run: each killed result's checks replace its old
    lines; a mutant this run judged otherwise loses them; others keep them."""
    merged = collections.OrderedDict((k, list(v)) for k, v in killers.items())
    for result in results:
        if result.kind != "firmware" or result.status in ("error", "unjudged"):
            continue
        merged.pop(result.id, None)
        if result.status == "killed":
            checks = checks_of(result.killed_by, result.campaign_kills)
            if checks:
                merged[result.id] = checks
    return collections.OrderedDict(sorted(merged.items()))


def write_record(path, record):
    lines = [f"{mutant_id}\t{check}" for mutant_id, checks in record.items()
             for check in checks]
    Path(path).write_text("".join(line + "\n" for line in lines))
