// `stereosim run --firmware PATH` (docs/firmware-abi.md) as a user runs it:
// the shipped firmware loaded as a plugin gives the run the built-in firmware
// gives (report.json but the firmware's identity, frames.csv, the pin and
// timeline hashes), the report names the plugin and its SHA-256, and a
// plugin that cannot run is one line and no output.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>

#include "tb/app/cli/host_figures.h"
#include "tests/support/shell.h"

namespace {

using nlohmann::json;

std::string stereosim(const std::string& args) {
    return std::string(STEREOSIM_BINARY) + " " + args;
}

json report_of(const std::string& dir) {
    return json::parse(testsupport::read_text(dir + "/report.json"));
}

TEST(FirmwarePluginRun, TheReferenceAsAPluginRunsAsTheBuiltIn) {
    const std::string dir = testsupport::temp_dir("fw_plugin");
    const std::string args = "run --quiet --frames 10 --set firmware.mode=sequential --out ";
    const auto built_in = testsupport::run_command(stereosim(args + dir + "/built_in"));
    const auto plugin = testsupport::run_command(
        stereosim(args + dir + "/plugin --firmware " + std::string(REFERENCE_FIRMWARE)));
    // Sequential capture is over budget (exit 1, a result): both alike.
    ASSERT_TRUE(built_in.exit_code == 0 || built_in.exit_code == 1) << built_in.output;
    ASSERT_EQ(plugin.exit_code, built_in.exit_code) << plugin.output;

    json a = cli::without_host_figures(report_of(dir + "/built_in"));
    json b = cli::without_host_figures(report_of(dir + "/plugin"));
    const json& fw = b["tool"]["firmware"];
    EXPECT_EQ(fw["name"], "stereosim-reference");
    EXPECT_EQ(fw["abi_version"], 1);
    EXPECT_EQ(fw["file"], REFERENCE_FIRMWARE);
    const auto digest = testsupport::run_command("sha256sum " + std::string(REFERENCE_FIRMWARE));
    EXPECT_EQ(fw["sha256"], digest.output.substr(0, 64));
    EXPECT_TRUE(a["tool"]["firmware"]["file"].is_null());
    EXPECT_EQ(a["tool"]["firmware"]["name"], "stereosim-reference");
    // Everything else is the same run.
    EXPECT_EQ(b["config"]["run"]["firmware"], REFERENCE_FIRMWARE);
    for (json* r : {&a, &b}) {
        (*r)["tool"].erase("firmware");
        (*r)["config"]["run"].erase("firmware");
    }
    EXPECT_EQ(a["summary"]["hashes"], b["summary"]["hashes"]);
    EXPECT_EQ(a, b);
    EXPECT_EQ(testsupport::read_text(dir + "/built_in/frames.csv"),
              testsupport::read_text(dir + "/plugin/frames.csv"));
}

TEST(FirmwarePluginRun, APluginThatCannotRunIsOneLineAndNoOutput) {
    const std::string dir = testsupport::temp_dir("fw_plugin_bad") + "/out";
    const std::string bad = MINIMAL_FIRMWARE_BAD_ABI;
    const auto r = testsupport::run_command(
        stereosim("run --quiet --frames 4 --firmware " + bad + " --out " + dir));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.output, "stereosim: error: firmware '" + bad +
                            "': built for ABI version 99, this stereosim speaks 1\n");
    EXPECT_FALSE(testsupport::file_exists(dir));
}

}  // namespace

namespace {

json campaign_of(const std::string& dir) {
    return json::parse(testsupport::read_text(dir + "/campaign.json"));
}

// Two rows of one seed that fork from a snapshot, and the sequential row
// that runs alone: a campaign of the plugin judges the same runs as the
// built-in's, and names its firmware; shards of two firmwares do not merge.
TEST(FirmwarePluginRun, ACampaignOfThePluginJudgesTheSameRuns) {
    const std::string dir = testsupport::temp_dir("fw_campaign");
    const std::string match =
        " --match 'skew:sensor=L,pixels=1@frame=2|drop-frame:sensor=R@frame=4|"
        "dead:sensor=L@ms=80' --jobs 2 --out ";
    const std::string plugin = std::string(" --firmware ") + REFERENCE_FIRMWARE;
    const auto a =
        testsupport::run_command(stereosim("faults --campaign smoke" + match + dir + "/built_in"));
    const auto b = testsupport::run_command(
        stereosim("faults --campaign smoke --keep-runs" + match + dir + "/plugin" + plugin));
    ASSERT_EQ(a.exit_code, 0) << a.output;
    ASSERT_EQ(b.exit_code, 0) << b.output;
    json built_in = cli::without_host_figures(campaign_of(dir + "/built_in"));
    // Whether a run was forked is a host figure: read from the whole file.
    const json loaded_whole = campaign_of(dir + "/plugin");
    json loaded = cli::without_host_figures(loaded_whole);
    EXPECT_TRUE(built_in["firmware"]["file"].is_null());
    EXPECT_EQ(loaded["firmware"]["file"], REFERENCE_FIRMWARE);
    ASSERT_EQ(loaded["rows"].size(), 3u);
    EXPECT_EQ(built_in["rows"], loaded["rows"]);
    int forked = 0;
    for (const json& row : loaded_whole.at("rows")) {
        forked += row.contains("snapshot_ms") && row.at("snapshot_ms").is_number();
        // Every run, forked or spawned, ran the plugin.
        const std::string run = dir + "/plugin/runs/" + std::to_string(row["index"].get<int>());
        EXPECT_EQ(report_of(run + "/out")["tool"]["firmware"]["file"], REFERENCE_FIRMWARE) << run;
    }
    EXPECT_EQ(forked, 2);

    // Shard 1 of the built-in firmware, shard 2 of the plugin: refused.
    const std::string shards =
        " --match 'skew:sensor=L,pixels=1@frame=2|drop-frame:sensor=R@frame=4'";
    testsupport::run_command(
        stereosim("faults --campaign smoke" + shards + " --shard 1/2 --out " + dir + "/s1"));
    testsupport::run_command(stereosim("faults --campaign smoke" + shards + " --shard 2/2 --out " +
                                       dir + "/s2" + plugin));
    const auto merged = testsupport::run_command(
        stereosim("merge " + dir + "/s1 " + dir + "/s2 --out " + dir + "/m"));
    EXPECT_EQ(merged.exit_code, 2) << merged.output;
    EXPECT_NE(merged.output.find("firmware"), std::string::npos) << merged.output;
    EXPECT_FALSE(testsupport::file_exists(dir + "/m/campaign.json"));

    // The Slurm job array's command runs it too.
    const auto emitted = testsupport::run_command(
        stereosim("faults --campaign smoke --emit-slurm --out " + dir + "/slurm" + plugin));
    ASSERT_EQ(emitted.exit_code, 0) << emitted.output;
    EXPECT_NE(testsupport::read_text(dir + "/slurm/job.sbatch")
                  .find("'--firmware' '" + std::string(REFERENCE_FIRMWARE) + "'"),
              std::string::npos);
}

}  // namespace

namespace {

TEST(FirmwareInfo, PrintsWhatAPluginDeclares) {
    const auto r =
        testsupport::run_command(stereosim(std::string("firmware info ") + MINIMAL_FIRMWARE));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::string file = MINIMAL_FIRMWARE;
    const auto digest = testsupport::run_command("sha256sum " + file);
    EXPECT_EQ(r.output.substr(0, r.output.find("  firmware.")),
              "firmware  minimal 0.1 (ABI version 1)\n"
              "file      " +
                  file +
                  "\n"
                  "sha256    " +
                  digest.output.substr(0, 64) +
                  "\n"
                  "stages    capture think\n"
                  "states    idle busy\n"
                  "host      no (no closed-form processing estimate)\n"
                  "keys      2\n");
    EXPECT_NE(r.output.find("firmware.cycles_per_wait"), std::string::npos);
    EXPECT_NE(r.output.find("0..1000000"), std::string::npos);
    EXPECT_NE(r.output.find("quiet|chatty"), std::string::npos);
    // Without a path: the built-in firmware.
    const auto built_in = testsupport::run_command(stereosim("firmware info"));
    EXPECT_EQ(built_in.output.rfind("firmware  stereosim-reference 1.0 (ABI version 1)\n"
                                    "file      built in\n",
                                    0),
              0u)
        << built_in.output;
    EXPECT_NE(built_in.output.find("\nhost      yes (the sweep's closed form prices its pairs)\n"),
              std::string::npos)
        << built_in.output;
    const auto reference =
        testsupport::run_command(stereosim(std::string("firmware info ") + REFERENCE_FIRMWARE));
    EXPECT_NE(reference.output.find("\nhost      yes"), std::string::npos) << reference.output;
    const auto bad = testsupport::run_command(
        stereosim("firmware info " + std::string(MINIMAL_FIRMWARE_BAD_ABI)));
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_EQ(bad.output, "stereosim: error: firmware '" + std::string(MINIMAL_FIRMWARE_BAD_ABI) +
                              "': built for ABI version 99, this stereosim speaks 1\n");
}

}  // namespace

namespace {

// The C test firmware does none of the sync protocol: every run breaks the
// contract. With --stop-on-violation the campaign ends at the first.
TEST(FirmwarePluginRun, AStopOnViolationCampaignEndsAtTheFirstBrokenRun) {
    const std::string dir = testsupport::temp_dir("fw_stop");
    // One run at a time, each from the start: the stop comes after one run.
    const std::string args =
        "faults --campaign smoke --match 'skew:sensor=L,pixels=1@frame=2|"
        "drop-frame:sensor=R@frame=4|dead:sensor=L@ms=80' --jobs 1 --no-snapshots --firmware " +
        std::string(MINIMAL_FIRMWARE) + " --out ";
    const auto all = testsupport::run_command(stereosim(args + dir + "/all"));
    EXPECT_EQ(all.exit_code, 1) << all.output;
    const json whole = campaign_of(dir + "/all");
    EXPECT_EQ(whole["complete"], true);
    EXPECT_EQ(whole["rows"].size(), 3u);
    for (const json& row : whole["rows"]) EXPECT_FALSE(row["contract_ok"].get<bool>());

    const auto stopped =
        testsupport::run_command(stereosim(args + dir + "/stopped --stop-on-violation"));
    EXPECT_EQ(stopped.exit_code, 1) << stopped.output;
    const json first = campaign_of(dir + "/stopped");
    EXPECT_EQ(first["complete"], false);
    ASSERT_TRUE(first.contains("stopped_at"));
    EXPECT_EQ(first["rows"].size(), 1u);
    EXPECT_EQ(first["rows"][0]["index"], first["stopped_at"]);
    EXPECT_NE(stopped.output.find("stopped at the first broken contract"), std::string::npos)
        << stopped.output;
}

}  // namespace

namespace {

// A firmware with a null-pointer bug in its stage think: one line naming the
// signal, the simulated time and the stage; exit 3; no report.
TEST(FirmwarePluginRun, ACrashingFirmwareIsOneLineWithItsTimeAndStage) {
    const std::string dir = testsupport::temp_dir("fw_crash") + "/out";
    const auto r = testsupport::run_command(stereosim("run --quiet --frames 8 --firmware " +
                                                      std::string(MINIMAL_FIRMWARE_CRASH_IN_RUN) +
                                                      " --out " + dir));
    EXPECT_EQ(r.exit_code, 3) << r.output;
    const std::string said = r.output;
    // 6,000,000 cycles at 600 MHz: 10 ms into the run.
    EXPECT_EQ(said, "stereosim: error: firmware crashed (signal 11) at 10.000 ms in stage think\n");
    // Nothing half written: the output folder the run created is gone.
    EXPECT_FALSE(testsupport::file_exists(dir));
}

// A firmware that polls for a flag without giving time back: simulated time
// stands still, so the run would never end. The guard stops it after 10 s
// of wall time with one line; exit 3; nothing written.
TEST(FirmwarePluginRun, AFirmwareThatNeverGivesTimeBackIsStoppedWithOneLine) {
    const std::string dir = testsupport::temp_dir("fw_hang") + "/out";
    const auto r = testsupport::run_command(stereosim("run --quiet --frames 8 --firmware " +
                                                      std::string(MINIMAL_FIRMWARE_HANG_IN_RUN) +
                                                      " --out " + dir));
    EXPECT_EQ(r.exit_code, 3) << r.output;
    EXPECT_EQ(r.output,
              "stereosim: error: firmware gave no time back for 10 s of wall time at 10.000 ms in "
              "stage think (a loop that neither charges cycles nor waits)\n");
    EXPECT_FALSE(testsupport::file_exists(dir));
}

// The ABI allows 15 stages: a firmware charging its last runs (the platform
// keeps every declared stage's cycles; under the sanitizer build, no access
// outside them), and one charging a stage it never declared is stopped with
// one line, exit 3 and nothing written, as for a crash.
TEST(FirmwarePluginRun, AllFifteenStagesRunAndAnUndeclaredStageIsOneLine) {
    const std::string dir = testsupport::temp_dir("fw_stages");
    const auto many = testsupport::run_command(
        stereosim("run --quiet --frames 4 --timeline-csv --firmware " +
                  std::string(MINIMAL_FIRMWARE_MANY_STAGES) + " --out " + dir + "/many"));
    EXPECT_TRUE(many.exit_code == 0 || many.exit_code == 1) << many.output;
    // 600 cycles charged to stage 14 at boot, on the timeline by its name.
    const std::string timeline = testsupport::read_text(dir + "/many/timeline.csv");
    EXPECT_NE(timeline.find(",stage_begin,s14,14,0,0\n"), std::string::npos) << timeline;
    EXPECT_NE(timeline.find(",stage_end,s14,14,600,0\n"), std::string::npos) << timeline;

    const auto bad = testsupport::run_command(
        stereosim("run --quiet --frames 4 --firmware " +
                  std::string(MINIMAL_FIRMWARE_UNDECLARED_STAGE) + " --out " + dir + "/bad"));
    EXPECT_EQ(bad.exit_code, 3) << bad.output;
    EXPECT_EQ(bad.output.rfind("stereosim: error: firmware broke the ABI: stage 5 used, of the 2 "
                               "it declares at ",
                               0),
              0u)
        << bad.output;
    EXPECT_EQ(std::count(bad.output.begin(), bad.output.end(), '\n'), 1) << bad.output;
    EXPECT_FALSE(testsupport::file_exists(dir + "/bad"));
}

// In a campaign a crashing firmware is a row with outcome `crash` (it breaks
// the contract), and the campaign goes on to its other rows: the ones a
// snapshot group's leader would have forked (its fault-free prefix crashed)
// and the one run from the start alike.
TEST(FirmwarePluginRun, ACrashingFirmwareInACampaignIsACrashRowAndTheCampaignGoesOn) {
    const std::string dir = testsupport::temp_dir("fw_crash_campaign") + "/c";
    const auto r = testsupport::run_command(stereosim(
        "faults --campaign smoke --match 'skew:sensor=L,pixels=1@frame=2|drop-frame:sensor=R@"
        "frame=4|dead:sensor=L@ms=80' --jobs 2 --out " +
        dir + " --firmware " + std::string(MINIMAL_FIRMWARE_CRASH_IN_RUN)));
    EXPECT_EQ(r.exit_code, 1) << r.output;  // the contract broken, the campaign complete
    const json campaign = json::parse(testsupport::read_text(dir + "/campaign.json"));
    ASSERT_EQ(campaign["rows"].size(), 3u);
    EXPECT_EQ(campaign["crashed"], 3);
    EXPECT_EQ(campaign["contract_broken"], 3);
    EXPECT_TRUE(campaign["complete"].get<bool>());
    for (const json& row : campaign["rows"]) {
        EXPECT_EQ(row["actual"], "crash") << row.dump();
        EXPECT_FALSE(row["contract_ok"].get<bool>());
        EXPECT_EQ(row["error"],
                  "exit 3, no report.json: stereosim: error: firmware crashed (signal 11) at "
                  "10.000 ms in stage think");
    }
    EXPECT_NE(testsupport::read_text(dir + "/campaign.txt").find("CRASH: exit 3"),
              std::string::npos);
}

}  // namespace

namespace {

// The firmware's own keys (docs/firmware-abi.md "Config keys"): `--set
// firmware.KEY=V` reaches create() (the reference firmware's capture_cycles,
// a key of its own beyond the platform's table: 600,000 cycles at 600 MHz
// are exactly 1 ms per pair in stage capture), the report keeps it and
// replays it, and a bad value or key is one line, exit 2, nothing written.
TEST(FirmwareKeys, AFirmwaresOwnKeyReachesItAndIsKeptInTheReport) {
    const std::string dir = testsupport::temp_dir("fw_keys");
    const std::string args = "run --quiet --frames 6 --out ";
    testsupport::run_command(stereosim(args + dir + "/default"));
    testsupport::run_command(stereosim(args + dir + "/set --set firmware.capture_cycles=600000"));
    const json plain = report_of(dir + "/default");
    const json set = report_of(dir + "/set");
    const auto capture_ms = [](const json& r) {
        return r["summary"]["timing"]["stage_ms"]["capture"]["max"].get<double>();
    };
    EXPECT_LT(capture_ms(plain), 0.01);
    EXPECT_DOUBLE_EQ(capture_ms(set), 1.0);
    EXPECT_EQ(set["config"]["firmware"]["capture_cycles"], 600000);
    // Every value it ran with is recorded, the defaults too.
    EXPECT_EQ(plain["config"]["firmware"]["capture_cycles"], 600);
    EXPECT_EQ(plain["config"]["firmware"]["mode"], "overlapped");
    // The report replays the run it describes, the firmware's key included.
    testsupport::run_command(
        stereosim("run --quiet --config " + dir + "/set/report.json --out " + dir + "/replayed"));
    EXPECT_DOUBLE_EQ(capture_ms(report_of(dir + "/replayed")), 1.0);
}

TEST(FirmwareKeys, ABadKeyOrValueIsOneLineAndNothingWritten) {
    const std::string dir = testsupport::temp_dir("fw_keys_bad") + "/out";
    const std::string minimal = std::string(" --firmware ") + MINIMAL_FIRMWARE;
    const struct {
        std::string args, said;
    } cases[] = {
        {" --set firmware.capture_cycles=2000000",
         "config key 'firmware.capture_cycles': 2000000 is out of range 0..1000000"},
        {" --set firmware.capture_cycles=many",
         "config key 'firmware.capture_cycles': expected an integer, got 'many'"},
        {minimal + " --set firmware.cycles_per_wait=1000001",
         "config key 'firmware.cycles_per_wait': 1000001 is out of range 0..1000000"},
        // The reference's key is not the plugin's.
        {minimal + " --set firmware.capture_cycles=10",
         "unknown config key 'firmware.capture_cycles' (the firmware 'minimal' declares of its "
         "own: firmware.cycles_per_wait, firmware.mode)"},
        // The fault extension's option is the firmware's key, checked alike.
        {" --hard-error-rearms 20",
         "--hard-error-rearms: config key 'firmware.hard_error_rearms': 20 is out of range "
         "0..16"},
        // Nor is a key of the same name: the plugin's own choices hold.
        {minimal + " --mode sequential",
         "config key 'firmware.mode': \"sequential\" is not one of quiet|chatty"},
        {" --set firmware.watchdg_ms=3",
         "unknown config key 'firmware.watchdg_ms' (did you mean 'firmware.watchdog_ms'?)"},
    };
    for (const auto& c : cases) {
        const auto r =
            testsupport::run_command(stereosim("run --quiet --frames 4 --out " + dir + c.args));
        EXPECT_EQ(r.exit_code, 2) << c.args;
        EXPECT_EQ(r.output, "stereosim: error: " + c.said + "\n") << c.args;
        EXPECT_FALSE(testsupport::file_exists(dir)) << c.args;
    }
}

// A plugin's key named like a reference key is the plugin's: its own
// choices and default (the minimal firmware's `mode`: quiet | chatty). The
// values create() gets are platform::plugin_values'
// (ReferencePlugin.AnotherFirmwaresKeysTakeItsOwnDefaults); the report
// records them.
TEST(FirmwareKeys, APluginsKeyNamedLikeTheReferencesIsItsOwn) {
    const std::string dir = testsupport::temp_dir("fw_keys_same_name");
    const std::string args =
        std::string("run --quiet --frames 3 --firmware ") + MINIMAL_FIRMWARE + " --out " + dir;
    const auto quiet = testsupport::run_command(stereosim(args + "/quiet"));
    const auto chatty =
        testsupport::run_command(stereosim(args + "/chatty --set firmware.mode=chatty"));
    // Both run (the minimal firmware processes nothing: the budget is not judged, exit 1).
    ASSERT_EQ(quiet.exit_code, 1) << quiet.output;
    ASSERT_EQ(chatty.exit_code, 1) << chatty.output;
    EXPECT_EQ(report_of(dir + "/quiet")["config"]["firmware"]["mode"], "quiet");
    EXPECT_EQ(report_of(dir + "/chatty")["config"]["firmware"]["mode"], "chatty");
}

TEST(FirmwareKeys, ConfigListShowsTheFirmwaresOwnKeys) {
    const auto built_in = testsupport::run_command(stereosim("config --list"));
    EXPECT_NE(built_in.output.find("# the firmware 'stereosim-reference'"), std::string::npos);
    EXPECT_NE(built_in.output.find("firmware.capture_cycles"), std::string::npos);
    const auto minimal = testsupport::run_command(
        stereosim(std::string("config --list --firmware ") + MINIMAL_FIRMWARE));
    EXPECT_EQ(minimal.exit_code, 0);
    EXPECT_NE(minimal.output.find("# the firmware 'minimal' 0.1 declares:\nfirmware.cycles_per_wait"
                                  "       integer 0..1000000                 default 600 "),
              std::string::npos)
        << minimal.output;
    EXPECT_EQ(minimal.output.find("firmware.capture_cycles"), std::string::npos);
    const auto bad = testsupport::run_command(
        stereosim(std::string("config --list --firmware ") + MINIMAL_FIRMWARE_BAD_ABI));
    EXPECT_EQ(bad.exit_code, 2);
}

}  // namespace

namespace {

// `stereosim firmware check`: the shipped firmware is deterministic (the
// default scenario twice, two fault runs forked from a snapshot against
// their runs from the start); a firmware whose first charge depends on the
// process id is caught, with the first difference named (the first pair
// period's CPU time, which that charge lengthens).
TEST(FirmwareCheck, TheReferenceIsDeterministic) {
    const auto r =
        testsupport::run_command(stereosim(std::string("firmware check ") + REFERENCE_FIRMWARE));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("the default scenario twice (12 frames): the same report.json and "
                            "frames.csv"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("2 of them forked from a snapshot"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("deterministic: yes"), std::string::npos) << r.output;
}

TEST(FirmwareCheck, AFirmwareThatReadsTheHostIsCaught) {
    const auto r = testsupport::run_command(
        stereosim(std::string("firmware check ") + MINIMAL_FIRMWARE_NONDETERMINISTIC));
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("stereosim: error: firmware 'minimal' is not deterministic: the "
                            "default scenario run twice differs first at report.json "
                            "frames[0].budget.cpu_busy_ms ("),
              std::string::npos)
        << r.output;
    // Alike in two runs one process starts, not in a run forked from a
    // snapshot (its parent the group's leader) and its run from the start.
    const auto forked = testsupport::run_command(
        stereosim(std::string("firmware check ") + MINIMAL_FIRMWARE_PARENT_DEPENDENT));
    EXPECT_EQ(forked.exit_code, 1) << forked.output;
    EXPECT_NE(forked.output.find("the same report.json and frames.csv"), std::string::npos)
        << forked.output;
    EXPECT_NE(forked.output.find("is not deterministic: a fault run forked from a snapshot differs "
                                 "from its run from the start first at report.json "),
              std::string::npos)
        << forked.output;
    const auto bad = testsupport::run_command(
        stereosim(std::string("firmware check ") + MINIMAL_FIRMWARE_BAD_ABI));
    EXPECT_EQ(bad.exit_code, 2) << bad.output;
}

}  // namespace

namespace {

// `sweep --firmware PATH`: every point runs the plugin (the shipped
// firmware loaded as one gives the built-in sweep's co-simulated figures),
// sweep.json names it, and the closed form prices its pairs through its host
// entry (the same figures as the built-in's), or says per point that a
// plugin without one has no processing estimate.
TEST(FirmwareSweep, EveryPointRunsThePlugin) {
    const std::string dir = testsupport::temp_dir("fw_sweep");
    const std::string grid = "sweep --grid dsk.cpu_mhz=300,600 --frames 3 --jobs 2 --out ";
    const auto a = testsupport::run_command(stereosim(grid + dir + "/built_in"));
    const auto b = testsupport::run_command(
        stereosim(grid + dir + "/plugin --firmware " + std::string(REFERENCE_FIRMWARE)));
    ASSERT_EQ(a.exit_code, 0) << a.output;
    ASSERT_EQ(b.exit_code, 0) << b.output;
    const json built_in = json::parse(testsupport::read_text(dir + "/built_in/sweep.json"));
    const json plugin = json::parse(testsupport::read_text(dir + "/plugin/sweep.json"));
    EXPECT_TRUE(built_in["firmware"]["file"].is_null());
    EXPECT_EQ(plugin["firmware"]["file"], REFERENCE_FIRMWARE);
    EXPECT_EQ(plugin["firmware"]["name"], "stereosim-reference");
    ASSERT_EQ(plugin["points"].size(), 2u);
    for (size_t i = 0; i < 2; ++i) {
        const json& p = plugin["points"][i];
        const json& q = built_in["points"][i];
        for (const char* field : {"verdict", "cpu_busy_ms_max", "emif_busy_ms_max", "capture_ms",
                                  "processing_ms_max", "stage_ms_max", "fifo_peak_words"})
            EXPECT_EQ(p[field], q[field]) << field;
        EXPECT_TRUE(q["closed_form"]["processing_ms"].is_number());
        EXPECT_EQ(p["closed_form"], q["closed_form"]);
    }
    // The minimal firmware exports no host entry: no estimate, and why.
    const auto c =
        testsupport::run_command(stereosim("sweep --grid dsk.cpu_mhz=600 --frames 3 --out " + dir +
                                           "/minimal --firmware " + std::string(MINIMAL_FIRMWARE)));
    ASSERT_EQ(c.exit_code, 0) << c.output;
    const json minimal = json::parse(testsupport::read_text(dir + "/minimal/sweep.json"));
    const json& cf = minimal["points"][0]["closed_form"];
    EXPECT_TRUE(cf["processing_ms"].is_null());
    EXPECT_TRUE(cf["verdict"].is_null());
    EXPECT_EQ(cf.value("processing_note", ""),
              "the firmware under test has no host entry (stereosim_firmware_host): no "
              "processing estimate");
    // The plugin's shards do not merge with the built-in firmware's.
    const auto mixed = testsupport::run_command(
        stereosim("merge " + dir + "/built_in " + dir + "/plugin --out " + dir + "/mixed"));
    EXPECT_EQ(mixed.exit_code, 2) << mixed.output;
    EXPECT_NE(mixed.output.find("not shards of one sweep"), std::string::npos) << mixed.output;
}

// The line time of report.txt's capture closed form, in ECLK ("line N").
long line_eclk(const std::string& dir) {
    const std::string text = testsupport::read_text(dir + "/report.txt");
    const size_t at = text.find("ECLK: line ");
    return at == std::string::npos ? -1 : std::stol(text.substr(at + 11));
}

// After a run, the card's bus timing in the report is the CECTL the
// firmware programmed, not what the reference would have: the minimal
// firmware never programs CE3, so on DSK v3 the bus keeps the DSK v1
// timing the EMIF starts with, while the reference programs v3's.
TEST(FirmwarePluginRun, TheReportedCardTimingIsWhatTheFirmwareProgrammed) {
    const std::string dir = testsupport::temp_dir("fw_cectl");
    const std::string run = "run --quiet --frames 2 --out ";
    testsupport::run_command(stereosim(run + dir + "/ref_v1 --dsk v1"));
    testsupport::run_command(stereosim(run + dir + "/ref_v3 --dsk v3"));
    testsupport::run_command(
        stereosim(run + dir + "/min_v3 --dsk v3 --firmware " + std::string(MINIMAL_FIRMWARE)));
    const long v1 = line_eclk(dir + "/ref_v1"), v3 = line_eclk(dir + "/ref_v3");
    ASSERT_GT(v1, 0);
    ASSERT_GT(v3, 0);
    EXPECT_NE(v1, v3);
    EXPECT_EQ(line_eclk(dir + "/min_v3"), v1);
}

}  // namespace
