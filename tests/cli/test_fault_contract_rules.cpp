// The fault contract's rules of issue 12 (docs/fault-contract.md), each shown
// to pass on a run that keeps it and to fail on one that breaks it. The
// observations are written by hand: what a run of the platform would record.
// That the rules catch real broken firmware and RTL is shown by the mutants
// (tests/mutants, docs/mutants.md).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tb/app/faults/contract.h"
#include "tb/app/faults/fault_spec.h"
#include "tb/platform/platform_config.h"

namespace {

using faults::outcome;

faults::fault_spec spec_of(const std::string& text) {
    std::string error;
    const std::optional<faults::fault_spec> s = faults::parse_fault_spec(text, &error);
    EXPECT_TRUE(s.has_value()) << error;
    return s.value_or(faults::fault_spec{});
}

faults::contract_params params() {
    return faults::params_for(platform::platform_config{});
}

// A skew on R at frame 4 of an 8-frame run, flagged, reported, recovered:
// keeps the contract.
faults::fault_observation good_skew() {
    faults::fault_observation f;
    f.in_effect = true;
    f.onset_ms = 74;
    f.detected = true;
    f.detected_by = "sync_error";
    f.detect_ms = 98;
    f.frames_to_detect = 0;
    f.causes = 0x22;
    f.detect_start_in_step = true;
    f.reported = true;
    f.reported_by = "sync_error";
    f.report_ms = 98.1;
    f.recovered = true;
    f.recover_ms = 147;
    f.resumed_ms = 155;
    f.frames_to_recover = 2;
    return f;
}

faults::run_observation good_run() {
    faults::run_observation run;
    run.frames = 8;
    run.end_ms = 196;
    run.pairs_forwarded = 5;
    run.pairs_in_step = 5;
    run.pairs_processed = 5;
    run.identity_checked = 5;
    return run;
}

bool has_violation(const faults::verdict& v, const std::string& text) {
    for (const std::string& why : v.violations)
        if (why.find(text) != std::string::npos) return true;
    return false;
}

const faults::fault_spec skew = spec_of("skew:sensor=R,lines=3@frame=4");

TEST(FaultContractRules, TheGoodRunKeepsTheContract) {
    const faults::verdict v = faults::check(good_skew(), skew, params(), good_run());
    EXPECT_TRUE(v.ok) << (v.violations.empty() ? "" : v.violations[0]);
    EXPECT_EQ(v.actual, outcome::resync);
}

// Rule 1: every in-step pair the card forwards is processed or dropped and
// reported; processing resumes after a recovery; a clean run processes.
TEST(FaultContractRules, TheFirmwareMustKeepWorking) {
    faults::run_observation run = good_run();
    run.pairs_unaccounted = 2;
    run.unaccounted_pairs = {4, 5};
    const faults::verdict v = faults::check(good_skew(), skew, params(), run);
    EXPECT_FALSE(v.ok);
    EXPECT_TRUE(has_violation(v, "neither processed nor reported dropped (pairs 4,5)"));

    faults::fault_observation idle = good_skew();
    idle.resumed_ms = -1;  // the card recovered at 147 ms, nothing processed by 245 ms
    faults::run_observation longer = good_run();
    longer.end_ms = 245;
    EXPECT_TRUE(faults::check(good_skew(), skew, params(), longer).ok);
    EXPECT_TRUE(has_violation(faults::check(idle, skew, params(), longer),
                              "processed no pair within 2 periods"));

    // A CPU 20 times slower: the pair in hand and the next take 160 ms each,
    // so processing resumes later than 2 periods after the card's recovery
    // (300 ms measured); the bound grows by what the slowdown adds, no more.
    faults::fault_observation slowed = good_skew();
    slowed.pair_ms_min = 4.3;
    slowed.slowed_ms_max = 164.2;
    slowed.resumed_ms = slowed.recover_ms + 300;
    faults::run_observation long_run = good_run();
    long_run.end_ms = 700;
    EXPECT_TRUE(faults::check(slowed, skew, params(), long_run).ok);
    slowed.resumed_ms = slowed.recover_ms + 2 * 24.5 + 2 * (164.2 - 4.3) + 1;
    EXPECT_TRUE(has_violation(faults::check(slowed, skew, params(), long_run),
                              "within 2 periods and the slowed CPU's 319 ms"));
    slowed.slowed_ms_max = 8.2;  // not slowed: 2 periods and 8 ms
    slowed.resumed_ms = slowed.recover_ms + 2 * 24.5 + 9;
    EXPECT_TRUE(has_violation(faults::check(slowed, skew, params(), long_run),
                              "processed no pair within 2 periods"));

    faults::run_observation empty;
    empty.frames = 6;
    EXPECT_TRUE(has_violation(faults::check_clean(empty), "no pair processed"));
    empty.pairs_processed = 3;
    EXPECT_TRUE(faults::check_clean(empty).ok);
}

// Working means right: a clean run's boxes and 3D points against the
// scene's ground truth.
TEST(FaultContractRules, ACleanRunTracksTheObjectRightly) {
    faults::run_observation clean = good_run();  // 8 frames
    EXPECT_TRUE(has_violation(faults::check_clean(clean), "no 3D point"));
    clean.boxes_scored = 2;
    clean.points_scored = 2;
    clean.max_box_err_px = 1.4;
    clean.max_depth_err_pct = 0.3;
    EXPECT_TRUE(faults::check_clean(clean).ok);
    faults::run_observation off = clean;
    off.max_box_err_px = 11;
    EXPECT_TRUE(has_violation(faults::check_clean(off), "px off"));
    off = clean;
    off.max_depth_err_pct = 12;
    EXPECT_TRUE(has_violation(faults::check_clean(off), "% off"));
}

// Rule 2: detected means reported by the firmware, per onset, in time,
// whatever other sync errors the run had.
TEST(FaultContractRules, DetectedMeansReportedPerOnset) {
    faults::fault_observation f = good_skew();
    faults::run_observation run = good_run();
    run.firmware_sync_errors = 1;  // a start-up mismatch's report does not count
    f.reported = false;
    EXPECT_TRUE(has_violation(faults::check(f, skew, params(), run), "never reported it"));
    f.reported = true;
    f.report_ms = f.onset_ms + 21 * 24.5;  // past the 20-period bound
    EXPECT_TRUE(has_violation(faults::check(f, skew, params(), run), "bound 20 periods"));
    run.unreported_sync_errors = 1;
    EXPECT_TRUE(has_violation(faults::check(good_skew(), skew, params(), run),
                              "SYNC_ERROR(s) the firmware never reported"));
    faults::run_observation overflow = good_run();
    overflow.unreported_overflows = 2;
    EXPECT_FALSE(faults::check(good_skew(), skew, params(), overflow).ok);
    faults::run_observation silent_start = good_run();
    silent_start.unreported_in_step = 1;
    EXPECT_TRUE(has_violation(faults::check_clean(silent_start), "without reporting in_step"));
}

// Rule 10: the firmware recovers as it is configured to: an overflow it
// reports is followed by its re-arm (an OE restart on the card's pins).
TEST(FaultContractRules, AnOverflowIsFollowedByTheConfiguredRearm) {
    faults::run_observation run = good_run();
    EXPECT_TRUE(faults::check(good_skew(), skew, params(), run).ok);
    run.unrearmed_overflows = 1;
    EXPECT_TRUE(has_violation(faults::check(good_skew(), skew, params(), run),
                              "not followed by the configured re-arm"));
}

// Rule 3: false alarms over the whole run.
TEST(FaultContractRules, FalseAlarmsCountOverTheWholeRun) {
    faults::run_observation run = good_run();
    run.false_alarms = 1;
    EXPECT_TRUE(has_violation(faults::check(good_skew(), skew, params(), run), "false alarm"));
    EXPECT_FALSE(faults::check_clean(run).ok);
}

// Rule 4: a fault that never took effect is its own outcome, and fails.
TEST(FaultContractRules, AFaultThatNeverActedFails) {
    faults::fault_observation f;
    f.in_effect = false;
    const faults::verdict v = faults::check(f, skew, params(), good_run());
    EXPECT_EQ(v.actual, outcome::not_in_effect);
    EXPECT_FALSE(v.ok);
    EXPECT_STREQ(faults::outcome_name(v.actual), "not_in_effect");
}

// Rule 4: no hang, and no give-up before the documented re-arms either.
TEST(FaultContractRules, TheFirmwareGivesUpNeitherLateNorEarly) {
    const faults::fault_spec leak = spec_of("dark-leak:sensor=R,level=48@frame=2");
    faults::contract_params p = params();
    p.retry_limit = 2;  // (1 + 1) x (2 + 1) = 6 failed checks, bound 8 periods
    faults::fault_observation f = good_skew();
    f.causes = 0x08;  // R_DARK
    f.recovered = false;
    faults::run_observation run = good_run();
    run.end_ms = 245;
    run.hard_error = true;
    run.hard_error_ms = f.onset_ms + 7 * 24.5;
    run.failed_checks_before_give_up = 6;
    run.recovery.give_up_cause = "hard_error";  // the card in HARD_ERROR at the give-up
    EXPECT_TRUE(faults::check(f, leak, p, run).ok);
    run.failed_checks_before_give_up = 3;  // gave up at the card's first HARD_ERROR
    EXPECT_TRUE(has_violation(faults::check(f, leak, p, run), "gave up after 3 failed checks"));
    // A card silent for a watchdog period: the watchdog's give-up, whatever
    // failed before the card fell silent.
    run.recovery.give_up_cause = "watchdog";
    EXPECT_TRUE(faults::check(f, leak, p, run).ok);
    run.failed_checks_before_give_up = 0;
    EXPECT_TRUE(faults::check(f, leak, p, run).ok);
    run.hard_error_ms = f.onset_ms + 9 * 24.5;  // past the 8-period bound
    EXPECT_FALSE(faults::check(f, leak, p, run).ok);
}

// Rule 5: dead / oe-stuck expectations follow the truth, not what the card
// chose to do: a restart due (out-of-step start) requires the hard error.
TEST(FaultContractRules, DeadSensorExpectationsFollowTheTruth) {
    const faults::fault_spec stuck = spec_of("oe-stuck:sensor=L");
    faults::fault_observation f;
    f.in_effect = true;
    f.onset_ms = 0;
    f.onset_start_out_of_step = true;
    f.oe_starts_after = 0;  // the card never restarted: no excuse
    faults::run_observation run = good_run();
    run.end_ms = 245;
    const faults::verdict v = faults::check(f, stuck, params(), run);
    EXPECT_EQ(v.expected, outcome::hard_error);
    EXPECT_FALSE(v.ok);
}

// Rule 6: cpu-slow and emif-wait rows whose parameters decide the outcome
// allow only that outcome.
TEST(FaultContractRules, CpuAndBusRowsThatSurelyOverrunOrFitAllowOneOutcome) {
    const faults::contract_params p = params();
    faults::fault_observation f;
    f.in_effect = true;
    f.pair_ms_min = 4;
    const faults::run_observation run = good_run();
    // Half of 4 ms is CPU time at least: x 20 = 40 ms > 1.2 x 24.5 ms.
    EXPECT_EQ(faults::expected_for(f, spec_of("cpu-slow:factor=20"), p, run).allowed,
              std::vector<outcome>{outcome::overrun});
    EXPECT_EQ(faults::expected_for(f, spec_of("cpu-slow:factor=10"), p, run).allowed.size(), 2u);
    // Every pair timed after the onset (>= 2) fitted the period.
    faults::fault_observation fits = f;
    fits.slowed_pairs = 3;
    fits.slowed_ms_max = 16;
    EXPECT_EQ(faults::expected_for(fits, spec_of("cpu-slow:factor=2"), p, run).allowed,
              std::vector<outcome>{outcome::harmless});
    fits.slowed_ms_max = 23;
    EXPECT_EQ(faults::expected_for(fits, spec_of("cpu-slow:factor=2"), p, run).allowed.size(), 2u);
    // Harmless where overrun is due: a firmware that never drops fails.
    const faults::verdict v = faults::check(f, spec_of("cpu-slow:factor=20@frame=4"), p, run);
    EXPECT_EQ(v.actual, outcome::harmless);
    EXPECT_FALSE(v.ok);
    // An overrun must name its dropped pairs.
    faults::fault_observation dropped = f;
    dropped.detected = true;
    dropped.detected_by = "pair_dropped";
    dropped.reported = true;
    dropped.reported_by = "pair_dropped";
    EXPECT_TRUE(has_violation(faults::check(dropped, spec_of("cpu-slow:factor=20"), p, run),
                              "dropped pairs named"));
    dropped.dropped_pairs = {6};
    EXPECT_TRUE(faults::check(dropped, spec_of("cpu-slow:factor=20"), p, run).ok);
    EXPECT_EQ(faults::expected_for(f, spec_of("emif-wait:cycles=40,ce=2"), p, run).allowed,
              std::vector<outcome>{outcome::harmless});
    // A pair read 40 % over the period overflows within 3 periods; one within
    // 20 % fills the FIFOs' 1.7 frames slowly, if at all in the run.
    const faults::expectation slow =
        faults::expected_for(f, spec_of("emif-wait:cycles=10"), p, run);
    EXPECT_EQ(slow.allowed, std::vector<outcome>{outcome::overflow});
    EXPECT_EQ(slow.max_frames_to_detect, 3);
    const faults::expectation marginal =
        faults::expected_for(f, spec_of("emif-wait:cycles=2"), p, run);
    EXPECT_EQ(marginal.allowed.size(), 2u);
    EXPECT_EQ(marginal.max_frames_to_detect, -1);
}

// A one-frame timing fault is judged by the check of the frame it hits;
// where that check fails anyway (its start out of step by the truth) or
// never comes (a restart decided on an earlier frame cuts the frame at its
// start), the restart may wipe it out.
TEST(FaultContractRules, AOneFrameFaultMaskedByARestartMayLeaveNoTrace) {
    faults::fault_observation f = good_skew();
    f.detected = false;
    f.recovered = false;
    f.resumed_ms = -1;
    EXPECT_FALSE(faults::check(f, skew, params(), good_run()).ok);
    faults::fault_observation masked = f;
    masked.onset_start_out_of_step = true;
    EXPECT_TRUE(faults::check(masked, skew, params(), good_run()).ok);
    masked = f;
    masked.onset_frame_cut = true;
    EXPECT_TRUE(faults::check(masked, skew, params(), good_run()).ok);
    // Detected late in such a frame: no detection bound either.
    masked = good_skew();
    masked.onset_frame_cut = true;
    masked.frames_to_detect = 3;
    EXPECT_TRUE(faults::check(masked, skew, params(), good_run()).ok);
    faults::fault_observation late = good_skew();
    late.frames_to_detect = 3;
    EXPECT_TRUE(
        has_violation(faults::check(late, skew, params(), good_run()), "detected 3 frames"));
}

// Two faults in one run: a persistent sensor fault forces the give-up, so a
// bus fault of the same run that alone would end in overflow may end there
// too; a run where no fault forces it may not.
TEST(FaultContractRules, AnotherFaultsGiveUpExplainsAHardError) {
    faults::contract_params p = params();
    p.retry_limit = 2;
    const std::vector<faults::fault_spec> specs = {spec_of("emif-wait:cycles=30@frame=3"),
                                                   spec_of("dark-leak:sensor=L,level=48@frame=5")};
    faults::fault_observation bus;
    bus.in_effect = true;
    bus.onset_ms = 73.5;
    bus.detected = true;
    bus.detected_by = "overflow";
    bus.detect_ms = 80;
    bus.reported = true;
    bus.reported_by = "overflow";
    bus.report_ms = 80.1;
    faults::fault_observation leak = good_skew();
    leak.onset_ms = 122;
    leak.causes = 0x04;
    leak.recovered = false;
    faults::run_observation run = good_run();
    run.end_ms = 294;
    run.hard_error = true;
    run.hard_error_ms = 122 + 7 * 24.5;
    run.failed_checks_before_give_up = 6;
    run.recovery.give_up_cause = "hard_error";
    run.faults = {bus, leak};
    EXPECT_TRUE(has_violation(faults::check(bus, specs[0], p, run), "outcome hard_error"));
    faults::note_expected_give_ups(specs, p, &run);
    EXPECT_EQ(run.give_up_expected, 1);
    EXPECT_TRUE(faults::check(bus, specs[0], p, run).ok)
        << faults::check(bus, specs[0], p, run).violations[0];
    EXPECT_TRUE(faults::check(leak, specs[1], p, run).ok);
}

// Each outcome in the classes of ISO 26262-5.
TEST(FaultContractRules, OutcomesAsSafetyClasses) {
    using faults::fault_type;
    EXPECT_STREQ(faults::safety_class(fault_type::skew, outcome::resync), "detected");
    EXPECT_STREQ(faults::safety_class(fault_type::emif_wait, outcome::overflow), "detected");
    EXPECT_STREQ(faults::safety_class(fault_type::extra_frame, outcome::stale_pair), "residual");
    EXPECT_STREQ(faults::safety_class(fault_type::skew, outcome::missed), "residual");
    EXPECT_STREQ(faults::safety_class(fault_type::dead, outcome::harmless), "latent");
    EXPECT_STREQ(faults::safety_class(fault_type::drift, outcome::harmless), "latent");
    EXPECT_STREQ(faults::safety_class(fault_type::dark_leak, outcome::harmless), "safe");
    EXPECT_STREQ(faults::safety_class(fault_type::skew, outcome::pending), "none");
}

// Rule 7: pending is not a pass.
TEST(FaultContractRules, PendingIsNotAPass) {
    faults::fault_observation f = good_skew();
    f.recovered = false;
    f.resumed_ms = -1;
    faults::run_observation run = good_run();
    run.end_ms = 110;  // ended 12 ms after the detection
    const faults::verdict v = faults::check(f, skew, params(), run);
    EXPECT_EQ(v.actual, outcome::pending);
    EXPECT_FALSE(v.ok);
    // The line says why and what to ask for: detected at 98 ms, recovery due
    // 2 periods later, at 147 ms = 6 periods, and a period of margin.
    EXPECT_TRUE(has_violation(v,
                              "rule 9: pending: detected at 98.0 ms, the run ended at 110.0 ms "
                              "before its recovery or hard error was due at 147.0 ms: ask for "
                              "--frames 7 or more"))
        << v.violations[0];
}

// Rule 8: the frames the firmware processed are those of the pair it names.
TEST(FaultContractRules, PairIdentityAtThePointOfUse) {
    faults::run_observation run = good_run();
    run.identity_mismatches = 1;
    run.mismatched_pairs = {3};
    EXPECT_TRUE(has_violation(faults::check(good_skew(), skew, params(), run),
                              "not the pair's own (pairs 3)"));
}

// Rule 9: the sync error blames the faulted sensor.
TEST(FaultContractRules, TheVerdictBlamesTheFaultedSensor) {
    faults::fault_observation f = good_skew();
    f.causes = 0x11;  // L_WINDOW | L_VSYNC for a skew of R
    EXPECT_TRUE(has_violation(faults::check(f, skew, params(), good_run()),
                              "do not name the faulted sensor R"));
    f.causes = 0x20;  // R_VSYNC alone names it
    EXPECT_TRUE(faults::check(f, skew, params(), good_run()).ok);
    // Detected in a start out of step by the truth: its causes may be the
    // start-up delay's, of either sensor.
    f.causes = 0x11;
    f.detect_start_in_step = false;
    EXPECT_TRUE(faults::check(f, skew, params(), good_run()).ok);
    // A drifting clock moves the streams against each other: the card flags
    // the late one, so either stream's timing causes name it; dark ones do not.
    const faults::fault_spec drift = spec_of("drift:sensor=R,ppm=1");
    faults::fault_observation d = good_skew();
    d.causes = 0x11;
    EXPECT_TRUE(faults::check(d, drift, params(), good_run()).ok);
    d.causes = 0x04;  // L_DARK
    EXPECT_FALSE(faults::check(d, drift, params(), good_run()).ok);
}

// Rule 1 without exception: with the card's frame-identity check on, a frame
// sent twice must be detected (R_FRAME_ID names R) and its pair never used;
// judged as the paper's card, the stale pair is the named hole, not a pass.
TEST(FaultContractRules, AnExtraFrameIsDetectedUnlessThePaperCardIsJudged) {
    const faults::fault_spec extra = spec_of("extra-frame:sensor=R@frame=2");
    faults::fault_observation detected = good_skew();
    detected.causes = 0x200;  // R_FRAME_ID
    const faults::verdict strict = faults::check(detected, extra, params(), good_run());
    EXPECT_TRUE(strict.ok) << (strict.violations.empty() ? "" : strict.violations[0]);
    detected.causes = 0x100;  // L_FRAME_ID blames the wrong sensor
    EXPECT_TRUE(has_violation(faults::check(detected, extra, params(), good_run()),
                              "do not name the faulted sensor R"));

    // Not detected, the repeat's pair used: the old exception is gone.
    faults::fault_observation used;
    used.in_effect = true;
    used.onset_ms = 49;
    used.unsynced_pairs_used = used.stale_pairs_used = 1;
    used.frame_id_check = false;  // the firmware had cleared CHECKS.FRAME_ID
    faults::run_observation run = good_run();
    run.unsynced_pairs_used = 1;
    const faults::verdict v = faults::check(used, extra, params(), run);
    EXPECT_EQ(v.actual, outcome::stale_pair);
    EXPECT_TRUE(has_violation(v, "rule 1: 1 pair(s) out of step used"));
    EXPECT_TRUE(has_violation(v, "CHECKS.FRAME_ID = 0 at the onset"));

    faults::contract_params paper = params();
    paper.paper_card = true;
    const faults::verdict hole = faults::check(used, extra, paper, run);
    EXPECT_EQ(hole.actual, outcome::stale_pair);
    EXPECT_FALSE(hole.ok);
    EXPECT_TRUE(has_violation(hole, "rule 1: the paper's hole: 1 pair(s)"));
    EXPECT_FALSE(has_violation(hole, "out of step used")) << "the hole, named once";
}

// Ten intermittent faults, seed 13 of the full campaign: R's one-pixel skew
// of 319.5 ms is checked at 344.027 ms, the very tick L's frame 14 was
// dropped, so L's drop is detected by a verdict that names R (0x22). That
// verdict may name R because R's fault explains it; no other fault, no excuse.
TEST(FaultContractRules, AVerdictOnAnotherFaultsFrameMayNameItsSensor) {
    const faults::fault_spec drop_l = spec_of("drop-frame:sensor=L@frame=14");
    faults::fault_observation f = good_skew();
    f.causes = 0x22;  // R_WINDOW | R_VSYNC
    EXPECT_TRUE(has_violation(faults::check(f, drop_l, params(), good_run()),
                              "do not name the faulted sensor L"));
    f.also_explained_by = 1u << 1;  // R's skew explains that SYNC_ERROR too
    EXPECT_TRUE(faults::check(f, drop_l, params(), good_run()).ok);
    f.also_explained_by = 1u << 0;  // another fault of L: the causes still miss L
    EXPECT_FALSE(faults::check(f, drop_l, params(), good_run()).ok);
}

}  // namespace
