// What the active pixel faults do to the sensor's pins (docs/sensor-faults.md):
// data bits stuck, VSYNC / HREF glitch windows, the dark-pixel leak, and the
// flags of the start / OE faults. Plain C++. sensor_core decides when a fault
// fires (its trigger, sensor_core_faults.cpp) and asks this class what the
// pins then show; the drifting clock is the core's own.
#pragma once

#include <cstdint>
#include <vector>

#include "model/sensor/fault.h"

namespace sensor {

class fault_effects {
  public:
    // Puts f into effect from cycle `cycle`. False for a kind with no effect
    // on the pins here (frame and line faults, pclk_drift).
    bool activate(const fault& f, uint64_t cycle);

    // Stuck bits, then glitch inversions, on the driven (valid) words
    // [from_col, to_col) of a segment whose word 0 is at cycle cycle_of_col0.
    void apply(uint16_t* words, int from_col, int to_col, uint64_t cycle_of_col0) const;
    void drop_finished_glitches(uint64_t now);
    // fault_bit of every glitch still open after cycle `cycle` begins.
    uint32_t open_glitch_bits(uint64_t cycle) const;

    int dark_level(int black_level) const { return m_leak ? m_leak_level : black_level; }
    bool never_start() const { return m_never_start; }
    bool ignore_oe() const { return m_ignore_oe; }

  private:
    struct glitch_window {
        uint64_t begin, end;  // cycles [begin, end)
        uint16_t bit;
    };

    std::vector<glitch_window> m_glitches;
    uint16_t m_stuck_mask = 0;  // data bits stuck (several faults may add up)
    uint16_t m_stuck_set = 0;   // their values
    bool m_leak = false;
    int m_leak_level = 0;
    bool m_never_start = false;
    bool m_ignore_oe = false;
};

}  // namespace sensor
