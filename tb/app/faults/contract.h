// The fault contract (docs/fault-contract.md) in code: what every fault kind
// must lead to, and the check of one run's observed outcome against it.
//
// Always, for every run (faulted or clean):
//   - unsynced_pairs_used == 0: no pair out of step by the sensors' timing
//     truth is used for tracking, stereo or 3D (the one documented exception
//     is extra-frame's stale pair, below);
//   - no pair is used before the card's verdict covering its last line;
//   - no false alarm: no SYNC_ERROR for an OE start the truth says was in step
//     while no fault that can cause one is in effect;
//   - no hang: an unrecoverable fault ends in the firmware's hard_error report
//     within hard_error_bound_periods() of its onset; a recoverable one never
//     does.
// Per kind (expected_for): detected or not, by what, within how many frames,
// and how the card and firmware react (resync, discard, hard error).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "stereosim/firmware.h"
#include "tb/app/faults/fault_spec.h"
#include "tb/app/faults/observation.h"

namespace faults {

// What a fault must lead to. Some parameters sit on a threshold (a dark level
// near DARK_THRESHOLD with noise on): then two outcomes are allowed.
enum class outcome : uint8_t {
    not_in_effect,  // never acted during the run (trigger after its end): the run proves nothing
    harmless,       // not detected, no pair out of step: pairs keep being used
    resync,         // detected by the sync check, the pair discarded, OE restarted, recovered
    hard_error,     // never recovers: the firmware reports hard_error within the bound
    stale_pair,     // extra-frame on the paper's card (no frame-identity check): the repeat's pair
                    // used
    overflow,       // bus fault: FIFO overflow (EXT_INT6), pairs discarded, no sync effect
    overrun,        // CPU fault: pairs dropped by the overrun policy, no sync effect
    pending,        // detected; the run ended before recovery was due: never a pass
    missed,         // out-of-step pairs went through undetected
    no_recovery,    // detected but not recovered (nor a hard error) although it was due
};
const char* outcome_name(outcome o);

// The observed outcome in the classes of ISO 26262-5 (docs/fault-contract.md,
// "Outcomes as safety classes"): "detected" (a safety mechanism saw it and
// the system reached its safe state: resync, hard_error, overflow, overrun,
// no_recovery), "residual" (it broke the safety goal unseen: stale_pair,
// missed), "latent" (unseen, harmless alone, but a second fault makes it
// matter: a dead or OE-stuck sensor before its restart, a drift with no slip
// yet), "safe" (no effect on the safety goal: the other harmless faults),
// "none" (the run proves nothing of it: not_in_effect, pending).
const char* safety_class(fault_type type, outcome actual);

struct expectation {
    std::vector<outcome> allowed;   // the first is the nominal one
    int max_frames_to_detect = -1;  // -1: not checked
    std::string why;                // one line: the reasoning in the contract
};

// Card and firmware settings the contract's bounds depend on.
struct contract_params {
    uint32_t retry_limit = 8;        // the card's RETRY_LIMIT
    uint32_t hard_error_rearms = 1;  // the firmware's re-arms before it gives up
    uint32_t dark_threshold = 32;    // the card's DARK_THRESHOLD (reset value 0x20)
    int black_level = 16;            // sensor profile
    double dark_sigma = 1.7;         // read + shot noise sigma of a dark pixel, DN (noise on)
    int line_pclks = 800, frame_lines = 525;
    // From a frame's first clock to its last readout pixel, pixel clocks: the
    // span over which a drifting sensor's lead on the master clock, set at its
    // start, must stay within half a clock (docs/fault-contract.md, drift).
    int checked_span_pclks = 0;
    double words_per_pair = 153600;  // 32-bit words the DSP reads per pair
    double eclk_per_word = 14;       // the card's programmed read (CECTL, docs/card.md)
    double eclk_ns = 10;
    double period_ms = 24.5;
    // Judged as the paper's card (--paper-card): no frame-identity check, so
    // extra-frame's stale pair is its named hole (docs/fault-contract.md).
    bool paper_card = false;
};
contract_params params_for(const platform::platform_config& config);
// The same for a run: the recovery policy the firmware under test declared
// (its re-arms after a hard error) in place of the run's setting, and the
// card's read time from the CECTL it programmed on the bus.
contract_params params_for(const platform::platform_config& config,
                           const stereosim_fw_policy& policy, uint32_t programmed_card_cectl);

// The contract's row for one fault, given the run's settings and what the
// run shows about preconditions (an OE restart after a dead / oe-stuck onset).
expectation expected_for(const fault_observation& f, const fault_spec& spec,
                         const contract_params& p, const run_observation& run);

// Periods from a fault's onset within which an unrecoverable fault must be
// reported as hard_error: (hard_error_rearms + 1) x (RETRY_LIMIT + 1) failed
// checks of one period each, + 2 for the detection and the re-arm gaps.
int hard_error_bound_periods(const contract_params& p);

struct verdict {
    outcome actual = outcome::not_in_effect;
    outcome expected = outcome::not_in_effect;  // nominal
    std::string expected_text;                  // allowed outcomes joined by '|'
    bool ok = true;
    std::vector<std::string> violations;  // one line each
    // Rules the run was too short to judge, one line each with the length
    // that would (a clean run: rule 5's processing and 3D points).
    std::vector<std::string> not_judged;
};

// Counts the faults whose only allowed outcome is hard_error into
// run->give_up_expected (call before check: the others may then end there).
void note_expected_give_ups(const std::vector<fault_spec>& specs, const contract_params& p,
                            run_observation* run);

// Classifies the fault's observed outcome and checks it and the run's
// invariants against the contract.
verdict check(const fault_observation& f, const fault_spec& spec, const contract_params& p,
              const run_observation& run);
// A clean run (no fault): the invariants only (false alarms, unsynced pairs).
verdict check_clean(const run_observation& run);

}  // namespace faults
