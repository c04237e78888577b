// What a platform run shows about its injected faults, taken after the run
// from the sensors' timing truth, the card's interrupt pins and the
// firmware's reports (the same sources as the scoreboard). These are the
// figures report.json carries in `faults` / `fault_run` and the contract
// (tb/app/faults/contract.h) checks.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tb/app/faults/fault_spec.h"
#include "tb/app/faults/observation.h"
#include "tb/platform/platform.h"
#include "tb/platform/scoreboard.h"

namespace faults {

// Builds the observation; adds each fault's onset to the platform's
// timeline (event_kind::fault).
run_observation observe(platform::platform_top& top, const platform::scoreboard_report& score,
                        const std::vector<fault_spec>& specs);

// Where the fault acted (onset_phase.cpp): one of vertical_blanking,
// dark_rows, active_rows, then oe_restart or first_check, and bus_burst.
std::vector<std::string> onset_phases(const platform::platform_top& top, const fault_spec& s,
                                      simtime::ticks onset, bool frame_cut);

struct recovery_inputs;
// Rule 11's inputs from the run (recovery_inputs.cpp); `onsets` per spec,
// recovery_rule.h's no_tick for a fault that did not act.
recovery_inputs gather_recovery_inputs(const platform::platform_top& top,
                                       const std::vector<fault_spec>& specs,
                                       const std::vector<simtime::ticks>& onsets);

struct protocol_inputs;
// The reporting protocol's inputs from the run (report_protocol_inputs.cpp):
// reports due `window` after their cause, up to `until`.
protocol_inputs gather_protocol_inputs(const platform::platform_top& top,
                                       const std::vector<platform::fw_event>& events,
                                       simtime::ticks window, simtime::ticks until);

}  // namespace faults
