// Stereo matching right -> left on real Middlebury pairs with ground truth
// (data/middlebury_2001_2003, data/middlebury_2006_aloe; see their READMEs).
//
// The GT is for the LEFT view: left (x, y) matches right (x - d, y). The
// firmware matches a RIGHT-image pattern, so the GT is forward-warped to the
// right view: each left pixel x with GT d lands on right column
// round(x - d); where several land on one right pixel the largest d wins
// (the nearest surface is the visible one); right pixels nothing lands on
// (occluded in the left view) have no GT and are not scored.
//
// Patches: 15x15, centred on a regular grid (step stated per scene), whose
// centre has right-view GT. Score: share with |d_est - d_gt| <= 1 px, d_est
// the sub-pixel disparity, d_gt the GT at the patch centre. An invalid match
// counts as a miss.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "dsp/sobel.h"
#include "dsp/stereo_edge.h"
#include "dsp/stereo_sad.h"
#include "tests/support/data_path.h"

namespace {

struct scene_case {
    const char* name;
    const char* left;
    const char* right;
    const char* gt;     // GT of the left view
    double gt_scale;    // GT value = gt_scale * d (README)
    int min_disparity;  // search range
    int max_disparity;
    int grid_step;  // px between patch centres
    double sad_floor;
    double edge_floor;      // default edge_params (7 lines spread over the patch)
    double edge_all_floor;  // edge method on all 15 rows of the patch
};

constexpr int patch_size = 15;

dsp::gray_cplane view(const cv::Mat& m) {
    return {m.ptr<uint8_t>(), m.cols, m.rows, static_cast<int>(m.step1())};
}

cv::Mat load_gray(const char* relative) {
    const cv::Mat colour = cv::imread(test_support::data_path(relative), cv::IMREAD_COLOR);
    EXPECT_FALSE(colour.empty()) << relative;
    cv::Mat gray;
    cv::cvtColor(colour, gray, cv::COLOR_BGR2GRAY);
    return gray;
}

// Right-view GT in px (float), -1 where unknown.
cv::Mat right_view_gt(const cv::Mat& left_gt, double scale) {
    cv::Mat right(left_gt.size(), CV_32F, cv::Scalar(-1.0f));
    for (int y = 0; y < left_gt.rows; ++y) {
        for (int x = 0; x < left_gt.cols; ++x) {
            const int value = left_gt.at<uint8_t>(y, x);
            if (value == 0) continue;  // unknown
            const float d = static_cast<float>(value / scale);
            const long xr = std::lround(x - d);
            if (xr < 0 || xr >= left_gt.cols) continue;
            float& slot = right.at<float>(y, static_cast<int>(xr));
            if (d > slot) slot = d;
        }
    }
    return right;
}

cv::Mat sobel(const cv::Mat& gray) {
    cv::Mat edges(gray.size(), CV_8U);
    dsp::sobel_3x3(view(gray),
                   {edges.ptr<uint8_t>(), edges.cols, edges.rows, static_cast<int>(edges.step1())});
    return edges;
}

struct rates {
    int patches = 0;
    int sad_good = 0, sad_int_good = 0;
    int edge_good = 0, edge_valid = 0;
    int edge_all_good = 0, edge_all_valid = 0;
    double pct(int n) const { return 100.0 * n / patches; }
};

rates evaluate(const scene_case& c) {
    const cv::Mat left = load_gray(c.left);
    const cv::Mat right = load_gray(c.right);
    const cv::Mat left_gt = cv::imread(test_support::data_path(c.gt), cv::IMREAD_GRAYSCALE);
    EXPECT_EQ(left_gt.size(), left.size());
    EXPECT_EQ(right.size(), left.size());
    const cv::Mat gt = right_view_gt(left_gt, c.gt_scale);
    const cv::Mat left_edges = sobel(left), right_edges = sobel(right);

    dsp::stereo_params sad;
    sad.min_disparity = c.min_disparity;
    sad.max_disparity = c.max_disparity;
    sad.row_slack = 1;
    dsp::edge_params edge;
    edge.min_disparity = c.min_disparity;
    edge.max_disparity = c.max_disparity;
    dsp::edge_params edge_all = edge;
    edge_all.lines = patch_size;
    edge_all.line_spacing = 1;

    rates r;
    const int half = patch_size / 2;
    for (int cy = half; cy + half < right.rows; cy += c.grid_step) {
        for (int cx = half; cx + half < right.cols; cx += c.grid_step) {
            const float d_gt = gt.at<float>(cy, cx);
            if (d_gt < 0) continue;
            const dsp::box patch{cx - half, cy - half, patch_size, patch_size};
            ++r.patches;
            const auto s = dsp::stereo_match_sad(view(right), view(left), patch, sad);
            if (s.valid && std::fabs(s.disparity_q8 / 256.0 - d_gt) <= 1.0) ++r.sad_good;
            if (s.valid && std::fabs(s.disparity - d_gt) <= 1.0) ++r.sad_int_good;
            const auto e = dsp::stereo_match_edge(view(right_edges), view(left_edges), patch, edge);
            if (e.valid) ++r.edge_valid;
            if (e.valid && std::fabs(e.disparity_q8 / 256.0 - d_gt) <= 1.0) ++r.edge_good;
            const auto a =
                dsp::stereo_match_edge(view(right_edges), view(left_edges), patch, edge_all);
            if (a.valid) ++r.edge_all_valid;
            if (a.valid && std::fabs(a.disparity_q8 / 256.0 - d_gt) <= 1.0) ++r.edge_all_good;
        }
    }
    return r;
}

void check(const scene_case& c) {
    const rates r = evaluate(c);
    std::printf(
        "%-8s d %d..%d, grid step %d px, %d patches 15x15: SAD within 1 px %.1f%% "
        "(integer d %.1f%%); edge %.1f%% (valid %.1f%%); edge on all 15 rows %.1f%% "
        "(valid %.1f%%)\n",
        c.name, c.min_disparity, c.max_disparity, c.grid_step, r.patches, r.pct(r.sad_good),
        r.pct(r.sad_int_good), r.pct(r.edge_good), r.pct(r.edge_valid), r.pct(r.edge_all_good),
        r.pct(r.edge_all_valid));
    ::testing::Test::RecordProperty(std::string(c.name) + "_sad_pct",
                                    std::to_string(r.pct(r.sad_good)));
    ::testing::Test::RecordProperty(std::string(c.name) + "_edge_pct",
                                    std::to_string(r.pct(r.edge_good)));
    EXPECT_GT(r.patches, 1000);
    EXPECT_GE(r.pct(r.sad_good), c.sad_floor);
    EXPECT_GE(r.pct(r.edge_good), c.edge_floor);
    EXPECT_GE(r.pct(r.edge_all_good), c.edge_all_floor);
}

// Floors: a little below the measured rates (in the comments), and at
// least the required tsukuba 85, venus 85, teddy 75, cones 80 for SAD.
TEST(middlebury, tsukuba) {
    // measured: SAD 88.6, edge 69.9, edge all rows 75.9
    check({"tsukuba", "middlebury_2001_2003/tsukuba/im3.png",
           "middlebury_2001_2003/tsukuba/im4.png", "middlebury_2001_2003/tsukuba/disp3.pgm", 16.0,
           0, 15, 8, 87.0, 66.0, 72.0});
}

TEST(middlebury, venus) {
    // measured: SAD 92.5, edge 58.5, edge all rows 65.8
    check({"venus", "middlebury_2001_2003/venus/im2.png", "middlebury_2001_2003/venus/im6.png",
           "middlebury_2001_2003/venus/disp2.pgm", 8.0, 0, 19, 8, 91.0, 55.0, 62.0});
}

TEST(middlebury, teddy) {
    // measured: SAD 79.2, edge 53.6, edge all rows 61.6
    check({"teddy", "middlebury_2001_2003/teddy/im2.png", "middlebury_2001_2003/teddy/im6.png",
           "middlebury_2001_2003/teddy/disp2.png", 4.0, 0, 59, 8, 77.5, 50.0, 58.0});
}

TEST(middlebury, cones) {
    // measured: SAD 84.3, edge 71.7, edge all rows 79.2
    check({"cones", "middlebury_2001_2003/cones/im2.png", "middlebury_2001_2003/cones/im6.png",
           "middlebury_2001_2003/cones/disp2.png", 4.0, 0, 59, 8, 82.5, 68.0, 76.0});
}

TEST(middlebury, aloe_full_size) {
    // GT values 43..211 px (README): search 39..215 (4 px margin). Full size,
    // so a coarser grid. measured: SAD 80.5 (integer d 85.1: the sub-pixel
    // estimates sit about +0.25 px from this integer GT on average), edge 58.5,
    // edge all rows 66.4.
    check({"aloe", "middlebury_2006_aloe/aloeL.jpg", "middlebury_2006_aloe/aloeR.jpg",
           "middlebury_2006_aloe/aloeGT.png", 1.0, 39, 215, 16, 78.0, 55.0, 63.0});
}

}  // namespace
