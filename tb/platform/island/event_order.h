// How an arrangement's pin events (OE, interrupts) reach the timeline
// (timeline.h). The fast island steps each tick before any other process
// acts at it, so it appends; the pin-level arrangement sees a tick only
// after every delta of it ran, so it places its events where the fast
// island's would be (timeline::add_pin_event). The same order decides how
// the pin tracer walks the firmware's events: by index when appended, by
// tick when placed.
#pragma once

#include <cstdint>

namespace platform {

enum class event_order : uint8_t { appended, placed };

}  // namespace platform
