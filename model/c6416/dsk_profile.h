// The clocks of a C6416 DSK (docs/hardware-facts.md section 2): CPU and EMIFA.
// v1 600 MHz / 100 MHz (the default, the paper's era), v2 720 / 120,
// v3 (C6416T DSK) 1 GHz / 125. Any other pair is settable; periods are exact
// rational tick counts (model/time/ticks.h), so e.g. 850 MHz (21.18 ticks)
// stays exact too.
#pragma once

#include <cstdint>

#include "model/time/ticks.h"

namespace c6416 {

struct dsk_profile {
    const char* name = "v1";
    int version = 1;             // DSK version (1..3), 0 = custom
    int64_t cpu_hz = 600000000;  // [RN]/[BSL] version table
    int64_t emif_hz = 100000000;

    simtime::rational_ticks cpu_period() const { return simtime::period_of_hz(cpu_hz); }
    simtime::rational_ticks emif_period() const { return simtime::period_of_hz(emif_hz); }
};

constexpr dsk_profile dsk_v1() {
    return dsk_profile{"v1", 1, 600000000, 100000000};
}
constexpr dsk_profile dsk_v2() {
    return dsk_profile{"v2", 2, 720000000, 120000000};
}
constexpr dsk_profile dsk_v3() {
    return dsk_profile{"v3", 3, 1000000000, 125000000};
}
// By version number 1..3; anything else gives v1.
constexpr dsk_profile dsk_version(int version) {
    return version == 2 ? dsk_v2() : version == 3 ? dsk_v3() : dsk_v1();
}
constexpr dsk_profile dsk_custom(int64_t cpu_hz, int64_t emif_hz) {
    return dsk_profile{"custom", 0, cpu_hz, emif_hz};
}

}  // namespace c6416
