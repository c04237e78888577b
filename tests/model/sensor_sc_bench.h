// SystemC helpers for the sensor pin tests: an OE driver, a pin monitor that
// records every change with its femtosecond time, and the same record derived
// from the plain core alone (what the fast RTL island would produce).
#pragma once

#include <cstdint>
#include <functional>
#include <systemc>
#include <vector>

#include "model/sensor/sensor_core.h"
#include "model/sensor/sensor_sc.h"
#include "model/time/ticks.h"

namespace sensor_test {

// One pin change: time in fs and pclk | pins (pin_word bits, pclk at bit 15).
struct pin_event {
    int64_t fs;
    uint16_t pins;
    friend bool operator==(const pin_event& a, const pin_event& b) {
        return a.fs == b.fs && a.pins == b.pins;
    }
};
constexpr uint16_t pclk_bit = 1u << 15;

// Records the sensor pins on every change (one record per delta in which any changed).
struct pin_monitor : sc_core::sc_module {
    sc_core::sc_in<bool> pclk, vsync, href, valid, fodd;
    sc_core::sc_in<uint32_t> data;
    std::vector<pin_event> events;

    explicit pin_monitor(sc_core::sc_module_name name)
        : sc_core::sc_module(name),
          pclk("pclk"),
          vsync("vsync"),
          href("href"),
          valid("valid"),
          fodd("fodd"),
          data("data") {
        SC_HAS_PROCESS(pin_monitor);
        SC_METHOD(sample);
        sensitive << pclk << vsync << href << valid << fodd << data;
        dont_initialize();
    }

    void sample() {
        uint16_t w = static_cast<uint16_t>(data.read() & 0xFF);
        if (href.read()) w |= sensor::pin_word::href_bit;
        if (vsync.read()) w |= sensor::pin_word::vsync_bit;
        if (valid.read()) w |= sensor::pin_word::valid_bit;
        if (fodd.read()) w |= sensor::pin_word::fodd_bit;
        if (pclk.read()) w |= pclk_bit;
        events.push_back({static_cast<int64_t>(sc_core::sc_time_stamp().value()), w});
    }
};

// Drives OE so that cycle n's rising edge samples oe(n): each change is made
// half-way between the previous falling edge and that rising edge, away from
// both (as the Verilator examples drive inputs).
struct oe_driver : sc_core::sc_module {
    sc_core::sc_out<bool> oe;
    std::vector<std::pair<int64_t, bool>> changes;  // (fs, value)

    oe_driver(sc_core::sc_module_name name, const simtime::tick_clock& pclk, uint64_t cycles,
              const std::function<bool(uint64_t)>& level)
        : sc_core::sc_module(name), oe("oe") {
        bool prev = false;
        for (uint64_t n = 0; n < cycles; ++n) {
            // OE starts low; cycle 0 samples it before any driver runs.
            if (n == 0 || level(n) == prev) continue;
            prev = level(n);
            const simtime::ticks before = (pclk.fall(n - 1) + pclk.rise(n)) / 2;
            changes.push_back({simtime::to_fs(before), prev});
        }
        SC_HAS_PROCESS(oe_driver);
        SC_THREAD(drive);
    }

    void drive() {
        oe.write(false);
        for (const auto& [fs, value] : changes) {
            const sc_core::sc_time at =
                sc_core::sc_time::from_value(static_cast<sc_dt::uint64>(fs));
            if (at > sc_core::sc_time_stamp()) wait(at - sc_core::sc_time_stamp());
            oe.write(value);
        }
    }
};

// The pin events a core alone produces over `cycles` clocks: pclk rises at
// each rise tick (pins unchanged), falls with the new pins at each fall tick.
inline std::vector<pin_event> core_events(sensor::sensor_core& core, uint64_t cycles,
                                          const std::function<bool(uint64_t)>& oe) {
    std::vector<pin_event> out;
    uint16_t pins = 0;
    for (uint64_t i = 0; i < cycles; ++i) {
        const uint64_t n = core.cycle();
        const sensor::pin_word w = core.step(oe(n));
        out.push_back(
            {simtime::to_fs(core.last_rise_tick()), static_cast<uint16_t>(pins | pclk_bit)});
        pins = w.bits;
        out.push_back({simtime::to_fs(core.last_fall_tick()), pins});
    }
    return out;
}

// Index of the first difference, or -1.
inline long first_difference(const std::vector<pin_event>& a, const std::vector<pin_event>& b) {
    const size_t n = std::min(a.size(), b.size());
    for (size_t i = 0; i < n; ++i)
        if (!(a[i] == b[i])) return static_cast<long>(i);
    return a.size() == b.size() ? -1 : static_cast<long>(n);
}

}  // namespace sensor_test
