// The TMS320C6416 as a loosely-timed SystemC / TLM-2.0 model (docs/c6416.md).
//
// What it holds: the CPU (a thread that runs a program natively on the
// chip's cpu_port, cpu_port.h), 1 MB L2 SRAM at 0x00000000 and the DSK's 16 MB
// SDRAM storage for EMIFA CE0 (0x80000000) (c6416_memory.h), the EMIFA
// control registers (emifa_registers.h), the interrupt selector, the EDMA
// (channel controller edma_core.h + one transfer controller
// edma_transfer_controller.h, run on the EDMA thread here) and timers 0-2 (timer_block.h), at their
// data-sheet addresses (model/c6416/c6416_regs.h). This module wires the blocks together and runs
// their SystemC processes; each block is its own class.
//
// Ports and sockets (named after the pins / roles):
//   ext_int4..7  bool signal inputs: the EXT_INT pins (J3), each may stay
//                unbound (low). An active edge (EXTPOL)
//                sets the IFR bit of every CPU interrupt the selector routes
//                GPINT4..7 to, and the EDMA event of channel 4..7.
//   emifa_cpu    TLM initiator: CPU accesses to EMIFA CE0-CE3
//                (0x80000000-0xBFFFFFFF), one b_transport per 32-bit word;
//                bind to the EMIF target's `cpu` socket.
//   emifa_edma   TLM initiator: EDMA accesses to EMIFA, one b_transport per
//                array (a burst: streaming width = its length, or the element
//                size for a fixed address such as a FIFO port); bind to the
//                EMIF target's `edma` socket.
//   The caller waits the delay b_transport returns; a target may also
//   consume time inside b_transport (the EMIF does). Sockets may stay
//   unbound where nothing uses them.
// The SDRAM's bytes live here (sdram_storage()); the EMIF model reads and
// writes them for CE0 accesses (emif_async_master::set_sdram_storage). With
// config.sdram_over_emifa = false the C6416 serves CE0 itself in zero time.
// EMIFA control register writes (CECTLn ...) reach the EMIF model through
// set_emifa_register_observer (-> emif_async_master::set_cectl).
//
// Time: the CPU clock is a simtime::tick_clock of the DSK profile's period.
// charge(stage, n) waits from the CPU edge at or after now to the edge n
// cycles later, each edge placed at to_fs(its exact tick): no rounded period
// is ever accumulated. The SystemC time resolution must be 1 fs
// (tests/support/sc_test_main.cpp).
// "CPU too slow" fault: set_cycle_scale(num, den, from): cycles charged
// after `from` are multiplied by num / den (rounded up).
//
// A program's own SDRAM traffic (cpu_port::charge, sdram_traffic_replay.h):
// the bytes a charge's kernels stream from / to SDRAM go out on emifa_cpu as L2
// line transfers (one 128-byte burst per line read; a line written is
// fetched (write-allocate) and later written back: two), spread evenly over
// the charge's CPU cycles (transfer k issued at CPU cycle k0 + n k / T), so
// they take EMIF bus time and compete with the EDMA's capture in parallel
// with the CPU's work. The charged cycles stay the cost model's (whose
// memory stalls already count the CPU's wait for these lines); only if the
// bus is so busy that the last transfer completes after the charged end
// does the CPU wait for it (sdram_late_time()). The transfers read and write
// a reserved SDRAM window (config), not the firmware's buffers.
#pragma once

#include <tlm_utils/simple_initiator_socket.h>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <systemc>
#include <tlm>
#include <vector>

#include "model/c6416/c6416_config.h"
#include "model/c6416/c6416_memory.h"
#include "model/c6416/cpu_clock_sc.h"
#include "model/c6416/cpu_port.h"
#include "model/c6416/dsk_profile.h"
#include "model/c6416/edma_core.h"
#include "model/c6416/edma_transfer_controller.h"
#include "model/c6416/emifa_registers.h"
#include "model/c6416/interrupt_selector.h"
#include "model/c6416/sdram_traffic_replay.h"
#include "model/c6416/timer_block.h"
#include "model/time/ticks.h"

namespace c6416 {

class c6416_sc : public sc_core::sc_module {
  public:
    // An input pin that may stay unbound (reads low): the card drives 4-6 only.
    using pin_in =
        sc_core::sc_port<sc_core::sc_signal_in_if<bool>, 1, sc_core::SC_ZERO_OR_MORE_BOUND>;
    pin_in ext_int4;
    pin_in ext_int5;
    pin_in ext_int6;
    pin_in ext_int7;
    tlm_utils::simple_initiator_socket_optional<c6416_sc> emifa_cpu;
    tlm_utils::simple_initiator_socket_optional<c6416_sc> emifa_edma;

    using firmware_entry = std::function<void(cpu_port&)>;
    using register_observer = std::function<void(uint32_t address, uint32_t value)>;

    SC_HAS_PROCESS(c6416_sc);
    c6416_sc(sc_core::sc_module_name name, const c6416_config& config = {});
    ~c6416_sc() override;

    // What the CPU runs (from time 0). Without one the CPU stays idle.
    void set_firmware(firmware_entry entry) { m_firmware = std::move(entry); }
    void set_cycle_scale(uint32_t num, uint32_t den, const sc_core::sc_time& from);
    // The firmware's stop_requested() turns true; wait_for_interrupt returns.
    void request_stop();
    bool firmware_returned() const { return m_firmware_returned; }
    const sc_core::sc_event& firmware_returned_event() const { return m_firmware_returned_event; }

    // Every write to an EMIFA control register (GBLCTL, CECTLn, SDCTL, ...):
    // the EMIF model takes its timing from them.
    void set_emifa_register_observer(register_observer f) {
        m_emifa_regs.set_observer(std::move(f));
    }

    // ---- inspection (tests, platform) -----------------------------------------------------
    const c6416_config& config() const { return m_config; }
    const simtime::tick_clock& cpu_clock() const { return m_cpu_clock.ticks(); }
    // The CPU cycle (edge index) at or after t, and the time of edge k.
    uint64_t cpu_cycle_at_or_after(const sc_core::sc_time& t) const {
        return m_cpu_clock.cycle_at_or_after(t);
    }
    sc_core::sc_time time_of_cpu_cycle(uint64_t k) const { return m_cpu_clock.time_of_cycle(k); }
    // Modelled memory (L2 or SDRAM), nullptr outside it.
    uint8_t* memory(uint32_t address, uint32_t bytes) { return m_memory.at(address, bytes); }
    uint8_t* sdram_storage() { return m_memory.sdram(); }
    std::size_t sdram_storage_bytes() const { return m_memory.sdram_bytes(); }
    // A C6416 register (EMIFA, selector, EDMA, timers), no time, no side effect.
    uint32_t peek_register(uint32_t address);
    uint32_t ifr() const { return m_ifr; }
    uint32_t ier() const { return m_ier; }
    edma_core& edma() { return m_edma; }
    const interrupt_selector& selector() const { return m_selector; }

    // ---- statistics ------------------------------------------------------------------------
    // Stages a firmware may charge (the firmware ABI's 15, and a spare).
    static constexpr int max_stages = 16;
    uint64_t charged_cycles(int stage) const { return m_stage_cycles[stage]; }
    uint64_t charged_cycles_total() const;
    sc_core::sc_time cpu_busy_time() const { return m_cpu_busy; }  // charges
    // When the charge the CPU is in ends (its cycles fixed as it began, the
    // slow-down included), or zero between charges.
    sc_core::sc_time charge_end() const { return m_charge_end; }
    sc_core::sc_time cpu_bus_stall_time() const { return m_cpu_bus; }  // CPU EMIFA accesses
    sc_core::sc_time edma_busy_time() const { return m_edma_busy; }
    uint64_t edma_bytes() const { return m_edma_bytes; }
    uint64_t bus_errors() const { return m_bus_errors; }
    // The firmware's SDRAM traffic replayed on emifa_cpu: L2 lines read
    // (reads and write-allocate fetches) and written back, the time the
    // transfers took (queue + bus, summed), and the time the CPU waited past
    // a charge's end for its last transfer.
    uint64_t sdram_lines_read() const { return m_replay.lines_read(); }
    uint64_t sdram_lines_written() const { return m_replay.lines_written(); }
    sc_core::sc_time sdram_transfer_time() const { return m_replay.transfer_time(); }
    sc_core::sc_time sdram_late_time() const { return m_sdram_late; }

  private:
    friend class cpu_port;
    class edma_port;

    // Processes.
    void cpu_thread();
    void edma_thread();
    void ext_int_method();
    void timer_method();

    // CPU side (called on the CPU thread through cpu_port).
    void charge(int stage, uint64_t cycles, const sdram_traffic& traffic);
    uint64_t scaled_cycles(uint64_t k0, uint64_t cycles) const;
    void replay_traffic(uint64_t first_cycle, uint64_t cycles, const sdram_traffic& traffic);
    void wait_cpu_cycles(uint64_t cycles);
    uint32_t cpu_read32(uint32_t address);
    void cpu_write32(uint32_t address, uint32_t value);
    int wait_for_interrupt();

    // Registers.
    bool is_peripheral(uint32_t address) const;
    uint32_t register_read(uint32_t address);
    void register_write(uint32_t address, uint32_t value);

    // Events and interrupts.
    void raise_interrupt_event(uint32_t selector_code);
    void after_edma_change();
    void arm_timer_event();

    // EMIFA.
    void bus_access(tlm_utils::simple_initiator_socket_optional<c6416_sc>& socket,
                    tlm::tlm_command command, uint32_t address, uint8_t* data, uint32_t length,
                    uint32_t streaming_width);

    c6416_config m_config;
    cpu_clock_sc m_cpu_clock;
    cpu_port m_port;
    firmware_entry m_firmware;

    c6416_memory m_memory;
    emifa_registers m_emifa_regs;
    interrupt_selector m_selector;
    edma_core m_edma;
    timer_block m_timers;
    sdram_traffic_replay m_replay;
    std::unique_ptr<edma_port> m_edma_port;  // the chip as the transfer controller sees it
    edma_transfer_controller m_edma_transfer;
    sc_core::sc_event m_timer_event;
    sc_core::sc_event m_edma_kick;
    sc_core::sc_event m_irq_event;

    uint32_t m_ifr = 0;
    uint32_t m_ier = 0;
    bool m_ext_level[4] = {};
    bool m_pins_sampled = false;
    bool m_stop = false;
    bool m_firmware_returned = false;
    sc_core::sc_event m_firmware_returned_event;

    uint32_t m_scale_num = 1, m_scale_den = 1;
    sc_core::sc_time m_scale_from;

    uint64_t m_stage_cycles[max_stages] = {};
    sc_core::sc_time m_cpu_busy, m_cpu_bus, m_edma_busy;
    uint64_t m_edma_bytes = 0;
    uint64_t m_bus_errors = 0;
    sc_core::sc_time m_sdram_late;
    sc_core::sc_time m_charge_end;
};

}  // namespace c6416
