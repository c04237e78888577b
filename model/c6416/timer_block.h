// Timers 0-2 as one register block: each timer_unit with the CPU cycle of
// its next interrupt (TINT), on a time axis of CPU clock cycles. Plain C++;
// c6416_sc turns the earliest due cycle into a SystemC event.
#pragma once

#include <cstdint>

#include "model/c6416/timer_unit.h"

namespace c6416 {

class timer_block {
  public:
    static constexpr int count = 3;
    static constexpr uint64_t never = timer_unit::never;

    timer_block();

    // The timer whose registers hold address, or -1.
    static int timer_at(uint32_t address);
    // Register access at CPU cycle `cycle` (address inside timer n's block).
    uint32_t read(int n, uint32_t address, uint64_t cycle) const;
    // Writes and reschedules timer n's interrupt.
    void write(int n, uint32_t address, uint32_t value, uint64_t cycle);

    // The earliest cycle any timer interrupts at, or never.
    uint64_t earliest_interrupt() const;
    // The timers whose interrupt is due at `cycle` (bit n = timer n), each
    // rescheduled to its next one after it.
    uint32_t take_due(uint64_t cycle);

  private:
    timer_unit m_timers[count];
    uint64_t m_next[count] = {never, never, never};
};

}  // namespace c6416
