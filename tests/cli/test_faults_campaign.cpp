// The stereosim binary as a user runs it (docs/faults.md, docs/fault-contract.md):
// a bad --fault is a one-line error, a good one lands in report.json, a
// slice of the smoke campaign keeps the contract with the real firmware, and
// runs forked from snapshots are the runs started from the beginning.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "tb/app/cli/host_figures.h"

namespace {

namespace fs = std::filesystem;
using cli::without_host_figures;
using nlohmann::json;

struct command_result {
    int exit_code = -1;
    std::string output;  // stdout + stderr
};

std::FILE* start(const std::string& args) {
    const std::string command = std::string(STEREOSIM_BINARY) + " " + args + " 2>&1";
    return popen(command.c_str(), "r");
}

command_result finish(std::FILE* pipe) {
    command_result r;
    if (!pipe) return r;
    char buf[4096];
    size_t n = 0;
    while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) r.output.append(buf, n);
    const int status = pclose(pipe);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

command_result run(const std::string& args) {
    return finish(start(args));
}

fs::path scratch(const std::string& name) {
    const fs::path dir =
        fs::temp_directory_path() / ("stereosim_test_faults_" + std::to_string(getpid())) / name;
    fs::remove_all(dir);
    return dir;
}

json read_json(const fs::path& path) {
    std::ifstream in(path);
    return json::parse(in);
}

TEST(FaultCli, MalformedSpecIsOneLineAndWritesNothing) {
    const fs::path out = scratch("bad");
    const command_result r =
        run("run --frames 4 --fault skew:sensor=R,lines=3@frm=5 --out " + out.string());
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.output,
              "stereosim: error: bad fault spec 'skew:sensor=R,lines=3@frm=5': bad trigger "
              "'@frm=5' (expected @frame=N with N >= 0 or @ms=T with T >= 0)\n");
    EXPECT_FALSE(fs::exists(out / "report.json"));
    const command_result list = run("faults --list");
    EXPECT_EQ(list.exit_code, 0);
    EXPECT_NE(list.output.find("emif-wait  (emif::ardy_fault)"), std::string::npos);
}

TEST(FaultCli, AFaultIsReportedWithItsOnsetAndOutcome) {
    const fs::path out = scratch("skew");
    const command_result r =
        run("run --quiet --frames 7 --fault skew:sensor=R,lines=3@frame=4 --out " + out.string());
    ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.output;
    const json report = read_json(out / "report.json");
    ASSERT_EQ(report["faults"].size(), 1u);
    const json& f = report["faults"][0];
    EXPECT_EQ(f["spec"], "skew:sensor=R,lines=3@frame=4");
    EXPECT_EQ(f["kind"], "skew");
    EXPECT_EQ(f["onset_frame"], 4);
    EXPECT_TRUE(f["in_effect"].get<bool>());
    // Right frame 4 starts between 3 and 4 periods in (seed 3: one restart).
    EXPECT_GT(f["onset_ms"].get<double>(), 49.0);
    EXPECT_LT(f["onset_ms"].get<double>(), 98.0);
    // Flagged by the verdict of the frame it hit, blaming the right stream:
    // R_WINDOW (bit 1) and / or R_VSYNC (bit 5), never a left cause.
    EXPECT_TRUE(f["detected"].get<bool>());
    EXPECT_EQ(f["detected_by"], "sync_error");
    EXPECT_LE(f["frames_to_detect"].get<int>(), 1);
    const int causes = f["verdict_causes"].get<int>();
    EXPECT_NE(causes & 0x22, 0);
    EXPECT_EQ(causes & 0x15, 0);
    EXPECT_EQ(f["unsynced_pairs_used"], 0);
    EXPECT_EQ(report["fault_run"]["unsynced_pairs_used"], 0);
    EXPECT_TRUE(f["contract_ok"].get<bool>()) << f.dump();
    std::printf(
        "skew R 3 lines @frame 4: onset %.3f ms, detected %.3f ms (%d frames), causes "
        "0x%02x, outcome %s\n",
        f["onset_ms"].get<double>(), f["detect_ms"].get<double>(), f["frames_to_detect"].get<int>(),
        causes, f["outcome"].get<std::string>().c_str());
}

// The output without what an AddressSanitizer build's runtime adds to
// stderr (its three-line note when SystemC switches thread stacks), so that
// a sanitizer pass judges the program's own lines.
std::string without_sanitizer_notes(const std::string& output) {
    std::istringstream in(output);
    std::string kept;
    for (std::string line; std::getline(in, line);) {
        if ((line.rfind("==", 0) == 0 && line.find("WARNING: ASan") != std::string::npos) ||
            line == "False positive error reports may follow" ||
            line.rfind("For details see https://github.com/google/sanitizers", 0) == 0)
            continue;
        kept += line + "\n";
    }
    return kept;
}

// A run that breaks the fault contract says so in its exit status and in one
// line on stderr, --quiet or not: here a skew whose recovery was not yet due
// when the run of 5 frames ended (rule 9, pending).
TEST(FaultCli, ABrokenContractIsInTheExitStatus) {
    const fs::path out = scratch("short");
    const command_result r =
        run("run --quiet --frames 5 --fault skew:sensor=R,lines=3@frame=4 --out " + out.string());
    const std::string said = without_sanitizer_notes(r.output);
    EXPECT_EQ(r.exit_code, 4) << r.output;
    EXPECT_EQ(said.rfind("stereosim: fault contract broken (", 0), 0u) << r.output;
    EXPECT_NE(said.find("rule 9: pending"), std::string::npos) << r.output;
    EXPECT_EQ(std::count(said.begin(), said.end(), '\n'), 1) << r.output;
    EXPECT_FALSE(read_json(out / "report.json")["fault_run"]["contract_ok"].get<bool>());
}

// The case: a frame the right sensor sends twice. The card's
// frame-identity check flags it (R_FRAME_ID, bit 9; never a left cause) and
// no unsynced pair is used; judged as the paper's card (check off) the
// repeat's pair is used one period stale: the named hole, exit 4.
TEST(FaultCli, ARepeatedFrameIsCaughtUnlessThePaperCardIsJudged) {
    const std::string fault = " --quiet --frames 10 --fault extra-frame:sensor=R@frame=2 --out ";
    const fs::path out = scratch("extra-frame");
    const command_result r = run("run" + fault + out.string());
    ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.output;
    const json f = read_json(out / "report.json")["faults"][0];
    EXPECT_EQ(f["outcome"], "resync");
    EXPECT_EQ(f["detected_by"], "sync_error");
    EXPECT_LE(f["frames_to_detect"].get<int>(), 1);
    EXPECT_EQ(f["verdict_causes"].get<int>() & 0x3FF, 0x200) << f.dump();
    EXPECT_EQ(f["unsynced_pairs_used"], 0);
    EXPECT_TRUE(f["contract_ok"].get<bool>()) << f.dump();

    const fs::path paper_out = scratch("extra-frame-paper");
    const command_result paper = run("run --paper-card" + fault + paper_out.string());
    EXPECT_EQ(paper.exit_code, 4) << paper.output;
    EXPECT_NE(without_sanitizer_notes(paper.output).find("rule 1: the paper's hole"),
              std::string::npos)
        << paper.output;
    const json report = read_json(paper_out / "report.json");
    const json p = report["faults"][0];
    EXPECT_EQ(p["outcome"], "stale_pair");
    EXPECT_FALSE(p["detected"].get<bool>());
    EXPECT_EQ(p["unsynced_pairs_used"], 1);
    EXPECT_FALSE(p["frame_id_check"].get<bool>()) << "the firmware turned the check off";
    EXPECT_TRUE(report["fault_run"]["contract_params"]["paper_card"].get<bool>());
}

// A sensor that dies by time acts at the next OE rise, which it ignores: that
// start can never be in step, so the give-up is what the truth requires, and
// a bus fault's hard error in the same run is explained by it. Here the rise
// is the overflow re-arm's (sequential capture, seed 11: 91.2 ms).
TEST(FaultCli, ASensorDeadAtARestartsRiseMustBringTheGiveUp) {
    const fs::path out = scratch("dead-at-rearm");
    const command_result r =
        run("run --quiet --set firmware.mode=sequential --seed 11 --frames 14 --card-retry-limit 2 "
            "--fault emif-wait:cycles=40@frame=3 --fault dead:sensor=L@ms=80 --out " +
            out.string());
    EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.output;
    const json report = read_json(out / "report.json");
    ASSERT_EQ(report["faults"].size(), 2u);
    const json& dead = report["faults"][1];
    EXPECT_GT(dead["onset_ms"].get<double>(), 80.0);
    EXPECT_TRUE(dead["onset_start_out_of_step"].get<bool>()) << dead.dump();
    EXPECT_EQ(dead["expected"], "hard_error");
    EXPECT_EQ(dead["outcome"], "hard_error");
    EXPECT_TRUE(report["fault_run"]["contract_ok"].get<bool>()) << report["fault_run"].dump();
}
// A slice of the smoke campaign keeps the contract with the firmware as it
// is. That the campaign fails a broken firmware is shown by the mutants
// (tests/mutants, docs/mutants.md, `make mutants-ci`).
TEST(FaultCampaign, SmokeSliceKeepsTheContract) {
    const fs::path good = scratch("good");
    const command_result ok =
        run("faults --campaign smoke --match dark-leak:sensor=R,level=48 --jobs 1 --out " +
            good.string());
    std::printf("%s\n", ok.output.c_str());
    EXPECT_EQ(ok.exit_code, 0);
    const json g = read_json(good / "campaign.json");
    ASSERT_EQ(g["rows"].size(), 1u);
    EXPECT_EQ(g["contract_broken"], 0);
    EXPECT_EQ(g["rows"][0]["actual"], "hard_error");
    EXPECT_EQ(g["rows"][0]["unsynced_pairs_used"], 0);
    EXPECT_TRUE(fs::exists(good / "campaign.csv") && fs::exists(good / "campaign.txt"));
    fs::remove_all(good.parent_path());
}

// A campaign slice run twice, forked from snapshots and every run from the
// start (--no-snapshots), with each run's report.json kept; both must keep
// the contract (no rows read otherwise).
struct forked_and_spawned {
    command_result forked_run, spawned_run;
    fs::path forked, spawned;
    json forked_campaign, spawned_campaign;
};

forked_and_spawned run_both_ways(const std::string& slice, const std::string& name) {
    forked_and_spawned r;
    r.forked = scratch(name + "-forked");
    r.spawned = scratch(name + "-spawned");
    r.forked_run = run(slice + " --keep-runs --out " + r.forked.string());
    r.spawned_run = run(slice + " --keep-runs --no-snapshots --out " + r.spawned.string());
    EXPECT_EQ(r.forked_run.exit_code, 0) << r.forked_run.output;
    EXPECT_EQ(r.spawned_run.exit_code, 0) << r.spawned_run.output;
    if (r.forked_run.exit_code == 0 && r.spawned_run.exit_code == 0) {
        r.forked_campaign = read_json(r.forked / "campaign.json");
        r.spawned_campaign = read_json(r.spawned / "campaign.json");
    }
    return r;
}

// The campaigns and every run's report.json alike but for host figures.
void expect_same_runs(const forked_and_spawned& r) {
    EXPECT_EQ(without_host_figures(r.forked_campaign), without_host_figures(r.spawned_campaign));
    for (const json& row : r.forked_campaign["rows"]) {
        const std::string run_dir = "runs/" + std::to_string(row["index"].get<int>());
        EXPECT_EQ(without_host_figures(read_json(r.forked / run_dir / "out/report.json")),
                  without_host_figures(read_json(r.spawned / run_dir / "out/report.json")))
            << run_dir;
    }
    for (const json& row : r.spawned_campaign["rows"]) EXPECT_TRUE(row["snapshot_ms"].is_null());
}

// Runs of one seed and length whose faults start later are forked from one
// fault-free run at their snapshots (docs/fault-contract.md "Snapshots"):
// the campaign and every run's report.json (pin hash, timeline, stage
// cycles, verdicts) are the same as when each run starts from the beginning.
TEST(FaultCampaign, SnapshotsGiveTheSameRunsAsRunsFromTheStart) {
    const forked_and_spawned r = run_both_ways(
        "faults --campaign smoke --match "
        "'skew:sensor=L,pixels=1@frame=2|drop-frame:sensor=R@frame=4|"
        "emif-wait:cycles=40@frame=3' --jobs 2",
        "snapshots");
    EXPECT_EQ(r.forked_campaign["snapshots"], true);
    EXPECT_EQ(r.spawned_campaign["snapshots"], false);
    // The emif-wait match also keeps the row where a sensor dies at the
    // overflow re-arm: sequential capture and RETRY_LIMIT 2, alone in its
    // group, so it runs from the start either way.
    ASSERT_EQ(r.forked_campaign["rows"].size(), 4u);
    expect_same_runs(r);
    // The others were forked (none ran from the start after a missed
    // snapshot), before their fault: skew at sensor frame 2, emif-wait at
    // 73.5 ms, drop-frame at sensor frame 4.
    for (const json& row : r.forked_campaign["rows"]) {
        if (row["fault"].get<std::string>().find("dead") != std::string::npos) continue;
        ASSERT_TRUE(row["snapshot_ms"].is_number()) << row.dump();
        EXPECT_GT(row["snapshot_ms"].get<double>(), 0.0);
        EXPECT_LT(row["snapshot_ms"].get<double>(), 98.0);
    }
    EXPECT_NE(r.forked_run.output.find("3 runs forked from snapshots"), std::string::npos)
        << r.forked_run.output;
    fs::remove_all(r.forked.parent_path());
}

// A CPU slow-down's charge in flight at a pause has its cycles fixed without
// it: forked there, seed 13's cpu-slow x 6 from 49 ms ran pair 1's 16.8 ms
// preprocess in 4.3 ms. Such a member runs from the start; every run of the
// slice equals its run from the start.
TEST(FaultCampaign, NoForkInsideACpuChargeThatASlowDownWouldStretch) {
    const forked_and_spawned r = run_both_ways(
        "faults --campaign full --seeds 3 --match "
        "'cpu-slow:factor=6@frame=2 emif-wait:cycles=40@frame=8|"
        "cpu-slow:factor=20@frame=4 drop-frame' --jobs 2",
        "cpu-charge");
    ASSERT_EQ(r.forked_campaign["rows"].size(), 6u);
    expect_same_runs(r);
    int from_start = 0;
    for (const json& row : r.forked_campaign["rows"]) from_start += row["snapshot_ms"].is_null();
    EXPECT_EQ(from_start, 1);  // seed 13's: pair 1's charge spans the onset at 49 ms
    fs::remove_all(r.forked.parent_path());
}

}  // namespace
