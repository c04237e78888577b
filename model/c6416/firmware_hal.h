// The firmware's HAL on the C6416 model: every dsp::hal call the firmware
// makes on the CPU thread, forwarded to the chip (charges, register and
// memory accesses, interrupts, reports). A nested class of c6416_sc so the
// firmware sees only dsp::hal, never the module.
#pragma once

#include "model/c6416/c6416_sc.h"

namespace c6416 {

class c6416_sc::firmware_hal final : public dsp::hal {
  public:
    explicit firmware_hal(c6416_sc& chip) : m_chip(chip) {}

    void charge_cycles(dsp::stage s, uint64_t cycles) override;
    void charge_with_traffic(dsp::stage s, uint64_t cycles,
                             const dsp::sdram_traffic& traffic) override;
    void stage_begin(dsp::stage s) override;
    void stage_end(dsp::stage s) override;
    uint32_t read32(uint32_t address) override;
    void write32(uint32_t address, uint32_t value) override;
    uint8_t* memory(uint32_t address, uint32_t bytes) override;
    void set_interrupt_enable(uint32_t ier) override;
    uint32_t interrupt_flags() override;
    void clear_interrupt_flags(uint32_t mask) override;
    int wait_for_interrupt() override;
    void report(const dsp::event_record& e) override;
    void report_result(uint32_t pair, const dsp::frame_output& out) override;
    bool stop_requested() override;

  private:
    c6416_sc& m_chip;
};

}  // namespace c6416
