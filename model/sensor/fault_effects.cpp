#include "model/sensor/fault_effects.h"

#include <algorithm>

#include "model/sensor/pin_word.h"

namespace sensor {

bool fault_effects::activate(const fault& f, uint64_t cycle) {
    switch (f.kind) {
        case fault_kind::vsync_glitch:
        case fault_kind::href_glitch:
            m_glitches.push_back(
                {cycle, cycle + static_cast<uint64_t>(f.width_pclks),
                 f.kind == fault_kind::vsync_glitch ? pin_word::vsync_bit : pin_word::href_bit});
            return true;
        case fault_kind::dark_leak:
            m_leak = true;
            m_leak_level = std::clamp(f.leak_level, 0, 255);
            return true;
        case fault_kind::stuck_data_bit: {
            const uint16_t bit_mask = static_cast<uint16_t>(1u << f.bit);
            m_stuck_mask |= bit_mask;
            m_stuck_set = static_cast<uint16_t>(f.stuck_value ? (m_stuck_set | bit_mask)
                                                              : (m_stuck_set & ~bit_mask));
            return true;
        }
        case fault_kind::never_start:
            m_never_start = true;
            return true;
        case fault_kind::ignore_oe:
            m_ignore_oe = true;
            return true;
        default:
            return false;
    }
}

void fault_effects::apply(uint16_t* w, int from_col, int to_col, uint64_t cycle_of_col0) const {
    if (m_stuck_mask != 0) {
        const uint16_t keep = static_cast<uint16_t>(~m_stuck_mask);
        for (int c = from_col; c < to_col; ++c)
            if (w[c] & pin_word::valid_bit)
                w[c] = static_cast<uint16_t>((w[c] & keep) | m_stuck_set);
    }
    for (const glitch_window& g : m_glitches) {
        const uint64_t lo = std::max(g.begin, cycle_of_col0 + static_cast<uint64_t>(from_col));
        const uint64_t hi = std::min(g.end, cycle_of_col0 + static_cast<uint64_t>(to_col));
        for (uint64_t cyc = lo; cyc < hi; ++cyc) {
            uint16_t& word = w[cyc - cycle_of_col0];
            if (word & pin_word::valid_bit) word ^= g.bit;
        }
    }
}

void fault_effects::drop_finished_glitches(uint64_t now) {
    m_glitches.erase(std::remove_if(m_glitches.begin(), m_glitches.end(),
                                    [now](const glitch_window& g) { return g.end <= now; }),
                     m_glitches.end());
}

uint32_t fault_effects::open_glitch_bits(uint64_t cycle) const {
    uint32_t bits = 0;
    for (const glitch_window& g : m_glitches)
        if (g.end > cycle)
            bits |= fault_bit(g.bit == pin_word::vsync_bit ? fault_kind::vsync_glitch
                                                           : fault_kind::href_glitch);
    return bits;
}

}  // namespace sensor
