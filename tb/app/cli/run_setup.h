// Everything one `stereosim run` is made of, as the user states it (docs/config.md):
// the scenario (a built-in name plus overrides), the rig, the sensor
// profile, the DSK, the firmware's parameters and the run. Every field is one
// config key of tb/app/cli/config_keys.h; platform_config_of() turns it into the
// platform's configuration.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "tb/platform/platform_config.h"

namespace cli {

struct scenario_params {
    std::string name = "default";
    int still_frames = 3;          // frames before the ball moves (docs/platform.md: 3, not 6)
    std::string path = "bounce";   // bounce | circle | line | still
    double depth_m = 2.6;          // the ball's starting depth (circle: the plane's depth)
    double speed = 1.0;            // 1 = the path's nominal speed; a time scale
    double ball_radius_mm = 50.0;  // docs/design-brief.md default ball radius 5 cm
    double spin_rpm = 0.0;         // the ball's spin once it moves, revolutions per minute
    std::string spin_axis = "x";   // x | y | z of the world (right camera) frame
    std::string light = "none";    // none | step | ramp
    int light_frame = 6;           // frame of the step / start of the ramp
    double light_gain = 0.6;       // global gain after the change
    int light_ramp_frames = 4;     // ramp length, frame periods
    std::string replay;            // replay manifest (model/scene/replay.h); empty: render
};

struct run_setup {
    scenario_params scenario;

    // docs/design-brief.md default rig: baseline 120 mm, 6 mm lenses, 7.6 um pitch (OV7620,
    // docs/hardware-facts.md section 6) -> f = 789.5 px.
    double baseline_mm = 120.0;
    double focal_length_mm = 6.0;
    double pixel_pitch_um = 7.6;

    std::string sensor_profile = "default";  // sensor::profile_by_name
    bool sensor_noise = true;
    // A centred readout window (sensor::windowed); 0: the profile's active size.
    int window_cols = 0;
    int window_rows = 0;

    // DSK version 1..3 (docs/hardware-facts.md section 2); a clock of 0 means the
    // version's own (v1 600/100, v2 720/120, v3 1000/125 MHz).
    int dsk_version = 1;
    double cpu_mhz = 0.0;
    double eclk_mhz = 0.0;
    // The card's CE2 / CE3 async timing, ECLK cycles (platform::card_bus_timing);
    // 0: the DSK version's (2/10/2 on v1, 2/12/2 on v2 and v3).
    int card_setup = 0;
    int card_strobe = 0;
    int card_hold = 0;

    // The platform's side of the firmware: its SDRAM traffic on the bus, the
    // cost model's compiled-C factor. The firmware's own keys are below.
    bool sdram_traffic_on_bus = true;
    double compiled_c_factor = 1.0;  // the cost model's (docs/paper.md)

    int frames = 12;
    int64_t seed = 3;
    // The firmware under test: a plugin (docs/firmware-abi.md); empty: the
    // built-in reference firmware.
    std::string firmware;
    // The firmware's own keys (`--set firmware.KEY=V`, a config file's
    // "firmware" object) as given, in order: checked once the firmware is
    // known (tb/app/cli/firmware_keys.h).
    std::vector<std::pair<std::string, nlohmann::json>> firmware_settings;
    int64_t quantum_ns = 0;  // 0: one line of the profile (800 pclk = 46,667 ns by default)
    bool hash_pins = true;

    double effective_cpu_mhz() const;
    double effective_eclk_mhz() const;
};

// The platform's configuration for a setup (the scene built from the
// scenario parameters, the rig, the profile, the DSK clocks, ...). The setup
// must have passed validate_setup (tb/app/cli/config_keys.h).
platform::platform_config platform_config_of(const run_setup& setup);

// The sensor profile of a setup: the named profile through its window.
// Throws std::invalid_argument for an unknown name or a window that does
// not fit (validate_setup reports both as bad input first).
sensor::sensor_profile sensor_profile_of(const run_setup& setup);

}  // namespace cli
