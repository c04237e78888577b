// The C6416's memories whose bytes the model holds: 1 MB L2 SRAM at
// 0x00000000 and the DSK's 16 MB SDRAM on EMIFA CE0 (0x80000000). Plain C++.
// The SDRAM lives here even when the EMIF model serves CE0 accesses: the EMIF
// reads and writes these bytes (emif_async_master::set_sdram_storage).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace c6416 {

class c6416_memory {
  public:
    // sdram_over_emifa: CE0 accesses go out on EMIFA (true) or are served
    // here in zero time (false).
    explicit c6416_memory(bool sdram_over_emifa);

    // Bytes [address, address + bytes) of L2 or SDRAM, nullptr outside them.
    uint8_t* at(uint32_t address, uint32_t bytes);
    // Served here in zero time: L2, and SDRAM unless it goes out on EMIFA.
    bool is_local(uint32_t address) const;

    uint8_t* sdram() { return m_sdram.data(); }
    std::size_t sdram_bytes() const { return m_sdram.size(); }

  private:
    bool m_sdram_over_emifa;
    std::vector<uint8_t> m_l2;
    std::vector<uint8_t> m_sdram;
};

}  // namespace c6416
