// The pin hash (docs/platform.md "Pin hash", docs/arrangements.md): every pin
// change of a run with its tick, folded into one 64-bit FNV-style hash in a
// CANONICAL order, so that two arrangements that make the changes in a
// different order (the fast island learns a sensor's word at its rising edge,
// the pin-level arrangement sees it on the signals at the falling edge) give
// the same hash when, and only when, their pins did the same.
//
// Canonical order: by tick, then by group (0/1 sensor L/R words, 2 the DSP's
// EMIF pins, 3 the card's outputs); one value per group and tick, the value
// the group settled at in that tick; only changes (a value equal to the
// group's previous one is dropped).
//
// A source adds each group's changes in non-decreasing tick order (groups may
// run ahead of each other) and calls flush_before(t) once no group can add a
// change before t; finish() flushes the rest. Cost: a deque push and pop per
// change.
#pragma once

#include <cstdint>
#include <deque>
#include <vector>

#include "model/emif/emif_pins.h"
#include "model/time/ticks.h"

namespace platform {

// The hash's pin groups and how each packs its pins into one value (both
// arrangements use these, so they hash the same bits).
inline constexpr uint32_t pin_group_sensor_left = 0;   // sensor::pin_word bits
inline constexpr uint32_t pin_group_sensor_right = 1;  // sensor::pin_word bits
inline constexpr uint32_t pin_group_emif_dsp = 2;      // pack_dsp_pins
inline constexpr uint32_t pin_group_card_out = 3;      // pack_card_outputs

// The DSP's EMIFA pins: CE0-3, AOE, ARE, AWE, ED_OE, BE, EA; ED as the DSP
// drives it matters only while it drives.
inline uint64_t pack_dsp_pins(const emif::emif_pins& p) {
    uint64_t v = 0;
    for (int i = 0; i < emif::ce_count; ++i) v |= static_cast<uint64_t>(p.ce_n[i]) << i;
    v |= static_cast<uint64_t>(p.aoe_n) << 4 | static_cast<uint64_t>(p.are_n) << 5 |
         static_cast<uint64_t>(p.awe_n) << 6 | static_cast<uint64_t>(p.ed_oe) << 7 |
         static_cast<uint64_t>(p.be_n & 0xF) << 8 | static_cast<uint64_t>(p.ea & 0xFFFFF) << 12;
    if (p.ed_oe) v ^= static_cast<uint64_t>(p.ed_out) << 32;
    return v;
}

// The card's outputs that reach pins: OE, ARDY, ED_OE, EXT_INT4-6, and ED
// while the card drives it.
inline uint64_t pack_card_outputs(bool sensor_oe, bool ardy, bool ed_oe, bool ext_int4,
                                  bool ext_int5, bool ext_int6, uint32_t ed_out) {
    uint64_t v = static_cast<uint64_t>(sensor_oe) | static_cast<uint64_t>(ardy) << 1 |
                 static_cast<uint64_t>(ed_oe) << 2 | static_cast<uint64_t>(ext_int4) << 3 |
                 static_cast<uint64_t>(ext_int5) << 4 | static_cast<uint64_t>(ext_int6) << 5;
    if (ed_oe) v |= static_cast<uint64_t>(ed_out) << 32;
    return v;
}

// One pin change as hashed.
struct pin_change {
    simtime::ticks tick = 0;
    uint32_t group = 0;
    uint64_t value = 0;
    friend bool operator==(const pin_change& a, const pin_change& b) {
        return a.tick == b.tick && a.group == b.group && a.value == b.value;
    }
};

class canonical_pin_hash {
  public:
    static constexpr int group_count = 4;

    // The groups' values before the first change (a change is a difference from these).
    void set_initial(uint32_t group, uint64_t value) { m_last[group] = value; }

    // Returns true if the value differs from the group's last one (counted, queued).
    bool add(simtime::ticks t, uint32_t group, uint64_t value) {
        std::deque<entry>& q = m_queue[group];
        if (!q.empty() && q.back().tick == t) {  // settled again within the tick
            q.back().value = value;
            return false;
        }
        q.push_back({t, value});
        return true;
    }

    // Folds every queued change before tick t, in canonical order.
    void flush_before(simtime::ticks t) {
        for (;;) {
            int best = -1;
            for (int g = 0; g < group_count; ++g) {
                if (m_queue[g].empty() || m_queue[g].front().tick >= t) continue;
                if (best < 0 || m_queue[g].front().tick < m_queue[best].front().tick) best = g;
            }
            if (best < 0) return;
            const entry e = m_queue[best].front();
            m_queue[best].pop_front();
            if (e.value == m_last[best]) continue;
            m_last[best] = e.value;
            uint64_t h = m_hash;
            h = (h ^ static_cast<uint64_t>(e.tick)) * 1099511628211ull;
            h = (h ^ static_cast<uint64_t>(best)) * 1099511628211ull;
            h = (h ^ e.value) * 1099511628211ull;
            m_hash = h;
            ++m_changes;
            if (e.tick >= m_log_from && e.tick < m_log_to)
                m_log.push_back({e.tick, static_cast<uint32_t>(best), e.value});
        }
    }
    void finish() { flush_before(INT64_MAX); }

    // Also keeps every change with its tick in [from, to), in canonical
    // order (the per-signal comparison of a window, docs/arrangements.md).
    void log_window(simtime::ticks from, simtime::ticks to) {
        m_log_from = from;
        m_log_to = to;
    }
    const std::vector<pin_change>& logged() const { return m_log; }

    uint64_t value() const { return m_hash; }
    // Changes folded so far.
    uint64_t changes() const { return m_changes; }

  private:
    struct entry {
        simtime::ticks tick;
        uint64_t value;
    };
    std::deque<entry> m_queue[group_count];
    uint64_t m_last[group_count] = {};
    uint64_t m_hash = 1469598103934665603ull;
    uint64_t m_changes = 0;
    simtime::ticks m_log_from = 0, m_log_to = 0;
    std::vector<pin_change> m_log;
};

}  // namespace platform
