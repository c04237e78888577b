// timeline.json (docs/waveforms.md): a run in the Chrome trace-event format
// (JSON object form, {"traceEvents": [...]}), for Perfetto (ui.perfetto.dev)
// or chrome://tracing. Times are microseconds of simulated time (tick /
// 18000, as doubles).
//
// One process, "stereosim", with one track (thread) per resource:
//   1 CPU     a complete event ("ph":"X", cat "stage") per firmware stage that
//             ran, stage_begin to stage_end, args: cycles charged, pair;
//             "sleep" spans (wait_for_interrupt, cat "idle"); instant events
//             for the interrupt taken on waking (cat "interrupt") and every
//             firmware report (cat "firmware");
//   2 EDMA    a complete event per capture chain (cat "edma": FRAME_READY to
//             the last EDMA burst before the next FRAME_READY, the figure
//             budget.h calls capture_ms) and an instant per burst completion;
//   3 card    instants for EXT_INT4/5/6 rises (cat "interrupt"), complete
//             events for the spans OE was high (cat "oe");
//   4 sensors instants for each VSYNC rise (cat "frame").
#pragma once

#include <string>

#include "tb/platform/platform.h"

namespace output {

// The trace of a finished run, as JSON text.
std::string trace_events_json(const platform::platform_top& top);

}  // namespace output
