// Fault campaigns from snapshots (docs/fault-contract.md "Snapshots"): runs
// of one seed, length and card setting that differ only in faults starting
// later share their fault-free prefix. A group's leader (a process forked
// from the campaign) builds the platform once from the runs' options without
// their faults and simulates it; just before a run's first fault could act it
// fork()s, and the child adds that run's faults to the paused platform and
// runs on to the end as `stereosim run` would (same report.json, same files).
// The simulation is single-threaded (SystemC's coroutines, the verilated card
// is plain memory), so a fork is a complete copy of the run so far.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "tb/app/cli/run_outputs.h"
#include "tb/app/faults/job_tokens.h"
#include "tb/app/faults/snapshot_trigger.h"

namespace faults {

// The run command's extensions, made anew for each run (app::make_run_extensions).
using extensions_factory = std::function<std::vector<std::unique_ptr<cli::run_extension>>()>;

// The leader, in a process of its own (its messages into `leader_log`),
// holding one of the campaign's job tokens: runs members[0]'s options
// without faults and forks each member at its snapshot (a member whose
// snapshot point was passed is run from the start, by exec of `binary`).
// A child computes once it holds a token (the leader puts it back when it
// reaps the child); the leader puts its own back when its fault-free run
// ends. Writes each member's DIR/status ("<wait status> <wall seconds>
// <snapshot ms, -1 from the start>") as it ends. Returns the leader's exit
// code (0; 2 or 3 if the fault-free run could not be set up or failed).
int run_snapshot_group(const std::vector<snapshot_member>& members, const std::string& binary,
                       const extensions_factory& make_extensions, const std::string& leader_log,
                       const job_tokens& tokens);

}  // namespace faults
