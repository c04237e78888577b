// frame_source adapters for the scene library: the renderer and the PNG
// replay. They keep the scene library free of sensor types (data flows
// scene -> sensor only).
#pragma once

#include <memory>

#include "model/scene/images.h"
#include "model/scene/renderer.h"
#include "model/scene/replay.h"
#include "model/sensor/frame_source.h"

namespace sensor {

// Renders each camera at the middle of the frame's exposure window (seconds =
// ticks / 18e9, plus time_offset_s). One image buffer per camera.
class renderer_source : public frame_source {
  public:
    explicit renderer_source(const scene::renderer& renderer, double time_offset_s = 0.0)
        : m_renderer(renderer), m_time_offset_s(time_offset_s) {}

    dsp::rgb_cplane frame(const frame_request& request) override;

    // The scene time rendered for a request.
    double scene_time_s(const frame_request& request) const;

  private:
    const scene::renderer& m_renderer;
    double m_time_offset_s;
    scene::rgb_image m_images[2];
};

// Scene frame k of each camera is the replay's frame k (its after_last policy
// decides beyond the sequence).
class replay_source : public frame_source {
  public:
    explicit replay_source(scene::replay& replay) : m_replay(replay) {}

    dsp::rgb_cplane frame(const frame_request& request) override {
        return m_replay.frame(request.camera, request.scene_frame).view();
    }

  private:
    scene::replay& m_replay;
};

}  // namespace sensor
