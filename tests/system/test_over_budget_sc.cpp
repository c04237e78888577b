// A configuration that cannot fit: a large SAD tracking window (radius 96,
// 193 x 193 positions instead of 49 x 49) on a C6416 at a low clock
// (300 MHz), overlapped mode. Each tracked pair then needs more CPU time
// than the 24.5 ms period, mostly in stage track; the closed-form estimate
// (host harness cycles at 300 MHz) says over budget and the simulated check
// must report it, naming the CPU and the stage track.
#include <gtest/gtest.h>

#include <cstdio>

#include "tests/system/system_run.h"

namespace {

TEST(over_budget, large_search_window_at_low_cpu_clock_is_reported_naming_the_stage) {
    platform::platform_config config;
    config.dsk = c6416::dsk_custom(300000000, 100000000);
    config.dsk.version = 1;  // the DSK v1 EMIF settings
    platform::set_firmware_key(&config, "search_radius", 96);
    const system_test::system_run r = system_test::simulate(config);

    const platform::capture_figures cf = system_test::closed_form_capture(*r.top);
    const double processing_ms = system_test::host_max_processing_ms(config, 12);
    const platform::traffic_figures tf = system_test::closed_form_traffic(*r.top);
    const platform::mode_estimate ovl =
        platform::estimate_overlapped(cf.total_ms(), tf.ms(), processing_ms, r.budget.period_ms);
    EXPECT_FALSE(ovl.fits);
    EXPECT_FALSE(r.budget.fits);
    EXPECT_EQ(r.budget.fits, ovl.fits);

    // Every pair that was tracked (not the detection pair) and overran names
    // the CPU and stage track.
    int tracked_overruns = 0;
    for (const platform::overrun& o : r.budget.overruns) {
        if (o.what != platform::resource::cpu || o.pair == 0) continue;
        const platform::pair_check& p = r.score.pairs[o.pair - 1];
        if (p.record.out.detected) continue;
        EXPECT_EQ(o.stage_name, "track") << o.describe();
        EXPECT_GT(o.value_ms, o.limit_ms);
        ++tracked_overruns;
        std::printf("%s\n", o.describe().c_str());
    }
    EXPECT_GE(tracked_overruns, 2);
    const int track = static_cast<int>(dsp::stage::track);
    EXPECT_GT(r.budget.stage_ms_max[track],
              r.budget.stage_ms_max[static_cast<int>(dsp::stage::preprocess)]);
    // The bus is not the problem.
    EXPECT_EQ(r.budget.first(platform::resource::emif), nullptr);
    EXPECT_EQ(r.budget.first(platform::resource::fifo), nullptr);
    std::printf(
        "over budget: closed form needs %.3f ms (host processing max) of %.1f; simulated "
        "processing max %.3f ms, track max %.3f ms, %zu overruns, %d drops\n",
        ovl.need_ms, r.budget.period_ms, r.budget.max_processing_ms, r.budget.stage_ms_max[track],
        r.budget.overruns.size(), r.budget.drops);
}

}  // namespace
