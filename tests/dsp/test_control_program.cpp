// The firmware's control program (dsp/control_program.h) against a plain
// C++ stand-in for the platform: a test HAL with an event-driven clock
// (600 MHz CPU, 24.5 ms frames), the daughter card's documented register
// behaviour (docs/card-registers.md: CTRL / STATUS / IRQ_STATUS / VERDICT /
// PAIRS_OK ..., FIFO pixel ports, EXT_INT4/5/6 pulses), and an EDMA
// channel controller written here from the C64x rules (PaRAM OPT / SRC /
// CNT / DST / IDX / RLD, ER / EER, completion codes, CCER chaining, LINK
// reload, CIER -> INT8), independent of the model's edma_core. The card's
// frames are scripted: good, sync error, FIFO overflow, or (not something
// the real card does) ready with a bad verdict, to test the firmware's own
// check. Every frame's pixels are a known function of its frame number, so
// the test knows which sensor frame each processed buffer holds.
//
// The real card RTL and the SystemC model replace the stand-in in the
// platform task. tests/support/heap_counter proves the frame loop allocates
// nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <vector>

#include "dsp/card_regs.h"
#include "dsp/control_program.h"
#include "model/c6416/c6416_regs.h"
#include "tests/support/heap_counter.h"
#include "tests/support/host/counting_hal.h"
#include "tests/support/host/scenarios.h"
#include "tests/support/host/stereo_runner.h"

namespace {

namespace regs = c6416;
namespace card = dsp::card_regs;
using dsp::firmware_event;

constexpr int64_t ticks_per_us = 18000;  // 1 tick = 1/18 ns (model/time/ticks.h)
constexpr int64_t ticks_per_ms = 1000 * ticks_per_us;

enum class outcome : uint8_t { good, sync_error, overflow, bad_verdict };

// The pixels of sensor frame `frame`: a pattern that differs per frame,
// side and position, or pre-rendered raw images.
struct frame_content {
    const std::vector<scene::gray_image>* left = nullptr;
    const std::vector<scene::gray_image>* right = nullptr;

    uint8_t pixel(uint32_t frame, int side, int x, int y) const {
        if (left) {
            const std::vector<scene::gray_image>& images = side == 0 ? *left : *right;
            return images[frame % images.size()].at(x, y);
        }
        return static_cast<uint8_t>(frame * 37u + static_cast<uint32_t>(side) * 101u +
                                    static_cast<uint32_t>(x) * 7u + static_cast<uint32_t>(y) * 13u);
    }
};

struct platform_config {
    int width = 64;
    int height = 48;
    int64_t cpu_period = 30;                      // ticks: 600 MHz (DSK v1)
    int64_t frame_period = 24500 * ticks_per_us;  // docs/design-brief.md: one sensor frame
    int64_t start_latency = 2 * ticks_per_ms;     // OE rise to the first frame's start
    int64_t first_start_latency = 0;              // the first OE only, if set (a silent card)
    int64_t restart_gap = 24500 * ticks_per_us;   // card's OE restart after a mismatch
    int64_t word_ticks = 14 * 180;  // one card word over EMIFA v1: RS+RST+RH = 14 ECLK of 10 ns
    int64_t stop_at = 0;            // stop_requested from this tick on (0: never)
    int64_t extra_preprocess_ticks = 0;  // a slow CPU: added to every preprocess charge
    uint32_t fifo_words = 1u << 17;      // card FIFO depth per side (FIFO_DEPTH)
    uint32_t card_id = card::id_reset;
    std::vector<outcome> script;  // outcome of sensor frame f (beyond its end: good)
    frame_content content;
};

struct logged_event {
    int64_t time;
    dsp::event_record e;
};

struct stage_mark {
    int64_t time;
    dsp::stage s;
    bool begin;
};

class stand_in final : public dsp::hal {
  public:
    explicit stand_in(const platform_config& config)
        : m_cfg(config), m_l2(regs::l2_bytes, 0), m_sdram(regs::sdram_bytes, 0) {
        // Logs are reserved so the frame loop's own allocations stay countable.
        events.reserve(4096);
        stages.reserve(16384);
        results.reserve(1024);
        ctrl_writes.reserve(256);
        ready_time.reserve(1024);
        frame_of_pair.reserve(1024);
        ready_time.push_back(0);  // pair numbers start at 1
        frame_of_pair.push_back(0);
        processed_pair.reserve(1024);
        processed_frame.reserve(1024);
        processed_end.reserve(1024);
        card_regs_[card::dark_threshold / 4] = card::dark_threshold_reset;
        card_regs_[card::irq_enable / 4] = card::irq_enable_reset;
        card_regs_[card::retry_limit / 4] = card::retry_limit_reset;
    }

    // ---- dsp::hal --------------------------------------------------------------------------
    void charge_cycles(dsp::stage s, uint64_t cycles) override {
        int64_t t = static_cast<int64_t>(cycles) * m_cfg.cpu_period;
        if (s == dsp::stage::preprocess) t += m_cfg.extra_preprocess_ticks;
        if (m_open_stage != static_cast<int>(s)) ++protocol_errors;
        cycles_charged[static_cast<int>(s)] += cycles;
        advance_to(m_now + t);
    }
    void stage_begin(dsp::stage s) override {
        if (m_open_stage >= 0) ++protocol_errors;
        m_open_stage = static_cast<int>(s);
        stages.push_back({m_now, s, true});
    }
    void stage_end(dsp::stage s) override {
        if (m_open_stage != static_cast<int>(s)) ++protocol_errors;
        m_open_stage = -1;
        stages.push_back({m_now, s, false});
    }
    uint32_t read32(uint32_t address) override {
        if (uint8_t* p = memory(address, 4)) {
            uint32_t v;
            std::memcpy(&v, p, 4);
            return v;
        }
        if (address >= card::ce2_base && address < card::ce3_base) {
            advance_to(m_now + m_cfg.word_ticks);
            return card_read(address - card::ce2_base);
        }
        if (address >= card::ce3_base && address < card::ce3_base + 2 * card::data_window_bytes) {
            advance_to(m_now + m_cfg.word_ticks);
            return fifo_pop(address >= card::data_right ? 1 : 0);
        }
        uint32_t v = 0;
        if (peripheral_read(address, v)) return v;
        ++bad_accesses;
        return 0;
    }
    void write32(uint32_t address, uint32_t value) override {
        if (uint8_t* p = memory(address, 4)) {
            std::memcpy(p, &value, 4);
            return;
        }
        if (address >= card::ce2_base && address < card::ce3_base) {
            advance_to(m_now + m_cfg.word_ticks);
            card_write(address - card::ce2_base, value);
            return;
        }
        if (peripheral_write(address, value)) return;
        ++bad_accesses;
    }
    uint8_t* memory(uint32_t address, uint32_t bytes) override {
        const uint64_t end = uint64_t{address} + bytes;
        if (end <= regs::l2_bytes) return &m_l2[address];
        if (address >= regs::sdram_base && end <= regs::sdram_base + uint64_t{regs::sdram_bytes}) {
            return &m_sdram[address - regs::sdram_base];
        }
        return nullptr;
    }
    void set_interrupt_enable(uint32_t ier) override { m_ier = ier; }
    uint32_t interrupt_flags() override { return m_ifr; }
    void clear_interrupt_flags(uint32_t mask) override { m_ifr &= ~mask; }
    int wait_for_interrupt() override {
        for (;;) {
            const uint32_t pending = m_ifr & m_ier & 0xFFF0u;
            if (pending) {
                int n = 4;
                while (!((pending >> n) & 1u)) ++n;
                m_ifr &= ~(1u << n);
                return n;
            }
            if (stop_requested() || !run_next_event()) return no_interrupt;
        }
    }
    void report(const dsp::event_record& e) override {
        events.push_back({m_now, e});
        if (e.kind != firmware_event::pair_processed || !program) return;
        // The buffer still holds the pair: it is freed after this report.
        const uint32_t frame = e.pair < frame_of_pair.size() ? frame_of_pair[e.pair] : ~0u;
        if (!buffer_holds(program->left_address(static_cast<int>(e.value)),
                          program->right_address(static_cast<int>(e.value)), frame)) {
            ++content_mismatches;
        }
        processed_pair.push_back(e.pair);
        processed_frame.push_back(frame);
        processed_end.push_back(m_now);
    }
    void report_result(uint32_t /*pair*/, const dsp::frame_output& out) override {
        results.push_back(out);
    }
    bool stop_requested() override { return m_cfg.stop_at != 0 && m_now >= m_cfg.stop_at; }

    // ---- inspection ------------------------------------------------------------------------
    int64_t now() const { return m_now; }
    uint32_t emifa_register(uint32_t address) const { return m_emifa[(address & 0x7Fu) / 4]; }
    uint32_t muxl() const { return m_muxl; }
    uint32_t muxh() const { return m_muxh; }
    uint32_t card_register(uint32_t offset) const { return card_regs_[offset / 4]; }
    uint32_t pairs_ok() const { return m_pairs_ok; }
    uint32_t frames_completed() const { return m_frame_counter; }
    int count(firmware_event k) const {
        int n = 0;
        for (const logged_event& le : events) n += le.e.kind == k;
        return n;
    }
    // The pixels of frame `frame` in a buffer (what a capture should leave).
    bool buffer_holds(uint32_t left_address, uint32_t right_address, uint32_t frame) {
        const uint8_t* l = memory(left_address, 1);
        const uint8_t* r = memory(right_address, 1);
        for (int y = 0; y < m_cfg.height; ++y) {
            for (int x = 0; x < m_cfg.width; ++x) {
                const int i = y * m_cfg.width + x;
                if (l[i] != m_cfg.content.pixel(frame, 0, x, y)) return false;
                if (r[i] != m_cfg.content.pixel(frame, 1, x, y)) return false;
            }
        }
        return true;
    }

    const dsp::control_program* program = nullptr;  // for the buffer addresses
    std::vector<logged_event> events;
    std::vector<stage_mark> stages;
    std::vector<uint32_t> processed_pair;   // pair numbers processed, in order
    std::vector<uint32_t> processed_frame;  // their sensor frames
    std::vector<int64_t> processed_end;     // when each pair's processing ended
    int content_mismatches = 0;
    std::vector<dsp::frame_output> results;
    std::vector<std::pair<int64_t, uint32_t>> ctrl_writes;  // (time, CTRL value)
    std::vector<int64_t> ready_time;      // FRAME_READY time of pair n (PAIRS_OK numbering)
    std::vector<uint32_t> frame_of_pair;  // sensor frame of pair n
    uint64_t cycles_charged[dsp::stage_count] = {};
    int protocol_errors = 0;
    int bad_accesses = 0;
    int fifo_underflows = 0;
    int64_t eer_enabled_at = -1;  // first time EER enabled channel 4
    int64_t oe_raised_at = -1;    // first CTRL = 1

  private:
    // ---- event queue: fixed slots, no allocation ------------------------------------------
    enum class kind : uint8_t { frame_end, edma_done, timer1 };
    struct timed {
        int64_t time = 0;
        uint64_t seq = 0;
        kind what = kind::frame_end;
        uint32_t arg = 0;
        uint32_t generation = 0;
        bool used = false;
    };

    void schedule(int64_t time, kind what, uint32_t arg, uint32_t generation) {
        for (timed& t : m_queue) {
            if (!t.used) {
                t = timed{time, m_seq++, what, arg, generation, true};
                return;
            }
        }
        ADD_FAILURE() << "stand-in event queue full";
    }

    // Runs the earliest event; false if there is none.
    bool run_next_event() {
        timed* next = nullptr;
        for (timed& t : m_queue) {
            if (t.used &&
                (!next || t.time < next->time || (t.time == next->time && t.seq < next->seq))) {
                next = &t;
            }
        }
        if (!next) return false;
        if (m_cfg.stop_at != 0 && next->time > m_cfg.stop_at) {
            m_now = std::max(m_now, m_cfg.stop_at);
            return true;
        }
        const timed t = *next;
        next->used = false;
        m_now = std::max(m_now, t.time);
        dispatch(t);
        return true;
    }

    void advance_to(int64_t t) {
        for (;;) {
            timed* next = nullptr;
            for (timed& e : m_queue) {
                if (e.used && e.time <= t &&
                    (!next || e.time < next->time || (e.time == next->time && e.seq < next->seq))) {
                    next = &e;
                }
            }
            if (!next) break;
            const timed e = *next;
            next->used = false;
            m_now = std::max(m_now, e.time);
            dispatch(e);
        }
        m_now = std::max(m_now, t);
    }

    void dispatch(const timed& t) {
        switch (t.what) {
            case kind::frame_end:
                if (t.generation == m_card_generation) frame_end();
                break;
            case kind::edma_done:
                edma_complete(t.arg);
                break;
            case kind::timer1:
                if (t.generation == m_timer_generation) {
                    raise_event(regs::irq::sel_tint1);
                    schedule(m_now + timer_period(), kind::timer1, 0, m_timer_generation);
                }
                break;
        }
    }

    // ---- interrupt selector -----------------------------------------------------------------
    void raise_event(uint32_t code) {
        for (int n = 4; n <= 15; ++n) {
            const uint32_t reg = n >= 10 ? m_muxh : m_muxl;
            const uint32_t shift = static_cast<uint32_t>(((n - 4) % 6) * 5 + ((n - 4) % 6 >= 3));
            if (((reg >> shift) & 0x1Fu) == code) m_ifr |= 1u << n;
        }
    }

    // ---- C6416 peripherals the firmware uses --------------------------------------------------
    bool peripheral_read(uint32_t address, uint32_t& v) {
        if (address >= regs::emifa::base &&
            address < regs::emifa::base + regs::emifa::block_bytes) {
            v = m_emifa[(address - regs::emifa::base) / 4];
            return true;
        }
        if (address >= regs::edma::pram_base &&
            address < regs::edma::pram_base + regs::edma::pram_bytes) {
            v = m_pram[(address - regs::edma::pram_base) / 4];
            return true;
        }
        switch (address) {
            case regs::edma::cipr_l:
                v = static_cast<uint32_t>(m_cipr);
                return true;
            case regs::edma::cier_l:
                v = m_cier;
                return true;
            case regs::edma::eer_l:
                v = m_eer;
                return true;
            case regs::timer::base1 + regs::timer::prd:
                v = m_timer_prd;
                return true;
            case regs::irq::muxl:
                v = m_muxl;
                return true;
            case regs::irq::muxh:
                v = m_muxh;
                return true;
            default:
                return false;
        }
    }

    bool peripheral_write(uint32_t address, uint32_t v) {
        if (address >= regs::emifa::base &&
            address < regs::emifa::base + regs::emifa::block_bytes) {
            m_emifa[(address - regs::emifa::base) / 4] = v;
            return true;
        }
        if (address >= regs::edma::pram_base &&
            address < regs::edma::pram_base + regs::edma::pram_bytes) {
            m_pram[(address - regs::edma::pram_base) / 4] = v;
            return true;
        }
        switch (address) {
            case regs::irq::muxl:
                m_muxl = v;
                return true;
            case regs::irq::muxh:
                m_muxh = v;
                return true;
            case regs::irq::extpol:
                m_extpol = v;
                return true;
            case regs::edma::cipr_l:
                m_cipr &= ~uint64_t{v};
                return true;
            case regs::edma::cipr_h:
                m_cipr &= ~(uint64_t{v} << 32);
                return true;
            case regs::edma::cier_l:
                m_cier = v;
                return true;
            case regs::edma::cier_h:
                return true;
            case regs::edma::ccer_l:
                m_ccer = (m_ccer & ~0xFFFFFFFFull) | v;
                return true;
            case regs::edma::ccer_h:
                m_ccer = (m_ccer & 0xFFFFFFFFull) | (uint64_t{v} << 32);
                return true;
            case regs::edma::ecr_l:
                m_er &= ~v;
                return true;
            case regs::edma::ecr_h:
                return true;
            case regs::edma::eer_h:
                return true;
            case regs::edma::eer_l: {
                const uint32_t newly = v & ~m_eer;
                m_eer = v;
                if ((v & 0x10u) && eer_enabled_at < 0) eer_enabled_at = m_now;
                for (int c = 0; c < 32; ++c) {
                    if ((newly & m_er) & (1u << c)) {
                        m_er &= ~(1u << c);
                        submit(c);
                    }
                }
                return true;
            }
            case regs::timer::base1 + regs::timer::ctl:
                ++m_timer_generation;
                if ((v & regs::timer::ctl_go) && (v & regs::timer::ctl_hld) &&
                    (v & regs::timer::ctl_clksrc) && m_timer_prd != 0) {
                    schedule(m_now + timer_period(), kind::timer1, 0, m_timer_generation);
                }
                return true;
            case regs::timer::base1 + regs::timer::prd:
                m_timer_prd = v;
                return true;
            default:
                return false;
        }
    }

    int64_t timer_period() const { return int64_t{m_timer_prd} * 8 * m_cfg.cpu_period; }

    // ---- EDMA channel controller (C64x rules, FS = 1 transfers) -----------------------------
    void edma_event(int channel) {
        m_er |= 1u << channel;
        if (m_eer & (1u << channel)) {
            m_er &= ~(1u << channel);
            submit(channel);
        }
    }

    // One element address of a transfer side.
    static uint32_t element_address(uint32_t base, uint32_t mode, bool two_d, int32_t frame_index,
                                    uint32_t array, uint32_t element, uint32_t elements) {
        if (mode == regs::edma::mode_fixed) return base;
        if (two_d) return base + static_cast<uint32_t>(frame_index) * array + 4 * element;
        return base + 4 * (array * elements + element);
    }

    void submit(int channel) {
        uint32_t* p = &m_pram[(regs::edma::entry(channel) - regs::edma::pram_base) / 4];
        const uint32_t opt = p[0];
        const uint32_t elements = p[2] & 0xFFFFu;
        const uint32_t arrays = (p[2] >> 16) + 1;
        if (elements == 0) return;
        if (!(opt & regs::edma::opt_fs) ||
            ((opt & regs::edma::opt_esize_mask) >> regs::edma::opt_esize_shift) != 0) {
            ADD_FAILURE() << "the stand-in EDMA runs 32-bit frame-synchronised transfers only";
            return;
        }
        const uint32_t sum = (opt & regs::edma::opt_sum_mask) >> regs::edma::opt_sum_shift;
        const uint32_t dum = (opt & regs::edma::opt_dum_mask) >> regs::edma::opt_dum_shift;
        const int32_t frame_index = static_cast<int16_t>(p[4] >> 16);
        int64_t bus_words = 0;
        for (uint32_t a = 0; a < arrays; ++a) {
            for (uint32_t e = 0; e < elements; ++e) {
                const uint32_t src = element_address(p[1], sum, opt & regs::edma::opt_2ds,
                                                     frame_index, a, e, elements);
                const uint32_t dst = element_address(p[3], dum, opt & regs::edma::opt_2dd,
                                                     frame_index, a, e, elements);
                uint32_t word = 0;
                if (const uint8_t* m = memory(src, 4)) {
                    std::memcpy(&word, m, 4);
                } else if (src >= card::ce3_base) {
                    word = fifo_pop(src >= card::data_right ? 1 : 0);
                    ++bus_words;
                } else if (src >= card::ce2_base) {
                    word = card_read(src - card::ce2_base);
                    ++bus_words;
                } else {
                    ++bad_accesses;
                }
                if (uint8_t* m = memory(dst, 4)) {
                    std::memcpy(m, &word, 4);
                } else {
                    ++bad_accesses;
                }
            }
        }
        // The transfer controller runs one request at a time.
        const int64_t start = std::max(m_now, m_tc_free);
        m_tc_free = start + bus_words * m_cfg.word_ticks;
        schedule(m_tc_free, kind::edma_done, opt, 0);
        if (opt & regs::edma::opt_link) {
            const uint32_t* from = &m_pram[(p[5] & 0xFFFFu) / 4];
            uint32_t copy[6];
            std::memcpy(copy, from, sizeof copy);
            std::memcpy(p, copy, sizeof copy);
        } else {
            p[2] = 0;
        }
    }

    void edma_complete(uint32_t opt) {
        if (!(opt & regs::edma::opt_tcint)) return;
        const uint32_t code = regs::edma::opt_tcc_code(opt);
        const uint64_t bit = uint64_t{1} << code;
        m_cipr |= bit;
        if (code < 32 && (m_cier & (1u << code))) raise_event(regs::irq::sel_edma_int);
        if (m_ccer & bit) submit(static_cast<int>(code));
    }

    // ---- the card -----------------------------------------------------------------------------
    uint32_t card_read(uint32_t offset) {
        switch (offset) {
            case card::id:
                return m_cfg.card_id;
            case card::status: {
                uint32_t s = m_card_state;
                if (m_card_state == 4) s |= card::status_hard_error_mask;
                if (m_card_state == 3 || m_card_state == 2) s |= card::status_oe_mask;
                return s;
            }
            case card::verdict:
                return m_verdict;
            case card::mismatch_pos:
                return m_mismatch_pos;
            case card::frames_l:
            case card::frames_r:
                return m_frame_counter;
            case card::pairs_ok:
                return m_pairs_ok;
            case card::mismatches:
                return m_mismatches;
            case card::overflows:
                return m_overflows;
            case card::irq_status:
                return m_irq_status;
            case card::fifo_depth:
                return m_cfg.fifo_words;
            default:
                return offset / 4 < 64 ? card_regs_[offset / 4] : 0;
        }
    }

    void card_write(uint32_t offset, uint32_t v) {
        if (offset == card::irq_status) {
            m_irq_status &= ~v;
            return;
        }
        if (offset == card::ctrl) {
            ctrl_writes.push_back({m_now, v});
            const bool enable = v & card::ctrl_enable_mask;
            const bool was = card_regs_[card::ctrl / 4] & card::ctrl_enable_mask;
            card_regs_[card::ctrl / 4] = v;
            if (enable && !was) {
                if (oe_raised_at < 0) oe_raised_at = m_now;
                ++m_card_generation;
                m_card_state = 2;  // WAIT_VSYNC
                m_consecutive_fails = 0;
                m_frame_in_run = 0;
                const int64_t latency = m_oe_starts++ == 0 && m_cfg.first_start_latency != 0
                                            ? m_cfg.first_start_latency
                                            : m_cfg.start_latency;
                schedule(m_now + latency + m_cfg.frame_period, kind::frame_end, 0,
                         m_card_generation);
            } else if (!enable) {
                ++m_card_generation;
                m_card_state = 0;  // IDLE
            }
            return;
        }
        if (offset / 4 < 64) card_regs_[offset / 4] = v;
    }

    void pulse(int ext, uint32_t irq_bit) {
        m_irq_status |= irq_bit;
        if (!(card_regs_[card::irq_enable / 4] & irq_bit)) return;
        raise_event(regs::irq::sel_gpint4 + static_cast<uint32_t>(ext));
        edma_event(regs::edma::channel_ext_int4 + ext);
    }

    uint32_t fifo_level(int side) const {
        uint32_t level = 0;
        for (int i = 0; i < m_fifo_count[side]; ++i) level += m_fifo[side][i].remaining;
        return level;
    }

    uint32_t fifo_pop(int side) {
        if (m_fifo_count[side] == 0) {
            ++fifo_underflows;
            return 0;
        }
        fifo_frame& f = m_fifo[side][0];
        const uint32_t words = frame_words();
        const uint32_t position = (words - f.remaining) * 4;  // first pixel of the word
        uint32_t word = 0;
        for (uint32_t n = 0; n < 4; ++n) {
            const int x = static_cast<int>((position + n) % static_cast<uint32_t>(m_cfg.width));
            const int y = static_cast<int>((position + n) / static_cast<uint32_t>(m_cfg.width));
            word |= uint32_t{m_cfg.content.pixel(f.frame, side, x, y)} << (8 * n);
        }
        if (--f.remaining == 0) {
            for (int i = 1; i < m_fifo_count[side]; ++i) m_fifo[side][i - 1] = m_fifo[side][i];
            --m_fifo_count[side];
        }
        return word;
    }

    uint32_t frame_words() const { return static_cast<uint32_t>(m_cfg.width * m_cfg.height) / 4; }

    void frame_end() {
        const uint32_t f = m_frame_counter++;
        const outcome what = f < m_cfg.script.size() ? m_cfg.script[f] : outcome::good;
        const uint32_t index = (m_frame_in_run++) << card::verdict_frame_shift;
        m_card_state = 3;  // RUN
        if (what == outcome::sync_error) {
            ++m_mismatches;
            m_verdict = index | card::verdict_l_dark_mask;
            m_mismatch_pos = (9u << card::mismatch_pos_line_shift) | 3u;
            pulse(1, card::irq_status_sync_error_mask);
            if (++m_consecutive_fails > card_regs_[card::retry_limit / 4]) {
                m_card_state = 4;  // HARD_ERROR: OE stays low until ENABLE 0 -> 1
                return;
            }
            m_frame_in_run = 0;
            schedule(m_now + m_cfg.restart_gap + m_cfg.frame_period, kind::frame_end, 0,
                     m_card_generation);
            return;
        }
        m_consecutive_fails = 0;
        const bool room = fifo_level(0) + frame_words() <= m_cfg.fifo_words &&
                          fifo_level(1) + frame_words() <= m_cfg.fifo_words;
        if (what == outcome::overflow || !room) {
            ++m_overflows;
            m_verdict = index | card::verdict_overflow_mask;
            pulse(2, card::irq_status_overflow_mask);
        } else {
            for (int side = 0; side < 2; ++side) {
                m_fifo[side][m_fifo_count[side]++] = fifo_frame{f, frame_words()};
            }
            ++m_pairs_ok;
            ready_time.push_back(m_now);
            frame_of_pair.push_back(f);
            m_verdict = index | (what == outcome::bad_verdict ? card::verdict_r_dark_mask : 0u);
            pulse(0, card::irq_status_frame_ready_mask);
        }
        schedule(m_now + m_cfg.frame_period, kind::frame_end, 0, m_card_generation);
    }

    struct fifo_frame {
        uint32_t frame = 0;
        uint32_t remaining = 0;
    };

    platform_config m_cfg;
    std::vector<uint8_t> m_l2;
    std::vector<uint8_t> m_sdram;
    int64_t m_now = 0;
    timed m_queue[64];
    uint64_t m_seq = 0;
    int m_open_stage = -1;

    uint32_t m_ifr = 0, m_ier = 0;
    uint32_t m_muxl = regs::irq::muxl_reset, m_muxh = regs::irq::muxh_reset, m_extpol = 0;
    uint32_t m_emifa[32] = {};
    uint32_t m_pram[regs::edma::pram_bytes / 4] = {};
    uint64_t m_cipr = 0, m_ccer = 0;
    uint32_t m_cier = 0, m_eer = 0, m_er = 0;
    int64_t m_tc_free = 0;
    uint32_t m_timer_prd = 0;
    uint32_t m_timer_generation = 0;

    uint32_t card_regs_[64] = {};
    uint32_t m_card_generation = 0;
    int m_oe_starts = 0;
    uint32_t m_card_state = 0;
    uint32_t m_frame_counter = 0, m_frame_in_run = 0;
    uint32_t m_pairs_ok = 0, m_mismatches = 0, m_overflows = 0, m_consecutive_fails = 0;
    uint32_t m_verdict = 0, m_mismatch_pos = 0, m_irq_status = 0;
    fifo_frame m_fifo[2][8] = {};
    int m_fifo_count[2] = {0, 0};
};

dsp::control_program_config small_config(dsp::pipeline_mode mode, int width = 64, int height = 48) {
    dsp::control_program_config c;
    c.pipeline.max_width = width;
    c.pipeline.max_height = height;
    c.card.active_cols = static_cast<uint32_t>(width);
    c.card.active_rows = static_cast<uint32_t>(height);
    c.mode = mode;
    return c;
}

double ms(int64_t ticks) {
    return static_cast<double>(ticks) / ticks_per_ms;
}

}  // namespace

namespace {

// Index of the first report of `kind`, -1 if none.
int first_index(const stand_in& p, firmware_event kind) {
    for (size_t i = 0; i < p.events.size(); ++i) {
        if (p.events[i].e.kind == kind) return static_cast<int>(i);
    }
    return -1;
}

void run_program(stand_in& platform, dsp::control_program& program,
                 const dsp::control_program_config& config) {
    ASSERT_TRUE(program.init(config, platform));
    platform.program = &program;
    program.run();
}

// Common checks of any run: the stage protocol, only mapped addresses, each
// processed buffer held exactly its pair's frame, pair numbers increasing.
void expect_sound_run(const stand_in& p) {
    EXPECT_EQ(p.protocol_errors, 0);
    EXPECT_EQ(p.bad_accesses, 0);
    EXPECT_EQ(p.fifo_underflows, 0);
    EXPECT_EQ(p.content_mismatches, 0);
    for (size_t i = 1; i < p.processed_pair.size(); ++i) {
        EXPECT_GT(p.processed_pair[i], p.processed_pair[i - 1]);
    }
}

}  // namespace

// Boot on each DSK version: the EMIFA values of the DSK's GEL file, the
// interrupt selector's reset mapping, the card's geometry, the EDMA armed
// before OE rises, and the documented order of the boot reports.
TEST(ControlProgramBoot, ProgramsTheDskEmifAndConfiguresTheCard) {
    struct dsk_case {
        dsp::dsk_version dsk;
        uint32_t cectl_card, sdtim, sdext;
    };
    const dsk_case cases[] = {{dsp::dsk_version::v1, 0x22A28A22u, 0x618u, 0x000A8529u},
                              {dsp::dsk_version::v2, 0x23228C22u, 0x750u, 0x001FAF4Du},
                              {dsp::dsk_version::v3, 0x23228C22u, 0x750u, 0x001FAF4Du}};
    for (const dsk_case& c : cases) {
        SCOPED_TRACE(static_cast<int>(c.dsk));
        platform_config pc;
        stand_in p(pc);
        dsp::control_program program;
        dsp::control_program_config config = small_config(dsp::pipeline_mode::overlapped);
        config.dsk = c.dsk;
        config.max_pairs = 2;
        run_program(p, program, config);
        EXPECT_EQ(p.emifa_register(regs::emifa::cectl2), c.cectl_card);
        EXPECT_EQ(p.emifa_register(regs::emifa::cectl3), c.cectl_card);
        EXPECT_EQ(p.emifa_register(regs::emifa::cectl0), 0xFFFFFFD3u);
        EXPECT_EQ(p.emifa_register(regs::emifa::sdtim), c.sdtim);
        EXPECT_EQ(p.emifa_register(regs::emifa::sdext), c.sdext);
        EXPECT_EQ(p.emifa_register(regs::emifa::sdctl), 0x47115000u);
        EXPECT_EQ(p.emifa_register(regs::emifa::gblctl), 0x00012070u);
        EXPECT_EQ(p.muxl(), 0x250718A4u);  // INT4-7 = GPINT4-7, INT8 = EDMA_INT, INT9 = 9
        EXPECT_EQ(p.muxh(), 0x08202D43u);  // INT14/15 = TINT0/1
        EXPECT_EQ(p.card_register(card::active_cols), 64u);
        EXPECT_EQ(p.card_register(card::active_rows), 48u);
        EXPECT_EQ(p.card_register(card::irq_enable), 7u);
        EXPECT_EQ(p.card_register(card::dark_cols_left), 16u);
        EXPECT_EQ(p.card_register(card::frame_lines), 525u);
        ASSERT_GE(p.eer_enabled_at, 0);
        EXPECT_LE(p.eer_enabled_at, p.oe_raised_at) << "channel 4 must be armed before OE";
        const firmware_event order[] = {firmware_event::boot,       firmware_event::emif_programmed,
                                        firmware_event::card_found, firmware_event::card_configured,
                                        firmware_event::oe_raised,  firmware_event::pair_captured,
                                        firmware_event::in_step,    firmware_event::pair_processed,
                                        firmware_event::stopped};
        for (size_t i = 1; i < sizeof order / sizeof order[0]; ++i) {
            EXPECT_LT(first_index(p, order[i - 1]), first_index(p, order[i]))
                << dsp::firmware_event_name(order[i - 1]) << " before "
                << dsp::firmware_event_name(order[i]);
        }
        EXPECT_EQ(p.events[first_index(p, firmware_event::emif_programmed)].e.value, c.cectl_card);
        EXPECT_EQ(p.events[first_index(p, firmware_event::in_step)].e.pair, 1u);
        EXPECT_EQ(program.stats().pairs_processed, 2u);
        ASSERT_EQ(p.processed_frame.size(), 2u);
        EXPECT_EQ(p.processed_frame[0], 0u);
        EXPECT_EQ(p.processed_frame[1], 1u);
        expect_sound_run(p);
        // OE rises after the boot's register accesses; the first pair is
        // ready one start latency plus one frame later.
        std::printf("DSK v%d: OE raised at %.4f ms, first pair processed at %.3f ms\n",
                    static_cast<int>(c.dsk), ms(p.oe_raised_at), ms(p.processed_end[0]));
    }
}

TEST(ControlProgramBoot, MissingCardStopsBeforeRaisingOe) {
    platform_config pc;
    pc.card_id = 0xFFFFFFFFu;  // nothing answers on CE2
    stand_in p(pc);
    dsp::control_program program;
    dsp::control_program_config config = small_config(dsp::pipeline_mode::overlapped);
    config.max_pairs = 1;
    run_program(p, program, config);
    EXPECT_EQ(p.count(firmware_event::card_missing), 1);
    EXPECT_EQ(p.count(firmware_event::oe_raised), 0);
    EXPECT_EQ(p.oe_raised_at, -1);
    EXPECT_TRUE(p.results.empty());
}

// The card retries a failed check itself (RETRY_LIMIT 2); after the third
// consecutive mismatch it gives up (HARD_ERROR) and the firmware re-arms it
// with ENABLE 0 -> 1. The first pair used is the first good one after that.
TEST(ControlProgramCard, RearmsWhenTheCardGivesUp) {
    platform_config pc;
    pc.script = {outcome::sync_error, outcome::sync_error, outcome::sync_error};
    stand_in p(pc);
    dsp::control_program program;
    dsp::control_program_config config = small_config(dsp::pipeline_mode::overlapped);
    config.card.retry_limit = 2;
    config.max_pairs = 3;
    run_program(p, program, config);
    EXPECT_EQ(p.count(firmware_event::sync_error), 3);
    ASSERT_EQ(p.count(firmware_event::card_rearmed), 1);
    EXPECT_EQ(p.events[first_index(p, firmware_event::card_rearmed)].e.value,
              static_cast<uint32_t>(dsp::rearm_cause::hard_error));
    EXPECT_EQ(p.count(firmware_event::oe_raised), 2);
    // CTRL: 0 (configure), 1 (boot), 0 and 1 (re-arm), 0 (stop).
    ASSERT_EQ(p.ctrl_writes.size(), 5u);
    const uint32_t expected_ctrl[] = {0, 1, 0, 1, 0};
    for (size_t i = 0; i < 5; ++i) EXPECT_EQ(p.ctrl_writes[i].second, expected_ctrl[i]) << i;
    // The sync errors carry the card's VERDICT and MISMATCH_POS.
    const dsp::event_record& first_error = p.events[first_index(p, firmware_event::sync_error)].e;
    EXPECT_EQ(first_error.value & card::verdict_l_dark_mask, card::verdict_l_dark_mask);
    EXPECT_EQ(first_error.detail, (9u << 16) | 3u);
    EXPECT_LT(first_index(p, firmware_event::card_rearmed),
              first_index(p, firmware_event::in_step));
    ASSERT_EQ(p.processed_frame.size(), 3u);
    EXPECT_EQ(p.processed_frame[0], 3u);  // frames 0-2 failed
    EXPECT_EQ(program.stats().sync_errors, 3u);
    expect_sound_run(p);
    std::printf("3 mismatches, re-armed at %.3f ms, first pair used at %.3f ms\n",
                ms(p.ctrl_writes[2].first), ms(p.processed_end[0]));

    // With rearm_on_every_sync_error the firmware re-arms after the first.
    platform_config pc2;
    pc2.script = {outcome::sync_error};
    stand_in p2(pc2);
    dsp::control_program program2;
    config.rearm_on_every_sync_error = true;
    config.max_pairs = 1;
    run_program(p2, program2, config);
    ASSERT_EQ(p2.count(firmware_event::card_rearmed), 1);
    EXPECT_EQ(p2.events[first_index(p2, firmware_event::card_rearmed)].e.value,
              static_cast<uint32_t>(dsp::rearm_cause::sync_error));
    ASSERT_EQ(p2.processed_frame.size(), 1u);
    EXPECT_EQ(p2.processed_frame[0], 1u);
    expect_sound_run(p2);
}

// Frames with a sync error or an overflow never reach a buffer (the card
// does not raise FRAME_READY for them); a pair whose copied VERDICT has a
// cause bit is captured but not used. None of them is processed; the
// firmware reports each and re-arms the card after the overflow.
TEST(ControlProgramCard, FailedPairsAreNeverUsed) {
    platform_config pc;
    pc.script = {outcome::good,     outcome::good, outcome::sync_error, outcome::good,
                 outcome::overflow, outcome::good, outcome::bad_verdict};
    stand_in p(pc);
    dsp::control_program program;
    dsp::control_program_config config = small_config(dsp::pipeline_mode::overlapped);
    config.max_pairs = 6;
    run_program(p, program, config);
    const std::vector<uint32_t> expected = {0, 1, 3, 5, 7, 8};
    EXPECT_EQ(p.processed_frame, expected);
    EXPECT_EQ(p.count(firmware_event::sync_error), 1);
    EXPECT_EQ(p.count(firmware_event::overflow), 1);
    ASSERT_EQ(p.count(firmware_event::card_rearmed), 1);
    EXPECT_EQ(p.events[first_index(p, firmware_event::card_rearmed)].e.value,
              static_cast<uint32_t>(dsp::rearm_cause::overflow));
    EXPECT_LT(first_index(p, firmware_event::overflow),
              first_index(p, firmware_event::card_rearmed));
    ASSERT_EQ(p.count(firmware_event::pair_rejected), 1);
    const dsp::event_record& rejected = p.events[first_index(p, firmware_event::pair_rejected)].e;
    EXPECT_EQ(p.frame_of_pair[rejected.pair], 6u);
    EXPECT_NE(rejected.value & card::verdict_r_dark_mask, 0u);
    EXPECT_EQ(program.stats().pairs_rejected, 1u);
    EXPECT_EQ(program.stats().pairs_dropped, 0u);
    EXPECT_EQ(p.results.size(), 6u);
    expect_sound_run(p);
    std::printf(
        "processed frames 0 1 3 5 7 8 of 9; sync error, overflow (re-armed), bad verdict"
        " rejected\n");
}

// A card that stays silent (its first start never comes) is re-armed by the
// watchdog (timer 1, TINT1 = INT15) after one period without progress.
TEST(ControlProgramCard, WatchdogRearmsASilentCard) {
    platform_config pc;
    pc.first_start_latency = 5000 * ticks_per_ms;
    stand_in p(pc);
    dsp::control_program program;
    dsp::control_program_config config = small_config(dsp::pipeline_mode::overlapped);
    config.watchdog_ms = 100;
    config.max_pairs = 1;
    run_program(p, program, config);
    ASSERT_EQ(p.count(firmware_event::watchdog), 1);
    const int64_t fired = p.events[first_index(p, firmware_event::watchdog)].time;
    // One period of 100 ms = 7,500,000 timer clocks of 8 CPU cycles after OE.
    EXPECT_EQ(p.events[first_index(p, firmware_event::watchdog)].e.value, 7500000u);
    EXPECT_GE(fired - p.oe_raised_at, 100 * ticks_per_ms);
    EXPECT_LT(fired - p.oe_raised_at, 101 * ticks_per_ms);
    ASSERT_EQ(p.count(firmware_event::card_rearmed), 1);
    EXPECT_EQ(p.events[first_index(p, firmware_event::card_rearmed)].e.value,
              static_cast<uint32_t>(dsp::rearm_cause::watchdog));
    EXPECT_EQ(program.stats().pairs_processed, 1u);
    expect_sound_run(p);
    std::printf("watchdog fired %.3f ms after OE; pair processed at %.3f ms\n",
                ms(fired - p.oe_raised_at), ms(p.processed_end[0]));
}

namespace {

// Buffers occupied at time t: pairs made ready before t whose processing
// had not ended (captured, waiting or being processed).
int occupied_at(const stand_in& p, int64_t t) {
    int n = 0;
    for (size_t i = 0; i < p.processed_pair.size(); ++i) {
        const int64_t ready = p.ready_time[p.processed_pair[i]];
        if (ready < t && p.processed_end[i] > t) ++n;
    }
    return n;
}

void check_overrun_policy(dsp::pipeline_mode mode) {
    platform_config pc;
    pc.extra_preprocess_ticks = 40 * ticks_per_ms;  // a pair takes > 40 ms: the CPU cannot keep up
    pc.stop_at = 1000 * ticks_per_ms;
    stand_in p(pc);
    dsp::control_program program;
    run_program(p, program, small_config(mode));
    expect_sound_run(p);
    const int buffers = mode == dsp::pipeline_mode::overlapped ? 2 : 1;
    ASSERT_GE(p.processed_pair.size(), 10u);
    const uint32_t last = p.processed_pair.back();
    uint32_t dropped = 0;
    size_t next = 0;
    for (uint32_t pair = 1; pair <= last; ++pair) {
        const bool used = next < p.processed_pair.size() && p.processed_pair[next] == pair;
        const int busy = occupied_at(p, p.ready_time[pair]);
        if (used) {
            ++next;
            EXPECT_LT(busy, buffers) << "pair " << pair << " was taken although no buffer was free";
        } else {
            ++dropped;
            EXPECT_EQ(busy, buffers)
                << "pair " << pair << " was dropped although a buffer was free";
        }
    }
    EXPECT_GT(dropped, 0u);
    EXPECT_EQ(program.stats().pairs_dropped, dropped);
    int reported = 0;
    for (const logged_event& le : p.events) {
        if (le.e.kind == firmware_event::pair_dropped) reported += static_cast<int>(le.e.value);
    }
    EXPECT_EQ(reported, static_cast<int>(dropped));
    std::printf("%s, 40 ms per pair: %u of %u pairs processed, %u dropped (%.0f %%)\n",
                dsp::pipeline_mode_name(mode), last - dropped, last, dropped,
                100.0 * dropped / last);
}

}  // namespace

// Overrun policy: a pair that becomes ready while every buffer is occupied
// (being processed, or captured and waiting) is the one dropped, and a pair
// that finds a free buffer is always taken. Checked for every pair against
// the stand-in's FRAME_READY times and the firmware's processing ends.
TEST(ControlProgramOverrun, NewPairIsDroppedWhenNoBufferIsFreeOverlapped) {
    check_overrun_policy(dsp::pipeline_mode::overlapped);
}

TEST(ControlProgramOverrun, NewPairIsDroppedWhenNoBufferIsFreeSequential) {
    check_overrun_policy(dsp::pipeline_mode::sequential);
}

// docs/design-brief.md: with the paper's figures only overlapped mode keeps up. The
// bus takes 21.5 ms per pair (two VGA frames at 14 ECLK per word, v1: here
// 1536 words of 14 us) and the CPU 12 ms; the sensor period is 24.5 ms.
// Sequential: 33.5 ms per pair -> every other pair dropped; overlapped:
// none, and captures run while the previous pair is processed.
TEST(ControlProgramModes, OnlyOverlappedKeepsUpWithPaperTimings) {
    int64_t mean_latency[2] = {};
    uint32_t drops[2] = {}, processed[2] = {};
    for (int m = 0; m < 2; ++m) {
        const dsp::pipeline_mode mode =
            m == 0 ? dsp::pipeline_mode::sequential : dsp::pipeline_mode::overlapped;
        platform_config pc;
        pc.word_ticks = 14 * 180 * 100;  // 14 us: 1536 words = 21.5 ms
        pc.extra_preprocess_ticks = 12 * ticks_per_ms;
        pc.stop_at = 1000 * ticks_per_ms;
        stand_in p(pc);
        dsp::control_program program;
        run_program(p, program, small_config(mode));
        expect_sound_run(p);
        drops[m] = program.stats().pairs_dropped;
        processed[m] = program.stats().pairs_processed;
        // Ordering: does a processed pair's capture overlap the previous
        // pair's processing?
        int overlapping = 0;
        for (size_t i = 1; i < p.processed_pair.size(); ++i) {
            if (p.ready_time[p.processed_pair[i]] < p.processed_end[i - 1]) ++overlapping;
        }
        int64_t latency = 0;
        for (size_t i = 0; i < p.processed_pair.size(); ++i) {
            latency += p.processed_end[i] - p.ready_time[p.processed_pair[i]];
        }
        mean_latency[m] = latency / static_cast<int64_t>(p.processed_pair.size());
        if (mode == dsp::pipeline_mode::sequential) {
            EXPECT_EQ(overlapping, 0) << "sequential: capture only after the previous pair";
        } else {
            EXPECT_GE(overlapping, static_cast<int>(p.processed_pair.size()) - 2);
        }
        std::printf(
            "%s: %u processed, %u dropped in 1 s; %d captures during processing; "
            "ready-to-result latency %.2f ms\n",
            dsp::pipeline_mode_name(mode), processed[m], drops[m], overlapping,
            ms(mean_latency[m]));
    }
    EXPECT_EQ(drops[1], 0u);
    EXPECT_GE(processed[1], 38u);
    EXPECT_GE(drops[0] + 1, processed[0]);  // every other pair
    EXPECT_LE(drops[0], processed[0] + 1);
    // ready -> result: capture 21.5 ms + processing 12 ms in both modes.
    EXPECT_NEAR(ms(mean_latency[1]), 33.5, 0.5);
}

// The frame loop (boot included, init excluded) allocates nothing, through
// captures, a sync error, an overflow re-arm and a rejected pair.
TEST(ControlProgramRules, RunAllocatesNothingAfterInit) {
    platform_config pc;
    pc.script = {outcome::good, outcome::sync_error, outcome::good, outcome::overflow,
                 outcome::bad_verdict};
    pc.extra_preprocess_ticks = 45 * ticks_per_ms;  // drops too
    stand_in p(pc);
    dsp::control_program program;
    dsp::control_program_config config = small_config(dsp::pipeline_mode::overlapped);
    config.max_pairs = 8;
    ASSERT_TRUE(program.init(config, p));
    p.program = &program;
    const test_support::heap_counter heap;
    program.run();
    const long allocations = heap.allocations();
    expect_sound_run(p);
    EXPECT_EQ(program.stats().pairs_processed, 8u);
    EXPECT_GT(program.stats().pairs_dropped, 0u);
    EXPECT_EQ(program.stats().sync_errors, 1u);
    EXPECT_EQ(program.stats().overflows, 1u);
    EXPECT_EQ(program.stats().pairs_rejected, 1u);
    EXPECT_EQ(allocations, 0);
    std::printf("run(): %ld heap allocations over %u pairs\n", allocations,
                program.stats().pairs_processed);
}

// End to end on rendered pairs (the ball circling at 2 m, VGA): the
// pipeline's output for each pair the program processed equals what the
// controller gives on the same raw pairs in the same order, so the program
// feeds it the right pixels; a sync error on the way changes nothing else.
TEST(ControlProgramPipeline, ResultsEqualTheControllerOnTheSamePairs) {
    const scene::scenario scenario = host::circling_scenario(2.0, 2, 10);
    const dsp::controller_config controller_config =
        host::controller_config_for(scenario.scene.rig);
    host::stereo_runner renderer(scenario, controller_config);
    std::vector<scene::gray_image> left, right;
    for (int n = 0; n < scenario.frame_count; ++n) {
        renderer.render(n);
        left.push_back(renderer.raw_left());
        right.push_back(renderer.raw_right());
    }
    const int width = left[0].width, height = left[0].height;

    platform_config pc;
    pc.width = width;
    pc.height = height;
    pc.content.left = &left;
    pc.content.right = &right;
    pc.script = {outcome::good, outcome::good, outcome::sync_error};
    stand_in p(pc);
    dsp::control_program program;
    dsp::control_program_config config =
        small_config(dsp::pipeline_mode::overlapped, width, height);
    config.pipeline = controller_config;
    config.max_pairs = static_cast<uint32_t>(scenario.frame_count) - 1;
    run_program(p, program, config);
    expect_sound_run(p);
    ASSERT_EQ(p.results.size(), config.max_pairs);

    host::counting_hal reference_hal;
    dsp::controller reference;
    reference.init(controller_config, reference_hal);
    int points = 0;
    for (size_t i = 0; i < p.results.size(); ++i) {
        const uint32_t frame = p.processed_frame[i];
        ASSERT_NE(frame, 2u);
        const dsp::frame_output expected =
            reference.process_pair(left[frame].view(), right[frame].view());
        const dsp::frame_output& got = p.results[i];
        SCOPED_TRACE(frame);
        EXPECT_EQ(got.state, expected.state);
        EXPECT_EQ(got.has_object, expected.has_object);
        EXPECT_EQ(got.box_right.x, expected.box_right.x);
        EXPECT_EQ(got.box_right.y, expected.box_right.y);
        EXPECT_EQ(got.box_right.width, expected.box_right.width);
        EXPECT_EQ(got.disparity_q8, expected.disparity_q8);
        EXPECT_EQ(got.has_point, expected.has_point);
        EXPECT_EQ(got.point.x, expected.point.x);
        EXPECT_EQ(got.point.y, expected.point.y);
        EXPECT_EQ(got.point.z, expected.point.z);
        EXPECT_EQ(got.gain_q8, expected.gain_q8);
        for (int s = 0; s < dsp::stage_count; ++s)
            EXPECT_EQ(got.stage_cycles[s], expected.stage_cycles[s]);
        points += got.has_point;
    }
    EXPECT_GE(points, 1);
    std::printf(
        "%zu VGA pairs through the program: outputs equal the controller's; %d 3D points;"
        " capture stage %llu cycles\n",
        p.results.size(), points,
        static_cast<unsigned long long>(p.cycles_charged[static_cast<int>(dsp::stage::capture)]));
}
