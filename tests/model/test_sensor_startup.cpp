// Start-up after OE (docs/design-brief.md): a fixed latency, plus with probability 0.25
// an extra delay of 1 pclk .. 2 lines, seeded. Measured from the pins over
// thousands of starts; two sensors on one master clock are in step exactly
// when their draws agree, and the timing truth says so.
#include <gtest/gtest.h>

#include <cstdio>

#include "model/sensor/sensor_core.h"
#include "sensor_test_util.h"

using namespace sensor;
using namespace sensor_test;

TEST(SensorStartup, DefaultProfileExtraDelayDistribution) {
    const sensor_profile p = default_profile();
    still_source source(p.active_cols, p.active_rows, {90, 120, 60});
    sensor_config cfg;
    cfg.seed = 2024;
    sensor_core core(p, scene::camera_id::left, source, cfg);
    const int starts = 4000;
    int with_extra = 0, below_100 = 0, above_1500 = 0, min_extra = 1 << 30, max_extra = 0;
    double extra_sum = 0;
    for (int s = 0; s < starts; ++s) {
        // OE low for 3 clocks, then high until VSYNC rises.
        for (int i = 0; i < 3; ++i) core.step(false);
        const uint64_t oe_cycle = core.cycle();
        uint64_t vsync_cycle = 0;
        for (;;) {
            const uint64_t n = core.cycle();
            if (core.step(true).vsync()) {
                vsync_cycle = n;
                break;
            }
            ASSERT_LT(n - oe_cycle, 3300u);
        }
        const int extra = static_cast<int>(vsync_cycle - oe_cycle) - 1600;
        ASSERT_GE(extra, 0);
        ASSERT_LE(extra, 1600);
        ASSERT_EQ(core.starts().back().extra_pclks, extra);
        if (extra > 0) {
            ++with_extra;
            extra_sum += extra;
            min_extra = std::min(min_extra, extra);
            max_extra = std::max(max_extra, extra);
            below_100 += extra < 100;
            above_1500 += extra > 1500;
        }
    }
    const double fraction = static_cast<double>(with_extra) / starts;
    const double mean = extra_sum / with_extra;
    std::printf(
        "%d starts: %.4f with an extra delay (expect 0.25); extra 1..1600: min %d max %d "
        "mean %.1f (expect 800.5); <100: %d, >1500: %d\n",
        starts, fraction, min_extra, max_extra, mean, below_100, above_1500);
    EXPECT_NEAR(fraction, 0.25, 0.03);  // binomial sd 0.0068: 4.4 sd
    EXPECT_NEAR(mean, 800.5, 45.0);     // uniform sd 462 / sqrt(~1000): 3 sd
    EXPECT_GT(below_100, 20);           // ~62 expected: both ends are reached
    EXPECT_GT(above_1500, 20);
}

TEST(SensorStartup, TwoSensorsAreInStepExactlyWhenTheirDrawsAgree) {
    sensor_profile q = small_profile();
    q.extra_delay_probability = 0.25;
    pattern_source sl(q.active_cols, q.active_rows), sr(q.active_cols, q.active_rows);
    sensor_config cl, cr;
    cl.seed = 11;
    cr.seed = 12;
    sensor_core left(q, scene::camera_id::left, sl, cl);
    sensor_core right(q, scene::camera_id::right, sr, cr);
    const int restarts = 400;
    const uint64_t on_clocks = 7 + 80 + 2 * 1200 + 10;  // latency + max extra + 2 frames
    int in_step_pins = 0, in_step_truth = 0, agree = 0;
    for (int s = 0; s < restarts; ++s) {
        for (int i = 0; i < 20; ++i) {
            left.step(false);
            right.step(false);
        }
        const size_t first_l = left.truth().size(), first_r = right.truth().size();
        std::vector<uint64_t> vs_l, vs_r;  // VSYNC rises
        bool prev_l = false, prev_r = false;
        for (uint64_t i = 0; i < on_clocks; ++i) {
            const uint64_t n = left.cycle();
            const pin_word a = left.step(true), b = right.step(true);
            if (a.vsync() && !prev_l) vs_l.push_back(n);
            if (b.vsync() && !prev_r) vs_r.push_back(n);
            prev_l = a.vsync();
            prev_r = b.vsync();
        }
        ASSERT_GE(vs_l.size(), 2u);
        ASSERT_GE(vs_r.size(), 2u);
        const bool pins_in_step = vs_l[0] == vs_r[0];
        const bool draws_agree =
            left.starts().back().extra_pclks == right.starts().back().extra_pclks;
        // The first complete frame of this start in each sensor.
        const frame_truth& tl = left.truth()[first_l];
        const frame_truth& tr = right.truth()[first_r];
        const bool truth_in_step = pair_in_step(tl, tr, q.pclk_period());
        EXPECT_EQ(pins_in_step, draws_agree) << "start " << s;
        EXPECT_EQ(truth_in_step, pins_in_step) << "start " << s;
        EXPECT_EQ(tl.start_cycle, vs_l[0]);
        if (!pins_in_step) {
            const int64_t d = static_cast<int64_t>(vs_l[0]) - static_cast<int64_t>(vs_r[0]);
            EXPECT_EQ(d, left.starts().back().extra_pclks - right.starts().back().extra_pclks);
            EXPECT_EQ(tl.vsync_tick - tr.vsync_tick, d * 1050)
                << "truth times differ by whole clocks";
        }
        in_step_pins += pins_in_step;
        in_step_truth += truth_in_step;
        agree += draws_agree;
    }
    std::printf(
        "%d restarts of two sensors: %d in step (pins), %d (truth), %d equal draws; "
        "expected fraction 0.5625 + P(equal extras)\n",
        restarts, in_step_pins, in_step_truth, agree);
    EXPECT_NEAR(in_step_pins / static_cast<double>(restarts), 0.5625, 0.08);
}

TEST(SensorStartup, SameSeedSameStartsDifferentSeedDifferentStarts) {
    const sensor_profile p = default_profile();
    const auto draws = [&](uint64_t seed) {
        pattern_source source(p.active_cols, p.active_rows);
        sensor_config cfg;
        cfg.seed = seed;
        sensor_core core(p, scene::camera_id::left, source, cfg);
        std::vector<int> out;
        for (int s = 0; s < 64; ++s) {
            core.step(false);
            core.step(true);
            out.push_back(core.starts().back().extra_pclks);
        }
        return out;
    };
    EXPECT_EQ(draws(5), draws(5));
    EXPECT_NE(draws(5), draws(6));
}
