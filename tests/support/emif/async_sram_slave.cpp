#include "tests/support/emif/async_sram_slave.h"

#include <algorithm>

namespace emif {

async_sram_slave::async_sram_slave(const sram_config& config)
    : m_config(config), m_mem(std::max(1u, config.words), 0) {}

emif_inputs async_sram_slave::outputs(const emif_pins& p) const {
    const bool reading = !p.ce_n[m_config.ce] && !p.aoe_n;
    emif_inputs out;
    if (m_config.read_latency == 0) {
        out.ed_in = reading ? m_mem[p.ea % m_mem.size()] : m_ed;
        return out;
    }
    out.ed_in = m_ed;  // meaningful only while reading (two-state stand-in for Z)
    out.ardy = !(m_config.use_ardy && reading && !m_ready);
    return out;
}

void async_sram_slave::eclk_edge(const emif_pins& p) {
    const bool sel = !p.ce_n[m_config.ce];
    const bool rd_start = sel && !p.are_n && !m_rd_busy;
    const bool wr_start = sel && !p.awe_n && !m_wr_busy;
    m_wr_busy = sel && !p.awe_n;
    if (rd_start) {
        m_rd_busy = true;
        m_ready = false;
        m_addr = p.ea;
        m_count = 1;
        ++m_reads;
    } else if (m_rd_busy && !m_ready) {
        ++m_count;
    }
    if (m_config.read_latency != 0 && m_rd_busy && !m_ready && m_count >= m_config.read_latency) {
        m_ed = word(m_addr);
        m_ready = true;
    }
    if (p.are_n) {  // the strobe is over: the next ARE low is a new read
        m_rd_busy = false;
        m_ready = false;
    }
    if (wr_start) {
        uint32_t& w = word(p.ea);
        for (int b = 0; b < 4; ++b)
            if (!((p.be_n >> b) & 1))
                w = (w & ~(0xFFu << (8 * b))) | (p.ed_out & (0xFFu << (8 * b)));
        ++m_writes;
    }
}

}  // namespace emif
