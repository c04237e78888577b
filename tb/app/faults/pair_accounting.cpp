#include "tb/app/faults/pair_accounting.h"

#include <algorithm>

namespace faults {

namespace {

// Whether a pair forwarded after pair `n` came more than `grace` before
// `stop`: the firmware had to take it by then, and with it report the gap.
bool next_pair_due(const std::vector<forwarded_pair>& pairs, uint32_t n, simtime::ticks grace,
                   simtime::ticks stop) {
    for (const forwarded_pair& later : pairs)
        if (later.pair > n && later.ready + grace <= stop) return true;
    return false;
}

bool restart_after(const std::vector<simtime::ticks>& oe_rises, simtime::ticks ready,
                   simtime::ticks grace) {
    for (simtime::ticks t : oe_rises)
        if (t > ready && t <= ready + grace) return true;
    return false;
}

}  // namespace

pair_accounting account_pairs(const std::vector<forwarded_pair>& pairs,
                              const std::set<uint32_t>& reported_dropped,
                              const std::vector<simtime::ticks>& oe_rises, simtime::ticks grace,
                              simtime::ticks stop) {
    pair_accounting out;
    uint32_t last_processed = 0;
    for (const forwarded_pair& p : pairs)
        if (p.processed) last_processed = std::max(last_processed, p.pair);
    for (const forwarded_pair& p : pairs) {
        if (!p.in_step) continue;
        ++out.in_step;
        if (p.processed || reported_dropped.count(p.pair) != 0) continue;
        const bool in_flight =
            p.ready + grace > stop ||
            (restart_after(oe_rises, p.ready, grace) && !next_pair_due(pairs, p.pair, grace, stop));
        if (p.pair > last_processed && in_flight) continue;
        ++out.unaccounted;
        if (out.unaccounted_pairs.size() < 8) out.unaccounted_pairs.push_back(p.pair);
    }
    return out;
}

}  // namespace faults
