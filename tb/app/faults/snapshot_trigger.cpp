#include "tb/app/faults/snapshot_trigger.h"

#include <algorithm>

namespace faults {

snapshot_trigger snapshot_trigger_of(const std::vector<fault_spec>& specs, simtime::ticks period) {
    snapshot_trigger t;
    if (specs.empty()) return t;
    for (const fault_spec& s : specs) {
        if (s.when.kind == trigger_spec::by::start) return t;
        const simtime::ticks tick = trigger_tick(s, period);
        if (tick < 0) {  // a sensor's own frame N
            if (s.when.frame < 1 || s.camera < 0) return t;
            t.frames.push_back({s.camera, s.when.frame});
            continue;
        }
        if (tick < snapshot_time_margin + snapshot_pause_step) return t;
        if (s.type == fault_type::cpu_slow)
            t.cpu_slow_tick = t.cpu_slow_tick < 0 ? tick : std::min(t.cpu_slow_tick, tick);
        const simtime::ticks before = tick - snapshot_time_margin;
        t.before_tick = t.before_tick < 0 ? before : std::min(t.before_tick, before);
    }
    t.usable = true;
    return t;
}

}  // namespace faults
