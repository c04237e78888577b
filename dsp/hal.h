// The firmware's only way to the hardware (docs/design-brief.md, "Layers"). The host
// harness implements it with plain counters (tests/support/host/counting_hal); the C6416
// TLM model (model/c6416) implements it with registers, EDMA, interrupts and
// simulated time. Everything a real C6416 program needs and nothing OS-like:
//   - time: charge_cycles (CPU cycles), kernel_cycles (a kernel call's cycles
//     under the run's cost model);
//   - registers and memory at physical addresses: read32 / write32 (C6416
//     peripheral registers of model/c6416/c6416_regs.h, the card's registers and
//     pixel ports of dsp/card_regs.h, L2 and SDRAM), and memory(): a pointer
//     into modelled L2 (0x00000000) or SDRAM (0x80000000) for the firmware's
//     buffers;
//   - CPU interrupts: IER / IFR, simplified (below), and wait_for_interrupt;
//   - reports: every decision the firmware makes (scoreboard, timeline);
//   - stop: the platform asks the firmware to end its loop.
// Every method but charge_cycles has a default, so a HAL that only counts
// cycles (the host harness) needs nothing else.
#pragma once

#include <cstdint>

#include "dsp/stage.h"
#include "model/c64x/cost_model.h"

namespace dsp {

struct frame_output;  // dsp/controller.h

// What the firmware reports. `pair` is the card's pair number (its PAIRS_OK
// count when the pair became ready) where one applies; `value` and `detail`
// are per kind (dsp/control_program.h lists them).
enum class firmware_event : uint8_t {
    boot,             // value: DSK version (1..3), detail: pipeline mode (0 seq, 1 overlapped)
    emif_programmed,  // value: CECTL2/3, detail: SDTIM
    card_found,       // value: card ID register
    card_missing,     // value: what the ID register read (not the card's magic)
    card_configured,  // value: IRQ_ENABLE
    oe_raised,        // value: how many times the firmware has raised OE (1 = boot)
    in_step,          // first pair after OE passed the card's check; pair: its number
    sync_error,       // EXT_INT5: value: VERDICT, detail: MISMATCH_POS
    overflow,         // EXT_INT6: value: STATUS, detail: card OVERFLOWS count
    card_rearmed,     // ENABLE 0 -> 1 by the firmware; value: the cause (rearm_cause)
    watchdog,         // the card was silent for a watchdog period; value: period (timer clocks)
    pair_captured,    // EDMA moved the pair into buffer `detail`; value: VERDICT copied with it
    pair_rejected,    // the pair's verdict says out of step: not used; value: VERDICT
    pair_dropped,     // overrun: pairs the card made ready while no buffer was free; value: count
    pair_processed,   // the pipeline ran on it; value: buffer, detail: 1 if it gave a 3D point
    stopped,          // the frame loop ended; value: pairs processed
    hard_error,       // the firmware gave up on the card (docs/fault-contract.md): OE low, no
                      // capture; value: the last rearm_cause, detail: consecutive failures
    frames_used,      // the pipeline reads the pair's frames; value / detail: the left / right
                      // frame's address (the ABI's left / right)
};

constexpr const char* firmware_event_name(firmware_event e) {
    switch (e) {
        case firmware_event::boot:
            return "boot";
        case firmware_event::emif_programmed:
            return "emif_programmed";
        case firmware_event::card_found:
            return "card_found";
        case firmware_event::card_missing:
            return "card_missing";
        case firmware_event::card_configured:
            return "card_configured";
        case firmware_event::oe_raised:
            return "oe_raised";
        case firmware_event::in_step:
            return "in_step";
        case firmware_event::sync_error:
            return "sync_error";
        case firmware_event::overflow:
            return "overflow";
        case firmware_event::card_rearmed:
            return "card_rearmed";
        case firmware_event::watchdog:
            return "watchdog";
        case firmware_event::pair_captured:
            return "pair_captured";
        case firmware_event::pair_rejected:
            return "pair_rejected";
        case firmware_event::pair_dropped:
            return "pair_dropped";
        case firmware_event::pair_processed:
            return "pair_processed";
        case firmware_event::stopped:
            return "stopped";
        case firmware_event::hard_error:
            return "hard_error";
        case firmware_event::frames_used:
            return "frames_used";
    }
    return "?";
}

struct event_record {
    firmware_event kind = firmware_event::boot;
    uint32_t pair = 0;
    uint32_t value = 0;
    uint32_t detail = 0;
};

// Bytes a stage's kernels move between the L2 cache and the DSK's SDRAM on
// EMIFA CE0 (the cost model's SDRAM streams, dsp/kernel_costs.h). The
// platform puts them on the EMIF bus as L2 line transfers, where they take
// bus time and compete with the card's capture (docs/c6416.md).
struct sdram_traffic {
    uint64_t bytes_read = 0;
    uint64_t bytes_written = 0;

    bool empty() const { return bytes_read == 0 && bytes_written == 0; }
    sdram_traffic& operator+=(const sdram_traffic& other) {
        bytes_read += other.bytes_read;
        bytes_written += other.bytes_written;
        return *this;
    }
};

class hal {
  public:
    virtual ~hal() = default;

    // Wait results: no interrupt can come any more (the platform asked the
    // firmware to stop, or the HAL has no interrupt source).
    static constexpr int no_interrupt = -1;

    // CPU time spent on a stage, in C64x cycles from the cost model
    // (model/c64x/cost_model.h). The platform advances simulated time by it.
    virtual void charge_cycles(stage s, uint64_t cycles) = 0;
    // The same charge, for kernels whose data lives in SDRAM: `traffic` is
    // what those cycles' memory stalls moved over EMIFA. A HAL with a bus
    // model replays it on the bus during the charge; the default ignores it.
    virtual void charge_with_traffic(stage s, uint64_t cycles, const sdram_traffic& traffic) {
        (void)traffic;
        charge_cycles(s, cycles);
    }

    // The cycles of one kernel call (its op profile, dsp/kernel_costs.h) under
    // the run's cost model: the platform's DSK clocks and compiled-C factor.
    // The default prices it with the default model (DSK v1, hand-scheduled).
    virtual uint64_t kernel_cycles(const c64x::kernel_profile& kernel) {
        static const c64x::cost_model default_model;
        return default_model.cycles(kernel);
    }

    // The firmware enters / leaves a stage (for the timeline and waveforms).
    virtual void stage_begin(stage) {}
    virtual void stage_end(stage) {}

    // ---- registers and memory ---------------------------------------------------------------
    // One aligned 32-bit access at a physical address. An access over EMIFA
    // takes the bus's time; a C6416 register or L2 access takes none beyond
    // what the model documents (docs/c6416.md).
    virtual uint32_t read32(uint32_t address) {
        (void)address;
        return 0;
    }
    virtual void write32(uint32_t address, uint32_t value) {
        (void)address;
        (void)value;
    }
    // Direct pointer to modelled memory [address, address + bytes) (L2 or
    // SDRAM), nullptr if the range is not memory. The firmware reads and
    // writes its buffers through it; the cost model charges that time.
    virtual uint8_t* memory(uint32_t address, uint32_t bytes) {
        (void)address;
        (void)bytes;
        return nullptr;
    }

    // ---- CPU interrupts (simplified IER / IFR / ICR) ---------------------------------------
    // Bits 4..15 are the maskable interrupts INT4..INT15 (routed to events by
    // the interrupt selector, model/c6416/c6416_regs.h irq::). IFR latches an
    // interrupt's event whatever IER says; GIE and NMIE are not modelled and
    // no interrupt service routine runs asynchronously: the firmware polls
    // (interrupt_flags) or sleeps (wait_for_interrupt).
    virtual void set_interrupt_enable(uint32_t ier) { (void)ier; }
    virtual uint32_t interrupt_flags() { return 0; }                   // IFR
    virtual void clear_interrupt_flags(uint32_t mask) { (void)mask; }  // ICR
    // Sleeps until IFR & IER has one of INT4..15 set, clears the lowest such
    // IFR bit (the highest priority, as the CPU taking it would) and returns
    // its number. Returns at once if one is already pending. Returns
    // no_interrupt when the platform asks the firmware to stop.
    virtual int wait_for_interrupt() { return no_interrupt; }

    // ---- reports and stop ------------------------------------------------------------------
    virtual void report(const event_record& e) { (void)e; }
    // The pipeline's result for one processed pair (the 3D point), with the
    // pair's number (the card's PAIRS_OK count copied with it).
    virtual void report_result(uint32_t pair, const frame_output& out) {
        (void)pair;
        (void)out;
    }
    // The platform asks the firmware to end its loop (checked between pairs).
    virtual bool stop_requested() { return false; }
};

}  // namespace dsp
