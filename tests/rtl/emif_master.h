// A cycle-level model of the C64x EMIFA as the master of asynchronous
// accesses, for the card tests (until the platform's EMIF model exists).
// It is stepped at every ECLKOUT rising edge with the card's outputs as they
// were just before that edge, and then drives its pins for the next cycle.
//
// Timing per access, in ECLK cycles, from the CECTL fields (docs/hardware-facts.md
// section 3): setup RS (CE, EA, BE and, for reads, AOE asserted), strobe RST
// (ARE or AWE low), hold RH (strobe high, the rest held). Back-to-back
// accesses of the same direction to the same CE follow each other directly
// (CE stays low: 14 cycles per read at 0x22A28A22); a change of direction or
// CE space inserts TA idle cycles unless the bus was idle that long already.
// Assumptions where the facts say NOT FOUND (docs/card.md, "EMIF"): a field
// of 0 acts as 1; the strobe ends at the first edge E >= S + RST (S = edge
// that lowered the strobe) at which ARDY was sampled high at edge
// E - ardy_lead (default 1: the EMIF synchronizes ARDY); read data is sampled
// at E, the edge where ARE rises.
#pragma once

#include <algorithm>
#include <cstdint>
#include <deque>

namespace rtl_test {

struct emif_timing {
    int ws = 2, wst = 10, wh = 2, rs = 2, rst = 10, rh = 2, ta = 2;
};

// CECTL (C64x, csl_emifahal.h): WRSETUP 31:28, WRSTRB 27:22, WRHLD 21:20 with
// WRHLDMSB bit 3, RDSETUP 19:16, TA 15:14, RDSTRB 13:8, MTYPE 7:4, RDHLD 2:0.
inline emif_timing decode_cectl(uint32_t v) {
    const auto at_least_1 = [](uint32_t f) { return static_cast<int>(f == 0 ? 1 : f); };
    emif_timing t;
    t.ws = at_least_1((v >> 28) & 0xF);
    t.wst = at_least_1((v >> 22) & 0x3F);
    t.wh = at_least_1(((v >> 20) & 0x3) | (((v >> 3) & 1) << 2));
    t.rs = at_least_1((v >> 16) & 0xF);
    t.ta = at_least_1((v >> 14) & 0x3);
    t.rst = at_least_1((v >> 8) & 0x3F);
    t.rh = at_least_1(v & 0x7);
    return t;
}

struct emif_pins {
    bool ce2_n = true, ce3_n = true, aoe_n = true, are_n = true, awe_n = true;
    uint32_t ea = 0;  // word address (AEA21..AEA2)
    uint8_t be_n = 0xF;
    uint32_t ed = 0;  // what the EMIF drives on ED
    bool ed_drive = false;
};

struct emif_access {
    enum class kind { read, write, foreign_read };  // foreign: CE0 (SDRAM side), not the card
    kind k = kind::read;
    uint32_t addr = 0;  // byte address: 0xA... (CE2) or 0xB... (CE3)
    uint32_t data = 0;  // write data, or the word read
    uint8_t be_n = 0;
    uint64_t tag = 0;  // free for the test
    // Measured (ECLK edge indices of the master).
    uint64_t setup_edge = 0;   // setup starts after this edge
    uint64_t strobe_edge = 0;  // S: strobe low after this edge
    uint64_t end_edge = 0;     // E: strobe rises after this edge; read data sampled here
    uint64_t done_edge = 0;    // the hold ends at this edge
    int wait_cycles = 0;       // strobe cycles added by ARDY
    bool ed_driven_at_sample = false;
};

class emif_master {
  public:
    explicit emif_master(emif_timing t, int ardy_lead = 1) : m_t(t), m_lead(ardy_lead) {}

    void set_timing(emif_timing t) { m_t = t; }
    void push(const emif_access& a) { m_queue.push_back(a); }
    bool idle() const { return m_phase == phase::idle && m_queue.empty(); }
    size_t queued() const { return m_queue.size(); }
    std::deque<emif_access>& done() { return m_done; }
    const emif_pins& pins() const { return m_pins; }
    uint64_t edges() const { return m_edge; }
    const emif_timing& timing() const { return m_t; }
    // Between the edge where ARE rose and the end of the hold of a read.
    bool in_read_hold() const { return m_phase == phase::hold && !is_write(m_cur); }
    const emif_access& current() const { return m_cur; }

    // One ECLKOUT rising edge: ardy / ed / ed_oe are the card's outputs just
    // before it. Afterwards pins() holds what the EMIF drives until the next edge.
    void edge(bool ardy, uint32_t ed, bool ed_oe) {
        ++m_edge;
        m_ardy_ring[m_edge % ring] = ardy;
        switch (m_phase) {
            case phase::idle:
                if (m_queue.empty()) break;
                m_cur = m_queue.front();
                m_queue.pop_front();
                if (m_have_last && needs_turnaround(m_cur)) {
                    const uint64_t idle_cycles = m_edge - m_last_done;
                    if (idle_cycles < static_cast<uint64_t>(m_t.ta)) {
                        m_count = m_t.ta - static_cast<int>(idle_cycles);
                        m_phase = phase::turnaround;
                        break;
                    }
                }
                begin_setup();
                break;
            case phase::turnaround:
                if (--m_count > 0) break;
                begin_setup();
                break;
            case phase::setup:
                if (--m_count > 0) break;
                m_phase = phase::strobe;
                m_cur.strobe_edge = m_edge;
                m_strobe_cycles = 0;
                if (is_write(m_cur))
                    m_pins.awe_n = false;
                else
                    m_pins.are_n = false;
                break;
            case phase::strobe: {
                ++m_strobe_cycles;
                const int programmed = is_write(m_cur) ? m_t.wst : m_t.rst;
                const bool ready = m_ardy_ring[(m_edge - m_lead) % ring];
                if (m_strobe_cycles >= programmed && ready) {
                    m_cur.end_edge = m_edge;
                    if (!is_write(m_cur)) {
                        m_cur.data = ed;
                        m_cur.ed_driven_at_sample = ed_oe;
                    }
                    m_pins.are_n = m_pins.awe_n = true;
                    m_phase = phase::hold;
                    m_count = is_write(m_cur) ? m_t.wh : m_t.rh;
                } else if (m_strobe_cycles >= programmed) {
                    ++m_cur.wait_cycles;
                }
                break;
            }
            case phase::hold:
                if (--m_count > 0) break;
                m_cur.done_edge = m_edge;
                m_done.push_back(m_cur);
                m_last = m_cur;
                m_have_last = true;
                m_last_done = m_edge;
                if (!m_queue.empty() && !needs_turnaround(m_queue.front())) {
                    m_cur = m_queue.front();
                    m_queue.pop_front();
                    begin_setup();
                } else {
                    m_phase = phase::idle;
                    m_pins = emif_pins{};
                    // The next access (if any) starts at the next edge, after TA.
                }
                break;
        }
    }

  private:
    enum class phase { idle, turnaround, setup, strobe, hold };
    static constexpr uint64_t ring = 16;

    static bool is_write(const emif_access& a) { return a.k == emif_access::kind::write; }
    static int space(const emif_access& a) {
        if (a.k == emif_access::kind::foreign_read) return 0;
        return (a.addr >> 28) == 0xA ? 2 : 3;
    }
    bool needs_turnaround(const emif_access& next) const {
        return !m_have_last || is_write(next) != is_write(m_last) || space(next) != space(m_last);
    }

    void begin_setup() {
        m_phase = phase::setup;
        m_count = is_write(m_cur) ? m_t.ws : m_t.rs;
        m_cur.setup_edge = m_edge;
        m_pins = emif_pins{};
        const int sp = space(m_cur);
        m_pins.ce2_n = sp != 2;
        m_pins.ce3_n = sp != 3;
        m_pins.ea = (m_cur.addr >> 2) & 0xFFFFF;
        if (is_write(m_cur)) {
            m_pins.be_n = m_cur.be_n;
            m_pins.ed = m_cur.data;
            m_pins.ed_drive = true;
        } else {
            m_pins.be_n = 0;
            m_pins.aoe_n = false;
        }
    }

    emif_timing m_t;
    int m_lead;
    std::deque<emif_access> m_queue, m_done;
    emif_access m_cur, m_last;
    bool m_have_last = false;
    uint64_t m_last_done = 0;
    phase m_phase = phase::idle;
    int m_count = 0;
    int m_strobe_cycles = 0;
    uint64_t m_edge = 0;
    bool m_ardy_ring[ring] = {};
    emif_pins m_pins;
};

}  // namespace rtl_test
