// Stereo matching cost on the host: the firmware's SAD matcher for a 32x32
// pattern over 64 disparities x 3 rows, beside OpenCV's matchTemplate
// (TM_SQDIFF, the nearest OpenCV has to SAD) over the same 95x34 strip, and
// the edge method on the same pattern (with and without its Sobel band).
#include <benchmark/benchmark.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "dsp/sobel.h"
#include "dsp/stereo_edge.h"
#include "dsp/stereo_sad.h"

namespace {

constexpr int image_width = 640, image_height = 480;
constexpr int pattern_size = 32, disparities = 64, row_slack = 1, true_shift = 23;
const cv::Rect pattern_rect(240, 200, pattern_size, pattern_size);

// A textured VGA pair: blurred noise, the left image moved true_shift px right.
struct stereo_pair {
    cv::Mat right, left, right_edges, left_edges;
    stereo_pair() {
        cv::Mat noise(image_height, image_width + true_shift, CV_8U);
        cv::randu(noise, 0, 256);
        cv::GaussianBlur(noise, noise, cv::Size(0, 0), 1.2);
        right = noise(cv::Rect(true_shift, 0, image_width, image_height)).clone();
        left = noise(cv::Rect(0, 0, image_width, image_height)).clone();
        right_edges = sobel(right);
        left_edges = sobel(left);
    }
    static cv::Mat sobel(const cv::Mat& gray) {
        cv::Mat out(gray.size(), CV_8U);
        dsp::sobel_3x3(view(gray),
                       {out.ptr<uint8_t>(), out.cols, out.rows, static_cast<int>(out.step1())});
        return out;
    }
    static dsp::gray_cplane view(const cv::Mat& m) {
        return {m.ptr<uint8_t>(), m.cols, m.rows, static_cast<int>(m.step1())};
    }
};

const stereo_pair& pair() {
    static const stereo_pair p;
    return p;
}

dsp::box pattern_box() {
    return {pattern_rect.x, pattern_rect.y, pattern_rect.width, pattern_rect.height};
}

void BM_stereo_match_sad(benchmark::State& state) {
    const auto& p = pair();
    dsp::stereo_params params;
    params.min_disparity = 0;
    params.max_disparity = disparities - 1;
    params.row_slack = row_slack;
    dsp::stereo_result r;
    for (auto _ : state) {
        r = dsp::stereo_match_sad(stereo_pair::view(p.right), stereo_pair::view(p.left),
                                  pattern_box(), params);
        benchmark::DoNotOptimize(r);
    }
    state.counters["positions"] = r.positions;
    state.counters["disparity"] = r.disparity_q8 / 256.0;
    state.counters["abs_diffs/s"] =
        benchmark::Counter(static_cast<double>(r.positions) * pattern_size * pattern_size,
                           benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_stereo_match_sad);

// OpenCV equivalent: the template over the strip the firmware searches,
// result 64 x 3, then its minimum.
void BM_opencv_match_template_sqdiff(benchmark::State& state) {
    const auto& p = pair();
    const cv::Mat templ = p.right(pattern_rect);
    const cv::Mat strip =
        p.left(cv::Rect(pattern_rect.x, pattern_rect.y - row_slack, pattern_size + disparities - 1,
                        pattern_size + 2 * row_slack));
    cv::Mat result;
    cv::Point best;
    for (auto _ : state) {
        cv::matchTemplate(strip, templ, result, cv::TM_SQDIFF);
        cv::minMaxLoc(result, nullptr, nullptr, &best, nullptr);
        benchmark::DoNotOptimize(best);
    }
    state.counters["positions"] = result.rows * result.cols;
    state.counters["disparity"] = best.x;
}
BENCHMARK(BM_opencv_match_template_sqdiff);

void BM_stereo_match_edge(benchmark::State& state) {
    const auto& p = pair();
    dsp::edge_params params;
    params.min_disparity = 0;
    params.max_disparity = disparities - 1;
    dsp::stereo_result r;
    for (auto _ : state) {
        r = dsp::stereo_match_edge(stereo_pair::view(p.right_edges),
                                   stereo_pair::view(p.left_edges), pattern_box(), params);
        benchmark::DoNotOptimize(r);
    }
    state.counters["disparity"] = r.disparity_q8 / 256.0;
    state.counters["valid"] = r.valid;
}
BENCHMARK(BM_stereo_match_edge);

// The edge method as the firmware runs it: Sobel on the pattern's rows of
// both images (full width), then the matching.
void BM_stereo_match_edge_with_sobel_band(benchmark::State& state) {
    const auto& p = pair();
    cv::Mat right_edges(p.right.size(), CV_8U), left_edges(p.left.size(), CV_8U);
    dsp::gray_plane re{right_edges.ptr<uint8_t>(), right_edges.cols, right_edges.rows,
                       static_cast<int>(right_edges.step1())};
    dsp::gray_plane le{left_edges.ptr<uint8_t>(), left_edges.cols, left_edges.rows,
                       static_cast<int>(left_edges.step1())};
    dsp::edge_params params;
    params.min_disparity = 0;
    params.max_disparity = disparities - 1;
    dsp::stereo_result r;
    for (auto _ : state) {
        dsp::sobel_3x3_rows(stereo_pair::view(p.right), pattern_rect.y,
                            pattern_rect.y + pattern_size, re);
        dsp::sobel_3x3_rows(stereo_pair::view(p.left), pattern_rect.y,
                            pattern_rect.y + pattern_size, le);
        r = dsp::stereo_match_edge(re.as_const(), le.as_const(), pattern_box(), params);
        benchmark::DoNotOptimize(r);
    }
    state.counters["disparity"] = r.disparity_q8 / 256.0;
}
BENCHMARK(BM_stereo_match_edge_with_sobel_band);

}  // namespace

BENCHMARK_MAIN();
