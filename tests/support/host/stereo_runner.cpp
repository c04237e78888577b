#include "tests/support/host/stereo_runner.h"

#include <utility>

#include "dsp/plugin/services_hal.h"
#include "model/scene/bayer_mosaic.h"

namespace host {

dsp::controller_config controller_config_for(const scene::stereo_rig& rig) {
    dsp::controller_config config;
    config.max_width = rig.width;
    config.max_height = rig.height;
    config.rig = scene::to_dsp_rig(rig);
    return config;
}

stereo_runner::stereo_runner(scene::scenario scenario, const dsp::controller_config& config,
                             const c64x::cost_model& model)
    : m_sequence(std::move(scenario)), m_hal(model), m_cfa(config.cfa) {
    m_controller.init(config, m_hal);
}

void stereo_runner::render(int n) {
    m_sequence.render(n, &m_frame);
    m_raw_left.resize(m_frame.left.width, m_frame.left.height);
    m_raw_right.resize(m_frame.right.width, m_frame.right.height);
    scene::mosaic(m_frame.left.view(), m_cfa, m_raw_left.plane());
    scene::mosaic(m_frame.right.view(), m_cfa, m_raw_right.plane());
    m_rendered = n;
}

std::vector<platform::frame_record> scored(const std::vector<host_record>& records) {
    return {records.begin(), records.end()};
}

host_record stereo_runner::process() {
    host_record record;
    record.index = m_rendered;
    record.time_s = m_frame.time_s;
    m_hal.begin_frame();
    record.firmware = m_controller.process_pair(m_raw_left.view(), m_raw_right.view());
    record.out = dsp::plugin::abi_result(0, record.firmware);
    if (!m_frame.balls.empty()) {
        record.has_truth = true;
        record.truth = m_frame.balls.front();
    }
    return record;
}

host_record stereo_runner::step(int n) {
    render(n);
    return process();
}

std::vector<host_record> stereo_runner::run(int first, int count) {
    std::vector<host_record> records;
    records.reserve(static_cast<size_t>(count > 0 ? count : 0));
    for (int n = first; n < first + count; ++n) records.push_back(step(n));
    return records;
}

}  // namespace host
