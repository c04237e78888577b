// A replayed sequence with ground truth is scored like a rendered scene
// (docs/replay.md): a textured ball composited over the real Middlebury
// 2006 "Aloe" pair with its published calibration (../shared/data,
// tests/support/replay_composite.h), replayed through the whole
// co-simulation at the sensors' 448 x 372 window. The
// report carries the truth CSV's rows, the errors against them, the
// detection latency from the first frame whose truth moves, the RMSE; a
// replay without truth keeps its nulls; a half-given column group is a
// one-line error.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/data_path.h"
#include "tests/support/replay_composite.h"
#include "tests/support/shell.h"

namespace {

using nlohmann::json;

const std::string window = " --set sensor.window_cols=448 --set sensor.window_rows=372";

testsupport::command_result stereosim(const std::string& args) {
    return testsupport::run_command(std::string(STEREOSIM_BINARY) + " " + args);
}

// The truth CSV's rows: frame -> {x, y, z, u, v, z_visible}.
std::vector<std::vector<double>> truth_rows(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);  // header
    std::vector<std::vector<double>> rows;
    while (std::getline(in, line)) {
        std::stringstream s(line);
        std::vector<double> v;
        std::string cell;
        while (std::getline(s, cell, ',')) v.push_back(std::stod(cell));
        rows.push_back({v[1], v[2], v[3], v[4], v[5], v[6]});
    }
    return rows;
}

// Middlebury 2006 "Aloe" (../shared/data/middlebury_2006_aloe, full size
// 1282 x 1110) with its published calibration (docs/replay.md has the
// sources): f = 3740 px and B = 160 mm at full size, the views cropped by
// dmin = 270 px (Z = f B / (d + dmin)). Scaled down by 2.8 to 458 x 396 and
// cropped to the 448 x 372 window: f = 1335.7 px, offset 96.4 px; the
// scene's GT disparities 43..211 px put it at 1.24-1.91 m. The ball (3 cm,
// ~73 px wide) passes at 1.1 m, in front of everything it covers.
testsupport::composite_spec aloe_spec() {
    testsupport::composite_spec spec;
    spec.left_png = test_support::data_path("middlebury_2006_aloe/aloeL.jpg");
    spec.right_png = test_support::data_path("middlebury_2006_aloe/aloeR.jpg");
    spec.calibration = {3740.0, 0.160, 270.0};
    spec.downscale = 2.8;
    spec.crop_x = 5;
    spec.crop_y = 12;
    spec.depth_m = 1.1;
    spec.radius_m = 0.03;
    spec.pass = true;
    spec.frames = 13;  // a run of 12 periods shows scene frames 0..12
    return spec;
}

std::string make_sequence(const std::string& dir,
                          const testsupport::composite_spec& spec = aloe_spec()) {
    std::string error;
    const std::string manifest = testsupport::write_composite_replay(spec, dir, &error);
    EXPECT_FALSE(manifest.empty()) << error;
    return manifest;
}

TEST(ReplayScoring, ABallOverARealPairIsScoredAgainstItsTruth) {
    const std::string dir = testsupport::temp_dir("replay-scoring");
    const std::string manifest = make_sequence(dir + "/seq");
    ASSERT_FALSE(manifest.empty());
    const auto r =
        stereosim("run --quiet --replay " + manifest + window + " --out " + dir + "/out");
    ASSERT_LE(r.exit_code, 1) << r.output;
    std::ifstream in(dir + "/out/report.json");
    const json report = json::parse(in);
    const auto rows = truth_rows(dir + "/seq/truth.csv");
    int scored = 0;
    std::vector<double> boxes;
    double depth_max = 0;
    for (const json& f : report["frames"]) {
        if (f["truth"].is_null()) continue;
        const int n = f["pair"]["scene_frame"].get<int>();
        const std::vector<double>& t = rows.at(static_cast<size_t>(n));
        // The truth in the report is the CSV's row of the pair's scene frame.
        EXPECT_NEAR(f["truth"]["x"].get<double>(), t[0], 1e-3) << "frame " << n;
        EXPECT_NEAR(f["truth"]["z"].get<double>(), t[2], 1e-3) << "frame " << n;
        EXPECT_NEAR(f["truth"]["u_right_px"].get<double>(), t[3], 1e-3) << "frame " << n;
        EXPECT_NEAR(f["truth"]["z_visible"].get<double>(), t[5], 1e-3) << "frame " << n;
        if (f["errors"]["depth_pct"].is_null()) continue;
        ++scored;
        // The error is the estimate against that row (z against z_visible).
        EXPECT_NEAR(f["errors"]["z_mm"].get<double>(), f["estimate"]["z"].get<double>() - t[5],
                    1e-3);
        const double box = f["errors"]["box_centre_px"].get<double>();
        // The box centre error recomputed here from the box and the row's u, v.
        const json& b = f["box_right"];
        const double cx = b["x"].get<double>() + 0.5 * (b["width"].get<double>() - 1);
        const double cy = b["y"].get<double>() + 0.5 * (b["height"].get<double>() - 1);
        EXPECT_NEAR(box, std::hypot(cx - t[3], cy - t[4]), 1e-3) << "frame " << n;
        boxes.push_back(box);
        depth_max = std::max(depth_max, std::fabs(f["errors"]["depth_pct"].get<double>()));
    }
    const json& acc = report["summary"]["accuracy"];
    EXPECT_GE(scored, 5);
    EXPECT_EQ(acc["points_scored"].get<int>(), scored);
    EXPECT_EQ(acc["first_motion_frame"], 3);  // the CSV's first moving row
    EXPECT_LE(acc["detect_latency_frames"].get<int>(), 3);
    EXPECT_TRUE(acc["rmse_mm"]["z"].is_number());
    // The ball passes in front of the real scene: its visible surface is
    // nearer than the scene's nearest point by the pair's own ground truth
    // and calibration (GT 8-bit, disparity in full-size pixels, 0 unknown).
    double gt_max = 0;
    cv::minMaxLoc(cv::imread(test_support::data_path("middlebury_2006_aloe/aloeGT.png"),
                             cv::IMREAD_GRAYSCALE),
                  nullptr, &gt_max);
    const double scene_nearest_mm = 3740.0 * 160.0 / (gt_max + 270.0);
    EXPECT_NEAR(scene_nearest_mm, 1244, 1);
    for (const auto& row : rows) EXPECT_LT(row[5], scene_nearest_mm - 100);
    // Bounds (regression guards; the oracle is the truth CSV above): the
    // issue's 1 % in depth (measured 0.40 % at most) and a box centre within
    // 3 px on average (measured 0.94 px, 1.72 px at most). With the
    // calibration's offset dropped from the manifest (principal points
    // equal) the same run's depth error is 96.5 %.
    EXPECT_LT(depth_max, 1.0) << "depth error, %";
    ASSERT_GE(boxes.size(), 5u);
    double mean_box = 0;
    for (const double b : boxes) mean_box += b / static_cast<double>(boxes.size());
    EXPECT_LT(mean_box, 3.0) << "box centre error, mean over the tracked frames, px";
    // frames.csv carries the truth; the trajectory plot is drawn with it.
    const std::string frames = testsupport::read_text(dir + "/out/frames.csv");
    EXPECT_NE(frames.find("true_x_mm"), std::string::npos);
    EXPECT_TRUE(testsupport::file_exists(dir + "/out/trajectory.png"));
}

TEST(ReplayScoring, WithoutTruthTheNullsStayAndHalfAGroupIsAnError) {
    const std::string dir = testsupport::temp_dir("replay-no-truth");
    const std::string manifest = make_sequence(dir + "/seq");
    ASSERT_FALSE(manifest.empty());
    // The same sequence without its truth line: nothing scored, truth null.
    std::string text = testsupport::read_text(manifest);
    text.erase(text.find("truth truth.csv"));
    std::ofstream(dir + "/seq/no-truth.txt") << text;
    const auto r = stereosim("run --quiet --frames 8 --replay " + dir + "/seq/no-truth.txt" +
                             window + " --out " + dir + "/out");
    ASSERT_LE(r.exit_code, 1) << r.output;
    std::ifstream in(dir + "/out/report.json");
    const json report = json::parse(in);
    EXPECT_EQ(report["summary"]["accuracy"]["points_scored"], 0);
    EXPECT_TRUE(report["summary"]["accuracy"]["first_motion_frame"].is_null());
    for (const json& f : report["frames"]) EXPECT_TRUE(f["truth"].is_null());
    // x and y without z: one line, exit 2, nothing written.
    std::ofstream(dir + "/seq/truth.csv") << "frame,x_mm,y_mm\n0,1,2\n";
    const auto bad =
        stereosim("run --quiet --replay " + manifest + window + " --out " + dir + "/bad");
    EXPECT_EQ(bad.exit_code, 2) << bad.output;
    EXPECT_NE(bad.output.find("x_mm, y_mm and z_mm come together"), std::string::npos)
        << bad.output;
    EXPECT_FALSE(testsupport::file_exists(dir + "/bad"));
}

// The scene of the issue on the box (docs/firmware.md, "Fast and spinning
// objects"): over the same real pair, a ball 3 cm in radius (about 73 px
// wide at 1.1 m) on the pass at 3.2 times its speed (about 27 px per frame,
// beyond the SAD search's 24 px) spinning at 10 revolutions per second
// about the horizontal axis. Scored against its truth CSV in every pair
// from the detection on while the ball is wholly in both views (the left
// view sees it 98 px further right and loses it first): the box centre
// within 3 px of the truth on average and 6 px in every pair, the depth
// within 1 %. The firmware before the box followed the silhouette: box
// 5.0, 6.1, 6.3, 7.1 px off in those four pairs.
TEST(ReplayScoring, AFastSpinningBallOverARealPairKeepsItsBox) {
    const std::string dir = testsupport::temp_dir("replay-spinning");
    testsupport::composite_spec spec = aloe_spec();
    spec.radius_m = 0.03;
    spec.speed = 3.2;
    spec.spin_rps = 10.0;
    spec.spin_axis = testsupport::scene_axis::x;
    spec.frames = 13;
    const std::string manifest = make_sequence(dir + "/seq", spec);
    ASSERT_FALSE(manifest.empty());
    const auto r = stereosim("run --quiet --frames 12 --replay " + manifest + window + " --out " +
                             dir + "/out");
    ASSERT_LE(r.exit_code, 1) << r.output;
    std::ifstream in(dir + "/out/report.json");
    const json report = json::parse(in);
    const auto rows = truth_rows(dir + "/seq/truth.csv");
    const json& acc = report["summary"]["accuracy"];
    ASSERT_FALSE(acc["detection_frame"].is_null()) << "never detected";
    const int detected = acc["detection_frame"].get<int>();
    // The sequence's rig (make_sequence): f and the views' offset at 1 / 2.8.
    const double f = 3740.0 / 2.8, offset = 270.0 / 2.8, baseline_m = 0.160;
    std::vector<double> boxes;
    double depth_max = 0;
    std::string per_pair;
    for (const json& f_json : report["frames"]) {
        if (f_json["truth"].is_null() || f_json["pair"].is_null()) continue;
        const int n = f_json["pair"]["scene_frame"].get<int>();
        const std::vector<double>& t = rows.at(static_cast<size_t>(n));
        const double z_m = t[2] / 1000.0, r_px = f * spec.radius_m / z_m + 1.0;
        const double u_left = t[3] + f * baseline_m / z_m - offset;
        const bool in_both_views =
            t[3] - r_px >= 0 && u_left + r_px <= 448 && t[4] - r_px >= 0 && t[4] + r_px <= 372;
        if (n < detected || !in_both_views) continue;
        ASSERT_FALSE(f_json["errors"]["depth_pct"].is_null()) << "no 3D point in pair " << n;
        const double box = f_json["errors"]["box_centre_px"].get<double>();
        const double depth = f_json["errors"]["depth_pct"].get<double>();
        char text[64];
        std::snprintf(text, sizeof text, " %d:%.2fpx,%.2f%%", n, box, depth);
        per_pair += text;
        boxes.push_back(box);
        depth_max = std::max(depth_max, std::fabs(depth));
    }
    std::printf("spinning ball over Aloe, pair:box,depth:%s\n", per_pair.c_str());
    ASSERT_GE(boxes.size(), 4u);
    double mean_box = 0;
    for (const double b : boxes) mean_box += b / static_cast<double>(boxes.size());
    EXPECT_LE(mean_box, 3.0);
    EXPECT_LE(*std::max_element(boxes.begin(), boxes.end()), 6.0);
    EXPECT_LE(depth_max, 1.0);
}

}  // namespace
