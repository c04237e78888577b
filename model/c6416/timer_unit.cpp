#include "model/c6416/timer_unit.h"

#include "model/c6416/c6416_regs.h"

namespace c6416 {

namespace timer = c6416::timer;

void timer_unit::reset() {
    m_ctl = 0;
    m_prd = 0;
    m_cnt_at_start = 0;
    m_start_cycle = 0;
}

bool timer_unit::counting() const {
    return (m_ctl & timer::ctl_hld) && (m_ctl & timer::ctl_clksrc);
}

uint64_t timer_unit::clocks_since_start(uint64_t cycle) const {
    if (!counting() || cycle < m_start_cycle) return 0;
    return (cycle - m_start_cycle) / timer::cpu_cycles_per_internal_clock;
}

uint32_t timer_unit::read_cnt(uint64_t cycle) const {
    const uint64_t total = m_cnt_at_start + clocks_since_start(cycle);
    return m_prd == 0 ? static_cast<uint32_t>(total) : static_cast<uint32_t>(total % m_prd);
}

void timer_unit::write_ctl(uint32_t value, uint64_t cycle) {
    const uint32_t now_count = read_cnt(cycle);
    m_ctl = value & ~timer::ctl_tstat;
    if ((value & timer::ctl_go) && (value & timer::ctl_hld)) {
        m_cnt_at_start = 0;
    } else {
        m_cnt_at_start = now_count;  // hold or resume from where it is
    }
    m_start_cycle = cycle;
}

void timer_unit::write_cnt(uint32_t value, uint64_t cycle) {
    m_cnt_at_start = value;
    m_start_cycle = cycle;
}

uint64_t timer_unit::next_interrupt(uint64_t cycle) const {
    if (!counting() || m_prd == 0) return never;
    // Timer clock k (k >= 1) falls on CPU cycle start + 8 k; TINT fires on
    // the clocks where (cnt_at_start + k) is a multiple of PRD.
    const uint64_t k_first = m_prd - (m_cnt_at_start % m_prd);
    const uint64_t per = timer::cpu_cycles_per_internal_clock;
    uint64_t k = k_first;
    if (cycle > m_start_cycle + per * k_first) {
        const uint64_t k_now = (cycle - m_start_cycle + per - 1) / per;  // first clock >= cycle
        k = k_first + (k_now - k_first + m_prd - 1) / m_prd * m_prd;
    }
    return m_start_cycle + per * k;
}

}  // namespace c6416
