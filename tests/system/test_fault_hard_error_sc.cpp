// No hang (docs/fault-contract.md, rule 4): with a dead right sensor the card
// fails every check, gives up after RETRY_LIMIT restarts (HARD_ERROR), the
// firmware re-arms it hard_error_rearms times and then reports hard_error,
// drops OE for good and stops, within (rearms + 1) x (RETRY_LIMIT + 1) + 2
// periods. One simulation (dead R, RETRY_LIMIT 2, one re-arm, 10 periods).
#include <gtest/gtest.h>

#include "tests/system/system_run.h"

namespace {

using platform::event_kind;

const system_test::system_run& dead_sensor_run() {
    static const system_test::system_run run = [] {
        platform::platform_config config;
        config.frames = 10;
        config.card_retry_limit = 2;
        platform::set_firmware_key(&config, "hard_error_rearms", 1);
        config.right_faults.push_back(sensor::fault::never_start());
        return system_test::simulate(config);
    }();
    return run;
}

TEST(FaultHardError, FirmwareGivesUpOnADeadSensorWithinTheBound) {
    const system_test::system_run& r = dead_sensor_run();
    const std::vector<platform::fw_event>& events = r.top->probe().fw_events();
    simtime::ticks hard_error = -1, stopped = -1;
    int hard_errors = 0, rearms = 0, sync_errors_before = 0;
    for (const platform::fw_event& e : events) {
        if (e.event.kind == STEREOSIM_EV_HARD_ERROR) {
            ++hard_errors;
            hard_error = e.tick;
            EXPECT_EQ(e.event.value, static_cast<uint32_t>(dsp::rearm_cause::hard_error));
            EXPECT_EQ(e.event.detail, 2u);  // the second consecutive card hard error
        }
        if (e.event.kind == STEREOSIM_EV_CARD_REARMED) {
            ++rearms;
            EXPECT_EQ(e.event.value, static_cast<uint32_t>(dsp::rearm_cause::hard_error));
        }
        if (e.event.kind == STEREOSIM_EV_SYNC_ERROR && hard_error < 0) ++sync_errors_before;
        if (e.event.kind == STEREOSIM_EV_STOPPED) stopped = e.tick;
    }
    ASSERT_EQ(hard_errors, 1);
    // Two card hard errors of RETRY_LIMIT + 1 = 3 failed checks each, one re-arm between.
    EXPECT_EQ(sync_errors_before, 6);
    EXPECT_EQ(rearms, 1);
    EXPECT_EQ(r.top->cycle_island().irq_rises(1).size(), 6u);
    // Bound: (1 + 1) x (2 + 1) + 2 = 8 periods.
    const simtime::ticks bound = 8 * r.top->config().period;
    EXPECT_LE(hard_error, bound);
    // It stopped: the frame loop returned right after, OE never rose again,
    // nothing was ever used.
    EXPECT_GE(stopped, hard_error);
    EXPECT_LT(stopped - hard_error, r.top->config().period / 100);
    int oe_rises_after = 0, oe_rises = 0;
    for (const platform::timeline_event& e : r.top->events().events()) {
        if (e.kind != event_kind::oe || e.a != 1) continue;
        ++oe_rises;
        oe_rises_after += e.tick > hard_error;
    }
    EXPECT_EQ(oe_rises_after, 0);
    // OE: boot, 2 card restarts, the firmware's re-arm, 2 card restarts.
    EXPECT_EQ(oe_rises, 6);
    EXPECT_EQ(r.score.pairs.size(), 0u);
    EXPECT_EQ(r.score.used_out_of_step, 0);
    std::printf(
        "dead R, RETRY_LIMIT 2: hard_error at %.3f ms (bound %.1f ms), %d sync errors, "
        "%d re-arm, %d OE rises\n",
        system_test::ticks_to_ms(hard_error), system_test::ticks_to_ms(bound), sync_errors_before,
        rearms, oe_rises);
}

// A firmware whose loop returned does no more work: the budget counts the
// CPU idle from then on, not busy to the end of the run.
TEST(FaultHardError, TheCpuIsIdleAfterTheGiveUp) {
    const system_test::system_run& r = dead_sensor_run();
    simtime::ticks stopped = -1;
    for (const platform::fw_event& e : r.top->probe().fw_events())
        if (e.event.kind == STEREOSIM_EV_STOPPED) stopped = e.tick;
    ASSERT_GE(stopped, 0);
    EXPECT_EQ(r.top->probe().halted_at(), stopped);
    int after = 0;
    for (const platform::period_budget& p : r.budget.periods) {
        if (p.begin <= stopped) continue;
        ++after;
        EXPECT_EQ(p.cpu_busy_ms, 0.0) << "period " << p.index;
    }
    EXPECT_GE(after, 1);
}

}  // namespace
