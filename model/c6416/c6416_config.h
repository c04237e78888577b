// The C6416 model's configuration (docs/c6416.md): the DSK profile, how CE0
// (SDRAM) is served, and the replay of the firmware's SDRAM traffic.
#pragma once

#include <cstddef>
#include <cstdint>

#include "model/c6416/dsk_profile.h"

namespace c6416 {

struct c6416_config {
    dsk_profile dsk = dsk_v1();
    // CE0 (SDRAM) accesses go out on emifa_cpu / emifa_edma (true) or are
    // served locally in zero time (false: no EMIF model, e.g. unit tests).
    bool sdram_over_emifa = true;
    // CPU cycles one access to a C6416 peripheral register costs (ASSUMED 0:
    // the C64x peripheral bus latency was not at hand).
    uint32_t peripheral_access_cycles = 0;
    // The firmware's SDRAM traffic goes out on emifa_cpu (see the top comment;
    // only with sdram_over_emifa). false: it is ignored (the cost model's
    // stall cycles are all it costs, as before issue 5).
    bool replay_sdram_traffic = true;
    // L2 cache line: the unit of the replayed transfers (ASSUMED 128 bytes,
    // as c64x::model_params::l2_line_bytes; NOT FOUND in the sheet).
    uint32_t l2_line_bytes = 128;
    // SDRAM window the replayed transfers read and write (line after line,
    // wrapping): the top 4 MB of the DSK's 16 MB, which the firmware's pair
    // buffers (from 0x80000000, ~1.2 MB) never reach. Its bytes are garbage.
    uint32_t sdram_traffic_base = 0x80C00000u;
    uint32_t sdram_traffic_bytes = 4u << 20;
    // Stack of the CPU thread that runs the firmware (docs/design-brief.md, "Known traps").
    std::size_t cpu_stack_bytes = std::size_t{64} << 20;
    // sc_stop() when the firmware's entry returns.
    bool stop_when_firmware_returns = false;
};

}  // namespace c6416
