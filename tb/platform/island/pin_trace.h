// Pin tracing (docs/waveforms.md): a sink that sees every traced signal of a
// run change, with its exact tick (1 tick = 1/18 ns), on ONE timeline. It is
// arrangement-neutral: both arrangements feed it through the island's
// pin_tracer (pin_tracer.h), the fast island from its C++ edge loop, the
// pin-level one from the settled sc_signals; both declare the same signals
// (pin_trace_signals below) and report the same changes.
//
// Contract for a source (what a sink may rely on):
//   1. declare() every signal before the first change; the returned id is
//      what change()/release() name.
//   2. At tick `window.from` (the first call with a tick >= from), report
//      the value of EVERY declared signal as it stands at `from` (a
//      snapshot: the values the last edge before `from` left), then the
//      changes in non-decreasing tick order. Nothing before `from`, nothing
//      at or after `window.to`.
//   3. Report a value only when it changed (a repeat is harmless, a sink
//      drops it). release() says nobody drives the signal (VCD 'z').
//   4. seal_before(t) whenever the card may change at t (pin_tracer does it
//      before each traced edge and at the window's end), then finish() once,
//      after the last change (the window closed or the run ended).
// Cost: a source with no sink attached does nothing per edge beyond a null
// pointer test (measured in docs/waveforms.md). With a sink, only the edges
// from a short warm-up before `window.from` (pin_tracer.h) to `window.to`
// make trace calls: a window costs about
// its own length, not the whole run.
#pragma once

#include <cstdint>
#include <string>

#include "model/time/ticks.h"

namespace platform {

class card_waves;

using trace_id = uint32_t;

// What the viewer should do with a signal's value (a GTKWave translate
// filter names the values of an enumerated signal; tb/app/output/gtkw_writer.h).
enum class trace_format : uint8_t {
    bits,            // a wire or a bus shown in hex
    decimal,         // a count (FIFO level)
    oe_state,        // the card's OE controller FSM (card_regs: STATUS.STATE)
    verdict,         // VERDICT causes
    card_register,   // word index of a card register on CE2 (EA[7:2])
    firmware_stage,  // the firmware's declared stage index, or `stage_idle`
    tracker_state,   // the firmware's declared tracker state index
    interrupt,       // the EXT_INT number the CPU took
};

struct trace_signal {
    std::string scope;  // dotted: "sensor_L", "card.sync_check", ...
    std::string name;   // "PCLK", "DATA", ...
    int width = 1;      // bits, 1..64
    trace_format format = trace_format::bits;
};

// [from, to) in ticks.
struct tick_window {
    simtime::ticks from = 0;
    simtime::ticks to = INT64_MAX;
    bool contains(simtime::ticks t) const { return t >= from && t < to; }
};

class pin_trace {
  public:
    virtual ~pin_trace() = default;
    virtual trace_id declare(const trace_signal& signal) = 0;
    virtual void change(simtime::ticks t, trace_id id, uint64_t value) = 0;
    virtual void release(simtime::ticks t, trace_id id) = 0;
    // Every change before tick t has been reported and the card has not
    // moved past them: a sink that reads the card itself (card_file)
    // writes those times now, before the card's next edge at t.
    virtual void seal_before(simtime::ticks /*t*/) {}
    virtual void finish(simtime::ticks end) = 0;
    // The file a traced build of the card writes into, or null (card_waves.h).
    virtual card_waves* card_file() { return nullptr; }
};

// The firmware stage signal's value when no stage runs (stages are
// 0..STEREOSIM_FW_MAX_STAGES - 1).
inline constexpr uint64_t stage_idle = 15;
// card.emif_slave.register while CE2 is high: no card register (the map
// ends at word 39, rtl/card_regs.csv); its filter says "(no access)".
inline constexpr uint64_t register_no_access = 63;

// The signals of a run, in declaration order: one table for every
// arrangement, so their VCDs are comparable signal by signal.
enum class trace_pin : uint8_t {
    // sensor_L, sensor_R (each): the sensor's pins and the OE it samples
    l_pclk,
    l_vsync,
    l_href,
    l_valid,
    l_data,
    l_oe,
    l_fodd,
    r_pclk,
    r_vsync,
    r_href,
    r_valid,
    r_data,
    r_oe,
    r_fodd,
    // card: master pixel clock, interrupt pins, the EMIF slave's outputs
    card_pclk,
    ext_int4,
    ext_int5,
    ext_int6,
    slave_ardy,
    slave_ed_oe,
    slave_ed,
    slave_register,
    // card.sync_check: OE controller state, causes so far, last verdict
    oe_state,
    sync_causes,
    verdict,
    // card.fifo: write-side levels and sticky overflow flags
    fifo_level_l,
    fifo_level_r,
    fifo_overflow_l,
    fifo_overflow_r,
    // emif: the DSP's EMIFA pins (ED: whoever drives it, z if nobody)
    eclkout,
    ce0_n,
    ce2_n,
    ce3_n,
    ea,
    ed,
    be_n,
    aoe_n,
    are_n,
    awe_n,
    ardy,  // the DSP's ARDY input: the card's through the board glue
    // interrupts / firmware: from the timeline
    irq_taken,
    cpu_asleep,
    fw_stage,
    fw_tracker,
    count_
};
inline constexpr int trace_pin_count = static_cast<int>(trace_pin::count_);

// Scope, name, width and format of each trace_pin.
const trace_signal& trace_pin_signal(trace_pin pin);

// Scope groups selectable with --vcd-scope: a signal belongs to the group
// named by the first component of its scope (sensor_L/sensor_R -> sensors,
// interrupts -> firmware).
enum class trace_group : uint8_t { sensors = 1, card = 2, emif = 4, firmware = 8 };
inline constexpr unsigned trace_all_groups = 15;
trace_group trace_pin_group(trace_pin pin);

}  // namespace platform
