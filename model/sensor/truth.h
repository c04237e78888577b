// Ground truth of a sensor's own timing: one record per frame it started, so
// the testbench knows which pairs really were in step, whatever the card
// concludes (docs/design-brief.md "When a pair may be used").
#pragma once

#include <cstdint>

#include "model/time/ticks.h"

namespace sensor {

struct frame_truth {
    uint64_t index = 0;             // frame number: frames started since power-on
    uint64_t scene_frame = 0;       // its time slot, or the repeated frame's (frame_request)
    uint64_t start_cycle = 0;       // pixel clock of line 0, column 0
    simtime::ticks start_tick = 0;  // rising edge of that clock (the true start)
    simtime::ticks vsync_tick = 0;  // falling edge of that clock: VSYNC goes high

    // First and last active pixel actually driven (their falling edges);
    // have_active is false if none was (dropped frame, stopped early).
    bool have_active = false;
    uint64_t first_active_cycle = 0;
    uint64_t last_active_cycle = 0;
    simtime::ticks first_active_tick = 0;
    simtime::ticks last_active_tick = 0;

    int lines_with_href = 0;  // readout lines that carried HREF
    bool complete = false;    // ran to its last line (OE did not stop it)
    bool dropped = false;     // dropped_frame: no VSYNC, no HREF
    bool repeated = false;    // extra_frame: repeats the previous scene frame
    // FODD during the frame: the low bit of the sensor's frame count since
    // OE rose; a repeat carries the repeated frame's (docs/sensor.md).
    bool fodd = false;
    int skew_before_pclks = 0;  // start_skew clocks inserted just before it
    uint32_t faults = 0;        // fault_bit() of every fault in effect during it
};

// Faults that change which pixel clock carries which active pixel.
uint32_t timing_fault_mask();

// docs/design-brief.md: out of step = the two streams differ by one pixel clock or more
// anywhere in the pair's active data. True when both frames are complete, show
// the same scene frame, carry all their active pixels with no timing fault,
// and their first and last active pixels are less than one pixel clock apart
// (edges move monotonically, so the whole active span is then within one
// clock). pclk_period: nominal pixel clock period in ticks (N/D).
bool pair_in_step(const frame_truth& a, const frame_truth& b, simtime::rational_ticks pclk_period);

}  // namespace sensor
