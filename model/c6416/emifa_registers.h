// The EMIFA control registers (GBLCTL, CECTL0-3, SDCTL, ...) at their
// data-sheet addresses (model/c6416/c6416_regs.h emifa::). Plain C++: they only hold
// values; the EMIF model takes its timing from the writes (observer).
#pragma once

#include <cstdint>
#include <functional>
#include <utility>

#include "model/c6416/c6416_regs.h"

namespace c6416 {

class emifa_registers {
  public:
    using observer = std::function<void(uint32_t address, uint32_t value)>;

    // CECTL0-3 at their reset value, the rest 0.
    emifa_registers();

    // False (value untouched) outside the block or at an unaligned address.
    bool read(uint32_t address, uint32_t& value) const;
    // Stores the value and tells the observer; false outside the block.
    bool write(uint32_t address, uint32_t value);
    void set_observer(observer f) { m_observer = std::move(f); }

  private:
    static bool index_of(uint32_t address, int& index);

    uint32_t m_regs[c6416::emifa::block_bytes / 4] = {};
    observer m_observer;
};

}  // namespace c6416
