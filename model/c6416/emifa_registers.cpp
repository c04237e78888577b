#include "model/c6416/emifa_registers.h"

namespace c6416 {

namespace regs = c6416;

emifa_registers::emifa_registers() {
    for (int ce = 0; ce < 4; ++ce) {
        int index = 0;
        index_of(regs::emifa::cectl(ce), index);
        m_regs[index] = regs::emifa::cectl_reset;
    }
}

bool emifa_registers::index_of(uint32_t address, int& index) {
    if (address < regs::emifa::base || address >= regs::emifa::base + regs::emifa::block_bytes ||
        (address & 3u) != 0) {
        return false;
    }
    index = static_cast<int>((address - regs::emifa::base) / 4);
    return true;
}

bool emifa_registers::read(uint32_t address, uint32_t& value) const {
    int index = 0;
    if (!index_of(address, index)) return false;
    value = m_regs[index];
    return true;
}

bool emifa_registers::write(uint32_t address, uint32_t value) {
    int index = 0;
    if (!index_of(address, index)) return false;
    m_regs[index] = value;
    if (m_observer) m_observer(address, value);
    return true;
}

}  // namespace c6416
