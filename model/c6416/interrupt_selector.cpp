#include "model/c6416/interrupt_selector.h"

#include "model/c6416/c6416_regs.h"

namespace c6416 {

namespace irq = c6416::irq;

void interrupt_selector::reset() {
    m_muxh = irq::muxh_reset;
    m_muxl = irq::muxl_reset;
    m_extpol = irq::extpol_reset;
}

bool interrupt_selector::read(uint32_t address, uint32_t& value) const {
    switch (address) {
        case irq::muxh:
            value = m_muxh;
            return true;
        case irq::muxl:
            value = m_muxl;
            return true;
        case irq::extpol:
            value = m_extpol;
            return true;
        default:
            return false;
    }
}

bool interrupt_selector::write(uint32_t address, uint32_t value) {
    // Only the INTSEL fields exist; the bits between them read 0.
    constexpr uint32_t fields =
        (0x1Fu << 0) | (0x1Fu << 5) | (0x1Fu << 10) | (0x1Fu << 16) | (0x1Fu << 21) | (0x1Fu << 26);
    switch (address) {
        case irq::muxh:
            m_muxh = value & fields;
            return true;
        case irq::muxl:
            m_muxl = value & fields;
            return true;
        case irq::extpol:
            m_extpol = value & irq::extpol_mask;
            return true;
        default:
            return false;
    }
}

uint32_t interrupt_selector::selected_event(int cpu_int) const {
    const uint32_t reg = irq::intsel_register(cpu_int) == irq::muxh ? m_muxh : m_muxl;
    return (reg >> irq::intsel_shift(cpu_int)) & irq::intsel_mask;
}

uint32_t interrupt_selector::cpu_interrupts_for(uint32_t event_code) const {
    uint32_t mask = 0;
    for (int n = 4; n <= 15; ++n) {
        if (selected_event(n) == event_code) mask |= 1u << n;
    }
    return mask;
}

bool interrupt_selector::active_edge(int n, bool was, bool now) const {
    const bool falling = (m_extpol >> n) & 1u;
    return falling ? (was && !now) : (!was && now);
}

}  // namespace c6416
