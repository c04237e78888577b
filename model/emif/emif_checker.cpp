#include "model/emif/emif_checker.h"

#include <algorithm>
#include <cstdio>

namespace emif {

namespace {
constexpr size_t max_stored = 4096;
}

const char* violation_name(violation_kind k) {
    switch (k) {
        case violation_kind::setup_short:
            return "setup_short";
        case violation_kind::strobe_short:
            return "strobe_short";
        case violation_kind::hold_short:
            return "hold_short";
        case violation_kind::hold_setup_short:
            return "hold_setup_short";
        case violation_kind::select_in_strobe:
            return "select_in_strobe";
        case violation_kind::are_awe_both_low:
            return "are_awe_both_low";
        case violation_kind::ed_in_read:
            return "ed_in_read";
        case violation_kind::ce_turnaround:
            return "ce_turnaround";
        case violation_kind::dir_turnaround:
            return "dir_turnaround";
        case violation_kind::multiple_ce:
            return "multiple_ce";
        case violation_kind::strobe_no_ce:
            return "strobe_no_ce";
    }
    return "?";
}

std::string to_string(const violation& v) {
    char text[160];
    std::snprintf(text, sizeof text, "cycle %llu: %s on CE%d (required %u, seen %u)",
                  static_cast<unsigned long long>(v.cycle), violation_name(v.kind), v.ce,
                  v.required, v.actual);
    return text;
}

emif_checker::emif_checker(const uint32_t (&cectl)[ce_count]) {
    for (int ce = 0; ce < ce_count; ++ce) set_cectl(ce, cectl[ce]);
    m_violations.reserve(64);
}

uint64_t emif_checker::total() const {
    uint64_t n = 0;
    for (uint64_t c : m_counts) n += c;
    return n;
}

void emif_checker::flag(uint64_t cycle, violation_kind k, int ce, uint32_t required,
                        uint32_t actual) {
    ++m_counts[static_cast<int>(k)];
    if (m_violations.size() < max_stored) m_violations.push_back({cycle, k, ce, required, actual});
}

// Same rule as the engine: the larger TA of the async spaces involved.
uint32_t emif_checker::turnaround(int a, int b) const {
    uint32_t gap = 0;
    if (async_space(a)) gap = std::max(gap, m_timing[a].turnaround);
    if (async_space(b)) gap = std::max(gap, m_timing[b].turnaround);
    return gap;
}

void emif_checker::observe(uint64_t c, const emif_pins& p) {
    ++m_observed;
    // Observations skipped since the last one held the previous pins.
    if (m_have_prev) {
        if (m_prev_ce >= 0) m_last_ce_cycle = c - 1;
        if (m_prev_read) m_last_read_cycle = c - 1;
        if (m_prev_drive) m_last_drive_cycle = c - 1;
    }

    int active = -1, selected = 0;
    for (int i = 0; i < ce_count; ++i) {
        if (!p.ce_n[i]) {
            if (active < 0) active = i;
            ++selected;
        }
    }
    if (selected > 1) flag(c, violation_kind::multiple_ce, active, 1, selected);
    const bool read_strobe = !p.are_n, write_strobe = !p.awe_n;
    if (read_strobe && write_strobe) flag(c, violation_kind::are_awe_both_low, active, 0, 1);
    if (p.ed_oe && (!p.aoe_n || read_strobe)) flag(c, violation_kind::ed_in_read, active, 0, 1);

    const bool reading = active >= 0 && !p.aoe_n;
    const bool driving = p.ed_oe;
    check_turnarounds(c, active, reading, driving);
    check_async_cycle(c, p, active, read_strobe, write_strobe);

    m_prev_strobe = read_strobe || write_strobe;
    m_prev_ce = active;
    m_prev_read = reading;
    m_prev_drive = driving;
    m_have_prev = true;
}

// Turnaround between CE spaces and, on one CE, between directions.
void emif_checker::check_turnarounds(uint64_t c, int active, bool reading, bool driving) {
    if (active >= 0 && active != m_prev_ce && m_last_ce >= 0 && m_last_ce != active) {
        const uint64_t gap = c - (m_last_ce_cycle + 1);
        const uint32_t required = turnaround(m_last_ce, active);
        if (gap < required)
            flag(c, violation_kind::ce_turnaround, active, required, static_cast<uint32_t>(gap));
    }
    if (reading && !m_prev_read && m_have_drive && m_drive_ce == active &&
        (!m_have_read || m_last_drive_cycle > m_last_read_cycle)) {
        const uint64_t gap = c - (m_last_drive_cycle + 1);
        const uint32_t required = turnaround(active, active);
        if (gap < required)
            flag(c, violation_kind::dir_turnaround, active, required, static_cast<uint32_t>(gap));
    }
    if (driving && !m_prev_drive && active >= 0 && m_have_read && m_read_ce == active &&
        (!m_have_drive || m_last_read_cycle > m_last_drive_cycle)) {
        const uint64_t gap = c - (m_last_read_cycle + 1);
        const uint32_t required = turnaround(active, active);
        if (gap < required)
            flag(c, violation_kind::dir_turnaround, active, required, static_cast<uint32_t>(gap));
    }
    if (active >= 0) {
        m_last_ce = active;
        m_last_ce_cycle = c;
    }
    if (reading) {
        m_have_read = true;
        m_read_ce = active;
        m_last_read_cycle = c;
    }
    if (driving) {
        m_have_drive = true;
        m_drive_ce = active;
        m_last_drive_cycle = c;
    }
}

// Setup / strobe / hold of async accesses: the strobe rising, the select
// changing, the strobe falling, in that order within one cycle.
void emif_checker::check_async_cycle(uint64_t c, const emif_pins& p, int active, bool read_strobe,
                                     bool write_strobe) {
    select sel;
    if (active >= 0) {
        sel.ce = active;
        sel.ea = p.ea;
        sel.be_n = p.be_n;
        sel.aoe_n = p.aoe_n;
        sel.ed_oe = p.ed_oe;
        sel.ed = p.ed_oe ? p.ed_out : 0;
    }
    const bool strobe = read_strobe || write_strobe;
    const bool sel_changed = !m_have_prev || !(sel == m_sel);

    if (m_in_strobe && !strobe) strobe_rose(c);
    if (sel_changed) {
        if (m_in_strobe && strobe) {
            flag(c, violation_kind::select_in_strobe, m_strobe_ce, 0, 1);
        } else if (m_hold_pending) {
            const uint64_t hold = c - m_strobe_end;
            if (hold < m_hold_required)
                flag(c, violation_kind::hold_short, m_strobe_ce, m_hold_required,
                     static_cast<uint32_t>(hold));
            m_hold_pending = false;
        }
        m_sel = sel;
        m_sel_since = c;
    }
    if (strobe && !m_prev_strobe) strobe_fell(c, active, write_strobe);
}

void emif_checker::strobe_rose(uint64_t c) {
    const async_timing& t = m_timing[m_strobe_ce];
    const uint32_t required = m_strobe_write ? t.write_strobe : t.read_strobe;
    const uint64_t length = c - m_strobe_start;
    if (length < required)
        flag(c, violation_kind::strobe_short, m_strobe_ce, required, static_cast<uint32_t>(length));
    m_in_strobe = false;
    m_hold_pending = true;
    m_hold_required = m_strobe_write ? t.write_hold : t.read_hold;
    m_strobe_end = c;
}

void emif_checker::strobe_fell(uint64_t c, int active, bool write_strobe) {
    ++m_strobes;
    if (!async_space(active)) {
        flag(c, violation_kind::strobe_no_ce, active, 0, 0);
        m_hold_pending = false;
        return;
    }
    const async_timing& t = m_timing[active];
    const uint32_t setup_required = write_strobe ? t.write_setup : t.read_setup;
    if (m_hold_pending && m_strobe_ce == active) {
        // CE held low and nothing changed since the last strobe: only
        // hold + setup together can be measured.
        const uint64_t gap = c - m_strobe_end;
        const uint32_t required = m_hold_required + setup_required;
        if (gap < required)
            flag(c, violation_kind::hold_setup_short, active, required, static_cast<uint32_t>(gap));
    } else {
        const uint64_t setup = c - m_sel_since;
        if (setup < setup_required)
            flag(c, violation_kind::setup_short, active, setup_required,
                 static_cast<uint32_t>(setup));
    }
    m_hold_pending = false;
    m_in_strobe = true;
    m_strobe_write = write_strobe;
    m_strobe_ce = active;
    m_strobe_start = c;
}

}  // namespace emif
