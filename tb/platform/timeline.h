// One simulated timeline for pins and firmware (docs/platform.md): every
// event of a run with its tick (1/18 ns), in the order it happened. The pin
// events come from the island, the firmware's stages, states and decisions
// from its HAL, so the waveforms of the next issue can show them together.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "model/time/ticks.h"

namespace platform {

enum class event_kind : uint8_t {
    oe,            // a: level; the card's OE pin to both sensors
    irq,           // a: EXT_INT number (4..6), b: level
    sensor_frame,  // a: camera (0 L, 1 R), b: truth index; VSYNC rose
    stage_begin,   // a: dsp::stage
    stage_end,     // a: dsp::stage, b: cycles charged in it
    firmware,      // a: dsp::firmware_event, b: pair, c: value
    cpu_sleep,     // the CPU waits for an interrupt
    cpu_wake,      // a: interrupt taken (-1 as 255: stop)
    result,  // a: dsp::tracker_state after the pair, b: pair (from pair_processed), c: 1 with a 3D
             // point
};

const char* event_kind_name(event_kind k);

struct timeline_event {
    simtime::ticks tick = 0;
    event_kind kind = event_kind::oe;
    uint8_t a = 0;
    uint32_t b = 0;
    uint32_t c = 0;
};

class timeline {
  public:
    void add(simtime::ticks tick, event_kind kind, uint8_t a = 0, uint32_t b = 0, uint32_t c = 0) {
        m_events.push_back({tick, kind, a, b, c});
    }
    const std::vector<timeline_event>& events() const { return m_events; }
    // The last event of a kind (to complete it), nullptr if none.
    timeline_event* last(event_kind kind) {
        for (size_t i = m_events.size(); i-- > 0;)
            if (m_events[i].kind == kind) return &m_events[i];
        return nullptr;
    }
    // Events are appended in time order (the island never runs past another
    // process's next activity); this checks it.
    bool in_time_order() const;
    // FNV-1a over every event's fields, in order.
    uint64_t hash() const;
    size_t count(event_kind k) const;
    // CSV: tick, time_ns, kind, name, a, b, c (names decoded for stages and
    // firmware events).
    bool write_csv(const std::string& path) const;

  private:
    std::vector<timeline_event> m_events;
};

// FNV-1a 64 over a byte range (checksums of frames, hashes).
inline uint64_t fnv1a(const uint8_t* p, size_t n, uint64_t h = 1469598103934665603ull) {
    for (size_t i = 0; i < n; ++i) {
        h ^= p[i];
        h *= 1099511628211ull;
    }
    return h;
}

}  // namespace platform
