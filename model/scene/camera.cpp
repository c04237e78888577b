#include "model/scene/camera.h"

#include <cmath>

namespace scene {

pinhole_camera stereo_rig::left() const {
    pinhole_camera c;
    c.focal_px = focal_px();
    c.cx = cx_left();
    c.cy = cy_left();
    c.width = width;
    c.height = height;
    c.centre = {-baseline_m, 0.0, 0.0};
    return c;
}

pinhole_camera stereo_rig::right() const {
    pinhole_camera c;
    c.focal_px = focal_px();
    c.cx = cx_right();
    c.cy = cy_right();
    c.width = width;
    c.height = height;
    c.centre = {0.0, 0.0, 0.0};
    return c;
}

int32_t to_q8(double px) {
    return static_cast<int32_t>(std::lround(px * 256.0));
}

dsp::camera_rig to_dsp_rig(const stereo_rig& rig) {
    dsp::camera_rig out;
    out.baseline_um = static_cast<int32_t>(std::lround(rig.baseline_m * 1e6));
    out.focal_length_um = static_cast<int32_t>(std::lround(rig.focal_length_m * 1e6));
    out.pixel_pitch_nm = static_cast<int32_t>(std::lround(rig.pixel_pitch_m * 1e9));
    out.cx_left_q8 = to_q8(rig.cx_left());
    out.cy_left_q8 = to_q8(rig.cy_left());
    out.cx_right_q8 = to_q8(rig.cx_right());
    out.cy_right_q8 = to_q8(rig.cy_right());
    return out;
}

dsp::point3_um to_point3_um(vec3 p_m) {
    dsp::point3_um out;
    out.x = static_cast<int32_t>(std::lround(p_m.x * 1e6));
    out.y = static_cast<int32_t>(std::lround(p_m.y * 1e6));
    out.z = static_cast<int32_t>(std::lround(p_m.z * 1e6));
    return out;
}

}  // namespace scene
