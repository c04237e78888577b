// A program's own SDRAM traffic (cpu_port::charge) replayed
// as L2 line transfers on EMIFA (docs/c6416.md): one burst per line read; a
// line written is fetched (write-allocate) and later written back (two),
// spread evenly over the charge's CPU cycles so the transfers compete with
// the EDMA's capture for the bus. They read and write a reserved SDRAM
// window, not the firmware's buffers: only their bus time matters.
#pragma once

#include <cstdint>
#include <functional>
#include <systemc>
#include <vector>

#include "model/c6416/cpu_clock_sc.h"
#include "model/c6416/cpu_port.h"

namespace c6416 {

struct sdram_window {
    uint32_t line_bytes = 128;  // the unit of the transfers (at least 4)
    uint32_t base = 0;
    uint32_t bytes = 0;
};

class sdram_traffic_replay {
  public:
    // One line transfer on the bus; it returns when the transfer is done.
    using line_transfer =
        std::function<void(bool write_back, uint32_t address, uint8_t* data, uint32_t bytes)>;

    explicit sdram_traffic_replay(const sdram_window& window);

    // Issues the charge's traffic over CPU cycles [first_cycle, first_cycle +
    // cycles) (waits on the calling thread).
    void run(const cpu_clock_sc& clock, uint64_t first_cycle, uint64_t cycles,
             const sdram_traffic& traffic, const line_transfer& transfer);

    uint64_t lines_read() const { return m_lines_read; }
    uint64_t lines_written() const { return m_lines_written; }
    // Time the transfers took, queue and bus, summed.
    sc_core::sc_time transfer_time() const { return m_transfer; }

  private:
    sdram_window m_window;
    std::vector<uint8_t> m_line_buffer;  // data of the transfers (garbage)
    uint64_t m_cursor = 0;               // next line of the window
    uint64_t m_lines_read = 0, m_lines_written = 0;
    sc_core::sc_time m_transfer;
};

}  // namespace c6416
