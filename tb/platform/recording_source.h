// The sensors' light: the scene renderer (sensor::renderer_source), with a
// note of the scene time each camera's scene frame was rendered at, so the
// scoreboard can ask the scene for the ground truth of exactly the images the
// firmware saw.
#pragma once

#include <cstdint>
#include <vector>

#include "model/sensor/scene_sources.h"

namespace platform {

class recording_source final : public sensor::frame_source {
  public:
    explicit recording_source(const scene::renderer& renderer) : m_source(renderer) {}

    dsp::rgb_cplane frame(const sensor::frame_request& request) override {
        const int c = request.camera == scene::camera_id::left ? 0 : 1;
        std::vector<double>& times = m_times[c];
        if (times.size() <= request.scene_frame) times.resize(request.scene_frame + 1, -1.0);
        times[request.scene_frame] = m_source.scene_time_s(request);
        ++m_renders;
        return m_replay ? m_replay->frame(request) : m_source.frame(request);
    }

    // Frames from `replay` (e.g. sensor::replay_source) instead of the
    // renderer; the scene times are still noted (frame k at its time slot).
    void use_replay(sensor::frame_source* replay) { m_replay = replay; }

    // Scene time (s) camera c's scene frame k was rendered at; < 0 if never.
    double scene_time_s(int camera, uint64_t scene_frame) const {
        const std::vector<double>& t = m_times[camera];
        return scene_frame < t.size() ? t[scene_frame] : -1.0;
    }
    uint64_t renders() const { return m_renders; }

  private:
    sensor::renderer_source m_source;
    std::vector<double> m_times[2];
    uint64_t m_renders = 0;
    sensor::frame_source* m_replay = nullptr;
};

}  // namespace platform
