// A sensor's settings beyond its profile: seeds, noise, gain, exposure and
// the clock and scene origins (docs/sensor.md).
#pragma once

#include <cstdint>

#include "model/time/ticks.h"

namespace sensor {

struct sensor_config {
    uint64_t seed = 1;                   // start-up delays and noise; give each sensor its own
    bool noise = false;                  // shot + read noise (off for exact tests)
    double read_noise_dn = 1.0;          // ASSUMED: read noise sigma, DN
    double shot_noise_dn2_per_dn = 0.1;  // ASSUMED: shot variance per DN (10 e-/DN)
    int gain_q8 = 256;                   // analogue gain, Q8 (256 = 1.0)
    int exposure_lines = 0;              // 0 = the profile's exposure_lines
    simtime::ticks clock_origin = 0;     // tick of cycle 0's rising edge
    // Time origin of the scene frame numbering: scene frame k is the frame
    // period slot centred on scene_origin + k * frame period. Give every sensor
    // of a rig the same origin (the default, 0 = simulation start, does).
    simtime::ticks scene_origin = 0;
};

}  // namespace sensor
