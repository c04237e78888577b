#include "tb/platform/firmware_board.h"

#include <cstring>

#include "model/emif/cectl.h"
#include "model/scene/camera.h"

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
    // The card's geometry registers from the sensor profile (docs/card.md,
    // "Sensor pins the card expects").
    const sensor::sensor_profile& p = config.profile;
    const auto u = [](int v) { return static_cast<uint32_t>(v); };
    b.h_start = u(p.href_start);
    b.dark_cols_left = u(p.dark_cols_left);
    b.border_cols_left = u(p.border_cols_before);
    b.active_cols = u(p.active_cols);
    b.border_cols_right = u(p.border_cols_after);
    b.dark_cols_right = u(p.dark_cols_right);
    b.line_total = u(p.line_pclks);
    b.v_start = u(p.first_row_line);
    b.dark_rows_top = u(p.dark_rows_top);
    b.border_rows_top = u(p.border_rows_before);
    b.active_rows = u(p.active_rows);
    b.border_rows_bottom = u(p.border_rows_after);
    b.dark_rows_bottom = u(p.dark_rows_bottom);
    b.frame_lines = u(p.frame_lines);
    b.cfa = static_cast<uint32_t>(p.cfa);
    const dsp::camera_rig rig = scene::to_dsp_rig(config.scenario.scene.rig);
    b.baseline_um = rig.baseline_um;
    b.focal_length_um = rig.focal_length_um;
    b.pixel_pitch_nm = rig.pixel_pitch_nm;
    b.cx_left_q8 = rig.cx_left_q8;
    b.cy_left_q8 = rig.cy_left_q8;
    b.cx_right_q8 = rig.cx_right_q8;
    b.cy_right_q8 = rig.cy_right_q8;
    return b;
}

std::vector<double> plugin_values(const stereosim_fw_descriptor& d, const platform_config& config) {
    std::vector<double> values;
    for (uint32_t k = 0; k < d.key_count; ++k)
        values.push_back(firmware_key(config, d.keys[k].name, d.keys[k].default_value));
    return values;
}

std::string key_choice(const stereosim_fw_descriptor& d, const platform_config& config,
                       const char* name) {
    for (uint32_t k = 0; k < d.key_count; ++k) {
        const stereosim_fw_key& key = d.keys[k];
        if (key.type != STEREOSIM_KEY_CHOICE || std::strcmp(key.name, name) != 0) continue;
        const auto chosen = static_cast<uint32_t>(firmware_key(config, name, key.default_value));
        return chosen < key.choice_count ? key.choices[chosen] : "";
    }
    return "";
}

bool asks_overlapped(const stereosim_fw_descriptor& d, const platform_config& config) {
    return key_choice(d, config, "mode") != "sequential";
}

uint32_t card_cectl_asked(const platform_config& config) {
    const bool v2_or_v3 = config.dsk.version == 2 || config.dsk.version == 3;
    emif::cectl_fields f = emif::cectl_unpack(v2_or_v3 ? emif::cectl_dsk_v2 : emif::cectl_dsk_v1);
    const card_bus_timing& t = config.card_timing;
    if (t.setup != 0) f.wrsetup = f.rdsetup = t.setup;
    if (t.strobe != 0) f.wrstrb = f.rdstrb = t.strobe;
    if (t.hold != 0) f.wrhld = f.rdhld = t.hold;
    return emif::cectl_pack(f);
}

}  // namespace platform
