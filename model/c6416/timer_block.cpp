#include "model/c6416/timer_block.h"

#include <algorithm>

#include "model/c6416/c6416_regs.h"

namespace c6416 {

namespace timer = c6416::timer;

timer_block::timer_block() {
    for (timer_unit& t : m_timers) t.reset();
}

int timer_block::timer_at(uint32_t address) {
    for (int n = 0; n < count; ++n) {
        const uint32_t base = timer::base(n);
        if (address >= base && address < base + timer::block_bytes) return n;
    }
    return -1;
}

uint32_t timer_block::read(int n, uint32_t address, uint64_t cycle) const {
    switch (address - timer::base(n)) {
        case timer::ctl:
            return m_timers[n].read_ctl();
        case timer::prd:
            return m_timers[n].read_prd();
        default:
            return m_timers[n].read_cnt(cycle);
    }
}

void timer_block::write(int n, uint32_t address, uint32_t value, uint64_t cycle) {
    switch (address - timer::base(n)) {
        case timer::ctl:
            m_timers[n].write_ctl(value, cycle);
            break;
        case timer::prd:
            m_timers[n].write_prd(value);
            break;
        default:
            m_timers[n].write_cnt(value, cycle);
            break;
    }
    // An interrupt due this very cycle has fired already (take_due) or
    // belongs to the old setting: look from the next cycle.
    m_next[n] = m_timers[n].next_interrupt(cycle + 1);
}

uint64_t timer_block::earliest_interrupt() const {
    uint64_t earliest = never;
    for (uint64_t next : m_next) earliest = std::min(earliest, next);
    return earliest;
}

uint32_t timer_block::take_due(uint64_t cycle) {
    uint32_t due = 0;
    for (int n = 0; n < count; ++n) {
        if (m_next[n] == never || m_next[n] > cycle) continue;
        due |= 1u << n;
        m_next[n] = m_timers[n].next_interrupt(cycle + 1);
    }
    return due;
}

}  // namespace c6416
