#include "model/sensor/scene_sources.h"

namespace sensor {

double renderer_source::scene_time_s(const frame_request& request) const {
    const double mid_ticks =
        static_cast<double>(request.exposure_start) + 0.5 * static_cast<double>(request.exposure);
    return m_time_offset_s + mid_ticks / (static_cast<double>(simtime::ticks_per_ns) * 1e9);
}

dsp::rgb_cplane renderer_source::frame(const frame_request& request) {
    scene::rgb_image& image = m_images[request.camera == scene::camera_id::left ? 0 : 1];
    m_renderer.render(request.camera, scene_time_s(request), &image);
    return image.view();
}

}  // namespace sensor
