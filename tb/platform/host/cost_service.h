// The ABI's cost service (include/stereosim/firmware.h, kernel_cycles): a
// firmware's kernel op profile priced under the run's C64x cost model
// (docs/c6416.md), with the SDRAM traffic its memory stalls move. Both the
// co-simulation's services and the host entry's serve it from here.
#pragma once

#include <cstdint>

#include "model/c64x/cost_model.h"
#include "stereosim/firmware.h"

namespace host {

// The cycles of one call of `kernel` under `model`; `traffic` (may be
// null) gets the bytes those cycles' SDRAM stalls moved.
uint64_t kernel_cycles(const c64x::cost_model& model, const stereosim_kernel_profile& kernel,
                       stereosim_sdram_traffic* traffic);

}  // namespace host
