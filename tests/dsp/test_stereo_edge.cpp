// Edge stereo matching (dsp/stereo_edge.h): exact integer shifts of textured
// patterns, the documented scoring against a plain re-implementation, and the
// sub-pixel refinement on anti-aliased edges.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "dsp/sobel.h"
#include "dsp/stereo_edge.h"

namespace {

struct image {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> pixels;

    image(int w, int h) : width(w), height(h), pixels(static_cast<size_t>(w) * h) {}
    uint8_t& at(int x, int y) { return pixels[static_cast<size_t>(y) * width + x]; }
    uint8_t at(int x, int y) const { return pixels[static_cast<size_t>(y) * width + x]; }
    dsp::gray_cplane view() const { return {pixels.data(), width, height, width}; }
    dsp::gray_plane mutable_view() { return {pixels.data(), width, height, width}; }
};

image sobel(const image& in) {
    image out(in.width, in.height);
    dsp::sobel_3x3(in.view(), out.mutable_view());
    return out;
}

// A piecewise-constant scene: bands of rows, each a sequence of bars of
// random width (3..14 px) and grey level. value(x, y) at a real x.
struct bar_scene {
    struct bar {
        double end;  // bar covers [previous end, end)
        double level;
    };
    int band_height = 5;
    std::vector<std::vector<bar>> bands;

    bar_scene(int width, int height, unsigned seed) {
        std::mt19937 rng(seed);
        for (int b = 0; b * band_height < height; ++b) {
            std::vector<bar> bars;
            double x = -80.0;
            double level = 128.0;
            while (x < width + 80.0) {
                x += 3.0 + static_cast<double>(rng() % 12);
                double next = 20.0 + static_cast<double>(rng() % 216);
                if (std::fabs(next - level) < 40.0)
                    next = level > 128.0 ? level - 70.0 : level + 70.0;
                level = next;
                bars.push_back({x, level});
            }
            bands.push_back(bars);
        }
    }

    // Mean of the scene over the pixel [x0 - 0.5, x0 + 0.5) of row y (area sampling).
    double pixel(double x0, int y) const {
        const auto& bars = bands[static_cast<size_t>(y / band_height)];
        double sum = 0.0, start = -80.0;
        const double a = x0 - 0.5, b = x0 + 0.5;
        for (const auto& bar : bars) {
            const double lo = std::max(a, start), hi = std::min(b, bar.end);
            if (hi > lo) sum += (hi - lo) * bar.level;
            start = bar.end;
            if (start >= b) break;
        }
        return sum;
    }
};

uint8_t quantise(double v) {
    const long q = std::lround(v);
    return static_cast<uint8_t>(q < 0 ? 0 : (q > 255 ? 255 : q));
}

// Right = scene; left = scene moved `shift` px right: left(x) = right(x - shift).
void render_pair(const bar_scene& scene, double shift, image* right, image* left) {
    for (int y = 0; y < right->height; ++y)
        for (int x = 0; x < right->width; ++x) {
            right->at(x, y) = quantise(scene.pixel(x, y));
            left->at(x, y) = quantise(scene.pixel(x - shift, y));
        }
}

// A smooth texture (sum of sinusoids), the kind the SAD test uses.
double smooth_texture(double x, double y) {
    const double two_pi = 6.283185307179586;
    return 128.0 + 50.0 * std::sin(two_pi * x / 13.7) +
           35.0 * std::sin(two_pi * (x / 6.1 + y / 17.0)) +
           25.0 * std::cos(two_pi * (y / 9.7 - x / 21.3));
}

TEST(stereo_edge, finds_known_integer_shifts_of_textured_patterns_exactly) {
    const int width = 220, height = 60;
    int runs = 0;
    for (unsigned seed = 1; seed <= 6; ++seed) {
        const bar_scene scene(width, height, seed);
        for (int shift : {0, 3, 17, 31, 46}) {
            image right(width, height), left(width, height);
            render_pair(scene, shift, &right, &left);
            const image re = sobel(right), le = sobel(left);
            dsp::edge_params p;
            p.min_disparity = 0;
            p.max_disparity = 63;
            for (int px = 12; px + 32 + 63 < width; px += 37) {
                const auto r = dsp::stereo_match_edge(re.view(), le.view(), {px, 14, 32, 32}, p);
                ASSERT_TRUE(r.valid) << "seed " << seed << " shift " << shift;
                EXPECT_EQ(r.disparity, shift) << "seed " << seed << " x " << px;
                EXPECT_EQ(r.disparity_q8, shift * 256) << "seed " << seed << " x " << px;
                EXPECT_EQ(r.dy, 0);
                ++runs;
            }
        }
    }
    // The smooth texture too: its edges are broad ridges of the Sobel magnitude.
    for (int shift : {5, 22, 40}) {
        image right(width, height), left(width, height);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                right.at(x, y) = quantise(smooth_texture(x, y));
                left.at(x, y) = quantise(smooth_texture(x - shift, y));
            }
        const image re = sobel(right), le = sobel(left);
        dsp::edge_params p;
        p.min_disparity = 0;
        p.max_disparity = 63;
        p.edge_threshold = 90;
        for (int px = 12; px + 32 + 63 < width; px += 37) {
            const auto r = dsp::stereo_match_edge(re.view(), le.view(), {px, 14, 32, 32}, p);
            ASSERT_TRUE(r.valid);
            EXPECT_EQ(r.disparity, shift) << "smooth, x " << px;
            EXPECT_EQ(r.disparity_q8, shift * 256) << "smooth, x " << px;
            ++runs;
        }
    }
    std::printf("edge method: %d patterns at known integer shifts, all exact\n", runs);
}

// The documented scoring, written plainly: boundaries by run centroids,
// nearest partners by exhaustive search, capped distances summed both ways.
struct plain_result {
    bool valid = false;
    int d = 0;
    uint32_t score = 0;
    int32_t disparity_q8 = 0;
};

// Every run of the row (whole row scanned), kept when its centroid is in [keep0, keep1).
std::vector<int32_t> plain_boundaries(const image& mag, int y, int32_t keep0, int32_t keep1,
                                      int threshold) {
    std::vector<int32_t> out;
    int x = 0;
    while (x < mag.width) {
        if (mag.at(x, y) <= threshold) {
            ++x;
            continue;
        }
        uint64_t w = 0, m = 0;
        while (x < mag.width && mag.at(x, y) > threshold) {
            w += mag.at(x, y);
            m += static_cast<uint64_t>(mag.at(x, y)) * x;
            ++x;
        }
        const int32_t c = static_cast<int32_t>((m * 256 + w / 2) / w);
        if (c >= keep0 && c < keep1) out.push_back(c);
    }
    return out;
}

int32_t plain_nearest(const std::vector<int32_t>& list, int32_t q) {
    int32_t best = list.front() - q;
    for (int32_t v : list)
        if (std::abs(v - q) < std::abs(best)) best = v - q;
    return best;
}

plain_result plain_edge_match(const image& re, const image& le, dsp::box b,
                              const dsp::edge_params& p) {
    int d0 = std::max(p.min_disparity, -b.x);
    int d1 = std::min(p.max_disparity, le.width - b.right());
    const int cap = p.edge_cap_px * 256;
    const int32_t p0 = b.x * 256 - 128, p1 = b.right() * 256 - 128;
    std::vector<uint32_t> score(static_cast<size_t>(d1 - d0 + 1), 0);
    std::vector<int32_t> rsum(score.size(), 0);
    std::vector<int> rcount(score.size(), 0);
    const int spacing = p.line_spacing > 0 ? p.line_spacing : std::max(1, b.height / p.lines);
    int right_total = 0;
    for (int k = 0; k < p.lines; ++k) {
        const int y = b.center_y2() / 2 + (k - (p.lines - 1) / 2) * spacing;
        if (y < b.y || y >= b.bottom()) continue;
        const auto rb = plain_boundaries(re, y, p0, p1, p.edge_threshold);
        const auto lb =
            plain_boundaries(le, y, p0 + d0 * 256 - cap, p1 + d1 * 256 + cap, p.edge_threshold);
        right_total += static_cast<int>(rb.size());
        for (int d = d0; d <= d1; ++d) {
            const size_t s = static_cast<size_t>(d - d0);
            for (int32_t r : rb) {
                if (lb.empty()) {
                    score[s] += cap;
                    continue;
                }
                const int32_t off = plain_nearest(lb, r + d * 256);
                score[s] += std::min(std::abs(off), cap);
                if (std::abs(off) < 256) {
                    rsum[s] += off;
                    ++rcount[s];
                }
            }
            for (int32_t l : lb) {
                if (l < p0 + d * 256 || l >= p1 + d * 256) continue;
                score[s] +=
                    rb.empty() ? cap : std::min(std::abs(plain_nearest(rb, l - d * 256)), cap);
            }
        }
    }
    plain_result out;
    if (right_total < 2) return out;
    const size_t best =
        static_cast<size_t>(std::min_element(score.begin(), score.end()) - score.begin());
    if (rcount[best] == 0) return out;
    out.valid = true;
    out.d = d0 + static_cast<int>(best);
    out.score = score[best];
    const int32_t offset = std::clamp(rsum[best] / rcount[best], -128, 128);
    out.disparity_q8 = out.d * 256 + offset;
    return out;
}

TEST(stereo_edge, scoring_identical_to_a_plain_reimplementation) {
    std::mt19937 rng(99);
    int compared = 0, valid = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const int width = 40 + static_cast<int>(rng() % 120),
                  height = 20 + static_cast<int>(rng() % 20);
        // Random magnitudes: sparse spikes and runs over a low floor.
        image re(width, height), le(width, height);
        for (auto* img : {&re, &le})
            for (auto& v : img->pixels)
                v = static_cast<uint8_t>(rng() % 5 == 0 ? 40 + rng() % 216 : rng() % 50);
        dsp::box b;
        b.width = 5 + static_cast<int>(rng() % 30);
        b.height = 3 + static_cast<int>(rng() % 15);
        b.width = std::min(b.width, width);
        b.height = std::min(b.height, height);
        b.x = static_cast<int>(rng() % (width - b.width + 1));
        b.y = static_cast<int>(rng() % (height - b.height + 1));
        dsp::edge_params p;
        p.edge_threshold = static_cast<uint8_t>(60 + rng() % 80);
        p.min_disparity = -5 + static_cast<int>(rng() % 10);
        p.max_disparity = p.min_disparity + static_cast<int>(rng() % 60);
        p.lines = 1 + static_cast<int>(rng() % 9);
        p.line_spacing = static_cast<int>(rng() % 4);
        p.edge_cap_px = 1 + static_cast<int>(rng() % 4);
        if (std::max(p.min_disparity, -b.x) > std::min(p.max_disparity, width - b.right()))
            continue;

        const plain_result want = plain_edge_match(re, le, b, p);
        const auto got = dsp::stereo_match_edge(re.view(), le.view(), b, p);
        ++compared;
        ASSERT_EQ(got.valid, want.valid) << "trial " << trial;
        if (!want.valid) continue;
        ++valid;
        EXPECT_EQ(got.disparity, want.d) << "trial " << trial;
        EXPECT_EQ(got.sad, want.score) << "trial " << trial;
        EXPECT_EQ(got.disparity_q8, want.disparity_q8) << "trial " << trial;
    }
    std::printf("edge scoring: %d random cases compared, %d valid, all identical\n", compared,
                valid);
    EXPECT_GT(valid, 150);
}

TEST(stereo_edge, invalid_without_edges_on_the_pattern_rows) {
    image flat(100, 30), left(100, 30);
    for (auto& v : flat.pixels) v = 0;
    for (auto& v : left.pixels) v = 200;
    dsp::edge_params p;
    p.max_disparity = 40;
    EXPECT_FALSE(dsp::stereo_match_edge(flat.view(), left.view(), {10, 5, 20, 20}, p).valid);
    // One boundary only: no complete segment.
    flat.at(20, 15) = 255;
    p.lines = 1;
    EXPECT_FALSE(dsp::stereo_match_edge(flat.view(), left.view(), {10, 5, 20, 20}, p).valid);
    // Pattern outside the image.
    EXPECT_FALSE(dsp::stereo_match_edge(flat.view(), left.view(), {90, 5, 20, 20}, p).valid);
}

TEST(stereo_edge, subpixel_refinement_on_anti_aliased_edges) {
    const int width = 220, height = 60;
    double worst_integer_only = 0.0, worst_refined = 0.0;
    for (double frac : {0.0, 0.25, 0.5, 0.75}) {
        double worst = 0.0, sum = 0.0;
        int n = 0;
        for (unsigned seed = 11; seed <= 14; ++seed) {
            const bar_scene scene(width, height, seed);
            const double shift = 20.0 + frac;
            image right(width, height), left(width, height);
            render_pair(scene, shift, &right, &left);
            const image re = sobel(right), le = sobel(left);
            dsp::edge_params p;
            p.min_disparity = 0;
            p.max_disparity = 63;
            for (int px = 12; px + 32 + 63 < width; px += 37) {
                const auto r = dsp::stereo_match_edge(re.view(), le.view(), {px, 14, 32, 32}, p);
                ASSERT_TRUE(r.valid);
                const double error = r.disparity_q8 / 256.0 - shift;
                worst = std::fmax(worst, std::fabs(error));
                worst_integer_only = std::fmax(worst_integer_only, std::fabs(r.disparity - shift));
                sum += error;
                ++n;
            }
        }
        std::printf("edge sub-pixel: shift 20%+.2f px: worst |error| %.3f px, mean %+.3f px\n",
                    frac, worst, sum / n);
        worst_refined = std::fmax(worst_refined, worst);
    }
    std::printf("edge sub-pixel: worst refined %.3f px vs integer-only %.3f px\n", worst_refined,
                worst_integer_only);
    // Not a requirement of the edge method; a bound on what was measured (0.215 px worst, at
    // +0.5 px where the integer shift is ambiguous and inliers are cut at 1 px).
    EXPECT_LT(worst_refined, 0.25);
    EXPECT_LT(worst_refined, worst_integer_only);
}

}  // namespace
