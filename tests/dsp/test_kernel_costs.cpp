// The firmware kernels' modelled cycles (dsp/kernel_costs.h): hand
// arithmetic of a documented profile, scaling with positions, pattern area
// and pixel count, the SUBABS4 throughput bound, memory placement, clocks,
// and a printout against the paper's DSK timings (not asserted).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "dsp/kernel_costs.h"
#include "model/c64x/cost_model.h"
#include "model/scene/sequence.h"
#include "tb/platform/scoring/frame_record.h"
#include "tests/support/host/counting_hal.h"
#include "tests/support/host/stereo_runner.h"

namespace {

using namespace dsp;
using namespace dsp::cost;

double ratio(uint64_t a, uint64_t b) {
    return static_cast<double>(a) / static_cast<double>(b);
}

double ms_at(uint64_t cycles, uint64_t cpu_hz) {
    return static_cast<double>(c64x::cycles_to_ps(cycles, cpu_hz)) * 1e-9;
}

class KernelCosts : public ::testing::Test {};

TEST_F(KernelCosts, SadSearchMatchesHandArithmetic) {
    // 40x40 pattern: k = 5 doublewords per row; per row d 10, l 10, m 10,
    // s 1, lsd 11 -> L and D full at II 5, S takes 9 of 11 flexible ops ->
    // II 6. Chain: load 5 + SUBABS4 1 + DOTPU4 4 + 4 ADDs + 1 = 15.
    // Per position: 40 x 6 + 14 + loop overhead 2 + compare block 2 = 258.
    // Per call: call overhead 6 + store block 2.
    for (int positions : {1, 195, 2401}) {
        EXPECT_EQ(sad_search_cycles(40, 40, positions), 8u + 258u * positions) << positions;
    }
    EXPECT_EQ(sad_search_cycles(40, 40, 0), 8u);
    EXPECT_EQ(sad_search_cycles(-5, 40, -3),
              8u);  // nonsense sizes cost only the call
}

TEST_F(KernelCosts, SadSearchIsLinearInPositions) {
    const std::pair<int, int> sizes[] = {{8, 8}, {40, 40}, {96, 96}, {33, 17}};
    for (auto [w, h] : sizes) {
        const uint64_t c0 = sad_search_cycles(w, h, 0);
        const uint64_t c1 = sad_search_cycles(w, h, 1000);
        const uint64_t c2 = sad_search_cycles(w, h, 2000);
        EXPECT_EQ(c2 - c1, c1 - c0) << w << "x" << h;
        EXPECT_NEAR(ratio(c2, c1), 2.0, 2.0 * 0.001) << w << "x" << h;
    }
}

TEST_F(KernelCosts, SadSearchScalesWithPatternArea) {
    const int positions = 1000;
    // Height: each row is one more iteration of the row loop.
    const double by_height =
        ratio(sad_search_cycles(40, 800, positions), sad_search_cycles(40, 400, positions));
    // Width: k doublewords cost II = k + 1 per row for large k ((6k + 2) ops
    // on 6 L/S/D units).
    const double by_width =
        ratio(sad_search_cycles(2048, 64, positions), sad_search_cycles(1024, 64, positions));
    const double by_area =
        ratio(sad_search_cycles(2048, 800, positions), sad_search_cycles(1024, 400, positions));
    std::printf("sad_search ratios for doubling: height %.4f, width %.4f, both %.4f\n", by_height,
                by_width, by_area);
    EXPECT_NEAR(by_height, 2.0, 2.0 * 0.02);
    EXPECT_NEAR(by_width, 2.0, 2.0 * 0.02);
    EXPECT_NEAR(by_area, 4.0, 4.0 * 0.02);
    // Width is exactly linear in doublewords once the row II is L/S/D bound
    // (72..88 px: 9..11 doublewords, same ADD-tree depth).
    const uint64_t w72 = sad_search_cycles(72, 40, positions);
    const uint64_t w80 = sad_search_cycles(80, 40, positions);
    const uint64_t w88 = sad_search_cycles(88, 40, positions);
    EXPECT_EQ(w88 - w80, w80 - w72);
    EXPECT_EQ(w80 - w72, 40u * positions);  // one cycle per row per doubleword
}

TEST_F(KernelCosts, SadSearchNeverBeatsTheSubabs4Bound) {
    // Two .L units, one SUBABS4 (4 abs-differences) each per cycle: at most
    // 8 abs-differences per cycle, the rate of IMG_mad_8x8's inner loop
    // (docs/hardware-facts.md section 1).
    const std::pair<int, int> sizes[] = {{8, 8}, {16, 16}, {40, 40}, {96, 96}, {1024, 64}};
    for (auto [w, h] : sizes) {
        const uint64_t positions = 500;
        const double diffs = static_cast<double>(w) * h * positions;
        const uint64_t cycles = sad_search_cycles(w, h, static_cast<int>(positions));
        std::printf("sad_search %4dx%-3d: %.2f abs-differences per cycle\n", w, h, diffs / cycles);
        EXPECT_LE(diffs / cycles, 8.0);
    }
    // ...and at 40x40 it stays within 1.4x of it (the loads share .D, the
    // accumulating ADDs the remaining L/S/D slots).
    EXPECT_GE(40.0 * 40 * 500 / sad_search_cycles(40, 40, 500), 8.0 / 1.4);
}

TEST_F(KernelCosts, FramePassesScaleWithPixelCount) {
    struct pass {
        const char* name;
        uint64_t (*cycles)(int, int);
    };
    const pass passes[] = {
        {"demosaic_gray", [](int w, int h) { return demosaic_gray_cycles(w, h); }},
        {"brightness", [](int w, int h) { return brightness_cycles(w, h); }},
        {"three_frame_difference",
         [](int w, int h) { return three_frame_difference_cycles(w, h); }},
        {"morphology x1", [](int w, int h) { return morphology_cycles(w, h, 1); }},
        {"sobel", [](int w, int h) { return sobel_cycles(w, h); }},
    };
    for (const pass& p : passes) {
        const uint64_t qvga = p.cycles(320, 240), vga = p.cycles(640, 480),
                       big = p.cycles(1280, 960);
        std::printf("%-24s QVGA %9llu  VGA %9llu  1280x960 %9llu  ratios %.3f %.3f\n", p.name,
                    static_cast<unsigned long long>(qvga), static_cast<unsigned long long>(vga),
                    static_cast<unsigned long long>(big), ratio(vga, qvga), ratio(big, vga));
        // 4x the pixels, 4x the cycles up to the per-row and per-call
        // overheads (loop fill, border columns: a few % at QVGA).
        EXPECT_NEAR(ratio(vga, qvga), 4.0, 4.0 * 0.05) << p.name;
        EXPECT_NEAR(ratio(big, vga), 4.0, 4.0 * 0.03) << p.name;
        // Every row costs the same: exactly linear in the height.
        const uint64_t h0 = p.cycles(640, 240), h1 = p.cycles(640, 480), h2 = p.cycles(640, 720);
        EXPECT_EQ(h2 - h1, h1 - h0) << p.name;
    }
}

TEST_F(KernelCosts, ThroughputMatchesTheDocumentedProfiles) {
    // Compute cycles per pixel at a large size against the II / pixels per
    // iteration the profiles document in kernel_costs.cpp.
    const int w = 2048, h = 2048;
    const double pixels = static_cast<double>(w) * h;
    const c64x::cost_model& m = default_model();
    const struct {
        const char* name;
        c64x::kernel_profile profile;
        double documented;
    } cases[] = {
        {"demosaic_gray (II 9 / 4 px)", demosaic_gray_profile(w, h), 9.0 / 4},
        {"brightness (II 5 / 8 px)", brightness_profile(w, h), 5.0 / 8},
        {"three_frame_difference (II 3 / 8 px)", three_frame_difference_profile(w, h), 3.0 / 8},
        {"morphology (II 4 / 8 px)", morphology_profile(w, h, 1), 4.0 / 8},
        {"sobel (II 8 / 4 px)", sobel_profile(w, h), 8.0 / 4},
    };
    for (const auto& c : cases) {
        const double per_pixel = m.compute_cycles(c.profile) / pixels;
        std::printf("%-40s %.4f cycles/pixel (documented %.4f)\n", c.name, per_pixel, c.documented);
        EXPECT_GE(per_pixel, c.documented) << c.name;
        EXPECT_LE(per_pixel, c.documented * 1.03) << c.name;
    }
}

TEST_F(KernelCosts, SdramPlacementCostsMoreThanL2) {
    const int w = 640, h = 480;
    const uint64_t frame = static_cast<uint64_t>(w) * h;
    // One burst per 128-byte line read, two per line written (fetch +
    // write-back); 7 + 16 EMIF cycles each at 100 MHz = 138 CPU cycles at 600
    // MHz.
    auto sdram_extra = [&](uint64_t read, uint64_t written) {
        return (read / 128 + 2 * (written / 128)) * 23 * 6;
    };
    struct {
        const char* name;
        uint64_t l2, sdram, expected_extra;
    } cases[] = {
        {"demosaic_gray", demosaic_gray_cycles(w, h, memory::l2),
         demosaic_gray_cycles(w, h, memory::sdram), sdram_extra(frame, frame)},
        {"brightness", brightness_cycles(w, h, memory::l2), brightness_cycles(w, h, memory::sdram),
         sdram_extra(frame, frame)},
        {"three_frame_difference", three_frame_difference_cycles(w, h, memory::l2),
         three_frame_difference_cycles(w, h, memory::sdram), sdram_extra(3 * frame, frame)},
        // The packed forms read 2 frames + the 1/8-frame mask and write the mask.
        {"three_frame_diff_packed", three_frame_difference_packed_cycles(w, h, memory::l2),
         three_frame_difference_packed_cycles(w, h, memory::sdram),
         sdram_extra(2 * frame + frame / 8, frame / 8)},
        {"difference_packed", difference_packed_cycles(w, h, memory::l2),
         difference_packed_cycles(w, h, memory::sdram), sdram_extra(2 * frame, frame / 8)},
        // The firmware's plan: raw from SDRAM, gray into L2: only the raw read
        // is an SDRAM stream.
        {"demosaic raw SDRAM->L2", demosaic_gray_cycles(w, h, memory::l2),
         demosaic_gray_cycles(w, h, memory::l2, memory::sdram), sdram_extra(frame, 0)},
        // Dif(key, t): the key region alone from SDRAM, f(t) from L2, the
        // bits consumed row by row (no mask written anywhere).
        {"key difference SDRAM+L2", difference_packed_cycles(w, h, memory::l2),
         default_model().cycles(key_difference_profile(w, h)), sdram_extra(frame, 0)},
    };
    for (const auto& c : cases) {
        std::printf("%-24s VGA in L2 %9llu cycles, in SDRAM %9llu (x%.2f)\n", c.name,
                    static_cast<unsigned long long>(c.l2), static_cast<unsigned long long>(c.sdram),
                    ratio(c.sdram, c.l2));
        EXPECT_GT(c.sdram, c.l2) << c.name;
        EXPECT_EQ(c.sdram - c.l2, c.expected_extra) << c.name;
    }
}

TEST_F(KernelCosts, ClocksTurnCyclesIntoTime) {
    // Pure compute: the same cycles take 5/3 as long at 600 as at 1000 MHz.
    const uint64_t track = sad_search_cycles(40, 40, 49 * 49);
    EXPECT_NEAR(ms_at(track, c64x::dsk_v1_cpu_hz) / ms_at(track, c64x::dsk_v3_cpu_hz), 5.0 / 3,
                1e-9);
    // SDRAM stalls are EMIF time: with the DSK v3 clocks (1 GHz CPU, 125 MHz
    // EMIF) the compute cycles stay, the stall cycles change with the ratio.
    const uint64_t v1_l2 = demosaic_gray_cycles(640, 480, memory::l2);
    const uint64_t v1_sdram = demosaic_gray_cycles(640, 480, memory::sdram);
    c64x::model_params v3;
    v3.cpu_hz = c64x::dsk_v3_cpu_hz;
    v3.emif_hz = c64x::dsk_v3_emif_hz;
    const c64x::cost_model v3_model(v3);
    EXPECT_EQ(v3_model.cycles(demosaic_gray_profile(640, 480, memory::l2)), v1_l2);
    const uint64_t v3_sdram = v3_model.cycles(demosaic_gray_profile(640, 480, memory::sdram));
    // 7200 bursts x 23 EMIF cycles x 8 ns = 1.325 ms of stall at 125 MHz:
    // 1,324,800 CPU cycles at 1 GHz vs 993,600 at 600 MHz / 100 MHz (1.656 ms).
    EXPECT_EQ(v3_sdram - v1_l2, 7200u * 23 * 8);
    EXPECT_EQ(v1_sdram - v1_l2, 7200u * 23 * 6);
    std::printf("demosaic VGA from SDRAM: v1 %.3f ms, v3 %.3f ms\n",
                ms_at(v1_sdram, c64x::dsk_v1_cpu_hz), ms_at(v3_sdram, c64x::dsk_v3_cpu_hz));
}

// The firmware prices its kernels through its HAL (hal::kernel_cycles): a
// HAL with a compiled-C model charges the firmware's stages accordingly.
TEST_F(KernelCosts, CompiledCFactorReachesTheFirmwareFigures) {
    const uint64_t hand = sad_search_cycles(40, 40, 2401);
    c64x::model_params compiled;
    compiled.compiled_c_factor_q8 = 3 * 256;
    host::counting_hal hal{c64x::cost_model(compiled)};
    EXPECT_NEAR(ratio(hal.kernel_cycles(sad_search_profile(40, 40, 2401)), hand), 3.0, 1e-6);

    const scene::scenario scenario = scene::default_scenario();
    const controller_config config = host::controller_config_for(scenario.scene.rig);
    host::stereo_runner by_hand(scenario, config);
    host::stereo_runner by_compiler(scenario, config, c64x::cost_model(compiled));
    for (int n = 0; n < 12; ++n) {
        by_hand.step(n);
        by_compiler.step(n);
    }
    // Compute cycles triple, the L2 / SDRAM stalls stay: every stage that ran
    // costs more, at most three times as much.
    for (int i = 0; i < stage_count; ++i) {
        const uint64_t hand_cycles = by_hand.hal().total_cycles(static_cast<stage>(i));
        const uint64_t compiled_cycles = by_compiler.hal().total_cycles(static_cast<stage>(i));
        std::printf("%-12s hand %10llu compiled %10llu\n", stage_name(static_cast<stage>(i)),
                    static_cast<unsigned long long>(hand_cycles),
                    static_cast<unsigned long long>(compiled_cycles));
        if (hand_cycles == 0) continue;
        EXPECT_GT(compiled_cycles, hand_cycles) << stage_name(static_cast<stage>(i));
        EXPECT_LE(ratio(compiled_cycles, hand_cycles), 3.0) << stage_name(static_cast<stage>(i));
    }
    EXPECT_GT(by_hand.hal().total_cycles(stage::track), 0u);
}

TEST_F(KernelCosts, DataDependentKernelsGrowWithTheirWork) {
    // Connected components: more foreground, more runs.
    const uint64_t none = connected_components_cycles(640, 480, 0);
    const uint64_t ball = connected_components_cycles(640, 480, 1257);  // r = 20 px disc
    const uint64_t lots = connected_components_cycles(640, 480, 20000);
    EXPECT_LT(none, ball);
    EXPECT_LT(ball, lots);
    // Edge matching: exactly linear in lines (every term is per line), and
    // linear in shifts beyond the fixed part.
    const uint64_t l1 = edge_match_cycles(640, 1, 64), l2 = edge_match_cycles(640, 2, 64),
                   l3 = edge_match_cycles(640, 3, 64);
    EXPECT_EQ(l3 - l2, l2 - l1);
    const uint64_t s50 = edge_match_cycles(640, 7, 50), s100 = edge_match_cycles(640, 7, 100),
                   s150 = edge_match_cycles(640, 7, 150);
    EXPECT_EQ(s150 - s100, s100 - s50);
    EXPECT_EQ(edge_match_cycles(640, 7, 100, 50), edge_match_cycles(640, 7, 50, 0));
    // Pattern copy: one doubleword per cycle.
    EXPECT_EQ(pattern_copy_cycles(80, 80) - pattern_copy_cycles(40, 40), 800u - 200u);
    // Constant-time kernels are small and nonzero.
    EXPECT_GT(subpixel_cycles(), 20u);
    EXPECT_LT(subpixel_cycles(), 100u);
    EXPECT_GT(triangulate_cycles(), 200u);
    EXPECT_LT(triangulate_cycles(), 1000u);
    // The window fit: 33 velocities, each a pass over the extents (one
    // loop-carried ALU op per extent) and a choice of 3 dependent ALU ops.
    std::printf("window fit: %llu cycles (3 extents), %llu (4)\n",
                static_cast<unsigned long long>(window_fit_cycles(3)),
                static_cast<unsigned long long>(window_fit_cycles(4)));
    EXPECT_GT(window_fit_cycles(4), window_fit_cycles(3));
    EXPECT_GT(window_fit_cycles(4), 33u * (4 + 3));
    EXPECT_LT(window_fit_cycles(4), 3000u);
    // The window's step: the call only below three extents (window_step2
    // reads none), then a sort of 2 (n - 1) steps, a part of the fit's work.
    std::printf("window step: %llu cycles (3 extents), %llu (4)\n",
                static_cast<unsigned long long>(window_step_cycles(3)),
                static_cast<unsigned long long>(window_step_cycles(4)));
    EXPECT_LT(window_step_cycles(2), 20u);
    EXPECT_GT(window_step_cycles(3), window_step_cycles(2) + 2 * 4 + 4);
    EXPECT_GT(window_step_cycles(4), window_step_cycles(3));
    EXPECT_LT(window_step_cycles(4), window_fit_cycles(4));
    // Sizes at the depth: each one a software divide of an 11-bit quotient
    // (a SUBC per bit, dependent) and its rounding; nothing without one.
    std::printf("size at depth: %llu cycles (12 divides)\n",
                static_cast<unsigned long long>(size_at_depth_cycles(12)));
    EXPECT_LT(size_at_depth_cycles(0), 10u);
    EXPECT_GT(size_at_depth_cycles(12), 12u * 11);
    EXPECT_LT(size_at_depth_cycles(12), 2000u);
}

TEST_F(KernelCosts, PrintsFiguresAgainstThePaper) {
    // Not asserted: the paper's figures were measured on compiled C, these
    // are hand-scheduled kernels (see compiled_c_factor_q8).
    const c64x::cost_model& m = default_model();
    const uint64_t track =
        sad_search_cycles(40, 40, 49 * 49) + pattern_copy_cycles(40, 40);  // +-24 window
    const uint64_t stereo =
        sad_search_cycles(40, 40, 65 * 3) + subpixel_cycles();  // 0..64 x 3 rows
    const uint64_t edge = 2 * sobel_cycles(640, 40) + edge_match_cycles(640, 7, 121, 13);
    const uint64_t xyz = triangulate_cycles();
    std::printf("model %s (loop overhead %u, call overhead %u)\n", m.id(), m.params().loop_overhead,
                m.params().call_overhead);
    std::printf("%-44s %10s %9s %9s %9s %8s\n", "", "cycles", "600MHz", "720MHz", "1GHz", "paper");
    auto row = [](const char* name, uint64_t cycles, const char* paper) {
        std::printf("%-44s %10llu %7.3fms %7.3fms %7.3fms %8s\n", name,
                    static_cast<unsigned long long>(cycles), ms_at(cycles, c64x::dsk_v1_cpu_hz),
                    ms_at(cycles, c64x::dsk_v2_cpu_hz), ms_at(cycles, c64x::dsk_v3_cpu_hz), paper);
    };
    row("track: SAD 40x40, +-24 (2401 pos) + copy", track, "1.756ms");
    row("stereo SAD: 40x40, 65 disp x 3 rows", stereo, "4.71ms");
    row("stereo edge: 2 Sobel 640x40 + match 7 lines", edge, "<5ms");
    row("xyz", xyz, "(in edge)");
    // The SAD stereo figure of the paper corresponds to this many positions
    // of a 40x40 pattern at 600 MHz:
    const double per_position =
        static_cast<double>(sad_search_cycles(40, 40, 1000) - sad_search_cycles(40, 40, 0)) / 1000;
    std::printf(
        "paper's 4.71 ms = %.0f positions of a 40x40 pattern at 600 MHz "
        "(%.0f cycles each)\n",
        4.71e-3 * 600e6 / per_position, per_position);

    // One VGA pair as the controller charges it (memory plan: raw in SDRAM,
    // gray frames and the packed mask in L2).
    const int w = 640, h = 480;
    const uint64_t preprocess =
        2 * (demosaic_gray_cycles(w, h, memory::l2, memory::sdram) + brightness_cycles(w, h));
    const uint64_t detect = three_frame_difference_packed_cycles(w, h) +
                            morphology_cycles(w, h, 6) + connected_components_cycles(w, h, 2000);
    row("VGA pair: preprocess (2 x demosaic raw SDRAM + gain L2)", preprocess, "");
    row("VGA: detect (3-frame diff packed L2, 6 morph, CC)", detect, "");
    row("VGA pair, tracking: all stages", preprocess + track + stereo + edge + xyz, "24.5ms");
    std::printf(
        "(720 MHz / 1 GHz columns rescale the cycles; the SDRAM stalls in them were "
        "counted for 600 MHz / 100 MHz EMIF: another model for other clocks)\n");
    // The two SAD figures differ only by their positions (258 cycles each).
    EXPECT_EQ(sad_search_cycles(40, 40, 49 * 49) - sad_search_cycles(40, 40, 65 * 3),
              258u * (49 * 49 - 65 * 3));
}

}  // namespace
