// When a campaign run can start from a snapshot of the fault-free run
// (snapshots.h, docs/fault-contract.md "Snapshots"). Plain data and the
// fault specs only: the campaign plans its groups with it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/time/ticks.h"
#include "tb/app/faults/fault_spec.h"

namespace faults {

// The fault-free run pauses every millisecond to see whether a snapshot is
// due; a time-triggered fault's snapshot is taken at least a millisecond
// before it (the island runs ahead of a pause by at most its quantum, 47 us).
inline constexpr simtime::ticks snapshot_pause_step = 1000000 * simtime::ticks_per_ns;
inline constexpr simtime::ticks snapshot_time_margin = snapshot_pause_step;

// When a snapshot for a run of these faults has to be taken, checked at
// pauses of the fault-free run: a time-triggered fault (@ms, and @frame of
// emif-wait / cpu-slow) before its tick less a margin; a sensor's @frame=N
// while that sensor is in its frame N - 1 (a frame's faults are looked up as
// it starts). Empty specs or a fault from the start: not snapshot-able.
struct snapshot_trigger {
    struct sensor_frame {
        int camera = 0;
        uint64_t frame = 0;  // N of @frame=N
    };
    bool usable = false;
    simtime::ticks before_tick = -1;   // fork at a pause at or before this tick; -1 none
    std::vector<sensor_frame> frames;  // fork while each sensor is before its frame N
    // A cpu-slow onset: a charge begun before the fork has its cycles fixed
    // without the slow-down, so no fork while one in flight ends after it.
    simtime::ticks cpu_slow_tick = -1;
};
snapshot_trigger snapshot_trigger_of(const std::vector<fault_spec>& specs, simtime::ticks period);

// A run of a snapshot group: its `stereosim run` options (after "run"),
// its folder (out/, log.txt, status) and when its snapshot is due.
struct snapshot_member {
    std::vector<std::string> args;
    std::string dir;
    snapshot_trigger trigger;
};

}  // namespace faults
