#include "model/c6416/c6416_sc.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "dsp/c6416_regs.h"
#include "model/time/sc_ticks.h"

namespace c6416 {

namespace regs = dsp::c6416;
using sc_core::sc_time;

// ---- the firmware's HAL: forwards to the module on the CPU thread ---------------------------
class c6416_sc::firmware_hal final : public dsp::hal {
  public:
    explicit firmware_hal(c6416_sc& chip) : m_chip(chip) {}

    void charge_cycles(dsp::stage s, uint64_t cycles) override { m_chip.charge(s, cycles, {}); }
    void charge_with_traffic(dsp::stage s, uint64_t cycles,
                             const dsp::sdram_traffic& traffic) override {
        m_chip.charge(s, cycles, traffic);
    }
    void stage_begin(dsp::stage s) override {
        if (m_chip.m_stage_observer) m_chip.m_stage_observer(sc_core::sc_time_stamp(), s, true);
    }
    void stage_end(dsp::stage s) override {
        if (m_chip.m_stage_observer) m_chip.m_stage_observer(sc_core::sc_time_stamp(), s, false);
    }
    uint32_t read32(uint32_t address) override { return m_chip.cpu_read32(address); }
    void write32(uint32_t address, uint32_t value) override { m_chip.cpu_write32(address, value); }
    uint8_t* memory(uint32_t address, uint32_t bytes) override {
        return m_chip.memory(address, bytes);
    }
    void set_interrupt_enable(uint32_t ier) override { m_chip.m_ier = ier & 0xFFF0u; }
    uint32_t interrupt_flags() override { return m_chip.m_ifr; }
    void clear_interrupt_flags(uint32_t mask) override { m_chip.m_ifr &= ~mask; }
    int wait_for_interrupt() override { return m_chip.wait_for_interrupt(); }
    void report(const dsp::event_record& e) override { m_chip.report(e); }
    void report_result(const dsp::frame_output& out) override {
        if (m_chip.m_result_observer) m_chip.m_result_observer(sc_core::sc_time_stamp(), out);
    }
    bool stop_requested() override { return m_chip.m_stop; }

  private:
    c6416_sc& m_chip;
};

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
      m_cpu_clock(config.dsk.cpu_period()),
      m_hal(std::make_unique<firmware_hal>(*this)),
      m_l2(regs::l2_bytes, 0),
      m_sdram(regs::sdram_bytes, 0),
      m_timer_event("timer_event"),
      m_edma_kick("edma_kick"),
      m_irq_event("irq_event"),
      m_firmware_returned_event("firmware_returned_event"),
      m_line_buffer(config.l2_line_bytes < 4 ? 4 : config.l2_line_bytes, 0) {
    if (sc_core::sc_get_time_resolution() != sc_time(1, sc_core::SC_FS)) {
        SC_REPORT_ERROR(this->name(), "the C6416 model needs a 1 fs time resolution");
    }
    for (int ce = 0; ce < 4; ++ce) {
        int index = 0;
        emifa_register_index(regs::emifa::cectl(ce), index);
        m_emifa_regs[index] = regs::emifa::cectl_reset;
    }
    for (timer_unit& t : m_timers) t.reset();

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

// ---- CPU clock ---------------------------------------------------------------------------
uint64_t c6416_sc::cpu_cycle_at_or_after(const sc_time& t) const {
    return m_cpu_clock.first_rise_at_or_after(simtime::tick_at_or_after(t));
}

sc_time c6416_sc::time_of_cpu_cycle(uint64_t k) const {
    return simtime::sc_time_of(m_cpu_clock.rise(k));
}

void c6416_sc::cpu_thread() {
    if (!m_firmware) return;
    m_firmware(*m_hal);
    m_firmware_returned = true;
    m_firmware_returned_event.notify(sc_core::SC_ZERO_TIME);
    if (m_config.stop_when_firmware_returns) sc_core::sc_stop();
}

void c6416_sc::charge(dsp::stage s, uint64_t cycles, const dsp::sdram_traffic& traffic) {
    const uint64_t k0 = cpu_cycle_at_or_after(sc_core::sc_time_stamp());
    uint64_t scaled = cycles;
    if (m_scale_num != m_scale_den) {
        // Cycles before the onset run at the nominal rate, the rest scaled.
        const uint64_t onset = cpu_cycle_at_or_after(m_scale_from);
        const uint64_t before = onset > k0 ? std::min<uint64_t>(cycles, onset - k0) : 0;
        const __int128 after = static_cast<__int128>(cycles - before) * m_scale_num;
        scaled = before + static_cast<uint64_t>((after + m_scale_den - 1) / m_scale_den);
    }
    m_stage_cycles[static_cast<int>(s)] += scaled;
    const sc_time start = time_of_cpu_cycle(k0);
    const sc_time target = time_of_cpu_cycle(k0 + scaled);
    replay_traffic(k0, scaled, traffic);
    const sc_time now = sc_core::sc_time_stamp();
    if (now > target) {  // the bus held the last line back: the CPU waited for it
        m_sdram_late += now - target;
        m_cpu_busy += now - start;
        return;
    }
    m_cpu_busy += target - start;
    if (target > now) sc_core::wait(target - now);
}

// The charge's SDRAM traffic as L2 line transfers on emifa_cpu, spread over
// its CPU cycles [first_cycle, first_cycle + cycles): transfer k of T waits
// for CPU cycle first_cycle + cycles k / T (or goes at once if the previous
// one ended later). Write-backs are interleaved evenly among the reads
// (Bresenham), each after at least one fetch.
void c6416_sc::replay_traffic(uint64_t first_cycle, uint64_t cycles,
                              const dsp::sdram_traffic& traffic) {
    if (traffic.empty() || !m_config.sdram_over_emifa || !m_config.replay_sdram_traffic ||
        emifa_cpu.size() == 0) {
        return;
    }
    const uint64_t line = m_line_buffer.size();
    const uint64_t written = (traffic.bytes_written + line - 1) / line;
    const uint64_t fetched = (traffic.bytes_read + line - 1) / line + written;
    const uint64_t transfers = fetched + written;
    const uint64_t window_lines = std::max<uint64_t>(1, m_config.sdram_traffic_bytes / line);
    for (uint64_t k = 0; k < transfers; ++k) {
        const uint64_t slot_cycle =
            first_cycle +
            static_cast<uint64_t>(static_cast<unsigned __int128>(cycles) * k / transfers);
        const sc_time slot = time_of_cpu_cycle(slot_cycle);
        if (slot > sc_core::sc_time_stamp()) sc_core::wait(slot - sc_core::sc_time_stamp());
        const bool write_back = (k + 1) * written / transfers > k * written / transfers;
        const uint32_t address = m_config.sdram_traffic_base +
                                 static_cast<uint32_t>((m_traffic_cursor++ % window_lines) * line);
        const sc_time issued = sc_core::sc_time_stamp();
        bus_access(emifa_cpu, write_back ? tlm::TLM_WRITE_COMMAND : tlm::TLM_READ_COMMAND, address,
                   m_line_buffer.data(), static_cast<uint32_t>(line), static_cast<uint32_t>(line));
        m_sdram_transfer += sc_core::sc_time_stamp() - issued;
        if (write_back) {
            ++m_sdram_lines_written;
        } else {
            ++m_sdram_lines_read;
        }
    }
}

void c6416_sc::wait_cpu_cycles(uint64_t cycles) {
    if (cycles == 0) return;
    const uint64_t k0 = cpu_cycle_at_or_after(sc_core::sc_time_stamp());
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
        if (m_stop) return dsp::hal::no_interrupt;
        sc_core::wait(m_irq_event);
    }
}

void c6416_sc::report(const dsp::event_record& e) {
    const timed_event te{sc_core::sc_time_stamp(), e};
    m_events.push_back(te);
    if (m_event_observer) m_event_observer(te);
}

// ---- memory and registers ----------------------------------------------------------------
uint8_t* c6416_sc::memory(uint32_t address, uint32_t bytes) {
    const uint64_t end = static_cast<uint64_t>(address) + bytes;
    if (end <= regs::l2_base + static_cast<uint64_t>(regs::l2_bytes)) return &m_l2[address];
    if (address >= regs::sdram_base && end <= regs::sdram_base + uint64_t{regs::sdram_bytes}) {
        return &m_sdram[address - regs::sdram_base];
    }
    return nullptr;
}

bool c6416_sc::local_memory(uint32_t address) const {
    if (address < regs::l2_base + regs::l2_bytes) return true;
    return !m_config.sdram_over_emifa && address >= regs::sdram_base &&
           address < regs::sdram_base + regs::sdram_bytes;
}

bool c6416_sc::is_peripheral(uint32_t address) const {
    return address >= regs::emifa::base && address < 0x02000000u;
}

bool c6416_sc::emifa_register_index(uint32_t address, int& index) const {
    if (address < regs::emifa::base || address >= regs::emifa::base + regs::emifa::block_bytes ||
        (address & 3u) != 0) {
        return false;
    }
    index = static_cast<int>((address - regs::emifa::base) / 4);
    return true;
}

uint32_t c6416_sc::peek_register(uint32_t address) {
    return register_read(address);
}

uint32_t c6416_sc::register_read(uint32_t address) {
    uint32_t value = 0;
    int index = 0;
    if (emifa_register_index(address, index)) return m_emifa_regs[index];
    if (m_selector.read(address, value)) return value;
    if (m_edma.read(address, value)) return value;
    for (int n = 0; n < 3; ++n) {
        const uint32_t base = regs::timer::base(n);
        if (address >= base && address < base + regs::timer::block_bytes) {
            const uint64_t cycle = cpu_cycle_at_or_after(sc_core::sc_time_stamp());
            switch (address - base) {
                case regs::timer::ctl:
                    return m_timers[n].read_ctl();
                case regs::timer::prd:
                    return m_timers[n].read_prd();
                default:
                    return m_timers[n].read_cnt(cycle);
            }
        }
    }
    SC_REPORT_WARNING(name(), ("read of an unmodelled register at 0x" +
                               sc_dt::sc_uint<32>(address).to_string(sc_dt::SC_HEX_US))
                                  .c_str());
    return 0;
}

void c6416_sc::register_write(uint32_t address, uint32_t value) {
    int index = 0;
    if (emifa_register_index(address, index)) {
        m_emifa_regs[index] = value;
        if (m_emifa_observer) m_emifa_observer(address, value);
        return;
    }
    if (m_selector.write(address, value)) return;
    if (m_edma.write(address, value)) {
        after_edma_change();
        return;
    }
    for (int n = 0; n < 3; ++n) {
        const uint32_t base = regs::timer::base(n);
        if (address >= base && address < base + regs::timer::block_bytes) {
            const uint64_t cycle = cpu_cycle_at_or_after(sc_core::sc_time_stamp());
            switch (address - base) {
                case regs::timer::ctl:
                    m_timers[n].write_ctl(value, cycle);
                    break;
                case regs::timer::prd:
                    m_timers[n].write_prd(value);
                    break;
                default:
                    m_timers[n].write_cnt(value, cycle);
                    break;
            }
            reschedule_timer(n);
            return;
        }
    }
    SC_REPORT_WARNING(name(), ("write of an unmodelled register at 0x" +
                               sc_dt::sc_uint<32>(address).to_string(sc_dt::SC_HEX_US))
                                  .c_str());
}

uint32_t c6416_sc::cpu_read32(uint32_t address) {
    uint32_t value = 0;
    if (local_memory(address)) {
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
    if (local_memory(address)) {
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

void c6416_sc::reschedule_timer(int n) {
    // An interrupt due this very cycle has fired already (timer_method) or
    // belongs to the old setting: look from the next cycle.
    const uint64_t cycle = cpu_cycle_at_or_after(sc_core::sc_time_stamp());
    m_timer_next[n] = m_timers[n].next_interrupt(cycle + 1);
    arm_timer_event();
}

void c6416_sc::arm_timer_event() {
    uint64_t earliest = timer_unit::never;
    for (uint64_t next : m_timer_next) earliest = std::min(earliest, next);
    m_timer_event.cancel();
    if (earliest != timer_unit::never) {
        m_timer_event.notify(time_of_cpu_cycle(earliest) - sc_core::sc_time_stamp());
    }
}

void c6416_sc::timer_method() {
    static constexpr uint32_t codes[3] = {regs::irq::sel_tint0, regs::irq::sel_tint1,
                                          regs::irq::sel_tint2};
    static constexpr int channels[3] = {regs::edma::channel_tint0, regs::edma::channel_tint1,
                                        regs::edma::channel_tint2};
    const uint64_t cycle = cpu_cycle_at_or_after(sc_core::sc_time_stamp());
    for (int n = 0; n < 3; ++n) {
        if (m_timer_next[n] == timer_unit::never || m_timer_next[n] > cycle) continue;
        raise_interrupt_event(codes[n]);
        m_edma.event(channels[n]);
        m_timer_next[n] = m_timers[n].next_interrupt(cycle + 1);
    }
    after_edma_change();
    arm_timer_event();
}

// ---- EDMA transfer controller ------------------------------------------------------------
void c6416_sc::edma_thread() {
    for (;;) {
        while (!m_edma.has_request()) sc_core::wait(m_edma_kick);
        const transfer_request r = m_edma.take_request();
        const sc_time start = sc_core::sc_time_stamp();
        execute(r);
        m_edma_busy += sc_core::sc_time_stamp() - start;
        m_edma_bytes += r.bytes();
        m_edma.complete(r);
        after_edma_change();
    }
}

void c6416_sc::execute(const transfer_request& r) {
    const uint64_t array_bytes = static_cast<uint64_t>(r.elements) * r.element_bytes;
    if (m_staging.size() < array_bytes) m_staging.resize(array_bytes);
    for (uint32_t a = 0; a < r.arrays; ++a) {
        const uint32_t src = static_cast<uint32_t>(r.src.start + r.src.array_step * a);
        const uint32_t dst = static_cast<uint32_t>(r.dst.start + r.dst.array_step * a);
        read_run(src, r.src.element_step, r.elements, r.element_bytes, m_staging.data());
        write_run(dst, r.dst.element_step, r.elements, r.element_bytes, m_staging.data());
    }
}

// One EDMA run of `elements` elements of `es` bytes on EMIFA: a whole burst
// when the addresses increment by the element size, a fixed-address stream
// when they do not move (a FIFO port), else one access per element.
void c6416_sc::bus_run(tlm::tlm_command command, uint32_t address, int64_t step, uint32_t elements,
                       uint32_t es, uint8_t* data) {
    const uint32_t length = elements * es;
    if (step == es) {
        bus_access(emifa_edma, command, address, data, length, length);
    } else if (step == 0) {
        bus_access(emifa_edma, command, address, data, length, es);
    } else {
        for (uint32_t i = 0; i < elements; ++i) {
            bus_access(emifa_edma, command, static_cast<uint32_t>(address + step * i),
                       data + i * es, es, es);
        }
    }
}

void c6416_sc::read_run(uint32_t address, int64_t step, uint32_t elements, uint32_t es,
                        uint8_t* out) {
    if (regs::in_emifa(address) && !local_memory(address)) {
        bus_run(tlm::TLM_READ_COMMAND, address, step, elements, es, out);
        return;
    }
    for (uint32_t i = 0; i < elements; ++i) {
        const uint32_t a = static_cast<uint32_t>(address + step * i);
        if (uint8_t* p = memory(a, es)) {
            std::memcpy(out + i * es, p, es);
        } else if (is_peripheral(a) && es == 4) {
            const uint32_t v = register_read(a);
            std::memcpy(out + i * es, &v, 4);
        } else {
            ++m_bus_errors;
            SC_REPORT_WARNING(name(), "EDMA read outside the memory map");
            return;
        }
    }
}

void c6416_sc::write_run(uint32_t address, int64_t step, uint32_t elements, uint32_t es,
                         const uint8_t* in) {
    if (regs::in_emifa(address) && !local_memory(address)) {
        // TLM payloads carry a non-const pointer; a write only reads it.
        bus_run(tlm::TLM_WRITE_COMMAND, address, step, elements, es, const_cast<uint8_t*>(in));
        return;
    }
    for (uint32_t i = 0; i < elements; ++i) {
        const uint32_t a = static_cast<uint32_t>(address + step * i);
        if (uint8_t* p = memory(a, es)) {
            std::memcpy(p, in + i * es, es);
        } else if (is_peripheral(a) && es == 4) {
            uint32_t v = 0;
            std::memcpy(&v, in + i * es, 4);
            register_write(a, v);
        } else {
            ++m_bus_errors;
            SC_REPORT_WARNING(name(), "EDMA write outside the memory map");
            return;
        }
    }
}

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
