// The fault campaign (docs/fault-contract.md "The campaign"): every fault
// kind over a range of parameters and seeds, plus clean runs, each an
// independent `stereosim run ... --out <dir>` child process (posix_spawn,
// `jobs` at a time), or a group of runs forked from one fault-free run at
// their snapshots (snapshots.h), each checked against the contract from its
// report.json.
// Writes campaign.json, campaign.csv and campaign.txt (the table also goes
// to stdout); `shard K/M` runs the K-th of M deterministic slices.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include <functional>
#include "tb/app/faults/fault_report.h"

#include "tb/app/faults/job_tokens.h"
#include "tb/app/faults/snapshot_trigger.h"

namespace faults {

struct campaign_run {
    int index = 0;      // position in the whole campaign (before sharding)
    std::string fault;  // spec(s), space-separated; empty for a clean run
    uint64_t seed = 3;
    int frames = 8;
    int retry_limit = 8;                // --card-retry-limit
    std::vector<std::string> settings;  // --set KEY=VALUE each (docs/config.md)
};

// The runs of a named campaign ("smoke" or "full"; else empty). `seeds`:
// seeds per fault spec (0: the campaign's default).
std::vector<campaign_run> campaign_plan(const std::string& name, int seeds);

// The space-separated words of a run's fault (its specs) or settings.
std::vector<std::string> spec_words(const std::string& text);

// Runs index % shards == shard - 1 (shard 1-based).
std::vector<campaign_run> shard_of(const std::vector<campaign_run>& runs, int shard, int shards);

struct campaign_options {
    std::string name = "smoke";
    int seeds = 0;
    int jobs = 2;
    int shard = 1, shards = 1;
    std::string out_dir;      // default: campaign-<name>
    std::string binary;       // the stereosim to spawn (default: this program)
    std::string firmware;     // every run's --firmware (absolute path); empty: the built-in one
    bool paper_card = false;  // every run's --paper-card: the card without its frame-identity check
    bool keep_runs = false;   // keep each run's folder (report.json, frames.csv)
    std::string match;        // only runs whose spec contains this ("clean": clean runs)
    // Runs of one seed, length and card setting whose faults all start later
    // share their fault-free prefix (snapshots.h): run_group runs such a
    // group in the leader process (run_snapshot_group with this program's
    // run extensions); without it, or with another binary, every run is
    // spawned.
    bool snapshots = true;
    // Keep the rows that ran in out_dir's campaign.json (an interrupted
    // campaign's) and run only the others.
    bool resume = false;
    // End the campaign at the first run that breaks the contract (or did not
    // run): the runs under way are stopped, the document marked incomplete
    // and `stopped_at` names that run. For qualification by mutants, where
    // one broken run is the verdict.
    bool stop_on_violation = false;
    std::function<int(const std::vector<snapshot_member>& members, const std::string& binary,
                      const std::string& leader_log, const job_tokens& tokens)>
        run_group;
};

struct campaign_row {
    campaign_run run;
    bool finished = false;  // its child ended (false: not started, or stopped by an interrupt)
    bool ran = false;       // the child wrote a report.json we could read
    int exit_code = -1;
    double wall_s = 0;
    double snapshot_ms = -1;  // forked from a snapshot at this simulated time; -1: from the start
    std::string error;        // why it did not run
    // The firmware under test crashed or hung (the child's exit 3 and its
    // one line, tb/platform/firmware_crash.h): the row's outcome `crash`.
    bool crashed = false;
    // What the run was too short to judge: its report's not_judged (a stage
    // that never ran) and the contract's rules, "; "-joined; empty: all.
    std::string not_judged;
    fault_run_result result;
    bool ok() const { return ran && result.contract_ok(); }
};

// Runs the campaign; returns the rows (in plan order) and writes the files
// (campaign_files.h), *document = campaign.json's content if given.
// Progress lines go to `log` (may be null). SIGINT or SIGTERM meanwhile
// stops the runs under way and writes the rows that finished, the document
// marked incomplete; *interrupted = the signal (else 0).
std::vector<campaign_row> run_campaign(const campaign_options& options, std::FILE* log,
                                       std::string* error, nlohmann::json* document = nullptr,
                                       int* interrupted = nullptr);

}  // namespace faults
