#include "tb/platform/platform_config.h"

#include <cmath>

namespace platform {

emif::emif_config engine_config(const platform_config& config) {
    emif::emif_config e;
    e.eclk = simtime::tick_clock(config.dsk.emif_period());
    // One SDRAM row refresh every 15.6 us ([TR]; SDTIM 0x618 at 100 MHz,
    // 0x750 at 120 MHz, docs/hardware-facts.md section 3).
    e.sdram.refresh_period = static_cast<uint32_t>(config.dsk.emif_hz * 156 / 10000000);
    return e;
}

c64x::cost_model cost_model_of(const platform_config& config) {
    c64x::model_params params;
    params.cpu_hz = static_cast<uint64_t>(config.dsk.cpu_hz);
    params.emif_hz = static_cast<uint64_t>(config.dsk.emif_hz);
    params.compiled_c_factor_q8 =
        static_cast<uint32_t>(std::lround(config.compiled_c_factor * 256.0));
    return c64x::cost_model(params);
}

void set_firmware_key(platform_config* config, const std::string& name, double value) {
    for (auto& [key, v] : config->firmware_settings)
        if (key == name) {
            v = value;
            return;
        }
    config->firmware_settings.emplace_back(name, value);
}

double firmware_key(const platform_config& config, const std::string& name, double fallback) {
    for (const auto& [key, v] : config.firmware_settings)
        if (key == name) return v;
    return fallback;
}

}  // namespace platform
