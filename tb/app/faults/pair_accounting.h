// Rule 5's pair accounting (docs/fault-contract.md): every in-step pair the
// card forwards is processed, or dropped and reported. The firmware reports
// a drop by the gap in PAIRS_OK when it takes the next pair, so a pair is
// judged only once a later one was due.
#pragma once

#include <cstdint>
#include <set>
#include <vector>

#include "model/time/ticks.h"

namespace faults {

// A pair the card forwarded (FRAME_READY), as the scoreboard saw it.
struct forwarded_pair {
    uint32_t pair = 0;  // PAIRS_OK after it: 1-based
    simtime::ticks ready = 0;
    bool in_step = false;    // by the sensors' truth
    bool processed = false;  // the pipeline ran on it
};

struct pair_accounting {
    int in_step = 0;                          // forwarded pairs in step by the truth
    int unaccounted = 0;                      // of those, neither processed nor reported dropped
    std::vector<uint32_t> unaccounted_pairs;  // their numbers (the first eight)
};

// `reported_dropped`: the pair numbers the firmware's pair_dropped reports
// name; `oe_rises`: the card's OE starts. A pair after the last one the
// firmware processed is still in flight if it came within `grace` of
// `stop` (the end, or the firmware's give-up); or if an OE restart within
// `grace` after it may have cut its transfer short, while no pair forwarded
// after it came more than `grace` before `stop` to carry the gap.
pair_accounting account_pairs(const std::vector<forwarded_pair>& pairs,
                              const std::set<uint32_t>& reported_dropped,
                              const std::vector<simtime::ticks>& oe_rises, simtime::ticks grace,
                              simtime::ticks stop);

}  // namespace faults
