// Detection and tracking kernels beside their OpenCV equivalents, on real
// frames (opencv_vtest, cropped to VGA 640x480):
//   three-frame difference (fused, one pass)  vs  absdiff x2 + threshold x2 +
//   bitwise_and erode / dilate 3x3                         vs  cv::erode /
//   cv::dilate (3x3 rect) connected components (runs, 2 label rows)  vs
//   cv::connectedComponentsWithStats sad_search 32x32, +-24 (49x49 positions)
//   vs  cv::matchTemplate(TM_SQDIFF) + minMaxLoc
// Host timings only: they say how the portable C++ compares with OpenCV's
// SIMD code on this machine, not what the C64x takes (dsp/kernel_costs.h).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "dsp/motion_detect.h"
#include "dsp/sad_search.h"

namespace {

// ../shared/data beside the repository, or $STEREOSIM_SHARED_DATA.
std::string shared_data(const std::string& relative) {
    if (const char* env = std::getenv("STEREOSIM_SHARED_DATA"))
        return std::string(env) + "/" + relative;
    std::string here = __FILE__;
    here = here.substr(0, here.find_last_of('/'));
    return here + "/../../shared/data/" + relative;
}

struct vga_frames {
    cv::Mat f[3];
    bool ok = false;
    vga_frames() {
        ok = true;
        for (int i = 0; i < 3; ++i) {
            char name[64];
            std::snprintf(name, sizeof name, "opencv_vtest/frames_gray/vtest_gray_%04d.png", i);
            const cv::Mat full = cv::imread(shared_data(name), cv::IMREAD_GRAYSCALE);
            if (full.cols < 640 || full.rows < 480) {
                ok = false;
                return;
            }
            // The crop keeps all three walkers (x 256-688, y 160-336).
            f[i] = full(cv::Rect(full.cols - 640, 0, 640, 480)).clone();
        }
    }
};

const vga_frames& frames() {
    static const vga_frames v;
    return v;
}

dsp::gray_cplane view(const cv::Mat& m) {
    return dsp::gray_cplane{m.ptr<uint8_t>(), m.cols, m.rows, static_cast<int>(m.step)};
}
dsp::gray_plane view_mut(cv::Mat& m) {
    return dsp::gray_plane{m.ptr<uint8_t>(), m.cols, m.rows, static_cast<int>(m.step)};
}

constexpr uint8_t threshold = 20;

void BM_three_frame_difference_dsp(benchmark::State& state) {
    const vga_frames& v = frames();
    if (!v.ok) return state.SkipWithError("opencv_vtest frames not found");
    cv::Mat mask(480, 640, CV_8U);
    for (auto _ : state) {
        dsp::three_frame_difference(view(v.f[0]), view(v.f[1]), view(v.f[2]), threshold,
                                    view_mut(mask));
        benchmark::DoNotOptimize(mask.data);
    }
    state.SetItemsProcessed(state.iterations() * 640 * 480);
}
BENCHMARK(BM_three_frame_difference_dsp);

void BM_three_frame_difference_opencv(benchmark::State& state) {
    const vga_frames& v = frames();
    if (!v.ok) return state.SkipWithError("opencv_vtest frames not found");
    cv::Mat d01(480, 640, CV_8U), d12(480, 640, CV_8U), b01(480, 640, CV_8U), b12(480, 640, CV_8U),
        mask(480, 640, CV_8U);
    for (auto _ : state) {
        cv::absdiff(v.f[0], v.f[1], d01);
        cv::absdiff(v.f[1], v.f[2], d12);
        cv::threshold(d01, b01, threshold, 255, cv::THRESH_BINARY);
        cv::threshold(d12, b12, threshold, 255, cv::THRESH_BINARY);
        cv::bitwise_and(b01, b12, mask);
        benchmark::DoNotOptimize(mask.data);
    }
    state.SetItemsProcessed(state.iterations() * 640 * 480);
}
BENCHMARK(BM_three_frame_difference_opencv);

cv::Mat motion_mask() {
    const vga_frames& v = frames();
    cv::Mat mask(480, 640, CV_8U);
    dsp::three_frame_difference(view(v.f[0]), view(v.f[1]), view(v.f[2]), threshold,
                                view_mut(mask));
    return mask;
}

void BM_erode_3x3_dsp(benchmark::State& state) {
    if (!frames().ok) return state.SkipWithError("opencv_vtest frames not found");
    const cv::Mat in = motion_mask();
    cv::Mat out(480, 640, CV_8U);
    for (auto _ : state) {
        dsp::erode_3x3(view(in), view_mut(out));
        benchmark::DoNotOptimize(out.data);
    }
    state.SetItemsProcessed(state.iterations() * 640 * 480);
}
BENCHMARK(BM_erode_3x3_dsp);

void BM_erode_3x3_opencv(benchmark::State& state) {
    if (!frames().ok) return state.SkipWithError("opencv_vtest frames not found");
    const cv::Mat in = motion_mask();
    cv::Mat out(480, 640, CV_8U);
    const cv::Mat kernel = cv::getStructuringElement(cv::MORPH_RECT, cv::Size(3, 3));
    for (auto _ : state) {
        cv::erode(in, out, kernel, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
        benchmark::DoNotOptimize(out.data);
    }
    state.SetItemsProcessed(state.iterations() * 640 * 480);
}
BENCHMARK(BM_erode_3x3_opencv);

// Masks for labelling: the raw three-frame mask (~100 small specks) and a
// frame's Canny edges (~700 thin curves, many label merges).
cv::Mat labelling_input(int which) {
    if (which == 0) return motion_mask();
    cv::Mat edges;
    cv::Canny(frames().f[1], edges, 60, 160);
    return edges;
}

void BM_connected_components_dsp(benchmark::State& state) {
    if (!frames().ok) return state.SkipWithError("opencv_vtest frames not found");
    const cv::Mat mask = labelling_input(static_cast<int>(state.range(0)));
    const int max_labels = 320 * 240;
    std::vector<int32_t> labels(2 * 640), parent(max_labels);
    std::vector<dsp::component> stats(max_labels), out(max_labels);
    int count = 0;
    for (auto _ : state) {
        count = dsp::connected_components(view(mask), labels.data(), parent.data(), stats.data(),
                                          max_labels, out.data(), max_labels);
        benchmark::DoNotOptimize(count);
    }
    state.counters["components"] = count;
    state.SetItemsProcessed(state.iterations() * 640 * 480);
}
BENCHMARK(BM_connected_components_dsp)->Arg(0)->Arg(1);

void BM_connected_components_opencv(benchmark::State& state) {
    if (!frames().ok) return state.SkipWithError("opencv_vtest frames not found");
    const cv::Mat mask = labelling_input(static_cast<int>(state.range(0)));
    cv::Mat labels, stats, centroids;
    int count = 0;
    for (auto _ : state) {
        count = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8, CV_32S) - 1;
        benchmark::DoNotOptimize(count);
    }
    state.counters["components"] = count;
    state.SetItemsProcessed(state.iterations() * 640 * 480);
}
BENCHMARK(BM_connected_components_opencv)->Arg(0)->Arg(1);

// A 32x32 pattern cut from frame 1 at a walker, searched +-24 px in frame 2.
constexpr int pattern_side = 32, radius = 24;
const cv::Rect pattern_box(650 - (768 - 640), 262, pattern_side,
                           pattern_side);  // walker 3

void BM_sad_search_32x32_r24_dsp(benchmark::State& state) {
    const vga_frames& v = frames();
    if (!v.ok) return state.SkipWithError("opencv_vtest frames not found");
    const cv::Mat pattern = v.f[1](pattern_box).clone();
    const dsp::box window{pattern_box.x - radius, pattern_box.y - radius, 2 * radius + 1,
                          2 * radius + 1};
    dsp::sad_result r;
    for (auto _ : state) {
        r = dsp::sad_search(view(v.f[2]), view(pattern), window);
        benchmark::DoNotOptimize(r);
    }
    state.counters["x"] = r.x;
    state.counters["y"] = r.y;
    state.SetItemsProcessed(state.iterations() * r.positions);  // positions per second
}
BENCHMARK(BM_sad_search_32x32_r24_dsp);

void BM_match_template_sqdiff_32x32_r24_opencv(benchmark::State& state) {
    const vga_frames& v = frames();
    if (!v.ok) return state.SkipWithError("opencv_vtest frames not found");
    const cv::Mat pattern = v.f[1](pattern_box).clone();
    const cv::Mat area = v.f[2](cv::Rect(pattern_box.x - radius, pattern_box.y - radius,
                                         2 * radius + pattern_side, 2 * radius + pattern_side));
    cv::Mat result;
    cv::Point best;
    for (auto _ : state) {
        cv::matchTemplate(area, pattern, result, cv::TM_SQDIFF);
        cv::minMaxLoc(result, nullptr, nullptr, &best, nullptr);
        benchmark::DoNotOptimize(best);
    }
    state.counters["x"] = pattern_box.x - radius + best.x;
    state.counters["y"] = pattern_box.y - radius + best.y;
    state.SetItemsProcessed(state.iterations() * (2 * radius + 1) * (2 * radius + 1));
}
BENCHMARK(BM_match_template_sqdiff_32x32_r24_opencv);

}  // namespace

BENCHMARK_MAIN();
