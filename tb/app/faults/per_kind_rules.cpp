// What each fault kind must lead to (docs/fault-contract.md "Per kind"),
// given the card's and firmware's settings: expected_for, declared in
// contract.h; the rules every run keeps are in contract.cpp.
#include <cmath>
#include <string>

#include "tb/app/faults/contract.h"

namespace faults {

namespace {

// Dark pixels under a persistent data fault: detected when even the darkest
// plausible one reaches DARK_THRESHOLD, harmless when even the brightest
// stays below it (6 sigma of noise either way), else either.
expectation dark_rule(int low, int high, const contract_params& p, const std::string& what) {
    expectation e;
    if (low >= static_cast<int>(p.dark_threshold)) {
        e.allowed = {outcome::hard_error};
        e.max_frames_to_detect = 1;
        e.why = what +
                " >= DARK_THRESHOLD on every frame: L_DARK/R_DARK each frame, retries "
                "exhausted, the firmware gives up";
    } else if (high < static_cast<int>(p.dark_threshold)) {
        e.allowed = {outcome::harmless};
        e.why = what + " stays below DARK_THRESHOLD: undetectable and harmless to timing";
    } else {
        e.allowed = {outcome::hard_error, outcome::harmless, outcome::resync};
        e.why = what + " straddles DARK_THRESHOLD with noise: detected or not";
    }
    return e;
}

// The rule of each fault kind, given that the fault acted during the run.

expectation timing_rule(const fault_observation& f) {
    expectation e;
    if (f.onset_start_out_of_step || f.onset_frame_cut) {
        // The check its frame gets fails anyway (an out-of-step start), or
        // never comes (OE stopped the frame): the restart may wipe it out.
        e.allowed = {outcome::resync, outcome::harmless};
        e.why =
            "timing fault of one frame in a start out of step or a frame an OE restart "
            "cut short: the restart may wipe it out before a check sees it";
        return e;
    }
    e.allowed = {outcome::resync};
    e.max_frames_to_detect = 1;
    e.why =
        "timing fault of one frame: the verdict of the common frame it hits flags it "
        "(window / VSYNC), the pair is discarded, OE restarts, the next in-step start "
        "recovers";
    return e;
}

expectation extra_frame_rule(const fault_observation& f, const contract_params& p) {
    expectation e;
    if (p.paper_card) {
        // Nothing on the pins tells the repeat apart: its pair is the hole.
        e.allowed = {outcome::harmless};
        e.why =
            "the paper's card (frame-identity check off): the repeat has exactly the "
            "reference's timing and dark pixels, so its pair is used one scene frame stale: "
            "the paper's hole, never a pass";
        return e;
    }
    e = timing_rule(f);
    if (!f.onset_start_out_of_step && !f.onset_frame_cut)
        e.why =
            "the card's frame-identity check sees the repeat's FODD unchanged at its VSYNC "
            "rise: the verdict of that common frame flags the sensor, the pair is discarded, "
            "OE restarts, the next in-step start recovers";
    if (!f.frame_id_check)
        e.why += "; the DSP had turned the check off (CHECKS.FRAME_ID = 0 at the onset)";
    return e;
}

expectation drift_rule(const fault_spec& s, const contract_params& p) {
    // A start puts the drifting sensor a phase lambda in [0, 1) clock
    // ahead of its partner (it samples OE at its own first rising edge
    // after the change, the partner a master clock later); the card
    // sees the pair aligned while the lead stays within half a clock.
    // Over a frame the lead moves by `slip`: down for a slower clock
    // (positive ppm), up for a faster one, so a faster clock passes
    // only from lambda <= 0.5 - slip (docs/fault-contract.md, drift).
    expectation e;
    const double slip = std::fabs(s.ppm) * 1e-6 * p.checked_span_pclks;
    const bool slower = s.ppm > 0;
    if (slower ? slip >= 1.0 : slip >= 0.5) {
        e.allowed = {outcome::hard_error};
        e.max_frames_to_detect = 1;
        e.why =
            "no start phase keeps the pair within half a clock of the master for a "
            "frame: every restart fails, the firmware gives up";
    } else if (slower && slip <= 0.5) {
        e.allowed = {outcome::resync, outcome::harmless};
        e.why =
            "a slower clock: half of the start phases pass and the phase after each "
            "slip is inside the window: a restart after each slip (harmless if none "
            "falls inside the run)";
    } else {
        e.allowed = {outcome::resync, outcome::hard_error};
        e.why =
            "only a start with phase <= 0.5 - slip (faster clock) passes; each restart "
            "walks the phase on: whether an in-step start lands in the window before "
            "the retries run out depends on the phase";
    }
    return e;
}

expectation stuck_bit_rule(const fault_spec& s, const contract_params& p, int sigma6) {
    // The darkest and brightest dark pixel with the bit forced.
    const int m = 1 << s.bit;
    int low = 255, high = 0;
    for (int v = std::max(0, p.black_level - sigma6); v <= p.black_level + sigma6; ++v) {
        const int forced = s.value ? (v | m) : (v & ~m);
        low = std::min(low, forced);
        high = std::max(high, forced);
    }
    return dark_rule(
        low, high, p,
        "dark pixels with bit " + std::to_string(s.bit) + " stuck at " + std::to_string(s.value));
}

expectation unresponsive_sensor_rule(const fault_observation& f, const fault_spec& s) {
    // What the truth forces, not what the card or firmware chose: a
    // sensor dead from the start, or a start the onset fell in that
    // was out of step (a restart is due), can never be in step again.
    expectation e;
    if ((s.type == fault_type::dead && s.when.kind == trigger_spec::by::start) ||
        f.onset_start_out_of_step) {
        e.allowed = {outcome::hard_error};
        e.why =
            "a sensor that does not follow OE, with a restart due: never in step again, "
            "retries exhausted, the firmware gives up within the bound";
    } else {
        e.allowed = {outcome::harmless};
        e.why = "the onset's start was in step and no restart is due: nothing to notice";
    }
    return e;
}

expectation emif_wait_rule(const fault_spec& s, const contract_params& p) {
    expectation e;
    const double pair_ms = p.words_per_pair * (p.eclk_per_word + s.cycles) * p.eclk_ns * 1e-6;
    if (s.ce != 3) {
        e.allowed = {outcome::harmless};
        e.why = "wait states on CE2 (registers only): a few slower reads per period";
    } else if (pair_ms > 1.2 * p.period_ms) {
        e.allowed = {outcome::overflow};
        e.max_frames_to_detect = 3;
        e.why =
            "a pair's read takes longer than the period: the FIFOs overflow, the "
            "card drops pairs (OVERFLOW), no sync effect";
    } else {
        // Within 20 % of the period the FIFOs' 1.7 frames fill slowly, and
        // the firmware's SDRAM traffic decides when (if in the run).
        e.allowed = {outcome::harmless, outcome::overflow};
        e.why =
            "the pair read fits the period alone or exceeds it by less than 20 %; with "
            "the firmware's SDRAM traffic it may overflow, late";
    }
    return e;
}

expectation cpu_slow_rule(const fault_observation& f, const fault_spec& s,
                          const contract_params& p) {
    // The workload's cost, not the firmware's choice to drop: at least
    // half of the cheapest pair before the onset is CPU time (the raw
    // read is the rest), so slowed it alone passes the period; or every
    // pair timed after the onset (>= 2) fitted it.
    expectation e;
    if (f.pair_ms_min > 0 && s.factor * f.pair_ms_min / 2 > 1.2 * p.period_ms) {
        e.allowed = {outcome::overrun};
        e.why = "every pair slowed past the period: the overrun policy drops pairs";
    } else if (f.slowed_pairs >= 2 && f.slowed_ms_max < 0.9 * p.period_ms) {
        e.allowed = {outcome::harmless};
        e.why = "every slowed pair still fitted the period: nothing to drop";
    } else {
        e.allowed = {outcome::overrun, outcome::harmless};
        e.why = "slowed pairs straddle the period: drops or not";
    }
    return e;
}

}  // namespace

expectation expected_for(const fault_observation& f, const fault_spec& s, const contract_params& p,
                         const run_observation& /*run*/) {
    if (!f.in_effect) {  // no outcome is allowed: the run proves nothing of the fault
        expectation e;
        e.why = "never acted during the run (trigger after the end?): it proves nothing";
        return e;
    }
    const int sigma6 = static_cast<int>(std::ceil(6 * p.dark_sigma));
    switch (s.type) {
        case fault_type::skew:
        case fault_type::drop_line:
        case fault_type::drop_frame:
        case fault_type::glitch:
            return timing_rule(f);
        case fault_type::extra_frame:
            return extra_frame_rule(f, p);
        case fault_type::drift:
            return drift_rule(s, p);
        case fault_type::dark_leak:
            return dark_rule(s.level - sigma6, s.level + sigma6, p,
                             "a dark level of " + std::to_string(s.level));
        case fault_type::stuck_bit:
            return stuck_bit_rule(s, p, sigma6);
        case fault_type::dead:
        case fault_type::oe_stuck:
            return unresponsive_sensor_rule(f, s);
        case fault_type::emif_wait:
            return emif_wait_rule(s, p);
        case fault_type::cpu_slow:
            return cpu_slow_rule(f, s, p);
    }
    return expectation{};
}

}  // namespace faults
