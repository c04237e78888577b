// Fault markers merged into a finished waveform (docs/waveforms.md).
//
// Every waveform a run writes (waves_writer.h, Verilator's VerilatedFstC or
// VerilatedVcdC, time unit 1 fs) declares the 8-bit signal
// platform.faults.kind, 0 at the file's first time (the window start) and
// never changed while the run writes it. Fault onsets are known only after
// the run (tb/app/faults/observe.cpp), when the file is finished, so
// add_fault_markers() rewrites the file once with the onsets in it:
//   - at the first time, kind is the value of the latest marker before the
//     window (0 if none);
//   - each marker inside the window, and not after the file's last time,
//     sets kind at to_fs(tick): it joins that time if the file has it, else
//     a time step of its own is inserted. Of several markers on one tick
//     (stable-sorted by tick), the last one stands;
//   - every other signal and value change is copied as it was.
// A VCD is copied line by line (files run to hundreds of MB); an FST is read
// and written again through fstapi (GTKWave's reader and writer, the ones
// Verilator's FST writer uses).
//
// The merge writes PATH.markers and renames it over PATH, so a failure leaves
// PATH as it was and no PATH.markers behind. If no marker would change the
// file, it is not rewritten at all.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/time/ticks.h"
#include "tb/app/output/waves_format.h"
#include "tb/platform/island/pin_trace.h"

namespace output {

// A fault's onset and the marker's value from it (1 + faults::fault_type).
struct fault_marker {
    simtime::ticks tick;
    uint8_t value;
};

// Merges `markers` (any order) into the finished waveform at `path`, written
// for `window`. False + *error (one line naming the file) if the file cannot
// be read, has no platform.faults.kind or cannot be rewritten. *added: the
// marker changes written inside the window (markers on one tick count once).
bool add_fault_markers(const std::string& path, waves_format format, platform::tick_window window,
                       std::vector<fault_marker> markers, uint64_t* added, std::string* error);

}  // namespace output
