// What one co-simulation run is (docs/platform.md): the scene, the two
// sensors, the daughter card, the DSK and its firmware settings, how long to
// run and how the cycle-accurate island syncs with SystemC.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "dsp/card_regs.h"
#include "model/c6416/dsk_profile.h"
#include "model/c64x/cost_model.h"
#include "model/emif/emif_async_master.h"
#include "model/scene/sequence.h"
#include "model/sensor/fault.h"
#include "model/sensor/profile.h"
#include "model/time/ticks.h"
#include "tb/platform/island/island_config.h"
#include "tb/platform/island/pin_trace.h"

namespace platform {

// Which arrangement of the sensors, the card and the EMIF runs
// (docs/arrangements.md): the cores stepped in one SystemC thread (fast), or
// SystemC modules wired with sc_signals, the card verilated with --sc (pins,
// the literal reference). Same pins, same reports.
enum class arrangement_kind { fast, pins };

// The card's CE2 / CE3 asynchronous access, ECLK cycles; 0: the DSK
// version's own (docs/card.md "Access lengths").
struct card_bus_timing {
    uint32_t setup = 0;
    uint32_t strobe = 0;
    uint32_t hold = 0;
};

struct platform_config {
    arrangement_kind arrangement = arrangement_kind::fast;

    // ---- scene -------------------------------------------------------------------------------
    // default_scenario(3): the default rig, background and 5 cm ball; three
    // still frames instead of six so the ball moves early inside the CI cap of
    // 12 frame pairs (docs/ci.md).
    scene::scenario scenario = scene::default_scenario(3);

    // Replay (model/scene/replay.h): the sensors see the manifest's PNG frames
    // instead of the renderer's; empty: render the scenario. The scenario
    // still gives the rig and the scene times (frame k at k periods).
    std::string replay_manifest;

    // ---- firmware ----------------------------------------------------------------------------
    // The firmware under test: a plugin built against include/stereosim/
    // firmware.h (docs/firmware-abi.md); empty: the built-in reference
    // firmware of dsp/.
    std::string firmware;
    // The firmware's keys the run sets (`--set firmware.KEY=V`), by name
    // without the prefix; a choice as its index. Every key not here takes the
    // default its descriptor declares (plugin_values). Checked against the
    // descriptor before the run (tb/app/cli/firmware_keys.h).
    std::vector<std::pair<std::string, double>> firmware_settings;

    // ---- sensors -----------------------------------------------------------------------------
    sensor::sensor_profile profile = sensor::default_profile();
    // Sensor seeds are 2 seed (left) and 2 seed + 1 (right). Seed 3: the left
    // sensor's first start has a 911-pclk extra delay, the right's none, so the
    // first pair is out of step and the card restarts OE; starts 1-3 are in
    // step (found by a seed search, docs/platform.md).
    uint64_t seed = 3;
    bool sensor_noise = true;  // shot + read noise (docs/sensor.md defaults)
    std::vector<sensor::fault> left_faults;
    std::vector<sensor::fault> right_faults;
    wire_fault wire;

    // ---- DSK and card -------------------------------------------------------------------------
    c6416::dsk_profile dsk = c6416::dsk_v1();
    // Whether the SDRAM traffic of the firmware's kernels goes out on EMIFA
    // as L2 line transfers (docs/c6416.md): bus time that competes with the
    // capture.
    bool sdram_traffic_on_bus = true;
    // The cost model's compiled-C factor (model/c64x/cost_model.h): 1 = the
    // hand-scheduled kernels the profiles describe; the `paper` scenario
    // models the paper's compiled C (docs/paper.md).
    double compiled_c_factor = 1.0;
    // The card's RETRY_LIMIT the run asks the firmware to program
    // (stereosim_board::card_retry_limit, docs/fault-contract.md).
    uint32_t card_retry_limit = dsp::card_regs::retry_limit_reset;
    // The card's CE2 / CE3 timing the firmware is asked to program (0: the DSK's).
    card_bus_timing card_timing;

    // ---- faults beyond the sensors' (tb/app/faults, docs/faults.md)
    // ------------------------------ Extra ARDY wait states on the card's CE spaces from a time on,
    // and a slower CPU: cycles charged after cpu_slow_from x num / den.
    std::vector<emif::ardy_fault> ardy_faults;
    uint32_t cpu_slow_num = 1, cpu_slow_den = 1;
    simtime::ticks cpu_slow_from = 0;

    // ---- run ---------------------------------------------------------------------------------
    // Simulated time: `frames` sync periods (the sensors deliver at most that
    // many frame pairs), then the firmware is asked to stop.
    int frames = 12;
    simtime::ticks period = period_24_5_ms;
    // The island syncs with SystemC at least once per quantum (one line of
    // the default profile: 800 pclk = 46.67 us), earlier at every bus
    // completion, interrupt pin change or other process's activity.
    simtime::ticks quantum = 800 * simtime::pclk_default_period;
    bool hash_pins = true;  // fold every pin change into the pin hash
    // Pin trace (tb/platform/island/pin_trace.h): every traced signal's change in
    // [trace_window.from, trace_window.to) ticks goes to this sink; none if null.
    pin_trace* trace = nullptr;
    tick_window trace_window;

    // Sensor seeds.
    uint64_t left_seed() const { return 2 * seed; }
    uint64_t right_seed() const { return 2 * seed + 1; }
};

// Sets the firmware key `name` (without the prefix) to `value`, replacing
// an earlier setting of it.
void set_firmware_key(platform_config* config, const std::string& name, double value);
// The value the run sets for key `name`, or `fallback` if it sets none.
double firmware_key(const platform_config& config, const std::string& name, double fallback);

// The EMIF engine's configuration (ECLK, SDRAM refresh) for `config`.
emif::emif_config engine_config(const platform_config& config);
// The kernel cost model for `config`: its CPU / EMIF clocks (SDRAM stalls
// depend on their ratio) and compiled-C factor (model/c64x/cost_model.h).
c64x::cost_model cost_model_of(const platform_config& config);

}  // namespace platform
