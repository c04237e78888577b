// The fault campaign both ways (issue 14; docs/performance.md "Fault
// campaigns from snapshots"), for bench_platform: `stereosim faults
// --campaign C --jobs 2` with snapshots (the default: runs of one seed fork
// from a fault-free leader at their first fault's onset) and with
// --no-snapshots (every run from the start), one after the other, the order
// alternating over the repetitions.
//
// STEREOSIM_BENCH_CAMPAIGN: smoke (default, about 2 min both ways) or full
// (about 25 min on 2 cores). STEREOSIM_BENCH_CAMPAIGN_REPS: repetitions
// (default 1).
// Each campaign's own output goes to a log beside its folder, kept when a
// campaign fails.
// Counters:
//   snapshots_wall_s, no_snapshots_wall_s  each way's campaign wall time (median)
//   snapshots_over_no_snapshots            median of the per-repetition ratios (< 1: a gain)
//   runs, runs_forked                      the campaign's runs, those forked at a snapshot
//   contract_broken                        runs that broke the contract, either way (0 expected)
//   rows_identical                         1 if both ways' campaign.json rows are equal but for
//                                          wall_s and snapshot_ms
// The program that includes this defines STEREOSIM_BINARY (bench/CMakeLists.txt).
#pragma once

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench/bench_support.h"

namespace bench {

using nlohmann::json;

struct campaign_run {
    double wall_s = -1.0;  // negative: the campaign failed
    json document;
};

// One campaign into `out` (removed first); wall time of the whole command.
// A campaign that broke the contract exits 1 but writes campaign.json: its
// timing counts, and contract_broken reports the breaks.
inline campaign_run run_campaign(const std::string& campaign, bool snapshots,
                                 const std::filesystem::path& out) {
    std::filesystem::remove_all(out);
    std::filesystem::create_directories(out.parent_path());
    // Its table and progress lines go to OUT.log beside OUT.
    const std::string command =
        std::string(STEREOSIM_BINARY) + " faults --campaign " + campaign + " --jobs 2 --out " +
        out.string() + (snapshots ? "" : " --no-snapshots") + " > " + out.string() + ".log 2>&1";
    const auto wall0 = std::chrono::steady_clock::now();
    if (std::system(command.c_str()) == -1) return {};  // no shell to run it
    campaign_run r;
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    std::ifstream in(out / "campaign.json");
    if (!in) return r;
    r.document = json::parse(in);
    r.wall_s = wall;
    return r;
}

// The rows without the fields that depend on the machine or on forking.
inline json comparable_rows(const json& document) {
    json rows = document.at("rows");
    for (json& row : rows) {
        row.erase("wall_s");
        row.erase("snapshot_ms");
    }
    return rows;
}

inline int forked_runs(const json& document) {
    int forked = 0;
    for (const json& row : document.at("rows")) forked += row.at("snapshot_ms").is_number();
    return forked;
}

inline void campaign_both_ways(benchmark::State& state) {
    const std::string campaign = env_text("STEREOSIM_BENCH_CAMPAIGN", "smoke");
    const int reps = env_int("STEREOSIM_BENCH_CAMPAIGN_REPS", 1);
    if (campaign.find_first_not_of("abcdefghijklmnopqrstuvwxyz") != std::string::npos) {
        // It goes into a shell command line: a name, nothing else.
        state.SkipWithError("STEREOSIM_BENCH_CAMPAIGN: a campaign name (smoke or full)");
        return;
    }
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("bench_campaign_" + std::to_string(getpid()));
    for (auto _ : state) {
        std::vector<double> with, without, ratio;
        campaign_run a, b;
        bool identical = true;
        for (int rep = 0; rep < reps; ++rep) {
            // Alternate the order so a change of the machine's load favours neither.
            if (rep % 2 == 0) {
                a = run_campaign(campaign, true, dir / "snapshots");
                b = run_campaign(campaign, false, dir / "no_snapshots");
            } else {
                b = run_campaign(campaign, false, dir / "no_snapshots");
                a = run_campaign(campaign, true, dir / "snapshots");
            }
            if (a.wall_s < 0.0 || b.wall_s < 0.0) {
                const std::string why = "a campaign wrote no campaign.json; see " +
                                        (dir / "snapshots.log").string() + " and " +
                                        (dir / "no_snapshots.log").string();
                state.SkipWithError(why.c_str());
                return;
            }
            std::printf("  repetition %d: %s campaign %.1f s with snapshots, %.1f s without\n",
                        rep + 1, campaign.c_str(), a.wall_s, b.wall_s);
            std::fflush(stdout);
            with.push_back(a.wall_s);
            without.push_back(b.wall_s);
            ratio.push_back(a.wall_s / b.wall_s);
            identical = identical && comparable_rows(a.document) == comparable_rows(b.document);
        }
        state.counters["snapshots_wall_s"] = median(with);
        state.counters["no_snapshots_wall_s"] = median(without);
        state.counters["snapshots_over_no_snapshots"] = median(ratio);
        state.counters["runs"] = a.document.at("runs").get<double>();
        state.counters["runs_forked"] = forked_runs(a.document);
        state.counters["contract_broken"] = a.document.at("contract_broken").get<double>() +
                                            b.document.at("contract_broken").get<double>();
        state.counters["rows_identical"] = identical ? 1 : 0;
    }
    std::filesystem::remove_all(dir);
}

}  // namespace bench
