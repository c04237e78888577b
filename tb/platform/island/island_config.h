// What an island is built from and what it reports (docs/platform.md): the
// configuration both arrangements take (tb/platform/arrangements/) and the
// samples their shared observer (island_observer.h) keeps.
#pragma once

#include <cstdint>
#include <vector>

#include "model/emif/ardy_glue.h"
#include "model/sensor/fault.h"
#include "model/sensor/profile.h"
#include "model/sensor/sensor_core.h"
#include "model/time/ticks.h"
#include "tb/platform/island/pin_trace.h"

namespace platform {

// docs/design-brief.md: one sensor frame = one sync period = 24.5 ms = 441,000,000 ticks.
inline constexpr simtime::ticks period_24_5_ms = 441000000;

// Words in each of the card's FIFOs: rtl_card is card_top with its default
// FIFO_AW = 17 (docs/card.md).
inline constexpr uint32_t card_fifo_words = 1u << 17;

// A board-level fault on the wire from a sensor's DATA[bit] to the card (a
// solder short): every word a sensor drives at or after `from_tick` reaches
// the card with that bit as `value`, whatever the sensor drives. The sensor
// itself is unaffected, so the data path integrity check must see it
// (docs/platform.md).
struct wire_fault {
    bool enabled = false;
    int camera = 0;  // 0 left, 1 right
    int bit = 2;
    bool value = true;
    simtime::ticks from_tick = 0;

    // DATA as the card sees it of a word `camera` drove at tick `driven`.
    uint8_t on_wire(int word_camera, uint8_t data, simtime::ticks driven) const {
        if (!enabled || word_camera != camera || driven < from_tick) return data;
        const uint8_t mask = static_cast<uint8_t>(1u << bit);
        return value ? static_cast<uint8_t>(data | mask) : static_cast<uint8_t>(data & ~mask);
    }
};

struct island_config {
    sensor::sensor_profile profile;
    sensor::sensor_config sensor[2];  // left, right
    std::vector<sensor::fault> faults[2];
    wire_fault wire;
    std::vector<emif::ardy_fault> ardy_faults;  // the board glue's wait states (emif-wait)
    simtime::tick_clock pclk;                   // the card's master pixel clock
    simtime::ticks quantum = 0;
    simtime::ticks end = INT64_MAX;          // the island never steps an edge after this tick
    simtime::ticks period = period_24_5_ms;  // for the per-period samples
    bool hash_pins = true;
    int frame_ring = 8;          // sensor frames whose pixels are kept (per sensor)
    pin_trace* trace = nullptr;  // every traced signal's change in `trace_window`
    tick_window trace_window;
};

// What happened in one sync period [k P, (k+1) P).
struct period_sample {
    uint64_t eclk_edges = 0;
    uint64_t emif_busy_edges = 0;      // engine: bus in use or turning around
    uint64_t cpu_words = 0;            // engine: words the CPU moved (SDRAM lines, registers)
    uint32_t fifo_peak_words[2] = {};  // card FIFO write-side level, maximum
    bool fifo_overflow[2] = {};        // the card's sticky overflow flag rose in the period
};

// The card's OE controller entered `state` (STATUS.STATE, docs/card-registers.md)
// at the pixel clock edge `tick`.
struct card_state_change {
    simtime::ticks tick = 0;
    uint8_t state = 0;
};

struct island_stats {
    uint64_t pclk_edges = 0;
    uint64_t eclk_edges = 0;
    uint64_t syncs = 0;        // waits of the island thread
    uint64_t stops_bus = 0;    // early stops at a bus completion
    uint64_t stops_irq = 0;    // early stops at an interrupt pin change
    uint64_t pin_changes = 0;  // pin changes folded into the hash
    uint64_t card_evals = 0;   // evaluations of the verilated card (fast arrangement)
    double wall_s = 0.0;       // host time spent stepping (sensors and scene included)
};

// One sensor frame as the island saw it on the sensor's pins.
struct frame_info {
    int slot = -1;        // ring slot holding its pixels, -1 if evicted / none
    uint64_t pixels = 0;  // active pixels recorded
    bool have_checksum = false;
    uint64_t checksum = 0;  // FNV-1a 64 of the active pixels in raster order
};

}  // namespace platform
