// Pre-processing kernels at VGA (640x480) against their OpenCV equivalents,
// side by side in one program so the ratios are like for like. OpenCV runs
// single-threaded (cv::setNumThreads(1)): the firmware is one C64x core.
// Host figures only: C64x cycles come from dsp/kernel_costs.h.
#include <benchmark/benchmark.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "dsp/bayer_demosaic.h"
#include "dsp/gray_convert.h"
#include "dsp/preprocess.h"
#include "dsp/sobel.h"

namespace {

constexpr int vga_width = 640;
constexpr int vga_height = 480;

// Smooth random texture (noise blurred), so values look like an image, not white noise.
cv::Mat vga_image(int type, unsigned seed) {
    cv::Mat m(vga_height, vga_width, type);
    cv::RNG(seed).fill(m, cv::RNG::UNIFORM, 0, 256);
    cv::GaussianBlur(m, m, cv::Size(5, 5), 1.5);
    return m;
}

dsp::gray_cplane as_cplane(const cv::Mat& m) {
    return dsp::gray_cplane{m.ptr<uint8_t>(), m.cols, m.rows, static_cast<int>(m.step1())};
}
dsp::gray_plane as_plane(cv::Mat& m) {
    return dsp::gray_plane{m.ptr<uint8_t>(), m.cols, m.rows, static_cast<int>(m.step1())};
}
dsp::rgb_plane as_rgb_plane(cv::Mat& m) {
    return dsp::rgb_plane{reinterpret_cast<dsp::rgb8*>(m.data), m.cols, m.rows,
                          static_cast<int>(m.step / 3)};
}

void set_pixels(benchmark::State& state) {
    state.SetItemsProcessed(state.iterations() * vga_width * vga_height);
}

struct single_thread_opencv {
    single_thread_opencv() { cv::setNumThreads(1); }
} const opencv_single_thread;

void BM_demosaic_ours(benchmark::State& state) {
    const cv::Mat raw = vga_image(CV_8UC1, 1);
    cv::Mat rgb(raw.size(), CV_8UC3);
    for (auto _ : state) {
        dsp::demosaic_bilinear(as_cplane(raw), dsp::cfa_order::rggb, as_rgb_plane(rgb));
        benchmark::DoNotOptimize(rgb.data);
    }
    set_pixels(state);
}
BENCHMARK(BM_demosaic_ours);

void BM_demosaic_opencv(benchmark::State& state) {
    const cv::Mat raw = vga_image(CV_8UC1, 1);
    cv::Mat rgb(raw.size(), CV_8UC3);
    for (auto _ : state) {
        cv::demosaicing(raw, rgb, cv::COLOR_BayerBG2RGB);
        benchmark::DoNotOptimize(rgb.data);
    }
    set_pixels(state);
}
BENCHMARK(BM_demosaic_opencv);

void BM_gray_ours(benchmark::State& state) {
    cv::Mat rgb = vga_image(CV_8UC3, 2);
    cv::Mat gray(rgb.size(), CV_8UC1);
    for (auto _ : state) {
        dsp::rgb_to_gray(as_rgb_plane(rgb).as_const(), as_plane(gray));
        benchmark::DoNotOptimize(gray.data);
    }
    set_pixels(state);
}
BENCHMARK(BM_gray_ours);

void BM_gray_opencv(benchmark::State& state) {
    const cv::Mat rgb = vga_image(CV_8UC3, 2);
    cv::Mat gray(rgb.size(), CV_8UC1);
    for (auto _ : state) {
        cv::cvtColor(rgb, gray, cv::COLOR_RGB2GRAY);
        benchmark::DoNotOptimize(gray.data);
    }
    set_pixels(state);
}
BENCHMARK(BM_gray_opencv);

void BM_preprocess_fused_ours(benchmark::State& state) {
    const cv::Mat raw = vga_image(CV_8UC1, 3);
    cv::Mat gray(raw.size(), CV_8UC1);
    std::vector<dsp::rgb8> line(vga_width);
    const dsp::brightness_params params;  // gain != 256 here, so the LUT pass runs
    for (auto _ : state) {
        const dsp::preprocess_result r = dsp::preprocess_raw_to_gray(
            as_cplane(raw), dsp::cfa_order::rggb, params, line.data(), as_plane(gray));
        benchmark::DoNotOptimize(r);
        benchmark::DoNotOptimize(gray.data);
    }
    set_pixels(state);
}
BENCHMARK(BM_preprocess_fused_ours);

// The same chain with OpenCV calls: full RGB frame, gray, mean, LUT.
void BM_preprocess_chain_opencv(benchmark::State& state) {
    const cv::Mat raw = vga_image(CV_8UC1, 3);
    cv::Mat rgb(raw.size(), CV_8UC3);
    cv::Mat gray(raw.size(), CV_8UC1);
    cv::Mat lut(1, 256, CV_8UC1);
    for (auto _ : state) {
        cv::demosaicing(raw, rgb, cv::COLOR_BayerBG2RGB);
        cv::cvtColor(rgb, gray, cv::COLOR_RGB2GRAY);
        const double gain = 110.0 / cv::mean(gray)[0];
        for (int p = 0; p < 256; ++p) lut.data[p] = cv::saturate_cast<uint8_t>(p * gain);
        cv::LUT(gray, lut, gray);
        benchmark::DoNotOptimize(gray.data);
    }
    set_pixels(state);
}
BENCHMARK(BM_preprocess_chain_opencv);

void BM_sobel_ours(benchmark::State& state) {
    const cv::Mat gray = vga_image(CV_8UC1, 4);
    cv::Mat edges(gray.size(), CV_8UC1);
    for (auto _ : state) {
        dsp::sobel_3x3(as_cplane(gray), as_plane(edges));
        benchmark::DoNotOptimize(edges.data);
    }
    set_pixels(state);
}
BENCHMARK(BM_sobel_ours);

// cv::Sobel dx and dy (CV_16S), |dx| + |dy|, saturated to 8 bits.
void BM_sobel_opencv(benchmark::State& state) {
    const cv::Mat gray = vga_image(CV_8UC1, 4);
    cv::Mat dx, dy, abs_dx, abs_dy, sum16, edges;
    for (auto _ : state) {
        cv::Sobel(gray, dx, CV_16S, 1, 0, 3);
        cv::Sobel(gray, dy, CV_16S, 0, 1, 3);
        abs_dx = cv::abs(dx);
        abs_dy = cv::abs(dy);
        cv::add(abs_dx, abs_dy, sum16);
        sum16.convertTo(edges, CV_8U);
        benchmark::DoNotOptimize(edges.data);
    }
    set_pixels(state);
}
BENCHMARK(BM_sobel_opencv);

}  // namespace

BENCHMARK_MAIN();
