#include "tb/platform/firmware_board.h"

#include <cstring>

#include "dsp/plugin/reference_firmware.h"

namespace platform {

stereosim_board board_of(const platform_config& config) {
    stereosim_board b{};
    const int version = config.dsk.version;
    b.dsk_version = version == 2 || version == 3 ? static_cast<uint32_t>(version) : 1u;
    b.cpu_hz = static_cast<uint64_t>(config.dsk.cpu_hz);
    b.emif_hz = static_cast<uint64_t>(config.dsk.emif_hz);
    b.card_setup = config.card_timing.setup;
    b.card_strobe = config.card_timing.strobe;
    b.card_hold = config.card_timing.hold;
    b.card_retry_limit = config.card_retry_limit;
    // The card's geometry registers as the platform derives them from the
    // sensor profile (program_config; docs/card.md, "Sensor pins the card expects").
    const dsp::card_setup g = program_config(config).card;
    b.h_start = g.h_start;
    b.dark_cols_left = g.dark_cols_left;
    b.border_cols_left = g.border_cols_left;
    b.active_cols = g.active_cols;
    b.border_cols_right = g.border_cols_right;
    b.dark_cols_right = g.dark_cols_right;
    b.line_total = g.line_total;
    b.v_start = g.v_start;
    b.dark_rows_top = g.dark_rows_top;
    b.border_rows_top = g.border_rows_top;
    b.active_rows = g.active_rows;
    b.border_rows_bottom = g.border_rows_bottom;
    b.dark_rows_bottom = g.dark_rows_bottom;
    b.frame_lines = g.frame_lines;
    b.cfa = static_cast<uint32_t>(config.profile.cfa);
    const dsp::camera_rig rig = pipeline_config(config).rig;
    b.baseline_um = rig.baseline_um;
    b.focal_length_um = rig.focal_length_um;
    b.pixel_pitch_nm = rig.pixel_pitch_nm;
    b.cx_left_q8 = rig.cx_left_q8;
    b.cy_left_q8 = rig.cy_left_q8;
    b.cx_right_q8 = rig.cx_right_q8;
    b.cy_right_q8 = rig.cy_right_q8;
    return b;
}

std::vector<double> reference_values(const platform_config& config) {
    using namespace dsp::plugin;
    std::vector<double> v(reference_key_count);
    const dsp::control_program_config defaults;
    v[key_mode] = static_cast<double>(config.mode);
    v[key_search_radius] = config.track_search_radius;
    v[key_stereo_method] = static_cast<double>(config.stereo_method);
    v[key_detect_threshold] = config.detect_threshold;
    v[key_frame_memory] = static_cast<double>(config.frame_memory);
    v[key_watchdog_ms] = config.watchdog_ms;
    v[key_card_start_timeout] = config.card_start_timeout;
    v[key_capture_cycles] = static_cast<double>(config.capture_cycles);
    v[key_hard_error_rearms] = config.hard_error_rearms;
    v[key_rearm_on_overflow] = defaults.rearm_on_overflow ? 1 : 0;
    v[key_rearm_on_every_sync_error] = defaults.rearm_on_every_sync_error ? 1 : 0;
    return v;
}

std::vector<double> plugin_values(const stereosim_fw_descriptor& d, const platform_config& config) {
    const stereosim_fw_descriptor& reference = dsp::plugin::reference_firmware();
    const std::vector<double> run = reference_values(config);
    std::vector<double> values;
    for (uint32_t k = 0; k < d.key_count; ++k) {
        const stereosim_fw_key& key = d.keys[k];
        double value = key.default_value;
        for (uint32_t r = 0; r < reference.key_count; ++r) {
            const stereosim_fw_key& ref = reference.keys[r];
            if (std::strcmp(ref.name, key.name) != 0 || ref.type != key.type) continue;
            if (key.type != STEREOSIM_KEY_CHOICE) {
                if (run[r] >= key.min && run[r] <= key.max) value = run[r];
                continue;
            }
            const char* chosen = ref.choices[static_cast<size_t>(run[r])];
            for (uint32_t c = 0; c < key.choice_count; ++c)
                if (std::strcmp(key.choices[c], chosen) == 0) value = c;
        }
        // What the user set by the key's own name has the last word.
        for (const auto& [name, set] : config.firmware_settings)
            if (name == key.name) value = set;
        values.push_back(value);
    }
    return values;
}

}  // namespace platform
