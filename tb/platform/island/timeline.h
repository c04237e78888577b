// One simulated timeline for pins and firmware (docs/platform.md): every
// event of a run with its tick (1/18 ns), in the order it happened. The pin
// events come from the island, the firmware's stages, states and decisions
// from its HAL, so the waveforms of the next issue can show them together.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "model/time/ticks.h"

namespace platform {

enum class event_kind : uint8_t {
    oe,            // a: level; the card's OE pin to both sensors
    irq,           // a: EXT_INT number (4..6), b: level
    sensor_frame,  // a: camera (0 L, 1 R), b: truth index; VSYNC rose
    stage_begin,   // a: the firmware's stage index (its descriptor's names)
    stage_end,     // a: stage index, b: cycles charged in it
    firmware,      // a: the report's stereosim_event_kind, b: pair, c: value
    cpu_sleep,     // the CPU waits for an interrupt
    cpu_wake,      // a: interrupt taken (-1 as 255: stop)
    result,        // a: tracker state index after the pair, b: pair, c: 1 with a 3D point
    // An injected fault took effect (tb/app/faults, docs/faults.md): a: its index
    // in the run's --fault list, b: faults::fault_type, c: the frame it hit
    // (sensor truth index, or sync period for bus / CPU faults). Inserted
    // after the run (the onset of a sensor fault is known from its truth).
    // timeline.json shows it (instant event "fault <kind>"); for the VCD
    // ("out": tb/app/output) a marker needs a signal declared before the run and
    // written at this tick after it, since the pin trace streams live.
    fault,
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
    // A pin event (oe, irq, sensor_frame) that an arrangement learns after
    // other processes may have added events at its tick (the pin-level
    // arrangement, tb/platform/arrangements/pins): placed where the fast island adds it, which
    // steps a tick before any other process acts at it. Order: events of
    // earlier ticks, then the tick's pin events (sensor_frame, then oe, then
    // irq, each in the order added), then the other processes' events.
    void add_pin_event(simtime::ticks tick, event_kind kind, uint8_t a = 0, uint32_t b = 0,
                       uint32_t c = 0) {
        const auto rank = [](event_kind k) {
            return k == event_kind::sensor_frame ? 0
                   : k == event_kind::oe         ? 1
                   : k == event_kind::irq        ? 2
                                                 : 3;
        };
        size_t at = m_events.size();
        while (at > 0 &&
               (m_events[at - 1].tick > tick ||
                (m_events[at - 1].tick == tick && rank(m_events[at - 1].kind) > rank(kind))))
            --at;
        m_events.insert(m_events.begin() + static_cast<std::ptrdiff_t>(at), {tick, kind, a, b, c});
    }
    const std::vector<timeline_event>& events() const { return m_events; }
    // The firmware's stage and tracker-state names (its descriptor's), for
    // the events that carry a stage or state number.
    void set_firmware_names(std::vector<std::string> stages, std::vector<std::string> states) {
        m_stage_names = std::move(stages);
        m_state_names = std::move(states);
    }
    const char* stage_name(int s) const { return name_of(m_stage_names, s); }
    const char* state_name(int s) const { return name_of(m_state_names, s); }
    // Inserts an event at its place in time, after the events of its tick:
    // markers known only after the run (a fault's onset).
    void insert(simtime::ticks tick, event_kind kind, uint8_t a = 0, uint32_t b = 0,
                uint32_t c = 0);
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
    static const char* name_of(const std::vector<std::string>& names, int i) {
        return i >= 0 && i < static_cast<int>(names.size()) ? names[static_cast<size_t>(i)].c_str()
                                                            : "?";
    }
    std::vector<std::string> m_stage_names, m_state_names;
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
