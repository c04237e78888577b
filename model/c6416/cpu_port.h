// What a program running on the C6416 model's CPU thread can do: spend CPU
// cycles (with the SDRAM lines its kernels stream over EMIFA), access
// registers and memory at physical addresses, and take interrupts. It is the
// chip's side of the CPU, nothing of any firmware: the platform's probe
// (tb/platform/probe_hal.h) serves the firmware ABI's services on it, and the
// model's own tests run small programs on it directly.
#pragma once

#include <cstdint>

namespace c6416 {

class c6416_sc;

// Bytes a charge's kernels move between L2 and the DSK's SDRAM on EMIFA CE0.
// The chip replays them on the bus as L2 line transfers (sdram_traffic_replay.h).
struct sdram_traffic {
    uint64_t bytes_read = 0;
    uint64_t bytes_written = 0;

    bool empty() const { return bytes_read == 0 && bytes_written == 0; }
};

class cpu_port {
  public:
    // wait_for_interrupt's answer when no interrupt can come any more: the
    // platform asked the program to stop.
    static constexpr int no_interrupt = -1;

    explicit cpu_port(c6416_sc& chip) : m_chip(chip) {}

    // `cycles` CPU cycles spent on `stage` (0..c6416_sc::max_stages - 1): simulated
    // time advances by them (scaled by a "CPU too slow" fault), while
    // `traffic` goes out on the bus.
    void charge(int stage, uint64_t cycles, const sdram_traffic& traffic = {});

    // One aligned 32-bit access: a C6416 register, L2, or EMIFA (bus time).
    uint32_t read32(uint32_t address);
    void write32(uint32_t address, uint32_t value);
    // Modelled memory [address, address + bytes) (L2 or SDRAM), nullptr outside it.
    uint8_t* memory(uint32_t address, uint32_t bytes);

    // Simplified IER / IFR / ICR: bits 4..15 are INT4..INT15. No service
    // routine runs asynchronously: the program polls or sleeps.
    void set_interrupt_enable(uint32_t ier);
    uint32_t interrupt_flags();
    void clear_interrupt_flags(uint32_t mask);
    // Sleeps until IFR & IER has one of INT4..15, clears the lowest and
    // returns its number; no_interrupt once a stop is requested.
    int wait_for_interrupt();
    bool stop_requested();

  private:
    c6416_sc& m_chip;
};

}  // namespace c6416
