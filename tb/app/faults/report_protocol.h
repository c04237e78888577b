// The reporting protocol's completeness (docs/firmware-abi.md, "The
// reporting protocol"): every rule of the fault contract judges the firmware
// on its reports, so a report the firmware never sends must not pass as
// "nothing to judge". Each finding names the missing report and the rule
// that needed it. The card's pins and the bus are the truth the reports are
// held to: ENABLE raises on the bus need OE_RAISED (and, after the first,
// CARD_REARMED); a pair named in any report needs its PAIR_CAPTURED; a
// captured pair with a cause bit needs PAIR_REJECTED; a result needs
// PAIR_PROCESSED and the other way round; a processed pair needs its
// FRAMES_USED; a re-arm or give-up for the watchdog needs WATCHDOG; a frame
// loop that returned unasked needs the reason (HARD_ERROR or CARD_MISSING).
// Plain C++ over recorded events, so it can be tested on hand-made
// sequences (tests/cli/test_report_protocol.cpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tb/app/faults/recovery_rule.h"
#include "tb/platform/firmware_report.h"

namespace faults {

struct protocol_inputs {
    std::vector<platform::fw_event> events;    // the firmware's reports, in order
    std::vector<uint32_t> result_pairs;        // the pair of every result, in order
    std::vector<uint32_t> unnamed_used_pairs;  // pair_processed with no FRAMES_USED first
    std::vector<tick_value> enable_writes;     // the card's CTRL on the bus (value: ENABLE)
    simtime::ticks returned = no_tick;         // the frame loop returned, no stop asked for
    simtime::ticks until = no_tick;            // reports of causes after this are not due
    simtime::ticks window = 0;                 // how late a report may follow its cause
    uint32_t verdict_causes = 0;               // VERDICT's cause bits (docs/card-registers.md)
};

struct missing_report {
    int rule = 0;
    std::string report;           // the ABI's name, e.g. "FRAMES_USED", "result"
    int count = 0;                // how many were due
    std::vector<uint32_t> pairs;  // the first few pairs, where one applies
    std::string what;             // what lacked it
};

std::vector<missing_report> find_missing_reports(const protocol_inputs& in);

// "rule 7: missing report FRAMES_USED: 5 processed pair(s) ... (pairs 1,2,3)".
std::string violation_text(const missing_report& m);

// OE raises after which a pair was processed with no in_step between
// (rule 6): the raises are the bus's, not the firmware's own reports.
int in_step_unreported(const protocol_inputs& in);

}  // namespace faults
