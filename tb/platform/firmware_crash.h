// A firmware that crashes (SIGSEGV, SIGBUS, SIGFPE, SIGILL, or SIGABRT from
// an exception thrown across the C ABI) is reported in one line, "firmware
// crashed (signal N) at T ms in stage S", and the process exits 3
// (docs/firmware-abi.md). Whether the firmware's code was running is known
// from the probe HAL: control is in the firmware between its HAL calls.
// A crash anywhere else is the simulator's, and said so. The whereabouts are
// process-wide because a signal handler can read nothing else.
#pragma once

#include <cstdint>

namespace platform {

// Installs the handlers (once per process; a forked child keeps them).
void install_firmware_crash_report();
// Control passes into the firmware at `tick` (simulation ticks), in stage
// `stage` (-1: none), whose names are `stage_names` (static storage).
void firmware_entered(int64_t tick, int stage, const char* const* stage_names, int stage_count);
// Control is back in the platform.
void firmware_left();

}  // namespace platform
