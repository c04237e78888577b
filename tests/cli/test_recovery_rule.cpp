// Rule 11 of the fault contract (docs/fault-contract.md, "No unexplained
// recovery") on hand-made event sequences: what the card's pins, its
// STATUS.STATE and the DSP's CTRL writes would show. Each case passes on a
// sequence a correct card and firmware make and fails on the one a broken
// design makes (the mutants of docs/mutants.md show the rule on real runs).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "tb/app/faults/recovery_rule.h"

namespace {

using faults::card_state;
using faults::recovery_inputs;
using faults::recovery_observation;
using simtime::ticks;

constexpr ticks ms(double v) {
    return static_cast<ticks>(v * 1e6 * simtime::ticks_per_ns);
}
constexpr ticks frame = ms(24.5);

// A card that boots at 0.1 ms; the sensors' VSYNC rises 1 ms after each OE
// rise and every frame after; RETRY_LIMIT 2; no watchdog unless set.
struct run_builder {
    recovery_inputs in;
    run_builder() {
        in.retry_limit = 2;
        in.card_frame = frame;
        in.end = ms(600);
        in.service = ms(49);
        enable(ms(0.1), 1);
        start(ms(0.1));
    }
    void enable(ticks t, uint32_t v) { in.enable_writes.push_back({t, v}); }
    void state(ticks t, card_state s) { in.card_states.push_back({t, static_cast<uint32_t>(s)}); }
    // An OE rise (WAIT_VSYNC) with its sensors' VSYNC rises for `frames` frames.
    void start(ticks t, int frames = 30) {
        in.oe_rises.push_back(t);
        state(t, card_state::wait_vsync);
        for (int k = 0; k < frames; ++k) in.vsync_rises.push_back(t + ms(1) + k * frame);
    }
    // The start's check k (1-based) fails: SYNC_ERROR, then a restart (OE
    // low for 47 us) or HARD_ERROR. Returns the failure's tick.
    ticks fail(ticks oe_rise, int k, card_state action) {
        const ticks check = oe_rise + ms(1) + k * frame;
        state(check, action);
        in.sync_errors.push_back(check + ms(0.0003));
        if (action == card_state::oe_low) start(check + ms(0.047));
        return check;
    }
    recovery_observation judge() {
        std::sort(in.vsync_rises.begin(), in.vsync_rises.end());
        std::sort(in.oe_rises.begin(), in.oe_rises.end());
        std::sort(in.card_states.begin(), in.card_states.end(),
                  [](const faults::tick_value& a, const faults::tick_value& b) {
                      return a.tick < b.tick;
                  });
        return faults::judge_recovery(in);
    }
};

std::string first(const recovery_observation& r) {
    return r.unexplained.empty() ? "" : r.unexplained.front();
}

TEST(RecoveryRule, AHealthyRunHasNoRecoveryAction) {
    run_builder b;
    for (int k = 1; k < 20; ++k) b.in.frame_readies.push_back(ms(1.1) + k * frame);
    const recovery_observation r = b.judge();
    EXPECT_EQ(r.broken(), 0) << first(r);
    EXPECT_EQ(r.firmware_rearms, 0);
    EXPECT_EQ(r.card_restarts, 0);
}

// Three failed checks in a row with RETRY_LIMIT 2: two restarts, then
// HARD_ERROR, which the firmware re-arms.
TEST(RecoveryRule, HardErrorAfterRetryLimitPlusOneFailedChecksInARow) {
    run_builder b;
    ticks t = b.fail(ms(0.1), 1, card_state::oe_low);
    t = b.fail(t + ms(0.047), 1, card_state::oe_low);
    t = b.fail(t + ms(0.047), 1, card_state::hard_error);
    b.enable(t + ms(0.01), 0);
    b.state(t + ms(0.011), card_state::idle);
    b.enable(t + ms(0.02), 1);
    b.start(t + ms(0.021));
    const recovery_observation r = b.judge();
    EXPECT_EQ(r.broken(), 0) << first(r);
    EXPECT_EQ(r.longest_streak, 3);
    EXPECT_EQ(r.card_restarts, 2);
    EXPECT_EQ(r.card_hard_errors, 1);
    EXPECT_EQ(r.firmware_rearms, 1);
}

// A passing check between failures starts the count again: a card that
// gives up on the third failure of three separated by good frames breaks
// the rule (a count of every failure, not of failures in a row).
TEST(RecoveryRule, HardErrorOnFailuresSeparatedByGoodFramesIsEarly) {
    run_builder b;
    ticks t = b.fail(ms(0.1), 3, card_state::oe_low);  // checks 1 and 2 passed
    t = b.fail(t + ms(0.047), 4, card_state::oe_low);
    t = b.fail(t + ms(0.047), 2, card_state::hard_error);
    b.enable(t + ms(0.01), 0);
    b.enable(t + ms(0.02), 1);
    b.start(t + ms(0.021));
    const recovery_observation r = b.judge();
    EXPECT_EQ(r.hard_errors_early, 1) << first(r);
    EXPECT_EQ(r.longest_streak, 1);
    EXPECT_NE(first(r).find("after 1 failed check(s) in a row"), std::string::npos) << first(r);
}

TEST(RecoveryRule, ARestartWhereHardErrorWasDueIsMissed) {
    run_builder b;
    ticks t = ms(0.1);
    for (int i = 0; i < 4; ++i) t = b.fail(t, 1, card_state::oe_low) + ms(0.047);
    const recovery_observation r = b.judge();
    EXPECT_EQ(r.hard_errors_missed, 2) << first(r);
    EXPECT_EQ(r.longest_streak, 4);
}

// IDLE (ENABLE 0) clears the card's count: a firmware re-arm after a
// HARD_ERROR gives the card RETRY_LIMIT restarts again.
TEST(RecoveryRule, TheFirmwaresReArmStartsTheCountAgain) {
    for (const bool idle : {true, false}) {
        run_builder b;
        ticks t = ms(0.1);
        for (int i = 0; i < 2; ++i) t = b.fail(t, 1, card_state::oe_low) + ms(0.047);
        t = b.fail(t, 1, card_state::hard_error);
        b.enable(t + ms(0.01), 0);
        if (idle) b.state(t + ms(0.0101), card_state::idle);
        b.enable(t + ms(0.02), 1);
        b.start(t + ms(0.021));
        t += ms(0.021);
        for (int i = 0; i < 2; ++i) t = b.fail(t, 1, card_state::oe_low) + ms(0.047);
        b.fail(t, 1, card_state::hard_error);
        const recovery_observation r = b.judge();
        // A card that never passed IDLE kept counting: its restarts were due
        // as HARD_ERRORs.
        EXPECT_EQ(r.hard_errors_missed, idle ? 0 : 2) << first(r);
        if (idle) {
            EXPECT_EQ(r.broken(), 0) << first(r);
        }
    }
}

TEST(RecoveryRule, TheCardActsOnlyOnAFailedCheckItPulses) {
    run_builder b;
    b.state(ms(30), card_state::oe_low);  // a restart with no SYNC_ERROR pulse
    b.start(ms(30.05));
    recovery_observation r = b.judge();
    EXPECT_EQ(r.actions_without_check, 1) << first(r);

    run_builder c;
    c.in.sync_errors.push_back(ms(25.6));  // a pulse, the card runs on
    r = c.judge();
    EXPECT_EQ(r.checks_without_action, 1) << first(r);
}

TEST(RecoveryRule, AFirmwareReArmNeedsACauseOnThePins) {
    run_builder b;
    for (int k = 1; k < 20; ++k) b.in.frame_readies.push_back(ms(1.1) + k * frame);
    b.enable(ms(200), 0);
    b.enable(ms(200.01), 1);
    b.start(ms(200.02));
    recovery_observation r = b.judge();
    EXPECT_EQ(r.unexplained_rearms, 1);
    EXPECT_NE(first(r).find("re-arm at 200.000 ms"), std::string::npos) << first(r);

    // An OVERFLOW before it explains it if the firmware re-arms on
    // overflows, and the OVERFLOW needs a bus fault in effect.
    b.in.overflows.push_back(ms(190));
    b.in.bus_fault_onsets.push_back(ms(150));
    r = b.judge();
    EXPECT_EQ(r.broken(), 0) << first(r);
    b.in.rearm_on_overflow = false;
    EXPECT_EQ(b.judge().unexplained_rearms, 1);
    b.in.rearm_on_overflow = true;
    b.in.bus_fault_onsets.clear();
    EXPECT_EQ(b.judge().unexplained_overflows, 1);

    // A SYNC_ERROR explains it only with rearm_on_every_sync_error.
    run_builder s;
    const ticks t = s.fail(ms(0.1), 2, card_state::oe_low);
    s.enable(t + ms(0.01), 0);
    s.enable(t + ms(0.02), 1);
    EXPECT_EQ(s.judge().unexplained_rearms, 1);
    s.in.rearm_on_every_sync_error = true;
    EXPECT_EQ(s.judge().broken(), 0) << first(s.judge());
}

// Both sensors dead: the card is silent from the raise; a 50 ms watchdog
// re-arms after a whole period and gives up after the next.
TEST(RecoveryRule, TheWatchdogFiresAfterAWholeSilentPeriod) {
    run_builder b;
    b.in.vsync_rises.clear();
    b.in.watchdog = ms(50);
    b.in.fault_onsets.push_back(ms(0.1));
    b.in.watchdog_reports = {ms(50.15), ms(100.2)};
    b.enable(ms(50.16), 0);
    b.enable(ms(50.17), 1);
    b.enable(ms(100.21), 0);
    b.in.give_up = ms(100.2);
    recovery_observation r = b.judge();
    EXPECT_EQ(r.broken(), 0) << first(r);
    EXPECT_EQ(r.watchdog_firings, 2);

    b.in.fault_onsets.clear();  // a card silent with no fault in effect
    EXPECT_EQ(b.judge().unexplained_silences, 2);
}

TEST(RecoveryRule, AWatchdogBeforeAWholeSilentPeriodIsEarly) {
    run_builder b;
    b.in.watchdog = ms(500);
    for (int k = 1; k < 24; ++k) b.in.frame_readies.push_back(ms(1.1) + k * frame);
    b.in.watchdog_reports = {ms(500.1)};  // pairs came every period
    b.enable(ms(500.11), 0);
    b.enable(ms(500.12), 1);
    const recovery_observation r = b.judge();
    EXPECT_EQ(r.early_watchdogs, 1) << first(r);
    EXPECT_EQ(r.unexplained_rearms, 1);

    // Silent since the raise, but only for 0.6 of the period.
    run_builder v;
    v.in.vsync_rises.clear();
    v.in.watchdog = ms(50);
    v.in.fault_onsets.push_back(0);
    v.in.watchdog_reports = {ms(30.1)};
    v.enable(ms(30.11), 0);
    v.enable(ms(30.12), 1);
    EXPECT_EQ(v.judge().early_watchdogs, 1);
}

TEST(RecoveryRule, ASilentCardMustBeActedOnWithinTwoPeriods) {
    run_builder b;
    b.in.watchdog = ms(50);
    b.in.fault_onsets.push_back(0);
    for (int k = 1; k < 4; ++k) b.in.frame_readies.push_back(ms(1.1) + k * frame);
    // Silent from 74.6 ms to the end at 600 ms: due by 74.6 + 2 x 50 + 49.
    recovery_observation r = b.judge();
    EXPECT_EQ(r.missed_watchdogs, 1) << first(r);
    b.in.end = ms(220);  // the end came first
    EXPECT_EQ(b.judge().missed_watchdogs, 0);
}

// A give-up long after the silence began: the firmware's report ends the
// judged time, the card's later pulses do not hide the silence before it.
TEST(RecoveryRule, ALateGiveUpAfterALongSilenceMissedTheWatchdog) {
    run_builder b;
    b.in.watchdog = ms(50);
    b.in.fault_onsets.push_back(0);
    for (int k = 1; k < 4; ++k) b.in.frame_readies.push_back(ms(1.1) + k * frame);
    b.in.give_up = ms(400);
    for (int k = 0; k < 4; ++k) b.in.frame_readies.push_back(ms(450) + k * frame);
    const recovery_observation r = b.judge();
    EXPECT_EQ(r.missed_watchdogs, 1) << first(r);
}

// A CTRL write that keeps ENABLE 1 is no action on a silent card.
TEST(RecoveryRule, AWriteThatKeepsEnableIsNoAction) {
    run_builder b;
    b.in.watchdog = ms(50);
    b.in.fault_onsets.push_back(0);
    for (int k = 1; k < 4; ++k) b.in.frame_readies.push_back(ms(1.1) + k * frame);
    for (int k = 1; k < 10; ++k) b.enable(ms(74.6) + k * ms(50), 1);
    const recovery_observation r = b.judge();
    EXPECT_EQ(r.missed_watchdogs, 1) << first(r);
}

TEST(RecoveryRule, TheFinalStopIsNoAction) {
    run_builder b;
    for (int k = 1; k < 20; ++k) b.in.frame_readies.push_back(ms(1.1) + k * frame);
    b.in.end = ms(490);
    b.enable(ms(490), 0);
    EXPECT_EQ(b.judge().broken(), 0) << first(b.judge());
}

}  // namespace
