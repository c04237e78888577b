// Rule 11 of the fault contract (docs/fault-contract.md, "No unexplained
// recovery"): every recovery action of the card and of the firmware has a
// cause on the card's pins, and every such cause a fault in effect (or an
// out-of-step start, which rule 3 judges):
//   - the card restarts OE or enters HARD_ERROR only on a failed check (a
//     SYNC_ERROR pulse), and enters HARD_ERROR exactly when the failed checks
//     in a row, counted from the pins, reach RETRY_LIMIT + 1;
//   - the firmware re-arms (ENABLE 0 -> 1 on the bus) or gives up only for a
//     card in HARD_ERROR, an OVERFLOW (rearm_on_overflow), a SYNC_ERROR
//     (rearm_on_every_sync_error) or a whole watchdog period of silence;
//   - its watchdog fires only after a whole watchdog period without a card
//     event or an OE raise, and does fire within two periods of silence;
//   - an OVERFLOW needs a bus fault in effect, a silent card a fault.
// Plain C++ over the events a run recorded, so that the rule can be tested
// on hand-made sequences (tests/cli/test_recovery_rule.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "model/time/ticks.h"
#include "tb/app/faults/observation.h"

namespace faults {

// The card's STATUS.STATE (docs/card-registers.md).
enum class card_state : uint8_t { idle = 0, oe_low = 1, wait_vsync = 2, run = 3, hard_error = 4 };

struct tick_value {
    simtime::ticks tick = 0;
    uint32_t value = 0;
};

inline constexpr simtime::ticks no_tick = INT64_MAX;

struct recovery_inputs {
    // The card's interrupt pins (rising edges), its OE pin's rises, the
    // sensors' VSYNC rises (either sensor, sorted) and STATUS.STATE after
    // each change.
    std::vector<simtime::ticks> sync_errors, frame_readies, overflows;
    std::vector<simtime::ticks> oe_rises, vsync_rises;
    std::vector<tick_value> card_states;
    // The DSP's writes of the card's CTRL (value: ENABLE) on the bus, in
    // order, and the ticks of the firmware's own watchdog reports.
    std::vector<tick_value> enable_writes;
    std::vector<simtime::ticks> watchdog_reports;
    // Onsets of the faults that explain an OVERFLOW (emif-wait) and of all
    // faults (a silent card needs one in effect).
    std::vector<simtime::ticks> bus_fault_onsets, fault_onsets;

    uint32_t retry_limit = 8;
    simtime::ticks card_frame = 0;  // LINE_TOTAL x FRAME_LINES pixel clocks
    simtime::ticks watchdog = 0;    // the firmware's watchdog period, 0: none
    simtime::ticks service = 0;     // how late the firmware may serve an interrupt
    bool rearm_on_overflow = true;
    bool rearm_on_every_sync_error = false;
    simtime::ticks end = 0;
    simtime::ticks give_up = no_tick;  // the firmware's hard_error report
};

// How far a card's reaction to a failed check may lead its SYNC_ERROR pulse
// (the check's verdict crosses to ECLK first: docs/card.md, <= 353 ns), and
// the slack on a watchdog period (the counters move a few clocks before
// their pins, the firmware reads them over the bus).
inline constexpr simtime::ticks reaction_window = 2000 * simtime::ticks_per_ns;
inline constexpr simtime::ticks watchdog_slack = 100000 * simtime::ticks_per_ns;

recovery_observation judge_recovery(const recovery_inputs& in);

// The ticks of ENABLE 0 -> 1 among the DSP's CTRL writes (the first write
// counts from ENABLE 0).
std::vector<simtime::ticks> enable_raises(const std::vector<tick_value>& writes);

}  // namespace faults
