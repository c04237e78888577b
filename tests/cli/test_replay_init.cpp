// `stereosim replay init` on images a user has (docs/replay.md, "Your own
// pairs"): the Middlebury 2001 Tsukuba pair of ../shared/data, as PNG and as
// JPEG, held for a run; the manifest is written and checked, the run's
// report.json repeats it from another folder, a replay without truth is not
// held to the clean run's output rules, the summary's detection is
// report.json's; bad input is one line, exit 2, nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <string>

#include "tests/support/data_path.h"
#include "tests/support/shell.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

testsupport::command_result stereosim(const std::string& args) {
    return testsupport::run_command("cd " + fs::temp_directory_path().string() + " && " +
                                    STEREOSIM_BINARY + " " + args);
}

json read_json(const std::string& path) {
    std::ifstream in(path);
    return json::parse(in);
}

const std::string left_png = test_support::data_path("middlebury_2001_2003/tsukuba/im3.png");
const std::string right_png = test_support::data_path("middlebury_2001_2003/tsukuba/im4.png");
const std::string window = " --set sensor.window_cols=384 --set sensor.window_rows=288";

TEST(ReplayInit, APairOfYourOwnIsWrittenCheckedAndRun) {
    const std::string dir = testsupport::temp_dir("replay-init");
    ASSERT_FALSE(dir.empty());
    const auto init = stereosim("replay init " + dir + "/png --left " + left_png + " --right " +
                                right_png + " --focal-px 615 --baseline-mm 100");
    ASSERT_EQ(init.exit_code, 0) << init.output;
    EXPECT_NE(init.output.find("1 frame(s) of 384 x 288"), std::string::npos) << init.output;
    EXPECT_NE(
        init.output.find("run it:  stereosim run --replay " + dir + "/png/replay.txt" + window),
        std::string::npos)
        << init.output;
    std::ifstream manifest(dir + "/png/replay.txt");
    std::stringstream text;
    text << manifest.rdbuf();
    EXPECT_NE(text.str().find("\nafter_last hold\n"), std::string::npos) << text.str();
    const std::string left_file = fs::path(left_png).lexically_normal().string();
    EXPECT_NE(text.str().find("\nleft " + left_file + "\n"), std::string::npos) << text.str();

    const auto run = stereosim("run --summary --replay " + dir + "/png/replay.txt" + window +
                               " --frames 9 --out " + dir + "/out");
    ASSERT_LE(run.exit_code, 1) << run.output;
    const json report = read_json(dir + "/out/report.json");
    // The manifest by its absolute path and its calibration; no rig keys.
    EXPECT_EQ(report["config"]["scenario"]["replay"], dir + "/png/replay.txt");
    EXPECT_FALSE(report["config"].contains("rig"));
    EXPECT_EQ(report["replay"]["calibration"]["focal_px"], 615.0);
    EXPECT_EQ(report["replay"]["calibration"]["baseline_mm"], 100.0);
    EXPECT_EQ(report["replay"]["truth"], false);
    // No truth: the clean run's output rules are not judged, not broken.
    EXPECT_TRUE(report["fault_run"]["contract_ok"].get<bool>())
        << report["fault_run"]["violations"].dump();
    // The summary says what report.json says about the detection.
    const json& detection = report["summary"]["accuracy"]["detection_frame"];
    if (detection.is_null())
        EXPECT_NE(run.output.find("no detection"), std::string::npos) << run.output;
    else
        EXPECT_NE(run.output.find("detected at scene frame " + detection.dump()), std::string::npos)
            << run.output;
    // Every pair's frames have no truth (the scenario's ball is not it).
    for (const json& f : report["frames"]) EXPECT_TRUE(f["truth"].is_null()) << f.dump();

    // The report repeats the run from another folder.
    const auto again = testsupport::run_command("cd / && " + std::string(STEREOSIM_BINARY) +
                                                " run --quiet --config " + dir +
                                                "/out/report.json --out " + dir + "/again");
    ASSERT_LE(again.exit_code, 1) << again.output;
    EXPECT_EQ(read_json(dir + "/again/report.json")["summary"]["hashes"],
              report["summary"]["hashes"]);
    fs::remove_all(dir);
}

TEST(ReplayInit, JpegFilesAndNumberedPatterns) {
    const std::string dir = testsupport::temp_dir("replay-init-jpeg");
    ASSERT_FALSE(dir.empty());
    fs::create_directories(dir + "/frames");
    const cv::Mat left = cv::imread(left_png), right = cv::imread(right_png);
    ASSERT_FALSE(left.empty());
    for (int n = 1; n <= 3; ++n) {  // numbered from 1: the first number is found
        cv::imwrite(dir + "/frames/L_" + std::to_string(n) + ".jpg", left);
        cv::imwrite(dir + "/frames/R_" + std::to_string(n) + ".jpg", right);
    }
    const auto init =
        stereosim("replay init " + dir + "/jpg --left " + dir + "/frames/L_%d.jpg --right " + dir +
                  "/frames/R_%d.jpg --focal-px 615 --baseline-mm 100 --after-last loop");
    ASSERT_EQ(init.exit_code, 0) << init.output;
    EXPECT_NE(init.output.find("3 frame(s) of 384 x 288"), std::string::npos) << init.output;
    const auto run = stereosim("run --quiet --replay " + dir + "/jpg/replay.txt" + window +
                               " --frames 4 --out " + dir + "/out");
    EXPECT_LE(run.exit_code, 1) << run.output;
    EXPECT_TRUE(fs::exists(dir + "/out/report.json"));

    cv::Mat small;
    cv::resize(right, small, cv::Size(192, 144));
    cv::imwrite(dir + "/frames/small.png", small);
    // Bad input: one line, exit 2, nothing written.
    const struct {
        std::string args, message;
    } bad[] = {
        {"--left " + dir + "/frames/L_%d.jpg --right " + dir + "/frames/nothing_%d.jpg",
         "--right: no file"},
        {"--left " + dir + "/frames/L_%d.jpg --right " + right_png,
         "--left has 3 frames from number 1, --right 1 from number 0"},
        {"--left " + dir + "/frames/L_%s.jpg --right " + right_png, "one %d or %0Nd"},
        {"--left " + left_png + " --right " + right_png + " --principal-left 3", "expected X,Y"},
        {"--left " + dir + "/frames/L_%5d.jpg --right " + right_png, "one %d or %0Nd"},
        {"--left " + dir + "/frames/L_%d_%d.jpg --right " + right_png, "one %d or %0Nd"},
        {"--left '" + dir + "/frames/L#1.jpg' --right " + right_png, "without '#'"},
        // Checked as a run reads it: the pair's sizes differ.
        {"--left " + left_png + " --right " + dir + "/frames/small.png", "small.png"},
    };
    for (const auto& b : bad) {
        const auto r = stereosim("replay init " + dir + "/bad " + b.args +
                                 " --focal-px 615 --baseline-mm 100");
        EXPECT_EQ(r.exit_code, 2) << b.args << "\n" << r.output;
        EXPECT_NE(r.output.find(b.message), std::string::npos) << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
        EXPECT_FALSE(fs::exists(dir + "/bad")) << b.args;
    }
    // A folder with a '%' in its name cannot be named by a manifest's pattern.
    fs::create_directories(dir + "/100%/frames");
    cv::imwrite(dir + "/100%/frames/L_0.png", left);
    cv::imwrite(dir + "/100%/frames/R_0.png", right);
    const auto percent = testsupport::run_command(
        "cd '" + dir + "/100%' && " + STEREOSIM_BINARY +
        " replay init out --left frames/L_%d.png --right frames/R_%d.png --focal-px 615 "
        "--baseline-mm 100");
    EXPECT_EQ(percent.exit_code, 2) << percent.output;
    EXPECT_NE(percent.output.find("outside the pattern"), std::string::npos) << percent.output;
    EXPECT_FALSE(fs::exists(dir + "/100%/out"));
    fs::remove_all(dir);
}

}  // namespace
