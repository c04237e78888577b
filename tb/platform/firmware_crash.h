// A firmware that crashes (SIGSEGV, SIGBUS, SIGFPE, SIGILL, or SIGABRT from
// an exception thrown across the C ABI) is reported in one line, "firmware
// crashed (signal N) at T ms in stage S", and the process exits 3
// (docs/firmware-abi.md). Whether the firmware's code was running is known
// from the probe HAL: control is in the firmware between its HAL calls.
// A crash anywhere else is the simulator's, and said so. The whereabouts are
// process-wide because a signal handler can read nothing else.
//
// A firmware that never gives time back (a loop that neither charges cycles
// nor waits: simulated time stands still while control stays in the
// firmware) is stopped by a guard thread after hang_guard_seconds of wall
// time, with one line "firmware gave no time back ..." and exit 3.
#pragma once

#include <cstdint>
#include <string>

namespace platform {

// The first words of the two lines, for a campaign that reads a child's log.
inline constexpr const char* firmware_crashed_prefix = "stereosim: error: firmware crashed";
inline constexpr const char* firmware_hung_prefix = "stereosim: error: firmware gave no time back";
inline constexpr const char* firmware_broke_abi_prefix = "stereosim: error: firmware broke the ABI";
inline bool is_firmware_failure_line(const std::string& line) {
    return line.rfind(firmware_crashed_prefix, 0) == 0 ||
           line.rfind(firmware_hung_prefix, 0) == 0 ||
           line.rfind(firmware_broke_abi_prefix, 0) == 0;
}
// Wall time with control in the firmware and simulated time standing still
// before the guard ends the run: far above any kernel's host time between
// two HAL calls (a few ms; under ASan a few hundred).
inline constexpr int hang_guard_seconds = 10;

// Installs the handlers and starts the hang guard (once per process; a
// forked child keeps the handlers and starts its own guard).
void install_firmware_crash_report();
// Control passes into the firmware at `tick` (simulation ticks), in stage
// `stage` (-1: none), whose names are `stage_names` (static storage).
void firmware_entered(int64_t tick, int stage, const char* const* stage_names, int stage_count);
// Control is back in the platform.
void firmware_left();
// The firmware called a service outside what it declared (a stage or a
// tracker state it has not got): "firmware broke the ABI: <what> at T ms",
// the half-written output removed, exit 3, as for a crash.
[[noreturn]] void firmware_broke_abi(const std::string& what);

// What a crash or hang report removes before the exit, so that nothing half
// written is left: the run's staging folder and, if the run created it, its
// output folder (removed only if empty then). Empty strings: nothing.
void remove_on_firmware_failure(const std::string& staging, const std::string& created_out);

}  // namespace platform
