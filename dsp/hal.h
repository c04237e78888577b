// The firmware's only way to the hardware (DESIGN.md, "Layers"). The host
// harness implements it with plain counters; the C6416 TLM model (platform
// issue) implements it with registers, EDMA, interrupts and simulated time.
#pragma once

#include <cstdint>

#include "dsp/stage.h"

namespace dsp {

class hal {
public:
    virtual ~hal() = default;

    // CPU time spent on a stage, in C64x cycles from the cost model
    // (dsp/c64x_cost_model.h). The platform advances simulated time by it.
    virtual void charge_cycles(stage s, uint64_t cycles) = 0;

    // The firmware enters / leaves a stage (for the timeline and waveforms).
    virtual void stage_begin(stage) {}
    virtual void stage_end(stage) {}
};

}  // namespace dsp
