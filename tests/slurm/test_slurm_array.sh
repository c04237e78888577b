#!/usr/bin/env bash
# CTest slurm.job_arrays (label slurm, docs/cluster.md): a real single-node
# Slurm cluster on localhost (scripts/slurm-local: munged, slurmctld, slurmd
# in a temp dir), the job arrays `--emit-slurm` writes for a small sweep and
# a slice of the smoke campaign submitted with sbatch, waited for, merged
# with `stereosim merge`, and compared with the same sweep and slice run
# locally in one go (wall times, job counts and snapshot times aside). The
# daemons are stopped however the test ends.
# Usage: test_slurm_array.sh STEREOSIM REPO
set -euo pipefail
stereosim=$1
repo=$2
slurm_local=$repo/scripts/slurm-local
work=$(mktemp -d /tmp/stereosim-slurm-XXXXXX)
chmod 755 "$work"  # munged wants every folder above its socket open to all
cluster=$work/cluster
cleanup() {
  "$slurm_local" stop "$cluster" >/dev/null 2>&1 || true
  rm -rf "$work"
}
trap cleanup EXIT

"$slurm_local" start "$cluster"
# shellcheck disable=SC1091
source "$cluster/env"

# Submits DIR/job.sbatch, waits, merges DIR/shard-* into DIR.
run_array() {
  local dir=$1 job
  job=$(sbatch --parsable "$dir/job.sbatch")
  echo "submitted $dir/job.sbatch as job $job"
  if ! "$slurm_local" wait "$cluster" "$job" 1200; then
    tail -n 5 "$dir"/logs/task-*.log >&2 || true
    echo "FAIL: job $job did not complete" >&2
    exit 1
  fi
  "$stereosim" merge "$dir"/shard-* --out "$dir"
}

# The two documents equal but for wall times, job counts and snapshot times.
same_json() {
  python3 - "$1" "$2" <<'PY'
import json, sys
def clean(o):
    if isinstance(o, dict):
        return {k: clean(v) for k, v in o.items() if k not in ("wall_s", "jobs", "snapshot_ms")}
    if isinstance(o, list):
        return [clean(v) for v in o]
    return o
a, b = (clean(json.load(open(p))) for p in sys.argv[1:3])
if a != b:
    print("FAIL: %s and %s differ" % tuple(sys.argv[1:3]), file=sys.stderr)
    sys.exit(1)
n = len(a.get("points", a.get("rows", [])))
print("same: %s and %s (%d entries)" % (sys.argv[1], sys.argv[2], n))
PY
}

# A sweep of 4 points as a 4-task array, one CPU each.
grid=(--grid dsk.cpu_mhz=250,600 --grid firmware.search_radius=8,48 --frames 6)
"$stereosim" sweep "${grid[@]}" --emit-slurm --slurm-tasks 4 --slurm-cpus 1 --out "$work/sweep"
run_array "$work/sweep"
"$stereosim" sweep "${grid[@]}" --jobs 2 --out "$work/sweep-local" >/dev/null 2>&1
same_json "$work/sweep/sweep.json" "$work/sweep-local/sweep.json"
cmp "$work/sweep/sweep.csv" "$work/sweep-local/sweep.csv" || {
  # the csv has no wall column: any difference is a real one
  echo "FAIL: sweep.csv differs" >&2
  exit 1
}
cmp "$work/sweep/frontier.csv" "$work/sweep-local/frontier.csv"

# A slice of the smoke campaign (3 runs) as a 2-task array.
slice=(--campaign smoke --match 'drop-frame:sensor=R@frame=4|dark-leak:sensor=L,level=8|skew:sensor=L,pixels=1@frame=2')
"$stereosim" faults "${slice[@]}" --emit-slurm --slurm-tasks 2 --slurm-cpus 1 --out "$work/campaign"
run_array "$work/campaign"
"$stereosim" faults "${slice[@]}" --jobs 2 --out "$work/campaign-local" >/dev/null 2>&1
same_json "$work/campaign/campaign.json" "$work/campaign-local/campaign.json"
python3 - "$work/campaign/campaign.json" <<'PY'
import json, sys
c = json.load(open(sys.argv[1]))
assert c["shard"] == "1/1" and c["runs"] >= 3, c
assert c["contract_broken"] == 0, c
print("campaign slice: %d runs, %d break the contract" % (c["runs"], c["contract_broken"]))
PY
"$slurm_local" stop "$cluster"
if pgrep -f "$cluster" >/dev/null; then
  echo "FAIL: daemons of $cluster still running" >&2
  exit 1
fi
echo "PASS"
