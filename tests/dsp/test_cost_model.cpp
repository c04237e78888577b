// The C64x cost model (model/c64x/cost_model.h): the unit scheduler against a
// brute-force assignment, the section formula against hand arithmetic, the
// fit against TI IMGLIB's published C64x cycle formulas (docs/hardware-facts.md
// section 5), the check set it was not fitted on, memory costs and the
// cycles-to-time conversion.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "model/c64x/cost_model.h"

namespace {

using namespace c64x;

// One IMGLIB case: the model's profile and the published cycle count.
struct imglib_case {
    std::string name;
    kernel_profile profile;
    double published;
};

double relative_error(double model, double published) {
    return (model - published) / published;
}

// Fitting set: the sizes of docs/hardware-facts.md section 5's examples plus
// others around them.
std::vector<imglib_case> fitting_cases() {
    std::vector<imglib_case> cases;
    cases.push_back({"IMG_sad_8x8", imglib::sad_8x8(), 31.0});
    const std::pair<int, int> mad8_sizes[] = {{4, 4}, {8, 8}, {16, 16}, {64, 32}};
    for (auto [sx, sy] : mad8_sizes)
        cases.push_back({"IMG_mad_8x8 " + std::to_string(sx) + "x" + std::to_string(sy),
                         imglib::mad_8x8(sx, sy), 8.0 * sx * sy + 66});
    for (int n : {64, 256, 640, 1024})
        cases.push_back(
            {"IMG_pix_sat " + std::to_string(n), imglib::pix_sat(n), n / 16 * 3.0 + 13});
    for (int n : {64, 248, 640})
        cases.push_back({"IMG_corr_3x3 " + std::to_string(n), imglib::corr_3x3(n), 1.5 * n + 22});
    return cases;
}

std::vector<imglib_case> check_cases() {
    std::vector<imglib_case> cases;
    cases.push_back({"IMG_sad_16x16", imglib::sad_16x16(), 67.0});
    const std::pair<int, int> mad16_sizes[] = {{4, 4}, {8, 8}, {16, 16}, {32, 32}};
    for (auto [h, v] : mad16_sizes)
        cases.push_back({"IMG_mad_16x16 " + std::to_string(h) + "x" + std::to_string(v),
                         imglib::mad_16x16(h, v), 38.0 * h * v + 20});
    for (int n : {256, 512, 1072, 2048})
        cases.push_back(
            {"IMG_pix_expand " + std::to_string(n), imglib::pix_expand(n), 3.0 * n / 16 + 15});
    for (int cols : {128, 320, 720, 1280})
        cases.push_back({"IMG_perimeter " + std::to_string(cols), imglib::perimeter(cols),
                         10.0 * cols / 16 + 55});
    return cases;
}

// Brute force: try every split of the flexible ops over their classes.
uint32_t brute_force_ii(const op_mix& ops) {
    uint32_t best = UINT32_MAX;
    for (uint32_t ls_on_l = 0; ls_on_l <= ops.ls; ++ls_on_l) {
        for (uint32_t lsd_on_l = 0; lsd_on_l <= ops.lsd; ++lsd_on_l) {
            for (uint32_t lsd_on_s = 0; lsd_on_l + lsd_on_s <= ops.lsd; ++lsd_on_s) {
                const uint32_t l = ops.l + ls_on_l + lsd_on_l;
                const uint32_t s = ops.s + (ops.ls - ls_on_l) + lsd_on_s;
                const uint32_t d = ops.d + (ops.lsd - lsd_on_l - lsd_on_s);
                uint32_t worst = 0;
                for (uint32_t load : {l, s, ops.m, d}) worst = std::max(worst, (load + 1) / 2);
                best = std::min(best, worst);
            }
        }
    }
    return best;
}

TEST(C64xCostModel, FlexibleOpPlacementIsOptimal) {
    std::mt19937 rng(6416);
    std::uniform_int_distribution<uint32_t> fixed(0, 12), flexible(0, 20);
    int checked = 0;
    for (int i = 0; i < 3000; ++i) {
        const op_mix ops{fixed(rng), fixed(rng),    fixed(rng),
                         fixed(rng), flexible(rng), flexible(rng)};
        const unit_load load = place_ops(ops);
        // Every op placed, none on a unit that cannot run it.
        ASSERT_EQ(load.l + load.s + load.d, ops.l + ops.s + ops.d + ops.ls + ops.lsd);
        ASSERT_EQ(load.m, ops.m);
        ASSERT_GE(load.l, ops.l);
        ASSERT_GE(load.s, ops.s);
        ASSERT_GE(load.d, ops.d);
        ASSERT_LE(load.d - ops.d, ops.lsd);
        ASSERT_EQ(resource_ii(ops), brute_force_ii(ops)) << "mix " << i;
        ++checked;
    }
    std::printf("placement: %d random op mixes, water-filling II == brute-force II\n", checked);
}

TEST(C64xCostModel, SectionCyclesFollowTheFormula) {
    model_params params;
    params.call_overhead = 6;
    params.loop_overhead = 2;
    const cost_model model(params);

    // 3 .L + 2 .M + 5 flexible: L 3, then S and D take the flexible ops ->
    // II 2; N = 10 iterations, chain 11, entered 4 times.
    const loop_profile l = loop("l", op_mix{3, 0, 2, 0, 0, 5}, 10, 11, 4);
    EXPECT_EQ(model.section(l).ii, 2u);
    EXPECT_EQ(model.section(l).cycles, 4u * (10 * 2 + 11 - 1 + 2));

    // A recurrence longer than the resource bound sets II.
    const loop_profile r = loop("r", op_mix{1, 0, 0, 0, 0, 0}, 32, 1, 1, 3);
    EXPECT_EQ(model.section(r).resource_ii, 1u);
    EXPECT_EQ(model.section(r).ii, 3u);
    EXPECT_EQ(model.section(r).cycles, 32u * 3 + 0 + 2);

    // A block pays no loop overhead: II + chain - 1.
    const loop_profile b = block("b", op_mix{0, 0, 0, 16, 0, 0}, 5, 3);
    EXPECT_EQ(model.section(b).cycles, 3u * (8 + 5 - 1));

    // Kernel: calls x call overhead + sections.
    kernel_profile k("k");
    k.add(l);
    k.add(b);
    EXPECT_EQ(model.compute_cycles(k), 6u + 4 * 32 + 3 * 12);
    k.calls = 3;
    EXPECT_EQ(model.compute_cycles(k), 18u + 4 * 32 + 3 * 12);
}

TEST(C64xCostModel, SoftwareDivideCostsOneCyclePerQuotientBit) {
    const cost_model model;
    // call 6 + normalise (II 1 + 3 - 1) + bits x SUBC + loop overhead +
    // extract 1.
    for (uint32_t bits : {1u, 8u, 18u, 32u}) {
        const uint64_t expected = 6 + 3 + bits + fitted_loop_overhead + 1;
        EXPECT_EQ(model.cycles(software_divide(bits)), expected) << bits;
    }
    // 64-bit operands: 3 dependent ops per bit.
    EXPECT_EQ(model.cycles(software_divide(24, true)),
              6u + 4 + 24 * 3 + 2 + fitted_loop_overhead + 1);
    EXPECT_EQ(quotient_bits(1), 1u);
    EXPECT_EQ(quotient_bits(4), 2u);
    EXPECT_EQ(quotient_bits(5), 3u);
    EXPECT_EQ(quotient_bits(1025), 11u);
}

TEST(C64xCostModel, LoopOverheadIsTheLeastSquaresFit) {
    // The model is linear in loop_overhead: cycles = a + b * overhead.
    // Minimise the sum of squared relative errors over the fitting set.
    model_params p0, p1;
    p0.loop_overhead = 0;
    p1.loop_overhead = 1;
    const cost_model m0(p0), m1(p1);
    double num = 0, den = 0;
    for (const imglib_case& c : fitting_cases()) {
        const double a = static_cast<double>(m0.cycles(c.profile));
        const double b = static_cast<double>(m1.cycles(c.profile)) - a;
        num += b * (c.published - a) / (c.published * c.published);
        den += b * b / (c.published * c.published);
    }
    const double optimum = num / den;
    std::printf(
        "fit: loop_overhead least-squares optimum %.3f cycles, used %u "
        "(call overhead %u, "
        "documented by IMGLIB)\n",
        optimum, fitted_loop_overhead, model_params{}.call_overhead);
    RecordProperty("loop_overhead_optimum", std::to_string(optimum));
    EXPECT_EQ(static_cast<uint32_t>(std::lround(optimum)), fitted_loop_overhead);
    EXPECT_EQ(model_params{}.loop_overhead, fitted_loop_overhead);
}

TEST(C64xCostModel, ReproducesTheFittingFormulasWithin5Percent) {
    const cost_model model;
    std::printf("%-22s %10s %10s %8s   (fitting set, tolerance 5%%)\n", "kernel", "model",
                "published", "error");
    for (const imglib_case& c : fitting_cases()) {
        const double cycles = static_cast<double>(model.cycles(c.profile));
        const double error = relative_error(cycles, c.published);
        std::printf("%-22s %10.0f %10.1f %+7.2f%%\n", c.name.c_str(), cycles, c.published,
                    100 * error);
        EXPECT_LE(std::fabs(error), 0.05) << c.name;
    }
}

TEST(C64xCostModel, SlopesComeFromTheInitiationInterval) {
    // The per-position / per-pixel slope is exactly the published one: it is
    // the II the unit scheduler derives, not a fitted number.
    const cost_model model;
    auto slope = [&](const std::function<kernel_profile(int)>& make, int a, int b) {
        return (static_cast<double>(model.cycles(make(b))) -
                static_cast<double>(model.cycles(make(a)))) /
               (b - a);
    };
    // mad_8x8: 8 cycles per position (sx varies, sy = 16; quotient bits of
    // the final division constant between the two sizes).
    EXPECT_DOUBLE_EQ(slope([](int sx) { return imglib::mad_8x8(sx, 16); }, 40, 60) / 16, 8.0);
    EXPECT_DOUBLE_EQ(slope(imglib::pix_sat, 320, 1280), 3.0 / 16);
    EXPECT_DOUBLE_EQ(slope(imglib::corr_3x3, 100, 1000), 1.5);
    EXPECT_DOUBLE_EQ(slope(imglib::pix_expand, 320, 1280), 3.0 / 16);  // check set
    EXPECT_DOUBLE_EQ(slope(imglib::perimeter, 320, 1280), 10.0 / 16);  // check set
    // mad_16x16 (check set): 38 published, the model gives 41 = (8 x 8 +
    // fill 13 + loop overhead 2 + pair compare 3) / 2.
    const double mad16 = slope([](int h) { return imglib::mad_16x16(h, 32); }, 20, 30) / 32;
    std::printf("per-position slope IMG_mad_16x16: model %.2f, published 38\n", mad16);
    EXPECT_NEAR(mad16, 38.0, 38.0 * 0.15);
}

TEST(C64xCostModel, CheckSetWithin15PercentUnfitted) {
    const cost_model model;
    std::printf("%-22s %10s %10s %8s   (check set, not fitted, tolerance 15%%)\n", "kernel",
                "model", "published", "error");
    for (const imglib_case& c : check_cases()) {
        const double cycles = static_cast<double>(model.cycles(c.profile));
        const double error = relative_error(cycles, c.published);
        std::printf("%-22s %10.0f %10.1f %+7.2f%%\n", c.name.c_str(), cycles, c.published,
                    100 * error);
        EXPECT_LE(std::fabs(error), 0.15) << c.name;
    }
}

TEST(C64xCostModel, CyclesToTimeAtTheDskClocks) {
    // 600 MHz: 5/3 ns per cycle; 720 MHz: 25/18 ns; 1 GHz: 1 ns.
    EXPECT_EQ(cycles_to_ps(600, dsk_v1_cpu_hz), 1'000'000u);
    EXPECT_EQ(cycles_to_ps(3, dsk_v1_cpu_hz), 5'000u);
    EXPECT_EQ(cycles_to_ps(1, dsk_v1_cpu_hz), 1'667u);  // 1666.67 rounded
    EXPECT_EQ(cycles_to_ps(720, dsk_v2_cpu_hz), 1'000'000u);
    EXPECT_EQ(cycles_to_ps(1000, dsk_v3_cpu_hz), 1'000'000u);
    // Ticks of 1/18 ns: 30, 25 and 18 per cycle (docs/design-brief.md "Time").
    EXPECT_EQ(cycles_to_ticks(1, dsk_v1_cpu_hz), 30u);
    EXPECT_EQ(cycles_to_ticks(1, dsk_v2_cpu_hz), 25u);
    EXPECT_EQ(cycles_to_ticks(1, dsk_v3_cpu_hz), 18u);
    // The paper's 1.756 ms of SAD tracking = 1,053,600 cycles at 600 MHz.
    EXPECT_EQ(cycles_to_ps(1'053'600, dsk_v1_cpu_hz), 1'756'000'000u);
    // Same cycles, 600 vs 1000 MHz: 5/3 the time; no overflow at 3 x 10^12
    // cycles (x 10^12 ps does not fit 64 bits).
    const uint64_t big = 3'000'000'000'000ull;
    EXPECT_EQ(cycles_to_ps(big, dsk_v1_cpu_hz), big * 5000 / 3);
    EXPECT_EQ(cycles_to_ps(big, dsk_v3_cpu_hz), big * 1000);
    EXPECT_EQ(cycles_to_ticks(big, dsk_v1_cpu_hz), big * 30);
}

TEST(C64xCostModel, MemoryCostsByPlacement) {
    const cost_model model;  // DSK v1: 600 MHz CPU, 100 MHz EMIF
    const uint64_t frame = 640 * 480;
    const memory_traffic in_l1d{frame, frame, placement::l1d};
    const memory_traffic in_l2{frame, frame, placement::l2};
    const memory_traffic in_sdram{frame, frame, placement::sdram};
    EXPECT_EQ(model.memory_cycles(in_l1d), 0u);
    // L2: one L1D miss per 64-byte line read (4800 lines x 6 cycles).
    EXPECT_EQ(model.memory_cycles(in_l2), frame / 64 * 6);
    // SDRAM: 2400 line reads + 2400 line writes (fetch + write-back), each
    // 7 + 128/8 = 23 EMIF cycles of 10 ns = 138 CPU cycles (the EMIF engine's
    // line with its row closed, docs/c6416.md), plus the L1D misses.
    const uint64_t bursts = frame / 128 + 2 * (frame / 128);
    EXPECT_EQ(model.memory_cycles(in_sdram), frame / 64 * 6 + bursts * 23 * 6);
    EXPECT_EQ(model.emif_busy_ps(in_sdram), bursts * 23 * 10'000);
    EXPECT_EQ(model.emif_busy_ps(in_l2), 0u);
    std::printf(
        "VGA frame read + written: L2 %llu stall cycles, SDRAM %llu "
        "(EMIF busy %.3f ms)\n",
        static_cast<unsigned long long>(model.memory_cycles(in_l2)),
        static_cast<unsigned long long>(model.memory_cycles(in_sdram)),
        model.emif_busy_ps(in_sdram) * 1e-9);

    // The same bursts stall a 1 GHz CPU for more cycles (same EMIF time).
    model_params v3;
    v3.cpu_hz = dsk_v3_cpu_hz;
    v3.emif_hz = dsk_v1_emif_hz;
    const cost_model fast(v3);
    EXPECT_EQ(fast.memory_cycles(in_sdram), frame / 64 * 6 + bursts * 23 * 10);
}

TEST(C64xCostModel, CompiledCFactorScalesComputeOnly) {
    model_params compiled;
    compiled.compiled_c_factor_q8 = 512;  // compiled C twice as slow
    const cost_model hand, slow(compiled);
    kernel_profile k = imglib::corr_3x3(248);
    k.add(memory_traffic{640 * 480, 0, placement::l2});
    EXPECT_EQ(slow.compute_cycles(k), 2 * hand.compute_cycles(k));
    EXPECT_EQ(slow.memory_cycles(k), hand.memory_cycles(k));
}

TEST(C64xCostModel, ProfileCapacityIsEnforced) {
    kernel_profile k("full");
    for (int i = 0; i < kernel_profile::max_sections; ++i)
        EXPECT_TRUE(k.add(loop("x", op_mix{1, 0, 0, 0, 0, 0}, 1, 1)));
    EXPECT_FALSE(k.add(loop("x", op_mix{1, 0, 0, 0, 0, 0}, 1, 1)));
    EXPECT_EQ(k.section_count, kernel_profile::max_sections);
}

}  // namespace
