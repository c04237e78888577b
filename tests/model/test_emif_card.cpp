// The EMIF engine against the verilated daughter card (rtl/card_top.v,
// 512-word FIFOs: rtl_card_small, verilator --cc), both clocked from C++ on
// the same ECLKOUT, the card's sensors on the 120/7 MHz pixel clock: proof
// that the engine and the card agree on the pin protocol.
//   - register reads and writes on CE2 (ID, read back, byte enables) take
//     exactly RS + RST + RH / WS + WST + WH = 14 ECLK at 0x22A28A22 with no
//     wait state, and TA on every direction change;
//   - the card is configured and enabled through the engine; after its
//     FRAME_READY interrupt EDMA bursts read pixel words from both ports
//     (incrementing and fixed address): every word is the test sensor's
//     pixel word of one frame;
//   - with a read strobe shorter than the card's ready time the card's ARDY
//     stretches it to exactly read_latency 2 + 1 + ardy_lead 1 = 4 cycles
//     (tests/model/test_emif_ardy.cpp's closed form), and the data is right;
//   - the protocol checker is silent, the card never drives ED with the EMIF.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <vector>

#include "Vcard_small.h"
#include "dsp/card_regs.h"
#include "model/emif/emif_async_master.h"
#include "model/emif/emif_checker.h"
#include "tests/rtl/rtl_sim.h"
#include "tests/rtl/sensor_pins.h"

using namespace emif;
namespace regs = dsp::card_regs;

namespace {

constexpr uint64_t eclk_phase = 7;  // no common start edge with pclk

// Card + sensors + engine, one clock event per call of step().
class card_rig : public emif_pin_observer {
  public:
    explicit card_rig(uint32_t cectl = cectl_dsk_v1)
        : layout(rtl_test::small_layout()),
          left(layout, 0, 100),
          right(layout, 1, 100),
          m_cfg(make_config(cectl)),
          engine(m_cfg),
          checker(m_cfg.cectl),
          m_context(std::make_unique<VerilatedContext>()),
          m_clocks(rtl_test::ticks_pclk_default, rtl_test::ticks_eclk_v1, 0, eclk_phase) {
        m_context->randSeed(1);
        m_card = std::make_unique<Vcard_small>(m_context.get(), "card");
        engine.set_observer(this);
        Vcard_small& d = *m_card;
        d.pclk = d.eclk = 0;
        d.rst_n = 0;
        apply_pins();
        d.eval();
        d.rst_n = 1;
        d.eval();
    }
    ~card_rig() override { m_card->final(); }

    void observe(uint64_t edge, const emif_pins& p, const emif_inputs& in) override {
        checker.observe(edge, p, in);
        strobe_lengths_track(edge, p);
    }

    void step() {
        Vcard_small& d = *m_card;
        const unsigned edges = m_clocks.advance();
        const bool p_edge = edges & rtl_test::two_clocks::edge_a;
        const bool e_edge = edges & rtl_test::two_clocks::edge_b;
        emif_inputs in;
        if (e_edge) {  // the card's outputs just before the edge, and who drives ED
            in.ed_in = d.ed_out;
            in.ardy = d.ardy;
            const emif_pins& p = engine.pins();
            const int ce = p.active_ce();
            if (d.ed_oe && p.ed_oe) ++ed_conflicts;
            if (d.ed_oe && !((ce == 2 || ce == 3) && !p.aoe_n)) ++ed_outside_read;
        }
        if (p_edge) d.pclk = 1;
        if (e_edge) d.eclk = 1;
        d.eval();  // the card samples the pins of the last cycle
        if (p_edge) {
            const bool oe = d.sensor_oe;
            const rtl_test::sensor_pin_state l = left.step(m_oe_seen);
            const rtl_test::sensor_pin_state r = right.step(m_oe_seen);
            m_oe_seen = oe;
            d.l_vsync = l.vsync;
            d.l_href = l.href;
            d.l_valid = l.valid;
            d.l_data = l.data;
            d.l_fodd = l.fodd;
            d.r_vsync = r.vsync;
            d.r_href = r.href;
            d.r_valid = r.valid;
            d.r_data = r.data;
            d.r_fodd = r.fodd;
        }
        if (e_edge) {
            engine.step(in);  // samples `in`, drives the next cycle's pins
            apply_pins();
            if (d.ext_int4 && !m_int4) ++frame_ready_pulses;
            m_int4 = d.ext_int4;
        }
        d.pclk = 0;
        d.eclk = 0;
        d.eval();
    }

    // Runs one access to completion (or times out).
    bool run(emif_access& a, uint64_t max_events = 200000) {
        if (!engine.submit(a)) return false;
        for (uint64_t n = 0; n < max_events && a.status == access_status::pending; ++n) step();
        return a.status == access_status::ok;
    }
    uint32_t read(uint32_t address, emif_access* out = nullptr) {
        uint8_t b[4] = {};
        emif_access a;
        a.address = address;
        a.data = b;
        EXPECT_TRUE(run(a)) << std::hex << address;
        if (out) *out = a;
        return b[0] | b[1] << 8 | b[2] << 16 | uint32_t(b[3]) << 24;
    }
    emif_access write(uint32_t address, uint32_t value, uint8_t be_n = 0) {
        uint8_t b[4] = {static_cast<uint8_t>(value), static_cast<uint8_t>(value >> 8),
                        static_cast<uint8_t>(value >> 16), static_cast<uint8_t>(value >> 24)};
        emif_access a;
        a.write = true;
        a.address = address;
        a.data = b;
        a.be_n = be_n;
        EXPECT_TRUE(run(a)) << std::hex << address;
        a.data = nullptr;
        return a;
    }
    template <class Pred>
    bool run_until(Pred done, uint64_t max_events) {
        for (uint64_t n = 0; n < max_events; ++n) {
            if (done()) return true;
            step();
        }
        return done();
    }

    rtl_test::sensor_layout layout;
    rtl_test::test_sensor left, right;

  private:
    static emif_config make_config(uint32_t cectl) {
        emif_config c;
        c.eclk =
            simtime::tick_clock(simtime::rational_ticks{rtl_test::ticks_eclk_v1, 1}, eclk_phase);
        c.cectl[2] = c.cectl[3] = cectl;
        c.sdram.refresh_period = 0;  // no SDRAM here
        return c;
    }
    void apply_pins() {
        Vcard_small& d = *m_card;
        const emif_pins& p = engine.pins();
        d.ce2_n = p.ce_n[2];
        d.ce3_n = p.ce_n[3];
        d.aoe_n = p.aoe_n;
        d.are_n = p.are_n;
        d.awe_n = p.awe_n;
        d.ea = p.ea;
        d.be_n = p.be_n;
        d.ed_in = p.ed_out;
    }
    void strobe_lengths_track(uint64_t e, const emif_pins& p) {
        const bool low = !p.are_n || !p.awe_n;
        if (low && !m_strobe_low) m_strobe_start = e;
        if (!low && m_strobe_low) strobe_lengths.push_back(e - m_strobe_start);
        m_strobe_low = low;
    }

    emif_config m_cfg;

  public:
    emif_async_master engine;
    emif_checker checker;
    std::vector<uint64_t> strobe_lengths;
    uint64_t ed_conflicts = 0, ed_outside_read = 0, frame_ready_pulses = 0;

  private:
    std::unique_ptr<VerilatedContext> m_context;
    std::unique_ptr<Vcard_small> m_card;
    rtl_test::two_clocks m_clocks;
    bool m_oe_seen = false, m_int4 = false, m_strobe_low = false;
    uint64_t m_strobe_start = 0;
};

uint32_t word_of(const std::vector<uint8_t>& d, size_t i) {
    return d[4 * i] | d[4 * i + 1] << 8 | d[4 * i + 2] << 16 | uint32_t(d[4 * i + 3]) << 24;
}

// Which frame serial starts with this word (the sensors number every frame).
int serial_of(int cam, uint32_t first_word) {
    for (uint32_t s = 0; s < 64; ++s)
        if (rtl_test::active_word(cam, s, 0, 0) == first_word) return static_cast<int>(s);
    return -1;
}

}  // namespace

TEST(emif_card, registers_over_the_pins_in_14_eclk_per_word) {
    card_rig rig;
    emif_access a;
    EXPECT_EQ(rig.read(regs::ce2_base + regs::id, &a), regs::id_reset);
    EXPECT_EQ(a.done_edge - a.grant_edge, 14u);
    EXPECT_EQ(a.wait_cycles, 0u);

    // Write after read on CE2: TA 2 first (the read ended one edge earlier: 1 left).
    const emif_access w = rig.write(regs::ce2_base + regs::h_start, 0x0000ABCD);
    EXPECT_EQ(w.turnaround_cycles, 1u);
    EXPECT_EQ(w.done_edge - w.grant_edge, 1u + 14);
    EXPECT_EQ(rig.read(regs::ce2_base + regs::h_start), 0x0000ABCDu);
    // Byte 1 only (ABE1 low): the card keeps byte 0.
    rig.write(regs::ce2_base + regs::h_start, 0x00001100, 0xD);
    EXPECT_EQ(rig.read(regs::ce2_base + regs::h_start), 0x000011CDu);
    rig.write(regs::ce2_base + regs::dark_threshold, 0x2A);
    EXPECT_EQ(rig.read(regs::ce2_base + regs::dark_threshold), 0x2Au);
    for (uint64_t len : rig.strobe_lengths) EXPECT_EQ(len, 10u);
    EXPECT_EQ(rig.checker.total(), 0u);
    for (const violation& v : rig.checker.violations()) ADD_FAILURE() << to_string(v);
    EXPECT_EQ(rig.ed_conflicts, 0u);
    EXPECT_EQ(rig.ed_outside_read, 0u);
    std::printf("card registers: read %llu ECLK, write %llu ECLK, %zu strobes all 10 ECLK\n",
                (unsigned long long)(a.done_edge - a.grant_edge),
                (unsigned long long)(w.done_edge - w.grant_edge - w.turnaround_cycles),
                rig.strobe_lengths.size());
}

TEST(emif_card, pixel_ports_deliver_the_sensor_frame_words_after_frame_ready) {
    card_rig rig;
    const rtl_test::sensor_layout& l = rig.layout;
    const std::pair<uint32_t, uint32_t> layout_regs[] = {
        {regs::h_start, l.h_start},
        {regs::dark_cols_left, l.dark_left},
        {regs::border_cols_left, l.border_left},
        {regs::active_cols, l.active_cols},
        {regs::border_cols_right, l.border_right},
        {regs::dark_cols_right, l.dark_right},
        {regs::line_total, l.line_total},
        {regs::v_start, l.v_start},
        {regs::dark_rows_top, l.dark_top},
        {regs::border_rows_top, l.border_top},
        {regs::active_rows, l.active_rows},
        {regs::border_rows_bottom, l.border_bottom},
        {regs::dark_rows_bottom, l.dark_bottom},
        {regs::frame_lines, l.frame_lines}};
    for (const auto& [offset, value] : layout_regs) rig.write(regs::ce2_base + offset, value);
    for (const auto& [offset, value] : layout_regs)
        EXPECT_EQ(rig.read(regs::ce2_base + offset), value) << offset;
    rig.write(regs::ce2_base + regs::ctrl, regs::ctrl_enable_mask);

    const uint64_t frame_events = l.frame_pclks() * (1 + 1050 / 180);
    ASSERT_TRUE(rig.run_until([&] { return rig.frame_ready_pulses > 0; }, 6 * frame_events));
    const uint32_t level_l = rig.read(regs::ce2_base + regs::level_l);
    EXPECT_GE(level_l, static_cast<uint32_t>(l.words_per_frame()));

    // Line 0 of the left frame, incrementing addresses inside the port window.
    const uint32_t words = static_cast<uint32_t>(l.words_per_line());
    std::vector<uint8_t> left(4 * words), right(4 * words);
    emif_access bl;
    bl.who = requester::edma;
    bl.address = regs::data_left;
    bl.words = words;
    bl.data = left.data();
    ASSERT_TRUE(rig.run(bl));
    // Line 0 of the right frame from one fixed address (a FIFO port).
    emif_access br = bl;
    br.address = regs::data_right;
    br.increment = false;
    br.data = right.data();
    ASSERT_TRUE(rig.run(br));
    // CE2 -> CE3: TA 2, one edge of it already idle (the burst was queued
    // one edge after the last register read ended).
    EXPECT_EQ(bl.turnaround_cycles, 1u);
    EXPECT_EQ(bl.done_edge - bl.grant_edge, 1 + 14ull * words);
    EXPECT_EQ(br.turnaround_cycles, 0u);
    EXPECT_EQ(br.done_edge - br.grant_edge, 14ull * words);
    EXPECT_EQ(bl.wait_cycles + br.wait_cycles, 0u);

    const int serial_l = serial_of(0, word_of(left, 0));
    const int serial_r = serial_of(1, word_of(right, 0));
    ASSERT_GE(serial_l, 0) << "first left word is no frame's first word";
    EXPECT_EQ(serial_l, serial_r);
    for (uint32_t w = 0; w < words; ++w) {
        EXPECT_EQ(word_of(left, w), rtl_test::active_word(0, serial_l, 0, w)) << w;
        EXPECT_EQ(word_of(right, w), rtl_test::active_word(1, serial_r, 0, w)) << w;
    }
    EXPECT_EQ(rig.read(regs::ce2_base + regs::level_l), level_l - words);
    EXPECT_EQ(rig.read(regs::ce2_base + regs::underflows), 0u);
    EXPECT_EQ(rig.checker.total(), 0u);
    for (const violation& v : rig.checker.violations()) ADD_FAILURE() << to_string(v);
    EXPECT_EQ(rig.ed_conflicts, 0u);
    EXPECT_EQ(rig.ed_outside_read, 0u);
    std::printf(
        "frame serial %d: %u words per port read after FRAME_READY (level %u), "
        "%llu ECLK per burst\n",
        serial_l, words, level_l, (unsigned long long)(br.done_edge - br.grant_edge));
}

TEST(emif_card, card_ardy_stretches_a_short_read_strobe_to_four_cycles) {
    for (uint32_t rst : {1u, 2u, 3u, 4u, 5u}) {
        cectl_fields f = cectl_unpack(cectl_dsk_v1);
        f.rdstrb = rst;
        card_rig rig(cectl_pack(f));
        rig.write(regs::ce2_base + regs::dark_threshold, 0x5C);
        emif_access a;
        EXPECT_EQ(rig.read(regs::ce2_base + regs::dark_threshold, &a), 0x5Cu) << "RST " << rst;
        EXPECT_EQ(rig.read(regs::ce2_base + regs::id), regs::id_reset);
        const uint32_t expected = std::max(rst, 4u);
        ASSERT_EQ(rig.strobe_lengths.size(), 3u);
        EXPECT_EQ(rig.strobe_lengths[1], expected) << "RST " << rst;
        EXPECT_EQ(a.wait_cycles, expected - rst);
        EXPECT_EQ(rig.checker.total(), 0u);
        std::printf("card, RST %u: read strobe %llu ECLK (%u wait states from ARDY)\n", rst,
                    (unsigned long long)rig.strobe_lengths[1], a.wait_cycles);
    }
}
