#include "tb/app/faults/report_protocol.h"

#include <algorithm>
#include <map>
#include <set>

namespace faults {

namespace {

using simtime::ticks;

class protocol_check {
  public:
    // Per kind the reports in time order, and the first tick each pair was
    // named: every lookup below is a search, not a pass over the run.
    explicit protocol_check(const protocol_inputs& in) : m_in(in) {
        for (const platform::fw_event& e : in.events) {
            m_kinds[e.event.kind].push_back(&e);
            m_ticks[e.event.kind].push_back(e.tick);
            m_first[e.event.kind].emplace(e.event.pair, e.tick);
        }
    }

    std::vector<missing_report> run() {
        raises();
        pairs();
        results();
        watchdog();
        loop_end();
        return m_found;
    }

  private:
    void add(int rule, const char* report, const std::vector<uint32_t>& pairs, int count,
             const std::string& what) {
        if (count == 0) return;
        missing_report m;
        m.rule = rule;
        m.report = report;
        m.count = count;
        m.pairs.assign(pairs.begin(), pairs.begin() + std::min<size_t>(pairs.size(), 8));
        m.what = what;
        m_found.push_back(m);
    }

    // A report of `kind` naming `pair` at or before `before`.
    bool has(uint32_t kind, uint32_t pair, ticks before = no_tick) const {
        const auto k = m_first.find(kind);
        if (k == m_first.end()) return false;
        const auto it = k->second.find(pair);
        return it != k->second.end() && it->second <= before;
    }

    // A report of `kind` within `window` of t, either side.
    bool near(uint32_t kind, ticks t) const {
        const auto k = m_ticks.find(kind);
        if (k == m_ticks.end()) return false;
        const auto it = std::lower_bound(k->second.begin(), k->second.end(), t - m_in.window);
        return it != k->second.end() && *it <= t + m_in.window;
    }

    // Every raise of ENABLE needs OE_RAISED; every one after the boot's is a
    // re-arm and needs CARD_REARMED (reported just before the raise).
    void raises() {
        const std::vector<ticks> up = enable_raises(m_in.enable_writes);
        int no_raise = 0, no_rearm = 0;
        for (size_t i = 0; i < up.size(); ++i) {
            if (up[i] > m_in.until) break;
            no_raise += !near(STEREOSIM_EV_OE_RAISED, up[i]);
            if (i > 0) no_rearm += !near(STEREOSIM_EV_CARD_REARMED, up[i]);
        }
        add(6, "OE_RAISED", {}, no_raise, "raise(s) of ENABLE on the bus");
        add(11, "CARD_REARMED", {}, no_rearm,
            "re-arm(s) (ENABLE 0 -> 1 after the first) on the bus");
    }

    // The pair reports: each named pair was captured first; a captured pair
    // with a cause bit is rejected, one processed had its frames named.
    void pairs() {
        std::vector<uint32_t> uncaptured, unrejected;
        std::set<uint32_t> seen;
        for (const platform::fw_event& e : m_in.events) {
            const uint32_t k = e.event.kind;
            if (k != STEREOSIM_EV_PAIR_REJECTED && k != STEREOSIM_EV_PAIR_PROCESSED &&
                k != STEREOSIM_EV_FRAMES_USED)
                continue;
            if (!has(STEREOSIM_EV_PAIR_CAPTURED, e.event.pair, e.tick) &&
                seen.insert(e.event.pair).second)
                uncaptured.push_back(e.event.pair);
        }
        for (const platform::fw_event* e : m_kinds[STEREOSIM_EV_PAIR_CAPTURED]) {
            if ((e->event.value & m_in.verdict_causes) == 0 || e->tick > m_in.until) continue;
            if (!has(STEREOSIM_EV_PAIR_REJECTED, e->event.pair) &&
                !has(STEREOSIM_EV_PAIR_PROCESSED, e->event.pair))
                unrejected.push_back(e->event.pair);
        }
        add(7, "PAIR_CAPTURED", uncaptured, static_cast<int>(uncaptured.size()),
            "pair(s) named by later reports but never reported captured");
        add(5, "PAIR_REJECTED", unrejected, static_cast<int>(unrejected.size()),
            "captured pair(s) with a cause bit in VERDICT neither rejected nor processed");
        add(7, "FRAMES_USED", m_in.unnamed_used_pairs,
            static_cast<int>(m_in.unnamed_used_pairs.size()),
            "processed pair(s) whose frames were never named before pair_processed");
    }

    // PAIR_PROCESSED and the result come together, pair for pair.
    void results() {
        std::vector<uint32_t> no_processed, no_result;
        const std::set<uint32_t> with_result(m_in.result_pairs.begin(), m_in.result_pairs.end());
        for (uint32_t pair : with_result)
            if (!has(STEREOSIM_EV_PAIR_PROCESSED, pair)) no_processed.push_back(pair);
        for (const platform::fw_event* e : m_kinds[STEREOSIM_EV_PAIR_PROCESSED])
            if (!with_result.count(e->event.pair)) no_result.push_back(e->event.pair);
        add(5, "PAIR_PROCESSED", no_processed, static_cast<int>(no_processed.size()),
            "pair(s) with a result but no pair_processed");
        add(5, "result", no_result, static_cast<int>(no_result.size()),
            "pair(s) reported processed with no result (box, point, stage cycles)");
    }

    // A re-arm or give-up the firmware itself puts down to its watchdog.
    void watchdog() {
        int unreported = 0;
        for (uint32_t kind : {STEREOSIM_EV_CARD_REARMED, STEREOSIM_EV_HARD_ERROR})
            for (const platform::fw_event* e : m_kinds[kind])
                if (e->event.value == STEREOSIM_REARM_WATCHDOG)
                    unreported += !near(STEREOSIM_EV_WATCHDOG, e->tick);
        add(11, "WATCHDOG", {}, unreported, "re-arm(s) or give-up(s) for the watchdog");
    }

    // A frame loop that returns unasked gave up or found no card, and says
    // which.
    void loop_end() {
        if (m_in.returned == no_tick) return;
        for (uint32_t kind : {STEREOSIM_EV_HARD_ERROR, STEREOSIM_EV_CARD_MISSING})
            if (!m_kinds[kind].empty()) return;
        add(4, "HARD_ERROR", {}, 1,
            "frame loop that returned unasked without saying why (no HARD_ERROR or "
            "CARD_MISSING)");
    }

    const protocol_inputs& m_in;
    std::map<uint32_t, std::vector<const platform::fw_event*>> m_kinds;
    std::map<uint32_t, std::vector<ticks>> m_ticks;
    std::map<uint32_t, std::map<uint32_t, ticks>> m_first;  // kind -> pair -> first tick
    std::vector<missing_report> m_found;
};

}  // namespace

std::vector<missing_report> find_missing_reports(const protocol_inputs& in) {
    return protocol_check(in).run();
}

std::string violation_text(const missing_report& m) {
    std::string text = "rule " + std::to_string(m.rule) + ": missing report " + m.report + ": " +
                       std::to_string(m.count) + " " + m.what;
    if (!m.pairs.empty()) {
        text += " (pairs ";
        for (size_t i = 0; i < m.pairs.size(); ++i)
            text += (i ? "," : "") + std::to_string(m.pairs[i]);
        text += m.count > static_cast<int>(m.pairs.size()) ? ",...)" : ")";
    }
    return text;
}

int in_step_unreported(const protocol_inputs& in) {
    const std::vector<ticks> up = enable_raises(in.enable_writes);
    int unreported = 0;
    size_t next_raise = 0;
    bool awaiting = false;  // a raise not yet followed by in_step
    for (const platform::fw_event& e : in.events) {
        while (next_raise < up.size() && up[next_raise] <= e.tick) {
            awaiting = true;
            ++next_raise;
        }
        if (e.event.kind == STEREOSIM_EV_IN_STEP) awaiting = false;
        if (e.event.kind == STEREOSIM_EV_PAIR_PROCESSED && awaiting) {
            ++unreported;
            awaiting = false;
        }
    }
    return unreported;
}

}  // namespace faults
