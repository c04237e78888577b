// The firmware's HAL (dsp/hal.h) over the platform's services of the C ABI
// (include/stereosim/firmware.h): what lets the firmware of dsp/ run behind
// the ABI unchanged. Reports go out as the ABI's events and results; a
// captured pair's event carries its frames' addresses, which the platform
// checks in DSP memory.
#pragma once

#include "dsp/control_program.h"
#include "dsp/hal.h"
#include "stereosim/firmware.h"

namespace dsp::plugin {

class services_hal final : public hal {
  public:
    explicit services_hal(const stereosim_services& services) : m_s(services) {}
    // The program whose buffer addresses PAIR_CAPTURED names (set before run()).
    void set_program(const control_program* program) { m_program = program; }

    void charge_cycles(stage s, uint64_t cycles) override;
    void charge_with_traffic(stage s, uint64_t cycles, const sdram_traffic& traffic) override;
    uint64_t kernel_cycles(const c64x::kernel_profile& kernel) override;
    void stage_begin(stage s) override;
    void stage_end(stage s) override;
    uint32_t read32(uint32_t address) override;
    void write32(uint32_t address, uint32_t value) override;
    uint8_t* memory(uint32_t address, uint32_t bytes) override;
    void set_interrupt_enable(uint32_t ier) override;
    uint32_t interrupt_flags() override;
    void clear_interrupt_flags(uint32_t mask) override;
    int wait_for_interrupt() override;
    void report(const event_record& e) override;
    void report_result(uint32_t pair, const frame_output& out) override;
    bool stop_requested() override;

  private:
    const stereosim_services& m_s;
    const control_program* m_program = nullptr;
};

// The ABI's form of a kernel's op profile (the cost service's argument).
stereosim_kernel_profile abi_profile(const c64x::kernel_profile& kernel);
// The ABI's form of a processed pair's result.
stereosim_result abi_result(uint32_t pair, const frame_output& out);

}  // namespace dsp::plugin
