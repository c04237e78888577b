#include "tb/platform/probe_hal.h"

#include "dsp/card_regs.h"

#include <systemc>

#include "model/c6416/c6416_sc.h"
#include "model/time/sc_ticks.h"
#include "tb/platform/firmware_crash.h"

namespace platform {

simtime::ticks probe_hal::now() {
    return simtime::tick_at_or_after(sc_core::sc_time_stamp());
}

void probe_hal::start() {
    m_started = true;
    m_left = std::chrono::steady_clock::now();
}

void probe_hal::enter() {
    firmware_left();
    if (!m_started) return;
    m_firmware_wall_s +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - m_left).count();
}

void probe_hal::leave() {
    firmware_entered(now(), m_open_stage, m_stage_names, m_stage_count);
    if (m_started) m_left = std::chrono::steady_clock::now();
}

void probe_hal::charge(int stage, uint64_t cycles, const stereosim_sdram_traffic* traffic) {
    enter();
    const simtime::ticks begin = now();
    // The model's stage tables hold every stage the ABI allows.
    c6416::sdram_traffic t;
    if (traffic != nullptr) t = {traffic->bytes_read, traffic->bytes_written};
    m_inner.charge(stage, cycles, t);
    // Counted once the charge is over: a run that stops inside one leaves it out.
    m_stage_traffic[stage].bytes_read += t.bytes_read;
    m_stage_traffic[stage].bytes_written += t.bytes_written;
    m_charges.push_back(
        {begin, now(), stage, cycles, traffic != nullptr ? *traffic : stereosim_sdram_traffic{}});
    m_stage_cycles[stage] += cycles;
    m_open_cycles += cycles;
    leave();
}

void probe_hal::stage_begin(int stage) {
    enter();
    m_open_stage = stage;
    m_open_cycles = 0;
    m_events.add(now(), event_kind::stage_begin, static_cast<uint8_t>(stage));
    leave();
}

void probe_hal::stage_end(int stage) {
    enter();
    m_events.add(now(), event_kind::stage_end, static_cast<uint8_t>(stage),
                 static_cast<uint32_t>(m_open_cycles));
    m_open_stage = -1;
    leave();
}

uint32_t probe_hal::read32(uint32_t address) {
    enter();
    const uint32_t v = m_inner.read32(address);
    leave();
    return v;
}

void probe_hal::write32(uint32_t address, uint32_t value) {
    enter();
    m_inner.write32(address, value);
    if (address == dsp::card_regs::ce2_base + dsp::card_regs::ctrl)
        m_card_control.push_back({now(), value});
    if (address == dsp::card_regs::ce2_base + dsp::card_regs::checks)
        m_card_checks.push_back({now(), value});
    leave();
}

uint32_t probe_hal::card_checks_at(simtime::ticks t) const {
    uint32_t checks = dsp::card_regs::checks_reset;
    for (const register_write& w : m_card_checks)
        if (w.tick <= t) checks = w.value;
    return checks;
}

uint8_t* probe_hal::memory(uint32_t address, uint32_t bytes) {
    if (m_memory_hook) m_memory_hook(address, bytes);
    return m_inner.memory(address, bytes);
}

void probe_hal::set_interrupt_enable(uint32_t ier) {
    m_inner.set_interrupt_enable(ier);
}

uint32_t probe_hal::interrupt_flags() {
    return m_inner.interrupt_flags();
}

void probe_hal::clear_interrupt_flags(uint32_t mask) {
    m_inner.clear_interrupt_flags(mask);
}

int probe_hal::wait_for_interrupt() {
    enter();
    const simtime::ticks begin = now();
    m_events.add(begin, event_kind::cpu_sleep);
    m_asleep_since = begin;
    const int n = m_inner.wait_for_interrupt();
    const simtime::ticks end = now();
    m_asleep_since = -1;
    m_sleeps.push_back({begin, end});
    m_events.add(end, event_kind::cpu_wake, static_cast<uint8_t>(n < 0 ? 255 : n));
    leave();
    return n;
}

void probe_hal::report(const stereosim_event& e) {
    enter();
    const fw_event te{now(), e};
    if (m_hook) m_hook(te);
    m_fw_events.push_back(te);
    m_events.add(te.tick, event_kind::firmware, static_cast<uint8_t>(e.kind), e.pair, e.value);
    leave();
}

void probe_hal::report_result(const stereosim_result& r) {
    enter();
    const simtime::ticks t = now();
    m_results.push_back({t, r.pair, r});
    m_events.add(t, event_kind::result, static_cast<uint8_t>(r.state), r.pair, r.has_point ? 1 : 0);
    leave();
}

bool probe_hal::stop_requested() {
    return m_inner.stop_requested();
}

}  // namespace platform
