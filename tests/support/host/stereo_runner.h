// Runs the firmware's controller over a rendered stereo sequence with no
// hardware: frame n of the scene is rendered, both images are mosaicked in
// the controller's CFA order (what the sensors deliver), the raw pair goes
// to controller::process_pair, and the output is kept beside the scene's
// ground truth. Used by the tests of dsp/ and system/
#pragma once

#include <cstdint>
#include <vector>

#include "dsp/controller.h"
#include "model/scene/images.h"
#include "model/scene/sequence.h"
#include "tb/platform/scoring/frame_record.h"
#include "tests/support/host/counting_hal.h"

namespace host {

// The controller configuration for a scene rig: image size, the firmware's
// integer rig, everything else at its default.
dsp::controller_config controller_config_for(const scene::stereo_rig& rig);

// One pair the host runner processed: what the platform scores (the ABI's
// result, frame_record::out) and the reference firmware's whole output.
struct host_record : platform::frame_record {
    dsp::frame_output firmware;
};

// The platform's part of each record (what platform::summarize reads).
std::vector<platform::frame_record> scored(const std::vector<host_record>& records);

class stereo_runner {
  public:
    // The firmware's kernels priced with `model` (dsp::hal::kernel_cycles).
    stereo_runner(scene::scenario scenario, const dsp::controller_config& config,
                  const c64x::cost_model& model = {});

    // Renders frame n and mosaics it into raw_left() / raw_right().
    void render(int n);
    // The raw pair of the last render(), which a test may alter (e.g. a
    // lighting change) before process().
    scene::gray_image& raw_left() { return m_raw_left; }
    scene::gray_image& raw_right() { return m_raw_right; }
    const scene::stereo_frame& frame() const { return m_frame; }

    // Feeds the current raw pair to the firmware; one HAL frame per call.
    host_record process();
    // render(n) then process().
    host_record step(int n);
    // Frames first .. first + count - 1.
    std::vector<host_record> run(int first, int count);

    dsp::controller& firmware() { return m_controller; }
    counting_hal& hal() { return m_hal; }
    const scene::sequence& sequence() const { return m_sequence; }

  private:
    scene::sequence m_sequence;
    counting_hal m_hal;
    dsp::controller m_controller;
    dsp::cfa_order m_cfa;
    scene::stereo_frame m_frame;
    scene::gray_image m_raw_left, m_raw_right;
    int m_rendered = -1;
};

}  // namespace host
