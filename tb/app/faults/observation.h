// What a platform run shows about its injected faults (tb/app/faults/observe.h
// builds it after the run): the figures report.json carries in `faults` /
// `fault_run` and the contract (tb/app/faults/contract.h) checks. Plain data, no
// SystemC, so the contract and the campaign read it back from a report.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tb/app/faults/fault_spec.h"

namespace faults {

// One injected fault.
struct fault_observation {
    std::string spec;  // canonical
    fault_type type = fault_type::skew;
    bool in_effect = false;    // it acted during the run
    double onset_ms = -1;      // when it took effect
    int64_t onset_frame = -1;  // sensor faults: the sensor's frame (truth index); else sync period
    // The card's CHECKS.FRAME_ID at the onset, as the DSP had programmed it.
    bool frame_id_check = true;
    // Detection: the first SYNC_ERROR (sensor faults), OVERFLOW (emif-wait)
    // or pair_dropped report (cpu-slow) at or after the onset.
    bool detected = false;
    std::string detected_by = "none";
    double detect_ms = -1;
    int frames_to_detect = -1;  // whole periods from the onset to the detection
    int masked_checks = 0;  // SYNC_ERRORs before it the fault cannot explain (out-of-step starts)
    uint32_t causes = 0;    // VERDICT cause bits of the firmware's first sync_error report
    // The detecting SYNC_ERROR's start was in step by the truth (else the
    // start-up delay of either sensor may be what its causes name).
    bool detect_start_in_step = false;
    // Sensors (bit 0 L, bit 1 R) whose other faults in effect explain that
    // same SYNC_ERROR: with several faults its causes may name any of them.
    uint32_t also_explained_by = 0;
    // The firmware's own report of this onset: the first sync_error, overflow,
    // hard_error or pair_dropped report at or after the detection.
    bool reported = false;
    std::string reported_by = "none";
    double report_ms = -1;
    // The start the onset fell in was out of step by the sensors' truth (a
    // restart is due whatever the fault): the truth, not the card's choice.
    bool onset_start_out_of_step = false;
    // Sensor faults: OE fell within a reaction window of the onset (a restart
    // decided on an earlier frame), so no check saw the onset frame.
    bool onset_frame_cut = false;
    std::vector<std::string> onset_phases;  // observe.h's onset_phases
    // Recovery: the first in-step pair the card forwards after the detection.
    bool recovered = false;
    double recover_ms = -1;
    int frames_to_recover = -1;   // periods from the detection to that pair's FRAME_READY, rounded
    int failed_starts = 0;        // OE starts after the detection whose first verdict was not good
    int oe_starts_after = 0;      // OE rises after the onset
    int pairs_discarded = 0;      // card SYNC_ERROR + OVERFLOW pulses from the onset on
    int pairs_used = 0;           // processed pairs made ready after the onset
    int unsynced_pairs_used = 0;  // of those, out of step by the sensors' truth
    int stale_pairs_used = 0;     // of those, in step by timing, a repeated (stale) frame
    int pairs_dropped = 0;        // the firmware's overrun drops after the onset
    std::vector<uint32_t> dropped_pairs;  // their card pair numbers (the report names them)
    double resumed_ms = -1;  // first pair processed after the recovery pair's FRAME_READY
    // Firmware time per processed pair (pair_captured -> pair_processed):
    // the cheapest before the onset, the dearest after it (slowed down), and
    // how many were timed after it. A CPU fault's expectation rests on them.
    double pair_ms_min = -1, slowed_ms_max = -1;
    int slowed_pairs = 0;
};

// Rule 10's window: a configured re-arm is a few register accesses after the
// report (microseconds); a period is 24.5 ms.
inline constexpr double rearm_window_ms = 1.0;

// Rule 11 (tb/app/faults/recovery_rule.h): the run's recovery actions as the
// card's pins and the DSP's bus show them, and those no cause explains.
struct recovery_observation {
    int failed_checks = 0;     // SYNC_ERROR pulses
    int card_restarts = 0;     // STATE -> OE_LOW
    int card_hard_errors = 0;  // STATE -> HARD_ERROR
    int longest_streak = 0;    // failed checks in a row, counted from the pins
    int firmware_rearms = 0;   // ENABLE 0 -> 1 after the boot's
    int watchdog_firings = 0;  // firmware actions only a silent card explains
    // What the pins show as the cause of the firmware's give-up, if it gave
    // up: hard_error, overflow, sync_error, watchdog, or none.
    std::string give_up_cause = "none";
    // Each breaks the rule.
    int hard_errors_early = 0;      // HARD_ERROR before RETRY_LIMIT + 1 failed checks in a row
    int hard_errors_missed = 0;     // a restart where RETRY_LIMIT + 1 called for HARD_ERROR
    int actions_without_check = 0;  // a restart or HARD_ERROR with no SYNC_ERROR pulse
    int checks_without_action = 0;  // a SYNC_ERROR pulse the card did not act on
    int unexplained_rearms = 0;     // a re-arm or give-up with no cause on the pins
    int early_watchdogs = 0;        // fired less than a period after a card event or raise
    int missed_watchdogs = 0;       // a silent, enabled card not acted on in 2 periods
    int unexplained_overflows = 0;  // OVERFLOW with no bus fault in effect
    int unexplained_silences = 0;   // the watchdog fired with no fault in effect
    std::vector<std::string> unexplained;  // the first few, one line each
    int broken() const {
        return hard_errors_early + hard_errors_missed + actions_without_check +
               checks_without_action + unexplained_rearms + early_watchdogs + missed_watchdogs +
               unexplained_overflows + unexplained_silences;
    }
};

// The whole run.
struct run_observation {
    int frames = 0;
    double period_ms = 24.5;
    std::string mode = "overlapped";  // the firmware's capture mode
    int dsk_version = 1;
    double end_ms = 0;
    bool firmware_started = false;
    int pairs_forwarded = 0, pairs_processed = 0, pairs_rejected = 0, pairs_dropped = 0;
    // Pairs the card forwarded in step by the truth, and of those the ones the
    // firmware neither processed nor dropped-and-reported although it had
    // moved past them or had time (a whole recovery bound) before the end.
    int pairs_in_step = 0, pairs_unaccounted = 0;
    std::vector<uint32_t> unaccounted_pairs;  // their numbers (the first few)
    // Card SYNC_ERROR / OVERFLOW pulses the firmware did not report within a
    // period (before it gave up and a period before the end).
    int unreported_sync_errors = 0, unreported_overflows = 0;
    // OE raises after which the firmware processed a pair without first
    // reporting in_step (the host learns the card is in step from it).
    int unreported_in_step = 0;
    // Overflows the firmware reported that its declared recovery (its
    // policy's rearm_on_overflow, include/stereosim/firmware.h) did not
    // follow with an OE restart on the card's pins within rearm_window_ms.
    int unrearmed_overflows = 0;
    // Pair identity at the point of use: the frames the firmware read for
    // each processed pair against the sensors' frames of the pair it names.
    int identity_checked = 0, identity_mismatches = 0;
    std::vector<uint32_t> mismatched_pairs;  // the first few
    // Reports a rule needs that the firmware never sent, each one line
    // naming the report and the rule (report_protocol.h).
    std::vector<std::string> missing_reports;
    int card_sync_errors = 0, card_overflows = 0, firmware_sync_errors = 0;
    int oe_starts = 0, rearms = 0;
    int unsynced_pairs_used = 0;  // scoreboard: processed pairs out of step by truth
    int misses = 0;               // forwarded pairs out of step by truth (the card let them by)
    int used_before_verdict = 0;
    // SYNC_ERROR pulses over the whole run that neither an out-of-step start
    // (by the truth) nor a fault in effect explains: a false alarm.
    int false_alarms = 0;
    int sync_errors_before_onset = 0;
    bool hard_error = false;  // the firmware reported hard_error
    double hard_error_ms = -1;
    // Card SYNC_ERROR pulses (failed checks) between the last FRAME_READY
    // before the give-up and the give-up: a give-up before the documented
    // count is as wrong as one after the bound.
    int failed_checks_before_give_up = 0;
    // The firmware's output against the scene's ground truth (scoreboard):
    // boxes and 3D points scored, and their worst errors.
    // The scene's ground truth exists (a replay without a truth CSV has none:
    // the output rules of a clean run cannot be judged).
    bool truth_available = true;
    int boxes_scored = 0, points_scored = 0;
    double max_box_err_px = 0, max_depth_err_pct = 0;
    recovery_observation recovery;  // rule 11
    // Faults of the run whose only allowed outcome is hard_error: the give-up
    // they force is no fault of the others (set before the check).
    int give_up_expected = 0;
    std::vector<fault_observation> faults;
};

}  // namespace faults
