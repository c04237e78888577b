#include "tb/app/cli/run_setup.h"

#include <cmath>
#include <stdexcept>

#include "model/scene/replay.h"
#include "model/sensor/profile.h"
#include "tb/app/cli/firmware_keys.h"
#include "tb/app/cli/scenarios.h"

namespace cli {

double run_setup::effective_cpu_mhz() const {
    return cpu_mhz > 0.0 ? cpu_mhz : c6416::dsk_version(dsk_version).cpu_hz / 1e6;
}

double run_setup::effective_eclk_mhz() const {
    return eclk_mhz > 0.0 ? eclk_mhz : c6416::dsk_version(dsk_version).emif_hz / 1e6;
}

sensor::sensor_profile sensor_profile_of(const run_setup& s) {
    const sensor::sensor_profile named = sensor::profile_by_name(s.sensor_profile);
    if (s.window_cols == 0 && s.window_rows == 0) return named;
    return sensor::windowed(named, s.window_cols > 0 ? s.window_cols : named.active_cols,
                            s.window_rows > 0 ? s.window_rows : named.active_rows);
}

platform::platform_config platform_config_of(const run_setup& s) {
    platform::platform_config c;
    c.profile = sensor_profile_of(s);
    c.sensor_noise = s.sensor_noise;
    c.seed = static_cast<uint64_t>(s.seed);

    scene::stereo_rig rig;
    rig.baseline_m = s.baseline_mm / 1000.0;
    rig.focal_length_m = s.focal_length_mm / 1000.0;
    rig.pixel_pitch_m = s.pixel_pitch_um * 1e-6;
    rig.width = c.profile.active_cols;
    rig.height = c.profile.active_rows;
    if (!s.scenario.replay.empty()) {
        // The replay's own calibration is the rig; no scene ball, so no truth.
        const scene::replay replay(s.scenario.replay, rig.width, rig.height);
        const scene::replay_calibration& cal = replay.calibration();
        rig.baseline_m = cal.baseline_m;
        rig.focal_length_m = cal.focal_px * rig.pixel_pitch_m;
        rig.principal_dx_left = cal.cx_left - 0.5 * (rig.width - 1);
        rig.principal_dy_left = cal.cy_left - 0.5 * (rig.height - 1);
        rig.principal_dx_right = cal.cx_right - 0.5 * (rig.width - 1);
        rig.principal_dy_right = cal.cy_right - 0.5 * (rig.height - 1);
        c.replay_manifest = s.scenario.replay;
    }
    c.scenario = build_scenario(s.scenario, rig);
    if (!s.scenario.replay.empty()) c.scenario.scene.balls.clear();

    // A version's own clocks keep its profile (name and all); others are custom
    // clocks with that version's EMIF settings (CECTL).
    const c6416::dsk_profile version = c6416::dsk_version(s.dsk_version);
    const int64_t cpu_hz = std::llround(s.effective_cpu_mhz() * 1e6);
    const int64_t emif_hz = std::llround(s.effective_eclk_mhz() * 1e6);
    c.dsk = version;
    if (cpu_hz != version.cpu_hz || emif_hz != version.emif_hz) {
        c.dsk = c6416::dsk_custom(cpu_hz, emif_hz);
        c.dsk.version = version.version;
    }

    c.sdram_traffic_on_bus = s.sdram_traffic_on_bus;
    c.compiled_c_factor = s.compiled_c_factor;
    c.card_timing.setup = static_cast<uint32_t>(s.card_setup);
    c.card_timing.strobe = static_cast<uint32_t>(s.card_strobe);
    c.card_timing.hold = static_cast<uint32_t>(s.card_hold);
    c.frames = s.frames;
    if (s.quantum_ns > 0) c.quantum = s.quantum_ns * simtime::ticks_per_ns;
    c.hash_pins = s.hash_pins;
    c.firmware = s.firmware;
    std::string error;
    if (!resolve_firmware_settings(s, &c.firmware_settings, &error))
        throw std::logic_error("a setup that passed validate_setup: " + error);
    return c;
}

}  // namespace cli
