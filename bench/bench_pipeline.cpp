// The whole firmware frame on the host: controller::process_pair on a VGA
// raw Bayer pair from the scene renderer, per state. Wall time per pair is
// the host's; the modelled C64x cycles per pair (dsp/kernel_costs.h, cost
// model id printed in the label) are reported as counters beside it.
//
//   detect: a static scene, so every pair runs the full-frame detection and
//           finds nothing (the state stays DETECT).
//   track:  the default scenario run until the ball is tracked, then the
//           same pair again and again (the ball found in place every time).
//   lost:   preprocess only (a LOST pair), the floor of every state.
//
// bench/ does not link the host harness, so this file has its own tiny HAL.
#include <benchmark/benchmark.h>

#include <cstdint>

#include "dsp/controller.h"
#include "dsp/kernel_costs.h"
#include "model/scene/bayer_mosaic.h"
#include "model/scene/sequence.h"

namespace {

class cycle_counter final : public dsp::hal {
  public:
    void charge_cycles(dsp::stage, uint64_t cycles) override { m_cycles += cycles; }
    uint64_t take() {
        const uint64_t c = m_cycles;
        m_cycles = 0;
        return c;
    }

  private:
    uint64_t m_cycles = 0;
};

struct raw_pair {
    scene::gray_image left, right;
};

raw_pair render_raw(const scene::sequence& sequence, int n, dsp::cfa_order cfa) {
    const scene::stereo_frame frame = sequence.render(n);
    return raw_pair{scene::mosaic(frame.left, cfa), scene::mosaic(frame.right, cfa)};
}

dsp::controller_config config_for(const scene::scenario& s) {
    dsp::controller_config config;
    config.max_width = s.scene.rig.width;
    config.max_height = s.scene.rig.height;
    config.rig = scene::to_dsp_rig(s.scene.rig);
    return config;
}

// Feeds `pair` while the controller is in `wanted`; the counters say what
// one pair costs.
void measure(benchmark::State& state, dsp::controller& firmware, cycle_counter& hal,
             const raw_pair& pair, dsp::tracker_state wanted) {
    uint64_t cycles = 0;
    for (auto _ : state) {
        const dsp::frame_output out = firmware.process_pair(pair.left.view(), pair.right.view());
        benchmark::DoNotOptimize(out);
        cycles = hal.take();
        if (out.state != wanted) {
            state.SkipWithError("the controller left the state under test");
            break;
        }
    }
    state.counters["modelled_cycles"] = static_cast<double>(cycles);
    state.counters["modelled_ms_600MHz"] = 1e3 * static_cast<double>(cycles) / 600e6;
    state.SetLabel(dsp::cost::default_model().id());
}

void BM_ProcessPairDetect(benchmark::State& state) {
    scene::scenario s = scene::default_scenario(6);  // frames 0..5: the ball still
    const scene::sequence sequence(s);
    const dsp::controller_config config = config_for(s);
    const raw_pair pair = render_raw(sequence, 0, config.cfa);
    cycle_counter hal;
    dsp::controller firmware;
    firmware.init(config, hal);
    for (int n = 0; n < 3; ++n) firmware.process_pair(pair.left.view(), pair.right.view());
    hal.take();
    measure(state, firmware, hal, pair, dsp::tracker_state::detect);
}
BENCHMARK(BM_ProcessPairDetect)->Unit(benchmark::kMillisecond);

void BM_ProcessPairTrack(benchmark::State& state) {
    const scene::scenario s = scene::default_scenario(6);
    const scene::sequence sequence(s);
    const dsp::controller_config config = config_for(s);
    cycle_counter hal;
    dsp::controller firmware;
    firmware.init(config, hal);
    raw_pair pair;
    for (int n = 0; n < 20 && firmware.state() != dsp::tracker_state::track; ++n) {
        pair = render_raw(sequence, n, config.cfa);
        firmware.process_pair(pair.left.view(), pair.right.view());
    }
    if (firmware.state() != dsp::tracker_state::track) {
        state.SkipWithError("the ball was not detected");
        return;
    }
    hal.take();
    measure(state, firmware, hal, pair, dsp::tracker_state::track);
}
BENCHMARK(BM_ProcessPairTrack)->Unit(benchmark::kMillisecond);

void BM_ProcessPairLost(benchmark::State& state) {
    // LOST lasts lost_frames_to_detect pairs: make it long so every
    // iteration is a LOST pair.
    const scene::scenario s = scene::default_scenario(6);
    const scene::sequence sequence(s);
    dsp::controller_config config = config_for(s);
    config.lost_frames_to_detect = 1 << 30;
    cycle_counter hal;
    dsp::controller firmware;
    firmware.init(config, hal);
    raw_pair pair;
    int n = 0;
    for (; n < 20 && firmware.state() != dsp::tracker_state::track; ++n) {
        pair = render_raw(sequence, n, config.cfa);
        firmware.process_pair(pair.left.view(), pair.right.view());
    }
    // A uniform pair: the pattern is gone, the track is lost.
    for (auto& p : pair.left.pixels) p = 0;
    for (auto& p : pair.right.pixels) p = 0;
    firmware.process_pair(pair.left.view(), pair.right.view());
    if (firmware.state() != dsp::tracker_state::lost) {
        state.SkipWithError("the track was not lost");
        return;
    }
    hal.take();
    measure(state, firmware, hal, pair, dsp::tracker_state::lost);
}
BENCHMARK(BM_ProcessPairLost)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
