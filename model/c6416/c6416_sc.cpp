#include "model/c6416/c6416_sc.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "model/c6416/c6416_regs.h"

namespace c6416 {

namespace regs = c6416;
using sc_core::sc_time;

// ---- the chip's memory map as the EDMA transfer controller sees it ------------------------
class c6416_sc::edma_port final : public edma_memory_map {
  public:
    explicit edma_port(c6416_sc& chip) : m_chip(chip) {}

    uint8_t* memory(uint32_t address, uint32_t bytes) override {
        return m_chip.memory(address, bytes);
    }
    bool is_local(uint32_t address) const override { return m_chip.m_memory.is_local(address); }
    bool is_peripheral(uint32_t address) const override { return m_chip.is_peripheral(address); }
    uint32_t register_read(uint32_t address) override { return m_chip.register_read(address); }
    void register_write(uint32_t address, uint32_t value) override {
        m_chip.register_write(address, value);
    }
    void emifa_access(bool write, uint32_t address, uint8_t* data, uint32_t length,
                      uint32_t streaming_width) override {
        m_chip.bus_access(m_chip.emifa_edma, write ? tlm::TLM_WRITE_COMMAND : tlm::TLM_READ_COMMAND,
                          address, data, length, streaming_width);
    }
    void map_error(const char* what) override {
        ++m_chip.m_bus_errors;
        SC_REPORT_WARNING(m_chip.name(), what);
    }

  private:
    c6416_sc& m_chip;
};

namespace {

sdram_window traffic_window(const c6416_config& config) {
    return {config.l2_line_bytes, config.sdram_traffic_base, config.sdram_traffic_bytes};
}

}  // namespace

// ---- construction ------------------------------------------------------------------------
c6416_sc::c6416_sc(sc_core::sc_module_name name, const c6416_config& config)
    : sc_core::sc_module(name),
      ext_int4("ext_int4"),
      ext_int5("ext_int5"),
      ext_int6("ext_int6"),
      ext_int7("ext_int7"),
      emifa_cpu("emifa_cpu"),
      emifa_edma("emifa_edma"),
      m_config(config),
      m_cpu_clock(simtime::tick_clock(config.dsk.cpu_period())),
      m_port(*this),
      m_memory(config.sdram_over_emifa),
      m_replay(traffic_window(config)),
      m_edma_port(std::make_unique<edma_port>(*this)),
      m_edma_transfer(*m_edma_port),
      m_timer_event("timer_event"),
      m_edma_kick("edma_kick"),
      m_irq_event("irq_event"),
      m_firmware_returned_event("firmware_returned_event") {
    if (sc_core::sc_get_time_resolution() != sc_time(1, sc_core::SC_FS)) {
        SC_REPORT_ERROR(this->name(), "the C6416 model needs a 1 fs time resolution");
    }

    SC_THREAD(cpu_thread);
    set_stack_size(m_config.cpu_stack_bytes);
    SC_THREAD(edma_thread);
    // Runs once at start (pins may all be unbound): samples the levels.
    SC_METHOD(ext_int_method);
    sensitive << ext_int4 << ext_int5 << ext_int6 << ext_int7;
    SC_METHOD(timer_method);
    sensitive << m_timer_event;
    dont_initialize();
}

c6416_sc::~c6416_sc() = default;

void c6416_sc::set_cycle_scale(uint32_t num, uint32_t den, const sc_time& from) {
    m_scale_num = num == 0 ? 1 : num;
    m_scale_den = den == 0 ? 1 : den;
    m_scale_from = from;
}

void c6416_sc::request_stop() {
    m_stop = true;
    m_irq_event.notify(sc_core::SC_ZERO_TIME);
}

uint64_t c6416_sc::charged_cycles_total() const {
    uint64_t sum = 0;
    for (uint64_t c : m_stage_cycles) sum += c;
    return sum;
}

// ---- the CPU -----------------------------------------------------------------------------
void c6416_sc::cpu_thread() {
    if (!m_firmware) return;
    m_firmware(m_port);
    m_firmware_returned = true;
    m_firmware_returned_event.notify(sc_core::SC_ZERO_TIME);
    if (m_config.stop_when_firmware_returns) sc_core::sc_stop();
}

// The "CPU too slow" fault: cycles before the onset run at the nominal
// rate, the rest scaled by num / den (rounded up).
uint64_t c6416_sc::scaled_cycles(uint64_t k0, uint64_t cycles) const {
    if (m_scale_num == m_scale_den) return cycles;
    const uint64_t onset = cpu_cycle_at_or_after(m_scale_from);
    const uint64_t before = onset > k0 ? std::min<uint64_t>(cycles, onset - k0) : 0;
    const __int128 after = static_cast<__int128>(cycles - before) * m_scale_num;
    return before + static_cast<uint64_t>((after + m_scale_den - 1) / m_scale_den);
}

void c6416_sc::charge(int stage, uint64_t cycles, const sdram_traffic& traffic) {
    if (stage < 0 || stage >= max_stages) {
        SC_REPORT_ERROR(name(), ("a charge to stage " + std::to_string(stage) + ", outside 0.." +
                                 std::to_string(max_stages - 1))
                                    .c_str());
        return;
    }
    const uint64_t k0 = m_cpu_clock.current_cycle();
    const uint64_t scaled = scaled_cycles(k0, cycles);
    m_stage_cycles[stage] += scaled;
    const sc_time start = time_of_cpu_cycle(k0);
    const sc_time target = time_of_cpu_cycle(k0 + scaled);
    m_charge_end = target;
    replay_traffic(k0, scaled, traffic);
    const sc_time now = sc_core::sc_time_stamp();
    if (now > target) {  // the bus held the last line back: the CPU waited for it
        m_sdram_late += now - target;
        m_cpu_busy += now - start;
        m_charge_end = sc_core::SC_ZERO_TIME;
        return;
    }
    m_cpu_busy += target - start;
    if (target > now) sc_core::wait(target - now);
    m_charge_end = sc_core::SC_ZERO_TIME;
}

void c6416_sc::replay_traffic(uint64_t first_cycle, uint64_t cycles, const sdram_traffic& traffic) {
    if (traffic.empty() || !m_config.sdram_over_emifa || !m_config.replay_sdram_traffic ||
        emifa_cpu.size() == 0) {
        return;
    }
    m_replay.run(m_cpu_clock, first_cycle, cycles, traffic,
                 [this](bool write_back, uint32_t address, uint8_t* data, uint32_t bytes) {
                     bus_access(emifa_cpu,
                                write_back ? tlm::TLM_WRITE_COMMAND : tlm::TLM_READ_COMMAND,
                                address, data, bytes, bytes);
                 });
}

void c6416_sc::wait_cpu_cycles(uint64_t cycles) {
    if (cycles == 0) return;
    const uint64_t k0 = m_cpu_clock.current_cycle();
    const sc_time target = time_of_cpu_cycle(k0 + cycles);
    sc_core::wait(target - sc_core::sc_time_stamp());
}

int c6416_sc::wait_for_interrupt() {
    for (;;) {
        const uint32_t pending = m_ifr & m_ier & 0xFFF0u;
        if (pending != 0) {
            int n = 4;
            while (!((pending >> n) & 1u)) ++n;
            m_ifr &= ~(1u << n);
            return n;
        }
        if (m_stop) return cpu_port::no_interrupt;
        sc_core::wait(m_irq_event);
    }
}

uint32_t c6416_sc::cpu_read32(uint32_t address) {
    uint32_t value = 0;
    if (m_memory.is_local(address)) {
        uint8_t* p = memory(address, 4);
        if (p) std::memcpy(&value, p, 4);
        return value;
    }
    if (is_peripheral(address)) {
        wait_cpu_cycles(m_config.peripheral_access_cycles);
        return register_read(address);
    }
    if (regs::in_emifa(address)) {
        const sc_time start = sc_core::sc_time_stamp();
        uint8_t bytes[4] = {};
        bus_access(emifa_cpu, tlm::TLM_READ_COMMAND, address, bytes, 4, 4);
        std::memcpy(&value, bytes, 4);
        m_cpu_bus += sc_core::sc_time_stamp() - start;
        return value;
    }
    SC_REPORT_WARNING(name(), "CPU read outside the memory map");
    return 0;
}

void c6416_sc::cpu_write32(uint32_t address, uint32_t value) {
    if (m_memory.is_local(address)) {
        uint8_t* p = memory(address, 4);
        if (p) std::memcpy(p, &value, 4);
        return;
    }
    if (is_peripheral(address)) {
        wait_cpu_cycles(m_config.peripheral_access_cycles);
        register_write(address, value);
        return;
    }
    if (regs::in_emifa(address)) {
        const sc_time start = sc_core::sc_time_stamp();
        uint8_t bytes[4];
        std::memcpy(bytes, &value, 4);
        bus_access(emifa_cpu, tlm::TLM_WRITE_COMMAND, address, bytes, 4, 4);
        m_cpu_bus += sc_core::sc_time_stamp() - start;
        return;
    }
    SC_REPORT_WARNING(name(), "CPU write outside the memory map");
}

// ---- registers: each block answers for its own addresses ---------------------------------
bool c6416_sc::is_peripheral(uint32_t address) const {
    return address >= regs::emifa::base && address < 0x02000000u;
}

uint32_t c6416_sc::peek_register(uint32_t address) {
    return register_read(address);
}

uint32_t c6416_sc::register_read(uint32_t address) {
    uint32_t value = 0;
    if (m_emifa_regs.read(address, value)) return value;
    if (m_selector.read(address, value)) return value;
    if (m_edma.read(address, value)) return value;
    const int timer = timer_block::timer_at(address);
    if (timer >= 0) return m_timers.read(timer, address, m_cpu_clock.current_cycle());
    SC_REPORT_WARNING(name(), ("read of an unmodelled register at 0x" +
                               sc_dt::sc_uint<32>(address).to_string(sc_dt::SC_HEX_US))
                                  .c_str());
    return 0;
}

void c6416_sc::register_write(uint32_t address, uint32_t value) {
    if (m_emifa_regs.write(address, value)) return;
    if (m_selector.write(address, value)) return;
    if (m_edma.write(address, value)) {
        after_edma_change();
        return;
    }
    const int timer = timer_block::timer_at(address);
    if (timer >= 0) {
        m_timers.write(timer, address, value, m_cpu_clock.current_cycle());
        arm_timer_event();
        return;
    }
    SC_REPORT_WARNING(name(), ("write of an unmodelled register at 0x" +
                               sc_dt::sc_uint<32>(address).to_string(sc_dt::SC_HEX_US))
                                  .c_str());
}

// ---- interrupts --------------------------------------------------------------------------
void c6416_sc::raise_interrupt_event(uint32_t selector_code) {
    const uint32_t ints = m_selector.cpu_interrupts_for(selector_code);
    if (ints == 0) return;
    m_ifr |= ints;
    m_irq_event.notify(sc_core::SC_ZERO_TIME);
}

void c6416_sc::after_edma_change() {
    if (m_edma.take_interrupt()) raise_interrupt_event(regs::irq::sel_edma_int);
    if (m_edma.has_request()) m_edma_kick.notify(sc_core::SC_ZERO_TIME);
}

void c6416_sc::ext_int_method() {
    const pin_in* pins[4] = {&ext_int4, &ext_int5, &ext_int6, &ext_int7};
    bool now[4];
    for (int n = 0; n < 4; ++n) now[n] = pins[n]->size() != 0 && (*pins[n])->read();
    if (!m_pins_sampled) {  // a level at start is no edge
        m_pins_sampled = true;
        for (int n = 0; n < 4; ++n) m_ext_level[n] = now[n];
        return;
    }
    for (int n = 0; n < 4; ++n) {
        const bool was = m_ext_level[n];
        m_ext_level[n] = now[n];
        if (was == now[n] || !m_selector.active_edge(n, was, now[n])) continue;
        raise_interrupt_event(regs::irq::sel_gpint4 + static_cast<uint32_t>(n));
        m_edma.event(regs::edma::channel_ext_int4 + n);
    }
    after_edma_change();
}

void c6416_sc::arm_timer_event() {
    const uint64_t earliest = m_timers.earliest_interrupt();
    m_timer_event.cancel();
    if (earliest != timer_block::never) {
        m_timer_event.notify(time_of_cpu_cycle(earliest) - sc_core::sc_time_stamp());
    }
}

void c6416_sc::timer_method() {
    static constexpr uint32_t codes[timer_block::count] = {
        regs::irq::sel_tint0, regs::irq::sel_tint1, regs::irq::sel_tint2};
    static constexpr int channels[timer_block::count] = {
        regs::edma::channel_tint0, regs::edma::channel_tint1, regs::edma::channel_tint2};
    const uint32_t due = m_timers.take_due(m_cpu_clock.current_cycle());
    for (int n = 0; n < timer_block::count; ++n) {
        if (!((due >> n) & 1u)) continue;
        raise_interrupt_event(codes[n]);
        m_edma.event(channels[n]);
    }
    after_edma_change();
    arm_timer_event();
}

// ---- EDMA --------------------------------------------------------------------------------
void c6416_sc::edma_thread() {
    for (;;) {
        while (!m_edma.has_request()) sc_core::wait(m_edma_kick);
        const transfer_request r = m_edma.take_request();
        const sc_time start = sc_core::sc_time_stamp();
        m_edma_transfer.execute(r);
        m_edma_busy += sc_core::sc_time_stamp() - start;
        m_edma_bytes += r.bytes();
        m_edma.complete(r);
        after_edma_change();
    }
}

// ---- EMIFA -------------------------------------------------------------------------------
void c6416_sc::bus_access(tlm_utils::simple_initiator_socket_optional<c6416_sc>& socket,
                          tlm::tlm_command command, uint32_t address, uint8_t* data,
                          uint32_t length, uint32_t streaming_width) {
    tlm::tlm_generic_payload t;
    t.set_command(command);
    t.set_address(address);
    t.set_data_ptr(data);
    t.set_data_length(length);
    t.set_streaming_width(streaming_width);
    t.set_byte_enable_ptr(nullptr);
    t.set_dmi_allowed(false);
    t.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
    sc_time delay = sc_core::SC_ZERO_TIME;
    if (socket.size() == 0) {
        ++m_bus_errors;
        SC_REPORT_WARNING(
            name(),
            (std::string("EMIFA access with nothing bound to ") + socket.basename()).c_str());
        return;
    }
    socket->b_transport(t, delay);
    if (t.is_response_error()) {
        ++m_bus_errors;
        SC_REPORT_WARNING(name(), ("EMIFA " + t.get_response_string() + " at 0x" +
                                   sc_dt::sc_uint<32>(address).to_string(sc_dt::SC_HEX_US))
                                      .c_str());
    }
    if (delay > sc_core::SC_ZERO_TIME) sc_core::wait(delay);
}

}  // namespace c6416
