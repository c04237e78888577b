#include "model/c6416/c6416_memory.h"

#include "model/c6416/c6416_regs.h"

namespace c6416 {

namespace regs = c6416;

c6416_memory::c6416_memory(bool sdram_over_emifa)
    : m_sdram_over_emifa(sdram_over_emifa),
      m_l2(regs::l2_bytes, 0),
      m_sdram(regs::sdram_bytes, 0) {}

uint8_t* c6416_memory::at(uint32_t address, uint32_t bytes) {
    const uint64_t end = static_cast<uint64_t>(address) + bytes;
    if (end <= regs::l2_base + static_cast<uint64_t>(regs::l2_bytes)) return &m_l2[address];
    if (regs::in_sdram(address, bytes)) return &m_sdram[address - regs::sdram_base];
    return nullptr;
}

bool c6416_memory::is_local(uint32_t address) const {
    if (address < regs::l2_base + regs::l2_bytes) return true;
    return !m_sdram_over_emifa && regs::in_sdram(address);
}

}  // namespace c6416
