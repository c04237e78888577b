// Test support: a simple asynchronous memory on one CE space that answers on the EMIF pins
// with the daughter card's timing (rtl/emif_slave.v), for tests of the EMIF
// engine and its TLM side without the card RTL.
//
// Per ECLK edge (pins = what the EMIF drove before the edge):
//   the first edge that samples ARE low with this CE selected latches EA;
//   `read_latency` edges after it counting that one (card: 2) the word is in the
//   output register and the access is ready; read_latency 0 is a plain
//   asynchronous SRAM instead: ED follows EA combinationally, ARDY stays high;
//   the first edge that samples AWE low writes ED (byte enables honoured).
// Outputs (combinational in the pins, as on the card): ED driven while CE
// and AOE are low; ARDY low while CE and AOE are low and the read data is not
// ready yet (if use_ardy), high otherwise.
// So with ardy_lead 1 a read strobe lasts at least read_latency + 2 cycles
// (docs/emif.md works the card's case through).
#pragma once

#include <cstdint>
#include <vector>

#include "model/emif/emif_pins.h"

namespace emif {

struct sram_config {
    int ce = 2;
    uint32_t words = 4096;      // size; the word address wraps modulo it
    uint32_t read_latency = 2;  // 0: combinational read (no ARDY)
    bool use_ardy = true;
};

class async_sram_slave : public emif_pin_slave {
  public:
    explicit async_sram_slave(const sram_config& config = {});

    emif_inputs outputs(const emif_pins& pins) const override;
    void eclk_edge(const emif_pins& pins) override;

    uint32_t& word(uint32_t index) { return m_mem[index % m_mem.size()]; }
    const sram_config& config() const { return m_config; }
    uint64_t reads() const { return m_reads; }
    uint64_t writes() const { return m_writes; }

  private:
    sram_config m_config;
    std::vector<uint32_t> m_mem;
    bool m_rd_busy = false, m_ready = false, m_wr_busy = false;
    uint32_t m_count = 0, m_addr = 0, m_ed = 0;
    uint64_t m_reads = 0, m_writes = 0;
};

}  // namespace emif
