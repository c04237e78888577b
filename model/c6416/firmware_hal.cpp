#include "model/c6416/firmware_hal.h"

namespace c6416 {

void c6416_sc::firmware_hal::charge_cycles(dsp::stage s, uint64_t cycles) {
    m_chip.charge(s, cycles, {});
}

void c6416_sc::firmware_hal::charge_with_traffic(dsp::stage s, uint64_t cycles,
                                                 const dsp::sdram_traffic& traffic) {
    m_chip.charge(s, cycles, traffic);
}

void c6416_sc::firmware_hal::stage_begin(dsp::stage s) {
    if (m_chip.m_stage_observer) m_chip.m_stage_observer(sc_core::sc_time_stamp(), s, true);
}

void c6416_sc::firmware_hal::stage_end(dsp::stage s) {
    if (m_chip.m_stage_observer) m_chip.m_stage_observer(sc_core::sc_time_stamp(), s, false);
}

uint32_t c6416_sc::firmware_hal::read32(uint32_t address) {
    return m_chip.cpu_read32(address);
}

void c6416_sc::firmware_hal::write32(uint32_t address, uint32_t value) {
    m_chip.cpu_write32(address, value);
}

uint8_t* c6416_sc::firmware_hal::memory(uint32_t address, uint32_t bytes) {
    return m_chip.memory(address, bytes);
}

void c6416_sc::firmware_hal::set_interrupt_enable(uint32_t ier) {
    m_chip.m_ier = ier & 0xFFF0u;
}

uint32_t c6416_sc::firmware_hal::interrupt_flags() {
    return m_chip.m_ifr;
}

void c6416_sc::firmware_hal::clear_interrupt_flags(uint32_t mask) {
    m_chip.m_ifr &= ~mask;
}

int c6416_sc::firmware_hal::wait_for_interrupt() {
    return m_chip.wait_for_interrupt();
}

void c6416_sc::firmware_hal::report(const dsp::event_record& e) {
    m_chip.report(e);
}

void c6416_sc::firmware_hal::report_result(uint32_t /*pair*/, const dsp::frame_output& out) {
    if (m_chip.m_result_observer) m_chip.m_result_observer(sc_core::sc_time_stamp(), out);
}

bool c6416_sc::firmware_hal::stop_requested() {
    return m_chip.m_stop;
}

}  // namespace c6416
