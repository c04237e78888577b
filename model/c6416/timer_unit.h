// One C6416 32-bit timer (model/c6416/c6416_regs.h timer::; [CSL csl_timerhal.h]),
// plain C++ on a time axis of CPU clock cycles. Semantics (ASSUMED where
// SPRU582 was not at hand, docs/c6416.md):
//   - CLKSRC = 1: the counter counts the internal clock, CPU clock / 8
//     [CSL TIMER_CTL_CLKSRC_CPUOVR8]; CLKSRC = 0 (the TINP pin) is not
//     modelled: the counter stands still.
//   - Writing CTL with GO = 1 and HLD = 1 clears CNT and starts counting from
//     that CPU cycle; HLD = 0 holds the counter (it keeps its value);
//     HLD = 1 without GO resumes it.
//   - CNT counts 0, 1, ..., PRD - 1; where it would reach PRD it becomes 0
//     and TINT fires: one interrupt every PRD timer clocks (PRD = 0: none,
//     the counter wraps at 2^32).
#pragma once

#include <cstdint>

namespace c6416 {

class timer_unit {
  public:
    static constexpr uint64_t never = ~uint64_t{0};

    void reset();

    uint32_t read_ctl() const { return m_ctl & ~0x40u; }  // GO reads 0
    uint32_t read_prd() const { return m_prd; }
    uint32_t read_cnt(uint64_t cycle) const;

    void write_ctl(uint32_t value, uint64_t cycle);
    void write_prd(uint32_t value) { m_prd = value; }
    void write_cnt(uint32_t value, uint64_t cycle);

    bool counting() const;
    // The first CPU cycle >= `cycle` at which TINT fires, or never.
    uint64_t next_interrupt(uint64_t cycle) const;

  private:
    uint64_t clocks_since_start(uint64_t cycle) const;

    uint32_t m_ctl = 0;
    uint32_t m_prd = 0;
    uint32_t m_cnt_at_start = 0;  // CNT when counting (re)started
    uint64_t m_start_cycle = 0;   // CPU cycle counting (re)started
};

}  // namespace c6416
