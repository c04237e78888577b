// Three-frame differencing kernels (dsp/motion_detect.h) against OpenCV on
// real frames (opencv_vtest, 768x576 gray, static camera, walkers):
// absdiff == cv::absdiff, threshold_binary == cv::threshold(THRESH_BINARY),
// mask_and == cv::bitwise_and, the fused three_frame_difference == their
// composition, erode/dilate == cv::erode/dilate (3x3 rect, BORDER_CONSTANT 0
// = background outside), connected components == the bounding boxes and
// areas of cv::connectedComponentsWithStats (8-connectivity). Every
// comparison is exact. Then the motion_detector: its cleaned mask equals
// the same pipeline built from OpenCV calls, its object equals OpenCV's
// largest component, a closed-form synthetic scene, and no allocation in
// detect().
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "dsp/motion_detect.h"
#include "tests/support/data_path.h"
#include "tests/support/heap_counter.h"


namespace {

dsp::gray_cplane view(const cv::Mat& m) {
    return dsp::gray_cplane{m.ptr<uint8_t>(), m.cols, m.rows, static_cast<int>(m.step)};
}
dsp::gray_plane view_mut(cv::Mat& m) {
    return dsp::gray_plane{m.ptr<uint8_t>(), m.cols, m.rows, static_cast<int>(m.step)};
}

cv::Mat load_vtest(int index) {
    char name[64];
    std::snprintf(name, sizeof name, "opencv_vtest/frames_gray/vtest_gray_%04d.png", index);
    cv::Mat m = cv::imread(test_support::data_path(name), cv::IMREAD_GRAYSCALE);
    EXPECT_FALSE(m.empty()) << name;
    return m;
}

int differing_pixels(const cv::Mat& a, const cv::Mat& b) {
    cv::Mat d;
    cv::compare(a, b, d, cv::CMP_NE);
    return cv::countNonZero(d);
}

// A view with stride != width and an odd start: a sub-rectangle of a frame.
cv::Mat odd_roi(const cv::Mat& m) {
    return m(cv::Rect(3, 5, m.cols - 10, m.rows - 9));
}

cv::Mat cv_three_frame(const cv::Mat& f0, const cv::Mat& f1, const cv::Mat& f2, int th) {
    cv::Mat d01, d12, b01, b12, out;
    cv::absdiff(f0, f1, d01);
    cv::absdiff(f1, f2, d12);
    cv::threshold(d01, b01, th, 255, cv::THRESH_BINARY);
    cv::threshold(d12, b12, th, 255, cv::THRESH_BINARY);
    cv::bitwise_and(b01, b12, out);
    return out;
}

const cv::Mat& rect3() {
    static const cv::Mat k = cv::getStructuringElement(cv::MORPH_RECT, cv::Size(3, 3));
    return k;
}
// The input is cloned: on a ROI OpenCV's filters would read the parent
// image's pixels beyond the ROI instead of the border value.
cv::Mat cv_erode(const cv::Mat& in) {
    cv::Mat out;
    cv::erode(in.clone(), out, rect3(), cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
    return out;
}
cv::Mat cv_dilate(const cv::Mat& in) {
    cv::Mat out;
    cv::dilate(in.clone(), out, rect3(), cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
    return out;
}

using comp_key = std::tuple<int, int, int, int, int>;  // area, x, y, w, h

std::vector<comp_key> cv_components(const cv::Mat& mask) {
    cv::Mat labels, stats, centroids;
    const int n = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8, CV_32S);
    std::vector<comp_key> keys;
    for (int i = 1; i < n; ++i) {
        keys.emplace_back(stats.at<int>(i, cv::CC_STAT_AREA), stats.at<int>(i, cv::CC_STAT_LEFT),
                          stats.at<int>(i, cv::CC_STAT_TOP), stats.at<int>(i, cv::CC_STAT_WIDTH),
                          stats.at<int>(i, cv::CC_STAT_HEIGHT));
    }
    std::sort(keys.begin(), keys.end());
    return keys;
}

// Our components with workspaces sized for the worst case.
struct our_components {
    int returned = 0;
    std::vector<dsp::component> list;
};
our_components dsp_components(const cv::Mat& mask, int max_out = -1) {
    const int max_labels = ((mask.cols + 1) / 2) * ((mask.rows + 1) / 2);
    std::vector<int32_t> labels(2 * static_cast<size_t>(mask.cols));
    std::vector<int32_t> parent(static_cast<size_t>(max_labels));
    std::vector<dsp::component> stats(static_cast<size_t>(max_labels));
    if (max_out < 0) max_out = max_labels;
    our_components result;
    result.list.resize(static_cast<size_t>(max_out));
    result.returned =
        dsp::connected_components(view(mask), labels.data(), parent.data(), stats.data(),
                                  max_labels, result.list.data(), max_out);
    result.list.resize(static_cast<size_t>(std::max(result.returned, 0)));
    return result;
}

std::vector<comp_key> keys_of(const std::vector<dsp::component>& list) {
    std::vector<comp_key> keys;
    for (const dsp::component& c : list) {
        keys.emplace_back(c.area, c.bbox.x, c.bbox.y, c.bbox.width, c.bbox.height);
    }
    std::sort(keys.begin(), keys.end());
    return keys;
}

class vtest_frames : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        for (int i : {0, 1, 2, 30}) s_frames.push_back(load_vtest(i));
    }
    static const cv::Mat& frame(int slot) { return s_frames[static_cast<size_t>(slot)]; }
    static std::vector<cv::Mat> s_frames;  // frames 0, 1, 2, 30
};
std::vector<cv::Mat> vtest_frames::s_frames;

TEST_F(vtest_frames, absdiff_equals_opencv) {
    const std::pair<int, int> pairs[] = {{0, 1}, {1, 2}, {0, 3}};
    for (auto [a, b] : pairs) {
        for (bool roi : {false, true}) {
            const cv::Mat fa = roi ? odd_roi(frame(a)) : frame(a);
            const cv::Mat fb = roi ? odd_roi(frame(b)) : frame(b);
            cv::Mat expected, ours(fa.size(), CV_8U, cv::Scalar(77));
            cv::absdiff(fa, fb, expected);
            dsp::absdiff(view(fa), view(fb), view_mut(ours));
            const int nonzero = cv::countNonZero(expected);
            double largest = 0;
            cv::minMaxLoc(expected, nullptr, &largest);
            std::printf("absdiff slots %d-%d roi %d: %dx%d, %d non-zero, max %g, differing %d\n", a,
                        b, roi, fa.cols, fa.rows, nonzero, largest,
                        differing_pixels(expected, ours));
            EXPECT_GT(nonzero, 1000);  // real change, not two equal frames
            EXPECT_EQ(differing_pixels(expected, ours), 0);
        }
    }
}

TEST_F(vtest_frames, threshold_equals_opencv) {
    cv::Mat diff;
    cv::absdiff(frame(0), frame(3), diff);
    for (const cv::Mat* src : std::initializer_list<const cv::Mat*>{&diff, &frame(1)}) {
        for (int th : {0, 1, 20, 25, 127, 200, 254, 255}) {
            cv::Mat expected, ours(src->size(), CV_8U, cv::Scalar(77));
            cv::threshold(*src, expected, th, 255, cv::THRESH_BINARY);
            dsp::threshold_binary(view(*src), static_cast<uint8_t>(th), view_mut(ours));
            EXPECT_EQ(differing_pixels(expected, ours), 0) << "threshold " << th;
            if (src == &diff && (th == 20 || th == 25)) {
                std::printf("threshold %d on |f0 - f30|: %d set pixels, identical\n", th,
                            cv::countNonZero(expected));
            }
        }
    }
}

TEST_F(vtest_frames, mask_and_equals_opencv) {
    cv::Mat d01, d12, b01, b12, expected;
    cv::absdiff(frame(0), frame(1), d01);
    cv::absdiff(frame(1), frame(2), d12);
    cv::threshold(d01, b01, 20, 255, cv::THRESH_BINARY);
    cv::threshold(d12, b12, 20, 255, cv::THRESH_BINARY);
    cv::bitwise_and(b01, b12, expected);
    cv::Mat ours(expected.size(), CV_8U, cv::Scalar(77));
    dsp::mask_and(view(b01), view(b12), view_mut(ours));
    std::printf("mask_and: %d & %d -> %d set pixels\n", cv::countNonZero(b01),
                cv::countNonZero(b12), cv::countNonZero(expected));
    EXPECT_GT(cv::countNonZero(expected), 100);
    EXPECT_EQ(differing_pixels(expected, ours), 0);
}

TEST_F(vtest_frames, fused_three_frame_difference_equals_opencv_composition) {
    for (int th : {10, 20, 25, 40}) {
        for (bool roi : {false, true}) {
            auto pick = [&](int s) { return roi ? odd_roi(frame(s)) : frame(s); };
            const cv::Mat expected = cv_three_frame(pick(0), pick(1), pick(2), th);
            cv::Mat ours(expected.size(), CV_8U, cv::Scalar(77));
            dsp::three_frame_difference(view(pick(0)), view(pick(1)), view(pick(2)),
                                        static_cast<uint8_t>(th), view_mut(ours));
            if (!roi) {
                std::printf("three-frame difference th %d: %d object pixels (OpenCV: 5 calls)\n",
                            th, cv::countNonZero(expected));
            }
            EXPECT_GT(cv::countNonZero(expected), 300);
            EXPECT_EQ(differing_pixels(expected, ours), 0) << "threshold " << th;
        }
    }
}

void expect_morphology_matches(const cv::Mat& in, const char* what) {
    cv::Mat eroded(in.size(), CV_8U, cv::Scalar(77)), dilated(in.size(), CV_8U, cv::Scalar(77));
    dsp::erode_3x3(view(in), view_mut(eroded));
    dsp::dilate_3x3(view(in), view_mut(dilated));
    const cv::Mat cv_e = cv_erode(in), cv_d = cv_dilate(in);
    EXPECT_EQ(differing_pixels(cv_e, eroded), 0) << what << " erode " << in.cols << "x" << in.rows;
    EXPECT_EQ(differing_pixels(cv_d, dilated), 0)
        << what << " dilate " << in.cols << "x" << in.rows;
}

TEST_F(vtest_frames, erode_dilate_equal_opencv_with_background_border) {
    // A real object mask and a thresholded frame whose regions touch all four
    // borders (the border rule matters there), whole and as a ROI.
    const cv::Mat motion = cv_three_frame(frame(0), frame(1), frame(2), 20);
    cv::Mat bright;
    cv::threshold(frame(1), bright, 120, 255, cv::THRESH_BINARY);
    for (const auto& [m, what] : {std::pair<cv::Mat, const char*>{motion, "motion mask"},
                                  {bright, "frame > 120"},
                                  {odd_roi(bright), "frame > 120, roi"}}) {
        expect_morphology_matches(m, what);
        std::printf("%s: %d set, eroded %d, dilated %d (compared with OpenCV)\n", what,
                    cv::countNonZero(m), cv::countNonZero(cv_erode(m)),
                    cv::countNonZero(cv_dilate(m)));
    }
    // The border really counts as background: a full mask loses its rim.
    cv::Mat full(6, 5, CV_8U, cv::Scalar(255)), eroded(6, 5, CV_8U);
    dsp::erode_3x3(view(full), view_mut(eroded));
    EXPECT_EQ(cv::countNonZero(eroded), (6 - 2) * (5 - 2));
}

TEST(morphology, tiny_and_random_images_equal_opencv) {
    std::mt19937 rng(7);
    int cases = 0;
    for (int h = 1; h <= 6; ++h) {
        for (int w = 1; w <= 9; ++w) {
            for (int rep = 0; rep < 8; ++rep) {
                cv::Mat m(h, w, CV_8U);
                for (int y = 0; y < h; ++y)
                    for (int x = 0; x < w; ++x)
                        m.at<uint8_t>(y, x) = (rng() % 3) ? uint8_t{255} : uint8_t{0};
                expect_morphology_matches(m, "random");
                ++cases;
            }
        }
    }
    std::printf("morphology: %d random masks from 1x1 to 9x6 identical to OpenCV\n", cases);
}

TEST_F(vtest_frames, connected_components_equal_opencv_on_real_masks) {
    const cv::Mat motion = cv_three_frame(frame(0), frame(1), frame(2), 20);
    const cv::Mat cleaned = cv_erode(cv_erode(cv_dilate(cv_dilate(cv_dilate(cv_erode(motion))))));
    cv::Mat bright, edges, change;
    cv::threshold(frame(1), bright, 120, 255, cv::THRESH_BINARY);
    cv::Canny(frame(1), edges, 60, 160);  // thin 8-connected curves: many label merges
    cv::Mat d;
    cv::absdiff(frame(0), frame(3), d);
    cv::threshold(d, change, 10, 255, cv::THRESH_BINARY);
    for (const auto& [m, what] : {std::pair<cv::Mat, const char*>{motion, "raw three-frame mask"},
                                  {cleaned, "cleaned mask"},
                                  {bright, "frame > 120"},
                                  {edges, "Canny edges"},
                                  {change, "|f0 - f30| > 10"},
                                  {odd_roi(edges), "Canny edges, roi"}}) {
        const std::vector<comp_key> expected = cv_components(m);
        const our_components ours = dsp_components(m);
        std::printf("%s: %d set pixels, %zu components (OpenCV %zu), largest %d px\n", what,
                    cv::countNonZero(m), ours.list.size(), expected.size(),
                    ours.list.empty() ? 0 : ours.list.front().area);
        EXPECT_GT(expected.size(), 2u) << what;
        EXPECT_EQ(ours.returned, static_cast<int>(expected.size())) << what;
        EXPECT_EQ(keys_of(ours.list), expected) << what;
        for (size_t i = 1; i < ours.list.size(); ++i) {
            ASSERT_GE(ours.list[i - 1].area, ours.list[i].area) << what << ": largest first";
        }
    }
}

TEST(connected_components, random_masks_equal_opencv) {
    // Dense random masks near the percolation threshold: long chains of
    // merges, U shapes, components that join far below where they start.
    std::mt19937 rng(11);
    int cases = 0, total_components = 0;
    for (int rep = 0; rep < 60; ++rep) {
        const int w = 1 + static_cast<int>(rng() % 80), h = 1 + static_cast<int>(rng() % 60);
        const unsigned density = 30 + rng() % 40;  // percent
        cv::Mat m(h, w, CV_8U);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                m.at<uint8_t>(y, x) = (rng() % 100 < density) ? uint8_t{255} : uint8_t{0};
        const std::vector<comp_key> expected = cv_components(m);
        const our_components ours = dsp_components(m);
        EXPECT_EQ(keys_of(ours.list), expected) << w << "x" << h << " density " << density;
        total_components += static_cast<int>(expected.size());
        ++cases;
    }
    std::printf("connected components: %d random masks, %d components, all equal to OpenCV\n",
                cases, total_components);
}

TEST(connected_components, keeps_the_largest_and_reports_label_overflow) {
    // Three separate squares of 9, 25 and 4 pixels.
    cv::Mat m(12, 20, CV_8U, cv::Scalar(0));
    m(cv::Rect(1, 1, 3, 3)).setTo(255);
    m(cv::Rect(8, 2, 5, 5)).setTo(255);
    m(cv::Rect(16, 8, 2, 2)).setTo(255);
    const our_components top = dsp_components(m, 2);
    ASSERT_EQ(top.returned, 2);
    EXPECT_EQ(top.list[0].area, 25);
    EXPECT_EQ(top.list[0].bbox.x, 8);
    EXPECT_EQ(top.list[0].bbox.y, 2);
    EXPECT_EQ(top.list[0].bbox.width, 5);
    EXPECT_EQ(top.list[1].area, 9);

    std::vector<int32_t> labels(2 * 20), parent(2);
    std::vector<dsp::component> stats(2), out(2);
    // Three components need three labels: two are too few, three suffice.
    EXPECT_EQ(dsp::connected_components(view(m), labels.data(), parent.data(), stats.data(), 2,
                                        out.data(), 2),
              -1);
    parent.resize(3);
    stats.resize(3);
    EXPECT_EQ(dsp::connected_components(view(m), labels.data(), parent.data(), stats.data(), 3,
                                        out.data(), 2),
              2);
}

// The detector's cleaned mask is the OpenCV pipeline: three-frame
// difference, opening (erode, dilate), closing (dilate x2, erode x2); its
// object is OpenCV's largest component.
TEST_F(vtest_frames, detector_equals_opencv_pipeline) {
    dsp::motion_detector detector;
    detector.init(frame(0).cols, frame(0).rows);
    const dsp::detect_params params{};  // threshold 20, open 1, close 2, min_area 30
    const test_support::heap_counter heap;
    const dsp::detection found =
        detector.detect(view(frame(0)), view(frame(1)), view(frame(2)), params);
    const long allocations = heap.allocations();

    cv::Mat expected = cv_three_frame(frame(0), frame(1), frame(2), params.threshold);
    expected = cv_dilate(cv_erode(expected));
    expected = cv_erode(cv_erode(cv_dilate(cv_dilate(expected))));
    cv::Mat ours(expected.size(), CV_8U);
    const dsp::gray_cplane mask = detector.last_mask();
    ASSERT_EQ(mask.width, expected.cols);
    ASSERT_EQ(mask.height, expected.rows);
    for (int y = 0; y < mask.height; ++y)
        std::copy(mask.row(y), mask.row(y) + mask.width, ours.ptr<uint8_t>(y));
    EXPECT_EQ(differing_pixels(expected, ours), 0);

    std::vector<comp_key> cv_keys = cv_components(expected);
    const comp_key largest = *std::max_element(
        cv_keys.begin(), cv_keys.end(),
        [](const comp_key& a, const comp_key& b) { return std::get<0>(a) < std::get<0>(b); });
    const long at_least_min = std::count_if(cv_keys.begin(), cv_keys.end(), [&](const comp_key& k) {
        return std::get<0>(k) >= params.min_area;
    });
    std::printf(
        "detector on vtest 0-2: cleaned mask %d px, %zu components, %ld >= min_area; object "
        "(%d,%d) %dx%d area %d; allocations in detect(): %ld\n",
        cv::countNonZero(expected), cv_keys.size(), at_least_min, found.bbox.x, found.bbox.y,
        found.bbox.width, found.bbox.height, found.area, allocations);
    ASSERT_TRUE(found.found);
    EXPECT_EQ(found.components, at_least_min);
    EXPECT_EQ(comp_key(found.area, found.bbox.x, found.bbox.y, found.bbox.width, found.bbox.height),
              largest);
    EXPECT_EQ(detector.last_foreground_pixels(), cv::countNonZero(expected));
    EXPECT_EQ(allocations, 0);
}

// Closed form: a bright textured 20x16 block jumps 24 px per frame (more than
// its width, so its three positions never overlap) over a dark textured
// background, and a 5x5 block (area 25 < min_area) does the same. With all
// object/background differences > threshold, object(t-1) is exactly the big
// block at its middle position; the small one is a component below min_area.
TEST(motion_detector, synthetic_object_found_exactly) {
    const int w = 160, h = 100;
    std::mt19937 rng(3);
    cv::Mat background(h, w, CV_8U);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) background.at<uint8_t>(y, x) = static_cast<uint8_t>(rng() % 60);
    cv::Mat big_texture(16, 20, CV_8U), small_texture(5, 5, CV_8U);
    for (cv::Mat* t : {&big_texture, &small_texture})
        for (int y = 0; y < t->rows; ++y)
            for (int x = 0; x < t->cols; ++x)
                t->at<uint8_t>(y, x) = static_cast<uint8_t>(180 + rng() % 76);
    cv::Mat frames[3];
    for (int t = 0; t < 3; ++t) {
        frames[t] = background.clone();
        big_texture.copyTo(frames[t](cv::Rect(20 + 24 * t, 30, 20, 16)));
        small_texture.copyTo(frames[t](cv::Rect(30 + 10 * t, 80, 5, 5)));
    }
    dsp::motion_detector detector;
    detector.init(w, h, 64);
    const dsp::detection found =
        detector.detect(view(frames[0]), view(frames[1]), view(frames[2]), dsp::detect_params{});
    std::printf("synthetic: found %d at (%d,%d) %dx%d area %d, %d components >= min_area\n",
                found.found, found.bbox.x, found.bbox.y, found.bbox.width, found.bbox.height,
                found.area, found.components);
    ASSERT_TRUE(found.found);
    EXPECT_EQ(found.bbox.x, 44);
    EXPECT_EQ(found.bbox.y, 30);
    EXPECT_EQ(found.bbox.width, 20);
    EXPECT_EQ(found.bbox.height, 16);
    EXPECT_EQ(found.area, 20 * 16);
    EXPECT_EQ(found.components, 1);
    EXPECT_EQ(detector.last_component_count(), 2);  // the small block is there, below min_area

    // Larger than the init size: refused, not overrun.
    const cv::Mat large(h + 1, w, CV_8U, cv::Scalar(0));
    EXPECT_FALSE(detector.detect(view(large), view(large), view(large), {}).found);
}

}  // namespace
