#include "model/c6416/cpu_port.h"

#include "model/c6416/c6416_sc.h"

namespace c6416 {

void cpu_port::charge(int stage, uint64_t cycles, const sdram_traffic& traffic) {
    m_chip.charge(stage, cycles, traffic);
}

uint32_t cpu_port::read32(uint32_t address) {
    return m_chip.cpu_read32(address);
}

void cpu_port::write32(uint32_t address, uint32_t value) {
    m_chip.cpu_write32(address, value);
}

uint8_t* cpu_port::memory(uint32_t address, uint32_t bytes) {
    return m_chip.memory(address, bytes);
}

void cpu_port::set_interrupt_enable(uint32_t ier) {
    m_chip.m_ier = ier & 0xFFF0u;
}

uint32_t cpu_port::interrupt_flags() {
    return m_chip.m_ifr;
}

void cpu_port::clear_interrupt_flags(uint32_t mask) {
    m_chip.m_ifr &= ~mask;
}

int cpu_port::wait_for_interrupt() {
    return m_chip.wait_for_interrupt();
}

bool cpu_port::stop_requested() {
    return m_chip.m_stop;
}

}  // namespace c6416
