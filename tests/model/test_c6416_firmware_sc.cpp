// The firmware's control program (dsp/control_program.h) running on the
// C6416 model's CPU thread, with a small behavioural card written here as a
// TLM target (registers on CE2, FIFO pixel ports on CE3, 140 ns per word as
// at 14 ECLK / 100 MHz, EXT_INT4/5 pulses): the model's own EDMA runs the
// firmware's PaRAM chains (status copy, left, right, link, CCER), so each
// pair lands in its buffer and INT8 comes exactly when the last word has
// crossed the bus. The real card RTL and EMIF replace the stand-in in the
// platform task.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <deque>
#include <functional>
#include <vector>

#include "c6416_test_util.h"
#include "dsp/card_regs.h"
#include "dsp/control_program.h"
#include "dsp/hal.h"
#include "model/c6416/c6416_regs.h"
#include "model/c6416/c6416_sc.h"

using namespace c6416_test;
namespace card = dsp::card_regs;

namespace {

// dsp::hal (the reference firmware's own HAL) on the bare chip, without the
// platform: charges, registers, memory and interrupts go to the CPU port;
// reports go to `on_report` with their simulated time.
class chip_hal final : public dsp::hal {
  public:
    using report_hook = std::function<void(const sc_core::sc_time&, const dsp::event_record&)>;

    chip_hal(c6416::cpu_port& cpu, report_hook on_report = {})
        : m_cpu(cpu), m_on_report(std::move(on_report)) {}

    void charge_cycles(dsp::stage s, uint64_t cycles) override {
        m_cpu.charge(static_cast<int>(s), cycles);
    }
    void charge_with_traffic(dsp::stage s, uint64_t cycles,
                             const dsp::sdram_traffic& traffic) override {
        m_cpu.charge(static_cast<int>(s), cycles, {traffic.bytes_read, traffic.bytes_written});
    }
    uint32_t read32(uint32_t address) override { return m_cpu.read32(address); }
    void write32(uint32_t address, uint32_t value) override { m_cpu.write32(address, value); }
    uint8_t* memory(uint32_t address, uint32_t bytes) override {
        return m_cpu.memory(address, bytes);
    }
    void set_interrupt_enable(uint32_t ier) override { m_cpu.set_interrupt_enable(ier); }
    uint32_t interrupt_flags() override { return m_cpu.interrupt_flags(); }
    void clear_interrupt_flags(uint32_t mask) override { m_cpu.clear_interrupt_flags(mask); }
    int wait_for_interrupt() override { return m_cpu.wait_for_interrupt(); }
    void report(const dsp::event_record& e) override {
        if (m_on_report) m_on_report(sc_core::sc_time_stamp(), e);
    }
    bool stop_requested() override { return m_cpu.stop_requested(); }

  private:
    c6416::cpu_port& m_cpu;
    report_hook m_on_report;
};

// A program written against dsp::hal, as the chip's firmware entry.
c6416::c6416_sc::firmware_entry on_hal(std::function<void(dsp::hal&)> program,
                                       chip_hal::report_hook on_report = {}) {
    return [program = std::move(program), on_report = std::move(on_report)](c6416::cpu_port& cpu) {
        chip_hal hal(cpu, on_report);
        program(hal);
    };
}

constexpr int width = 64, height = 48;
constexpr uint32_t frame_words = width * height / 4;

uint8_t pixel(uint32_t frame, int side, int x, int y) {
    return static_cast<uint8_t>(frame * 37u + static_cast<uint32_t>(side) * 101u +
                                static_cast<uint32_t>(x) * 7u + static_cast<uint32_t>(y) * 13u);
}

// The card's documented register behaviour (docs/card-registers.md), with
// frames ending every 24.5 ms after ENABLE; frame `sync_error_frame` fails.
class card_stand_in : public sc_core::sc_module {
  public:
    tlm_utils::simple_target_socket_optional<card_stand_in> cpu;
    tlm_utils::simple_target_socket_optional<card_stand_in> edma;
    sc_core::sc_signal<bool> int4{"int4"}, int5{"int5"}, int6{"int6"};
    std::vector<sc_core::sc_time> ready_time{sc_core::SC_ZERO_TIME};  // per pair number
    std::vector<uint32_t> frame_of_pair{0};
    uint32_t sync_error_frame = 2;

    SC_HAS_PROCESS(card_stand_in);
    explicit card_stand_in(sc_core::sc_module_name name)
        : sc_core::sc_module(name), cpu("cpu"), edma("edma") {
        cpu.register_b_transport(this, &card_stand_in::transport);
        edma.register_b_transport(this, &card_stand_in::transport);
        m_regs[card::irq_enable / 4] = card::irq_enable_reset;
        SC_THREAD(frames);
        SC_THREAD(pulses);
    }

  private:
    void transport(tlm::tlm_generic_payload& t, sc_core::sc_time& delay) {
        const uint32_t address = static_cast<uint32_t>(t.get_address());
        const uint32_t words = t.get_data_length() / 4;
        const bool fixed = t.get_streaming_width() == 4;
        for (uint32_t i = 0; i < words; ++i) {
            const uint32_t a = fixed ? address : address + 4 * i;
            uint32_t v = 0;
            if (t.is_read()) {
                v = a >= card::ce3_base ? pop(a >= card::data_right ? 1 : 0)
                                        : read_reg(a - card::ce2_base);
                std::memcpy(t.get_data_ptr() + 4 * i, &v, 4);
            } else {
                std::memcpy(&v, t.get_data_ptr() + 4 * i, 4);
                write_reg(a - card::ce2_base, v);
            }
        }
        delay += sc_core::sc_time(140, sc_core::SC_NS) * static_cast<double>(words);
        t.set_response_status(tlm::TLM_OK_RESPONSE);
    }

    uint32_t read_reg(uint32_t offset) {
        switch (offset) {
            case card::id:
                return card::id_reset;
            case card::status:
                return m_enabled ? 3u | card::status_oe_mask : 0u;
            case card::verdict:
                return m_verdict;
            case card::pairs_ok:
                return m_pairs_ok;
            case card::mismatches:
                return m_mismatches;
            case card::irq_status:
                return m_irq_status;
            default:
                return m_regs[offset / 4 % 64];
        }
    }

    void write_reg(uint32_t offset, uint32_t v) {
        if (offset == card::irq_status) {
            m_irq_status &= ~v;
        } else if (offset == card::ctrl) {
            const bool enable = v & 1u;
            if (enable && !m_enabled) m_next_end = sc_core::sc_time_stamp() + us(2000.0 + 24500.0);
            m_enabled = enable;
            m_ctrl_event.notify(sc_core::SC_ZERO_TIME);
        } else {
            m_regs[offset / 4 % 64] = v;
        }
    }

    uint32_t pop(int side) {
        if (m_fifo[side].empty()) {
            ++m_underflows;
            return 0;
        }
        auto& [frame, position] = m_fifo[side].front();
        uint32_t word = 0;
        for (uint32_t n = 0; n < 4; ++n) {
            const uint32_t p = position * 4 + n;
            word |= uint32_t{pixel(frame, side, static_cast<int>(p % width),
                                   static_cast<int>(p / width))}
                    << (8 * n);
        }
        if (++position == frame_words) m_fifo[side].pop_front();
        return word;
    }

    void frames() {
        for (;;) {
            if (!m_enabled) {
                sc_core::wait(m_ctrl_event);
                continue;
            }
            if (sc_core::sc_time_stamp() < m_next_end) {
                sc_core::wait(m_next_end - sc_core::sc_time_stamp(), m_ctrl_event);
                continue;
            }
            const uint32_t f = m_frame++;
            m_next_end += us(24500.0);
            if (f == sync_error_frame) {
                ++m_mismatches;
                m_verdict = card::verdict_l_dark_mask;
                m_irq_status |= card::irq_status_sync_error_mask;
                m_pulse_pin = &int5;
            } else {
                for (int side = 0; side < 2; ++side) m_fifo[side].push_back({f, 0});
                ++m_pairs_ok;
                ready_time.push_back(sc_core::sc_time_stamp());
                frame_of_pair.push_back(f);
                m_verdict = 0;
                m_irq_status |= card::irq_status_frame_ready_mask;
                m_pulse_pin = &int4;
            }
            m_pulse_event.notify(sc_core::SC_ZERO_TIME);
        }
    }

    void pulses() {
        for (;;) {
            sc_core::wait(m_pulse_event);
            sc_core::sc_signal<bool>* pin = m_pulse_pin;
            pin->write(true);
            sc_core::wait(40, sc_core::SC_NS);
            pin->write(false);
        }
    }

    uint32_t m_regs[64] = {};
    bool m_enabled = false;
    sc_core::sc_time m_next_end;
    sc_core::sc_event m_ctrl_event, m_pulse_event;
    sc_core::sc_signal<bool>* m_pulse_pin = nullptr;
    uint32_t m_frame = 0, m_pairs_ok = 0, m_mismatches = 0, m_verdict = 0, m_irq_status = 0;
    std::deque<std::pair<uint32_t, uint32_t>> m_fifo[2];  // (frame, words read)
    int m_underflows = 0;
};

bool buffer_holds(c6416::c6416_sc& chip, const dsp::control_program& program, int buffer,
                  uint32_t frame) {
    const uint8_t* l = chip.memory(program.left_address(buffer), width * height);
    const uint8_t* r = chip.memory(program.right_address(buffer), width * height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            if (l[y * width + x] != pixel(frame, 0, x, y)) return false;
            if (r[y * width + x] != pixel(frame, 1, x, y)) return false;
        }
    }
    return true;
}

}  // namespace

TEST(C6416FirmwareSc, ControlProgramCapturesThroughTheModelsEdma) {
    c6416::c6416_config config;
    config.stop_when_firmware_returns = true;
    config.sdram_over_emifa = false;  // no EMIF model here: SDRAM buffers in zero time
    c6416::c6416_sc chip("chip", config);
    card_stand_in card_model("card");
    chip.emifa_cpu.bind(card_model.cpu);
    chip.emifa_edma.bind(card_model.edma);
    chip.ext_int4(card_model.int4);
    chip.ext_int5(card_model.int5);
    chip.ext_int6(card_model.int6);

    std::vector<uint32_t> cectl2;
    chip.set_emifa_register_observer([&](uint32_t address, uint32_t value) {
        if (address == c6416::emifa::cectl2) cectl2.push_back(value);
    });
    dsp::control_program program;
    std::vector<uint32_t> processed_frames;
    std::vector<sc_core::sc_time> captured_at;
    int content_errors = 0;
    const auto on_report = [&](const sc_core::sc_time& at, const dsp::event_record& e) {
        if (e.kind == dsp::firmware_event::pair_captured) captured_at.push_back(at);
        if (e.kind != dsp::firmware_event::pair_processed) return;
        const uint32_t frame = card_model.frame_of_pair[e.pair];
        processed_frames.push_back(frame);
        if (!buffer_holds(chip, program, static_cast<int>(e.value), frame)) ++content_errors;
    };
    dsp::control_program_config pc;
    pc.pipeline.max_width = width;
    pc.pipeline.max_height = height;
    pc.card.active_cols = width;
    pc.card.active_rows = height;
    pc.max_pairs = 4;
    bool initialised = false;
    chip.set_firmware(on_hal(
        [&](dsp::hal& h) {
            initialised = program.init(pc, h);
            program.run();
        },
        on_report));
    sc_core::sc_start(us(300000.0));

    ASSERT_TRUE(initialised);
    EXPECT_TRUE(chip.firmware_returned());
    EXPECT_EQ(processed_frames, (std::vector<uint32_t>{0, 1, 3, 4}));
    EXPECT_EQ(content_errors, 0);
    EXPECT_EQ(program.stats().sync_errors, 1u);
    EXPECT_EQ(program.stats().pairs_dropped, 0u);
    ASSERT_EQ(cectl2.size(), 1u);
    EXPECT_EQ(cectl2[0], 0x22A28A22u);
    // Pair 1: status (5 words) + left + right (768 words each) at 140 ns,
    // then the 600 capture cycles (1 us) before the firmware reports it.
    ASSERT_GE(captured_at.size(), 1u);
    const sc_core::sc_time transfer = sc_core::sc_time(140, sc_core::SC_NS) * 1541.0;
    EXPECT_EQ(captured_at[0], card_model.ready_time[1] + transfer + us(1.0));
    EXPECT_EQ(chip.edma_bytes(), 4u * 4u * (5 + 2 * frame_words));  // 4 captures, no drain
    EXPECT_EQ(chip.bus_errors(), 0u);
    std::printf(
        "pair 1 ready at %s, captured and reported at %s (%s over the bus); "
        "EDMA moved %llu bytes, busy %s; CPU busy %s\n",
        card_model.ready_time[1].to_string().c_str(), captured_at[0].to_string().c_str(),
        transfer.to_string().c_str(), static_cast<unsigned long long>(chip.edma_bytes()),
        chip.edma_busy_time().to_string().c_str(), chip.cpu_busy_time().to_string().c_str());
}
