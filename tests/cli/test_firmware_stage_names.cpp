// A firmware's stages and tracker states are its own (docs/firmware-abi.md):
// the budget, report.json, frames.csv, report.txt and the waveform name and
// count them as its descriptor declares them, not as the reference's enum.
// The firmware under test is the shipped one behind a wrapper that declares
// 15 stages, runs its 7 as stages 8..14 under other names and renames its
// tracker states (tests/firmware/plugins/omitting_firmware.c, RENAMED_STAGES):
// every figure must equal the built-in run's, under the new names and
// indices.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/support/shell.h"
#include "tests/support/vcd_reader.h"

namespace {

using nlohmann::json;

const std::vector<std::string> reference_stages = {"capture",    "preprocess",  "detect", "track",
                                                   "stereo_sad", "stereo_edge", "xyz"};
const std::vector<std::string> renamed_stages = {
    "x_capture", "x_gray", "x_detect", "x_track", "x_stereo_sad", "x_stereo_edge", "x_xyz"};
constexpr int stage_shift = 8;  // the wrapper's stages 0..7 never run

struct run_output {
    int exit_code = -1;
    json report;
    std::string text, csv, stage_filter;
    testsupport::vcd_file vcd;
};

run_output run(const std::string& dir, const std::string& firmware) {
    const std::string args =
        "run --quiet --frames 10 --vcd --vcd-from 100 --vcd-to 160 "
        "--vcd-scope firmware --out " +
        dir + (firmware.empty() ? "" : " --firmware " + firmware);
    run_output r;
    r.exit_code = testsupport::run_command(std::string(STEREOSIM_BINARY) + " " + args).exit_code;
    r.report = json::parse(testsupport::read_text(dir + "/report.json"));
    r.text = testsupport::read_text(dir + "/report.txt");
    r.csv = testsupport::read_text(dir + "/frames.csv");
    r.stage_filter = testsupport::read_text(dir + "/waves/firmware_stage.txt");
    r.vcd = testsupport::read_vcd(dir + "/waves/default.vcd");
    return r;
}

TEST(FirmwareStageNames, TheBudgetReportAndWavesFollowTheFirmwaresDescriptor) {
    const std::string dir = testsupport::temp_dir("fw_stage_names");
    const run_output built_in = run(dir + "/built_in", "");
    const run_output renamed = run(dir + "/renamed", RENAMING_FIRMWARE);
    ASSERT_EQ(built_in.exit_code, 0);
    ASSERT_EQ(renamed.exit_code, 0);

    // The same run: pins and verdict; judged, the never-run pads being optional.
    EXPECT_EQ(renamed.report["summary"]["hashes"]["pins"],
              built_in.report["summary"]["hashes"]["pins"]);
    EXPECT_EQ(renamed.report["verdict"], built_in.report["verdict"]);
    EXPECT_TRUE(renamed.report["judged"].get<bool>());
    const json& fw = renamed.report["tool"]["firmware"];
    ASSERT_EQ(fw["stages"].size(), 15u);
    EXPECT_EQ(fw["stages"][11], "x_track");
    EXPECT_EQ(fw["tracker_states"][1], "X_TRACK");

    // Per stage, whole run and per frame: the built-in's figure under the new name.
    const json& a = built_in.report["summary"]["timing"]["stage_ms"];
    const json& b = renamed.report["summary"]["timing"]["stage_ms"];
    EXPECT_EQ(b.size(), 15u);
    EXPECT_EQ(b["pad3"]["max"], 0.0);
    for (size_t s = 0; s < reference_stages.size(); ++s) {
        EXPECT_EQ(b[renamed_stages[s]], a[reference_stages[s]]) << reference_stages[s];
        EXPECT_GT(a[reference_stages[s]]["max"].get<double>(), 0.0) << reference_stages[s];
    }
    int processed = 0;
    const json& rows_a = built_in.report["frames"];
    const json& rows_b = renamed.report["frames"];
    ASSERT_EQ(rows_a.size(), rows_b.size());
    for (size_t i = 0; i < rows_a.size(); ++i) {
        if (rows_a[i]["stage_ms"].is_null()) continue;
        ++processed;
        EXPECT_EQ(rows_b[i]["pair"]["processing_ms"], rows_a[i]["pair"]["processing_ms"]) << i;
        EXPECT_EQ(rows_b[i]["tracker_state"], "X_" + rows_a[i]["tracker_state"].get<std::string>());
        for (size_t s = 0; s < reference_stages.size(); ++s)
            EXPECT_EQ(rows_b[i]["stage_ms"][renamed_stages[s]],
                      rows_a[i]["stage_ms"][reference_stages[s]])
                << i << " " << reference_stages[s];
    }
    EXPECT_GE(processed, 4);

    // frames.csv and report.txt by the firmware's names; the paper's
    // figures only beside stages that carry the paper's names.
    EXPECT_NE(renamed.csv.find(",stage_pad0_ms,"), std::string::npos);
    EXPECT_NE(renamed.csv.find(",stage_x_track_ms,"), std::string::npos);
    EXPECT_EQ(renamed.csv.find(",stage_track_ms,"), std::string::npos);
    EXPECT_NE(renamed.text.find("\n  x_stereo_sad "), std::string::npos) << renamed.text;
    EXPECT_NE(built_in.text.find("\n  paper (DSK): track"), std::string::npos);
    EXPECT_EQ(renamed.text.find("paper (DSK)"), std::string::npos);

    // The waveform's stage signal: the built-in's stage + 8, idle 15 in both.
    EXPECT_NE(renamed.stage_filter.find("\n11 x_track\n"), std::string::npos);
    EXPECT_NE(renamed.stage_filter.find("\n15 idle\n"), std::string::npos);
    const std::string stage = "platform.firmware.stage[3:0]";
    const std::vector<testsupport::vcd_change> sa = built_in.vcd.history(stage);
    const std::vector<testsupport::vcd_change> sb = renamed.vcd.history(stage);
    ASSERT_EQ(sa.size(), sb.size());
    int busy = 0;
    for (size_t i = 0; i < sa.size(); ++i) {
        const int va = std::stoi(sa[i].value, nullptr, 2), vb = std::stoi(sb[i].value, nullptr, 2);
        EXPECT_EQ(sa[i].fs, sb[i].fs) << i;
        EXPECT_EQ(vb, va == 15 ? 15 : va + stage_shift) << i;
        busy += va != 15;
    }
    EXPECT_GE(busy, 10);
}

}  // namespace
