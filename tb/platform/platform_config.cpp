#include "tb/platform/platform_config.h"

#include <cmath>

#include "tb/platform/scoring/frame_record.h"

namespace platform {

dsp::controller_config pipeline_config(const platform_config& config) {
    dsp::controller_config c = platform::controller_config_for(config.scenario.scene.rig);
    c.cfa = config.profile.cfa;
    c.track.search_radius = config.track_search_radius;
    c.detect.threshold = static_cast<uint8_t>(config.detect_threshold);
    c.method = config.stereo_method;
    c.frame_memory = config.frame_memory;
    return c;
}

emif::emif_config engine_config(const platform_config& config) {
    emif::emif_config e;
    e.eclk = simtime::tick_clock(config.dsk.emif_period());
    // One SDRAM row refresh every 15.6 us ([TR]; SDTIM 0x618 at 100 MHz,
    // 0x750 at 120 MHz, docs/hardware-facts.md section 3).
    e.sdram.refresh_period = static_cast<uint32_t>(config.dsk.emif_hz * 156 / 10000000);
    return e;
}

dsp::c64x::cost_model cost_model_of(const platform_config& config) {
    dsp::c64x::model_params params;
    params.cpu_hz = static_cast<uint64_t>(config.dsk.cpu_hz);
    params.emif_hz = static_cast<uint64_t>(config.dsk.emif_hz);
    params.compiled_c_factor_q8 =
        static_cast<uint32_t>(std::lround(config.compiled_c_factor * 256.0));
    return dsp::c64x::cost_model(params);
}

dsp::control_program_config program_config(const platform_config& config) {
    dsp::control_program_config c;
    c.pipeline = pipeline_config(config);
    const sensor::sensor_profile& p = config.profile;
    // The card's geometry registers from the sensor profile (docs/card.md,
    // "Sensor pins the card expects").
    c.card.h_start = static_cast<uint32_t>(p.href_start);
    c.card.dark_cols_left = static_cast<uint32_t>(p.dark_cols_left);
    c.card.border_cols_left = static_cast<uint32_t>(p.border_cols_before);
    c.card.active_cols = static_cast<uint32_t>(p.active_cols);
    c.card.border_cols_right = static_cast<uint32_t>(p.border_cols_after);
    c.card.dark_cols_right = static_cast<uint32_t>(p.dark_cols_right);
    c.card.line_total = static_cast<uint32_t>(p.line_pclks);
    c.card.v_start = static_cast<uint32_t>(p.first_row_line);
    c.card.dark_rows_top = static_cast<uint32_t>(p.dark_rows_top);
    c.card.border_rows_top = static_cast<uint32_t>(p.border_rows_before);
    c.card.active_rows = static_cast<uint32_t>(p.active_rows);
    c.card.border_rows_bottom = static_cast<uint32_t>(p.border_rows_after);
    c.card.dark_rows_bottom = static_cast<uint32_t>(p.dark_rows_bottom);
    c.card.frame_lines = static_cast<uint32_t>(p.frame_lines);
    c.dsk = config.dsk.version == 2   ? dsp::dsk_version::v2
            : config.dsk.version == 3 ? dsp::dsk_version::v3
                                      : dsp::dsk_version::v1;
    c.cpu_mhz = static_cast<uint32_t>(config.dsk.cpu_hz / 1000000);
    c.mode = config.mode;
    c.capture_cycles = config.capture_cycles;
    c.watchdog_ms = config.watchdog_ms;
    c.card.retry_limit = config.card_retry_limit;
    c.card.start_timeout = config.card_start_timeout;
    c.card_timing = config.card_timing;
    c.hard_error_rearms = config.hard_error_rearms;
    return c;
}

}  // namespace platform
