// What the platform's services (firmware_services.h) run on: every call the
// firmware makes through the ABI goes to the C6416 model's CPU port
// (model/c6416/cpu_port.h) unchanged, and the probe records, with the simulated tick of
// each, what the firmware did: stage intervals and the cycles charged in
// them, when the CPU slept in wait_for_interrupt, every report and result
// (docs/platform.md, "Timeline"). It also measures the host time the
// firmware itself takes (time on the CPU thread outside the HAL's blocking
// calls), for the firmware's share of the wall time.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <vector>

#include "model/c6416/cpu_port.h"
#include "model/time/ticks.h"
#include "stereosim/firmware.h"
#include "tb/platform/firmware_report.h"
#include "tb/platform/host/cost_service.h"
#include "tb/platform/island/timeline.h"

namespace platform {

struct charge_record {
    simtime::ticks begin = 0, end = 0;  // simulated interval the CPU spent on it
    int stage = 0;                      // the firmware's declared stage index
    uint64_t cycles = 0;
    stereosim_sdram_traffic traffic{};  // SDRAM bytes its kernels moved (replayed on the EMIF)
};

struct tick_interval {
    simtime::ticks begin = 0, end = 0;
};

// A register write of the DSP as it completed on the bus.
struct register_write {
    simtime::ticks tick = 0;
    uint32_t value = 0;
};

struct fw_result {
    simtime::ticks tick = 0;
    uint32_t pair = 0;       // the pair's number, as the firmware reports it
    stereosim_result out{};  // as the firmware reported it
};

class probe_hal {
  public:
    using event_hook = std::function<void(const fw_event&)>;
    // Every memory() the firmware asks for: what it reads of DSP memory.
    using memory_hook = std::function<void(uint32_t address, uint32_t bytes)>;

    // The firmware's kernels are priced with `model` (kernel_cycles).
    probe_hal(c6416::cpu_port& inner, timeline& events, const c64x::cost_model& model)
        : m_inner(inner), m_events(events), m_model(model) {}

    // Called once on the CPU thread before the firmware starts.
    void start();
    // Called by report() before the event is recorded (scoreboard checks).
    void set_event_hook(event_hook hook) { m_hook = std::move(hook); }
    void set_memory_hook(memory_hook hook) { m_memory_hook = std::move(hook); }
    // The platform's own look at DSP memory: not a read of the firmware's.
    const uint8_t* peek(uint32_t address, uint32_t bytes) { return m_inner.memory(address, bytes); }
    // The firmware's stage names, for a crash report (firmware_crash.h).
    void set_stage_names(const char* const* names, int count) {
        m_stage_names = names;
        m_stage_count = count;
    }

    // Stage indices are the firmware's declared ones (firmware_services
    // checked them); traffic may be null.
    void charge(int stage, uint64_t cycles, const stereosim_sdram_traffic* traffic);
    uint64_t kernel_cycles(const stereosim_kernel_profile& kernel,
                           stereosim_sdram_traffic* traffic) const {
        return host::kernel_cycles(m_model, kernel, traffic);
    }
    void stage_begin(int stage);
    void stage_end(int stage);
    uint32_t read32(uint32_t address);
    void write32(uint32_t address, uint32_t value);
    uint8_t* memory(uint32_t address, uint32_t bytes);
    void set_interrupt_enable(uint32_t ier);
    uint32_t interrupt_flags();
    void clear_interrupt_flags(uint32_t mask);
    int wait_for_interrupt();
    // A report as the firmware ABI has it (the frames' addresses included).
    void report(const stereosim_event& e);
    void report_result(const stereosim_result& r);
    bool stop_requested();

    const std::vector<charge_record>& charges() const { return m_charges; }
    // Intervals the CPU was asleep in wait_for_interrupt.
    const std::vector<tick_interval>& sleeps() const { return m_sleeps; }
    // Tick the CPU went to sleep if it is asleep now, else -1.
    simtime::ticks asleep_since() const { return m_asleep_since; }
    // The firmware's run() returned (a give-up, a missing card): the CPU
    // does no more work, so the budget counts it idle from now on.
    void halted() {
        m_asleep_since = m_halted_at = now();
        m_halted_on_request = stop_requested();
    }
    // When run() returned, -1 while it runs; whether a stop was asked for then.
    simtime::ticks halted_at() const { return m_halted_at; }
    bool halted_on_request() const { return m_halted_on_request; }
    const std::vector<fw_event>& fw_events() const { return m_fw_events; }
    // Every write of the card's CTRL (ENABLE: OE on / off), the truth the
    // contract judges the firmware's re-arms by, whatever it reports.
    const std::vector<register_write>& card_control_writes() const { return m_card_control; }
    // The card's CHECKS at `t`: the DSP's last write at or before it, else
    // the register's reset value.
    uint32_t card_checks_at(simtime::ticks t) const;
    const std::vector<fw_result>& results() const { return m_results; }
    uint64_t stage_cycles(int stage) const { return m_stage_cycles[stage]; }
    // SDRAM bytes charged per stage, whole run.
    const stereosim_sdram_traffic& stage_traffic(int stage) const { return m_stage_traffic[stage]; }
    double firmware_wall_s() const { return m_firmware_wall_s; }
    // The stage the firmware is in (between stage_begin and stage_end), -1 none.
    int open_stage() const { return m_open_stage; }

  private:
    // Host time bookkeeping around every call into the HAL.
    void enter();
    void leave();
    static simtime::ticks now();

    c6416::cpu_port& m_inner;
    timeline& m_events;
    const char* const* m_stage_names = nullptr;
    int m_stage_count = 0;
    c64x::cost_model m_model;
    event_hook m_hook;
    memory_hook m_memory_hook;
    std::vector<charge_record> m_charges;
    std::vector<tick_interval> m_sleeps;
    std::vector<fw_event> m_fw_events;
    std::vector<register_write> m_card_control;
    std::vector<register_write> m_card_checks;
    std::vector<fw_result> m_results;
    // Per stage the firmware may declare (the ABI's limit, not the reference's 7).
    uint64_t m_stage_cycles[STEREOSIM_FW_MAX_STAGES] = {};
    stereosim_sdram_traffic m_stage_traffic[STEREOSIM_FW_MAX_STAGES] = {};
    uint64_t m_open_cycles = 0;
    int m_open_stage = -1;
    simtime::ticks m_asleep_since = -1;
    simtime::ticks m_halted_at = -1;
    bool m_halted_on_request = false;
    bool m_started = false;
    std::chrono::steady_clock::time_point m_left;
    double m_firmware_wall_s = 0.0;
};

}  // namespace platform
