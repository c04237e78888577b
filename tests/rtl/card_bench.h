// Test bench around the verilated card (rtl/card_top.v, any parameter set):
// two test sensors on the master pixel clock, the EMIF master on ECLKOUT,
// monitors on OE and the interrupt pins, an EMIF protocol checker, and a DSP
// model that reads every frame pair after its FRAME_READY interrupt in the
// documented order and checks every word. Stepped cycle by cycle from C++
// (verilator --cc), clocks on the integer tick base.
//
// Per clock event: sample the card's outputs just before the edge (EMIF
// master, checker, monitors), raise the clocks and eval, then drive the new
// inputs (sensor pins, EMIF pins) and lower the clocks, eval again.
#pragma once

#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <vector>

#include "dsp/card_regs.h"
#include "tests/rtl/emif_master.h"
#include "tests/rtl/rtl_sim.h"
#include "tests/rtl/sensor_pins.h"

namespace rtl_test {

namespace regs = dsp::card_regs;

enum class read_order { interleaved_lines, left_then_right };

struct bench_options {
    sensor_layout layout = small_layout();
    uint64_t pclk_ticks = ticks_pclk_default;
    uint64_t eclk_ticks = ticks_eclk_v1;
    uint64_t pclk_phase = 0;
    uint64_t eclk_phase = 7;  // no common start edge
    uint32_t cectl = regs::cectl_v1;
    int ardy_lead = 1;
    int sensor_latency = 100;  // pclk from OE to the first frame
    int seed = 1;
    const char* design = "card";
};

// Level history of one interrupt pin, sampled at every ECLK edge.
struct irq_monitor {
    std::vector<uint64_t> rise_ticks;
    uint64_t min_high = UINT64_MAX, min_low = UINT64_MAX;  // ECLK cycles (low: between pulses)
    bool level = false;
    uint64_t run = 0;
    bool seen_rise = false;

    void sample(bool now, uint64_t tick) {
        if (now == level) {
            ++run;
            return;
        }
        if (level && run < min_high) min_high = run;
        if (!level && seen_rise && run < min_low) min_low = run;
        if (now) {
            rise_ticks.push_back(tick);
            seen_rise = true;
        }
        level = now;
        run = 1;
    }
};

template <class Model>
class card_bench {
  public:
    explicit card_bench(const bench_options& o)
        : opt(o),
          left(o.layout, 0, o.sensor_latency),
          right(o.layout, 1, o.sensor_latency),
          master(decode_cectl(o.cectl), o.ardy_lead),
          m_context(std::make_unique<VerilatedContext>()),
          m_clocks(o.pclk_ticks, o.eclk_ticks, o.pclk_phase, o.eclk_phase) {
        m_context->randSeed(o.seed);
        m_dut = std::make_unique<Model>(m_context.get(), "card");
        Model& d = *m_dut;
        d.pclk = d.eclk = 0;
        d.rst_n = 1;
        apply_emif_pins();
        d.eval();
        d.rst_n = 0;  // a falling edge: the asynchronous resets act
        d.eval();
        d.rst_n = 1;
        d.eval();
    }
    ~card_bench() {
        m_dut->final();
        write_coverage(*m_context, opt.design);
    }
    card_bench(const card_bench&) = delete;
    card_bench& operator=(const card_bench&) = delete;

    Model& dut() { return *m_dut; }
    VerilatedContext& context() { return *m_context; }
    uint64_t now() const { return m_clocks.now(); }
    uint64_t pclk_edges() const { return m_pclk_edges; }
    uint64_t eclk_edges() const { return m_eclk_edges; }
    // Tick at which the sensors drove the pins of step `cycle` (after pclk edge cycle + 1).
    uint64_t drive_tick(uint64_t cycle) const { return opt.pclk_phase + cycle * opt.pclk_ticks; }
    // Tick of the pclk edge at which the card samples the pins of step `cycle`.
    uint64_t sample_tick(uint64_t cycle) const { return drive_tick(cycle) + opt.pclk_ticks; }

    // ---- one clock event ------------------------------------------------------------------
    void step() {
        Model& d = *m_dut;
        const unsigned edges = m_clocks.advance();
        const uint64_t t = m_clocks.now();
        const bool p_edge = edges & two_clocks::edge_a;
        const bool e_edge = edges & two_clocks::edge_b;

        if (e_edge) {
            check_emif_pins();
            if (trace_bus) ardy_trace.push_back(d.ardy);
            int4.sample(d.ext_int4, t);
            int5.sample(d.ext_int5, t);
            int6.sample(d.ext_int6, t);
            master.edge(d.ardy, d.ed_out, d.ed_oe);
        }
        if (p_edge) d.pclk = 1;
        if (e_edge) d.eclk = 1;
        d.eval();
        if (after_eval) after_eval();

        if (p_edge) {
            ++m_pclk_edges;
            const bool oe = d.sensor_oe;
            if (oe != m_oe_level) {
                (oe ? oe_rise_edges : oe_fall_edges).push_back(m_pclk_edges);
                m_oe_level = oe;
            }
            // The sensors sample OE at this edge: the value the card drove before it.
            const sensor_pin_state l = left.step(m_oe_seen);
            const sensor_pin_state r = right.step(m_oe_seen);
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
            ++m_eclk_edges;
            apply_emif_pins();
            if (reader_enabled) feed_reader();
            if (on_eclk) on_eclk();
        }
        d.pclk = 0;
        d.eclk = 0;
        d.eval();
        if (after_eval) after_eval();
    }

    template <class Pred>
    bool run_until(Pred done, uint64_t max_ticks) {
        const uint64_t limit = now() + max_ticks;
        while (!done()) {
            if (now() >= limit) return false;
            step();
        }
        return true;
    }
    void run_ticks(uint64_t ticks) {
        const uint64_t limit = now() + ticks;
        while (now() < limit) step();
    }
    void run_frames(double frames) {
        run_ticks(static_cast<uint64_t>(frames * opt.layout.frame_pclks() * opt.pclk_ticks));
    }

    // ---- register access through the EMIF (blocking) --------------------------------------
    emif_access access(emif_access a) {
        a.tag = (uint64_t{1} << 62) | ++m_access_serial;
        master.push(a);
        auto& done = master.done();
        auto find = [&] {
            for (auto it = done.begin(); it != done.end(); ++it)
                if (it->tag == a.tag) return it;
            return done.end();
        };
        if (!run_until([&] { return find() != done.end(); }, uint64_t{200000} * opt.eclk_ticks)) {
            ++timeouts;
            return a;
        }
        const auto it = find();
        const emif_access r = *it;
        done.erase(it);
        return r;
    }
    uint32_t read_reg(uint32_t offset) {
        emif_access a;
        a.k = emif_access::kind::read;
        a.addr = regs::ce2_base + offset;
        return access(a).data;
    }
    void write_reg(uint32_t offset, uint32_t value, uint8_t be_n = 0) {
        emif_access a;
        a.k = emif_access::kind::write;
        a.addr = regs::ce2_base + offset;
        a.data = value;
        a.be_n = be_n;
        access(a);
    }
    void configure_layout(const sensor_layout& l) {
        write_reg(regs::h_start, l.h_start);
        write_reg(regs::dark_cols_left, l.dark_left);
        write_reg(regs::border_cols_left, l.border_left);
        write_reg(regs::active_cols, l.active_cols);
        write_reg(regs::border_cols_right, l.border_right);
        write_reg(regs::dark_cols_right, l.dark_right);
        write_reg(regs::line_total, l.line_total);
        write_reg(regs::v_start, l.v_start);
        write_reg(regs::dark_rows_top, l.dark_top);
        write_reg(regs::border_rows_top, l.border_top);
        write_reg(regs::active_rows, l.active_rows);
        write_reg(regs::border_rows_bottom, l.border_bottom);
        write_reg(regs::dark_rows_bottom, l.dark_bottom);
        write_reg(regs::frame_lines, l.frame_lines);
    }
    void enable(bool on) { write_reg(regs::ctrl, on ? regs::ctrl_enable_mask : 0); }

    // ---- DSP model: reads each pair after FRAME_READY and checks every word ----------------
    bool reader_enabled = false;
    uint64_t reader_budget = UINT64_MAX;  // total words the DSP model may queue (a stall)
    read_order order = read_order::interleaved_lines;
    struct pair_record {
        uint32_t serial_l = 0, serial_r = 0;
        uint64_t irq_tick = 0, first_read_tick = 0, last_read_tick = 0;
        uint64_t bad_words = 0;
    };
    std::vector<pair_record> pairs;  // pairs read, in order
    uint64_t words_read = 0;

    // Words still to be queued for the pair being read.
    uint64_t reads_pending() const { return m_to_queue; }

    irq_monitor int4, int5, int6;
    std::vector<uint64_t> oe_rise_edges, oe_fall_edges;  // pclk edge numbers
    uint64_t ed_conflicts = 0;                           // card and EMIF drive ED in the same cycle
    uint64_t ed_outside_ce = 0;                          // card drives ED without its CE and AOE
    uint64_t ardy_outside_ce = 0;                        // card pulls ARDY low without its CE
    uint64_t ed_hold_errors = 0;                         // read data not held on ED during the hold
    bool trace_bus = false;
    std::vector<uint8_t> ardy_trace;  // ARDY before master edge n is ardy_trace[n - 1]
    uint64_t timeouts = 0;
    std::function<void()> on_eclk;
    std::function<void()> after_eval;  // after each eval of step() (a shadow model follows)

    bench_options opt;
    test_sensor left, right;
    emif_master master;

  private:
    void apply_emif_pins() {
        Model& d = *m_dut;
        const emif_pins& p = master.pins();
        d.ce2_n = p.ce2_n;
        d.ce3_n = p.ce3_n;
        d.aoe_n = p.aoe_n;
        d.are_n = p.are_n;
        d.awe_n = p.awe_n;
        d.ea = p.ea;
        d.be_n = p.be_n;
        d.ed_in = p.ed;
    }

    void check_emif_pins() {
        Model& d = *m_dut;
        const emif_pins& p = master.pins();
        const bool card_selected = !p.ce2_n || !p.ce3_n;
        if (d.ed_oe && p.ed_drive) ++ed_conflicts;
        if (d.ed_oe && !(card_selected && !p.aoe_n)) ++ed_outside_ce;
        if (!d.ardy && !card_selected) ++ardy_outside_ce;
        // Read data stays on ED through the hold (data hold after ARE rises).
        if (master.in_read_hold() && card_selected &&
            (!d.ed_oe || d.ed_out != master.current().data))
            ++ed_hold_errors;
    }

    // Queue one pair's reads when FRAME_READY rose, a line (or a sensor's
    // frame) at a time, keeping the EMIF busy back to back.
    void feed_reader() {
        if (int4.rise_ticks.size() > m_irqs_taken && m_to_queue == 0 && m_in_flight == 0) {
            ++m_irqs_taken;
            m_to_queue = 2ull * opt.layout.words_per_frame();
            m_queued = 0;
            pairs.push_back({});
            pairs.back().irq_tick = int4.rise_ticks[m_irqs_taken - 1];
            m_pair_first = true;
        }
        while (m_to_queue > 0 && master.queued() < 8 && m_total_queued < reader_budget) {
            const uint64_t wpl = opt.layout.words_per_line();
            const uint64_t wpf = opt.layout.words_per_frame();
            uint64_t line, word;
            int cam;
            if (order == read_order::interleaved_lines) {
                line = m_queued / (2 * wpl);
                cam = static_cast<int>((m_queued / wpl) % 2);
                word = m_queued % wpl;
            } else {
                cam = m_queued < wpf ? 0 : 1;
                line = (m_queued % wpf) / wpl;
                word = m_queued % wpl;
            }
            emif_access a;
            a.k = emif_access::kind::read;
            a.addr = (cam ? regs::data_right : regs::data_left) +
                     4 * static_cast<uint32_t>(line * wpl + word);
            a.tag = (uint64_t{1} << 63) | (uint64_t(cam) << 40) | (line << 20) | word;
            master.push(a);
            ++m_queued;
            ++m_total_queued;
            --m_to_queue;
            ++m_in_flight;
        }
        auto& done = master.done();
        for (auto it = done.begin(); it != done.end();) {
            if (it->tag >> 63) {
                check_read(*it);
                it = done.erase(it);
            } else {
                ++it;
            }
        }
    }

    void check_read(const emif_access& a) {
        --m_in_flight;
        ++words_read;
        pair_record& pr = pairs.back();
        const int cam = static_cast<int>((a.tag >> 40) & 1);
        const int line = static_cast<int>((a.tag >> 20) & 0xFFFFF);
        const int word = static_cast<int>(a.tag & 0xFFFFF);
        if (m_pair_first) pr.first_read_tick = now();
        pr.last_read_tick = now();
        uint32_t& serial = cam ? pr.serial_r : pr.serial_l;
        bool& known = cam ? m_serial_known_r : m_serial_known_l;
        if (line == 0 && word == 0) {
            // Which frame is it? Search from the previous pair's serial on (a
            // frame sent twice comes again). Candidates: later frames of the
            // same OE start, or early frames of later starts.
            known = false;
            uint32_t from = 0;
            if (pairs.size() > 1) {
                const pair_record& prev = pairs[pairs.size() - 2];
                from = cam ? prev.serial_r : prev.serial_l;
            }
            const uint32_t start0 = from / frames_per_start;
            for (uint32_t st = start0; st < start0 + 16 && !known; ++st) {
                const uint32_t f0 = st == start0 ? from % frames_per_start : 0;
                for (uint32_t f = f0; f < f0 + 64; ++f) {
                    if (active_word(cam, frame_serial(st, f), 0, 0) == a.data) {
                        serial = frame_serial(st, f);
                        known = true;
                        break;
                    }
                }
            }
        }
        m_pair_first = false;
        if (!known || active_word(cam, serial, line, word) != a.data) ++pr.bad_words;
    }

    std::unique_ptr<VerilatedContext> m_context;
    std::unique_ptr<Model> m_dut;
    two_clocks m_clocks;
    uint64_t m_pclk_edges = 0, m_eclk_edges = 0;
    bool m_oe_seen = false, m_oe_level = false;
    size_t m_irqs_taken = 0;
    uint64_t m_to_queue = 0, m_queued = 0, m_in_flight = 0, m_total_queued = 0;
    bool m_pair_first = false;
    bool m_serial_known_l = false, m_serial_known_r = false;
    uint64_t m_access_serial = 0;
};

}  // namespace rtl_test
