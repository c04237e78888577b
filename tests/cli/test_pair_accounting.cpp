// Rule 5's pair accounting (tb/app/faults/pair_accounting.h) on the pair
// sequences of real runs: the firmware reports a drop by the gap in
// PAIRS_OK when it takes the next pair, so a pair lost in a card restart is
// judged once a later pair was due, and not before.
#include <gtest/gtest.h>

#include <set>
#include <vector>

#include "tb/app/faults/pair_accounting.h"

namespace {

using faults::account_pairs;
using simtime::ticks;

constexpr ticks ms(double v) {
    return static_cast<ticks>(v * 1e6 * simtime::ticks_per_ns);
}
constexpr ticks grace = ms(98);  // two windows of one period, as observe.cpp passes

faults::forwarded_pair pair(uint32_t n, double ready_ms, bool processed) {
    faults::forwarded_pair p;
    p.pair = n;
    p.ready = ms(ready_ms);
    p.in_step = true;
    p.processed = processed;
    return p;
}

// `stereosim run --fault emif-wait:cycles=40@frame=3 --seed 11 --frames 8
// --set firmware.mode=sequential`: the overflow re-arm at 91.2 ms cuts pair
// 2's slow transfer; pair 3 comes at 189.3 ms, 6.7 ms before the end, so
// the gap that reports pair 2 dropped is not due yet (with 14 frames the
// firmware reports it at 273.7 ms).
TEST(PairAccounting, APairLostInARestartIsJudgedWhenTheNextPairIsDue) {
    const std::vector<faults::forwarded_pair> pairs = {pair(1, 49.2, true), pair(2, 73.7, false),
                                                       pair(3, 189.3, false)};
    const std::vector<ticks> restarts = {ms(0.004), ms(91.207)};
    const faults::pair_accounting a = account_pairs(pairs, {}, restarts, grace, ms(196));
    EXPECT_EQ(a.in_step, 3);
    EXPECT_EQ(a.unaccounted, 0);
}

// Seed 13's emif-wait + drop-frame R row (12 frames): pair 5's transfer is
// cut by the card's restart at 147.1 ms and the card fails every check to
// the end, so no later pair comes to carry the gap.
TEST(PairAccounting, NoLaterPairLeavesTheLastOneInFlight) {
    const std::vector<faults::forwarded_pair> pairs = {pair(4, 98.1, true), pair(5, 122.6, false)};
    const std::vector<ticks> restarts = {ms(0.004), ms(147.1), ms(171.8), ms(196.4), ms(221.1)};
    EXPECT_EQ(account_pairs(pairs, {}, restarts, grace, ms(294)).unaccounted, 0);
}

// The firmware that stops taking pairs while the card keeps forwarding:
// pair 3 came 100 ms before the end, so 2 and 3 are both lost unreported,
// with or without a restart after pair 2.
TEST(PairAccounting, APairDueLongBeforeTheEndMustBeTaken) {
    const std::vector<faults::forwarded_pair> pairs = {pair(1, 49.2, true), pair(2, 73.7, false),
                                                       pair(3, 96.0, false)};
    for (const std::vector<ticks>& restarts :
         {std::vector<ticks>{ms(0.004)}, std::vector<ticks>{ms(0.004), ms(80.0)}}) {
        const faults::pair_accounting a = account_pairs(pairs, {}, restarts, grace, ms(196));
        EXPECT_EQ(a.unaccounted, 2);
        EXPECT_EQ(a.unaccounted_pairs, (std::vector<uint32_t>{2, 3}));
    }
}

// The last pair of a run with no restart after it reached the firmware
// whole: ignored for longer than the grace, it is lost, later pair or not.
TEST(PairAccounting, ALastPairNoRestartCutMustBeTaken) {
    const std::vector<faults::forwarded_pair> pairs = {pair(1, 49.2, true), pair(2, 73.7, false)};
    EXPECT_EQ(account_pairs(pairs, {}, {ms(0.004)}, grace, ms(196)).unaccounted, 1);
    EXPECT_EQ(account_pairs(pairs, {}, {ms(0.004), ms(180.0)}, grace, ms(196)).unaccounted, 1);
}

// A later pair processed without the gap reported: pair 2 is lost silently,
// however close to the end pair 3 came.
TEST(PairAccounting, ALaterPairTakenWithoutTheGapReportedFails) {
    const std::vector<faults::forwarded_pair> pairs = {pair(1, 49.2, true), pair(2, 73.7, false),
                                                       pair(3, 189.3, true)};
    const std::vector<ticks> restarts = {ms(0.004), ms(91.207)};
    EXPECT_EQ(account_pairs(pairs, {}, restarts, grace, ms(196)).unaccounted, 1);
    EXPECT_EQ(account_pairs(pairs, {2}, restarts, grace, ms(196)).unaccounted, 0);
}

// Pairs out of step by the truth are not the firmware's to account for.
TEST(PairAccounting, OutOfStepPairsAreNotCounted) {
    std::vector<faults::forwarded_pair> pairs = {pair(1, 49.2, true), pair(2, 73.7, false),
                                                 pair(3, 98.2, true)};
    pairs[1].in_step = false;
    const std::vector<ticks> restarts = {ms(0.004)};
    const faults::pair_accounting a = account_pairs(pairs, {}, restarts, grace, ms(196));
    EXPECT_EQ(a.in_step, 2);
    EXPECT_EQ(a.unaccounted, 0);
}

}  // namespace
