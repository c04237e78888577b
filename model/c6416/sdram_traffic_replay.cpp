#include "model/c6416/sdram_traffic_replay.h"

#include <algorithm>

namespace c6416 {

sdram_traffic_replay::sdram_traffic_replay(const sdram_window& window)
    : m_window(window), m_line_buffer(window.line_bytes < 4 ? 4 : window.line_bytes, 0) {}

// Transfer k of T waits for CPU cycle first_cycle + cycles k / T (or goes at
// once if the previous one ended later). Write-backs are interleaved evenly
// among the reads (Bresenham), each after at least one fetch.
void sdram_traffic_replay::run(const cpu_clock_sc& clock, uint64_t first_cycle, uint64_t cycles,
                               const sdram_traffic& traffic, const line_transfer& transfer) {
    const uint64_t line = m_line_buffer.size();
    const uint64_t written = (traffic.bytes_written + line - 1) / line;
    const uint64_t fetched = (traffic.bytes_read + line - 1) / line + written;
    const uint64_t transfers = fetched + written;
    const uint64_t window_lines = std::max<uint64_t>(1, m_window.bytes / line);
    for (uint64_t k = 0; k < transfers; ++k) {
        const uint64_t slot_cycle =
            first_cycle +
            static_cast<uint64_t>(static_cast<unsigned __int128>(cycles) * k / transfers);
        const sc_core::sc_time slot = clock.time_of_cycle(slot_cycle);
        if (slot > sc_core::sc_time_stamp()) sc_core::wait(slot - sc_core::sc_time_stamp());
        const bool write_back = (k + 1) * written / transfers > k * written / transfers;
        const uint32_t address =
            m_window.base + static_cast<uint32_t>((m_cursor++ % window_lines) * line);
        const sc_core::sc_time issued = sc_core::sc_time_stamp();
        transfer(write_back, address, m_line_buffer.data(), static_cast<uint32_t>(line));
        m_transfer += sc_core::sc_time_stamp() - issued;
        if (write_back) {
            ++m_lines_written;
        } else {
            ++m_lines_read;
        }
    }
}

}  // namespace c6416
