// Sequential mode at the default settings (docs/design-brief.md: "with the paper's
// figures only overlapped mode can fit, and the tool should show exactly
// that"): the pair is read (~22.5 ms), then processed (~10-16 ms), so the
// next pair is ready while the CPU still works on this one and is dropped.
// The closed-form estimate says so (capture + processing > 24.5 ms) and the
// simulated budget check must say so too, naming the resource and stage.
#include <gtest/gtest.h>

#include <cstdio>

#include "tests/system/system_run.h"

namespace {

TEST(sequential_mode, over_budget_as_the_closed_form_says_naming_the_stage) {
    platform::platform_config config;
    platform::set_firmware_key(&config, "mode", 0);  // sequential
    const system_test::system_run r = system_test::simulate(config);

    const platform::capture_figures cf = system_test::closed_form_capture(*r.top);
    const double processing_ms = system_test::host_max_processing_ms(config, 12);
    const platform::traffic_figures tf = system_test::closed_form_traffic(*r.top);
    const platform::mode_estimate seq =
        platform::estimate_sequential(cf.total_ms(), tf.ms(), processing_ms, r.budget.period_ms);
    EXPECT_FALSE(seq.fits);
    EXPECT_EQ(r.budget.fits, seq.fits);
    ASSERT_GE(r.budget.judged_periods, 8);

    // Every other pair is dropped: it becomes ready ~2 ms into the
    // processing of the one before, whose first stage is preprocess.
    EXPECT_GE(r.budget.drops, 3);
    const platform::overrun* drop = r.budget.first(platform::resource::pair_buffers);
    ASSERT_NE(drop, nullptr);
    EXPECT_EQ(drop->stage_name, "preprocess");
    int processed = 0, dropped = 0;
    for (const platform::pair_check& p : r.score.pairs) {
        processed += p.processed;
        dropped += !p.captured && p.pair < r.score.pairs.size();
    }
    EXPECT_GE(dropped, 3);
    EXPECT_GE(processed, 4);

    // Neither the bus nor the CPU alone is over: the serial path is.
    EXPECT_EQ(r.budget.first(platform::resource::cpu), nullptr);
    EXPECT_EQ(r.budget.first(platform::resource::emif), nullptr);
    EXPECT_EQ(r.budget.first(platform::resource::fifo), nullptr);
    EXPECT_LT(r.budget.max_processing_ms, r.budget.period_ms);
    EXPECT_LT(r.budget.max_capture_ms, r.budget.period_ms);

    // The drops are the firmware's overrun policy, not data errors.
    EXPECT_EQ(r.score.used_before_verdict, 0);
    EXPECT_EQ(r.score.integrity_equal, r.score.integrity_checked);
    std::printf(
        "sequential: closed form needs %.3f ms (capture %.3f + processing %.3f) of %.1f ms; "
        "simulated: %d drops, %d processed, first overrun: %s\n",
        seq.need_ms, cf.total_ms(), processing_ms, r.budget.period_ms, r.budget.drops, processed,
        drop->describe().c_str());
}

}  // namespace
