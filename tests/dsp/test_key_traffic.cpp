// What a held key costs the EMIF (dsp/key_frame.h, "Memory"): each tracked
// pair of a slow 320 px ball reads its key's ring and pattern from SDRAM,
// not the whole region around it. The expected bytes are the geometry of
// the key's box written out here (the region grown by max_shift + margin,
// the hole shrunk by as much: 96 (w + h) bytes unclipped, plus the 96 x 96
// pattern), not the firmware's own accounting.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "dsp/controller.h"
#include "dsp/key_frame.h"
#include "model/scene/ball_paths.h"
#include "tests/support/host/scenarios.h"
#include "tests/support/host/stereo_runner.h"

namespace {

// Stage track's SDRAM traffic of the last pair.
class track_traffic_hal final : public dsp::hal {
  public:
    void charge_cycles(dsp::stage, uint64_t) override {}
    void charge_with_traffic(dsp::stage s, uint64_t, const dsp::sdram_traffic& t) override {
        if (s == dsp::stage::track) track += t;
    }
    dsp::sdram_traffic track;
};

scene::scenario slow_large_pass() {
    scene::scenario s;
    s.scene.background =
        scene::background_desc::procedural_plane(scene::procedural_texture_params{}, 5.0);
    scene::ball_desc ball;
    ball.radius_m = host::ball_radius_for_width(320, 1.4, s.scene.rig.focal_px());
    ball.path = scene::pass_path(1.4, 0.2, scene::motion_start_s(3, s.frame_period_s));
    s.scene.balls.push_back(ball);
    s.frame_count = 22;
    return s;
}

TEST(KeyTraffic, ATrackedPairReadsTheKeysRingAndPatternNotItsRegion) {
    const scene::scenario scenario = slow_large_pass();
    host::stereo_runner runner(scenario, host::controller_config_for(scenario.scene.rig));
    track_traffic_hal hal;
    dsp::controller firmware;
    firmware.init(host::controller_config_for(scenario.scene.rig), hal);
    const int band = dsp::key_frame::hole_inset;  // max_shift + margin, each side
    const int pattern_bytes = 96 * 96;            // the tracker's max_size squared
    int keyed_pairs = 0;
    for (int n = 0; n < scenario.frame_count; ++n) {
        runner.render(n);
        hal.track = dsp::sdram_traffic{};
        const dsp::frame_output out =
            firmware.process_pair(runner.raw_left().view(), runner.raw_right().view());
        if (out.state != dsp::tracker_state::track || hal.track.bytes_read == 0) continue;
        ++keyed_pairs;
        // The key was taken on a box of this pair's size within a few px.
        const int w = out.box_right.width, h = out.box_right.height;
        const int64_t ring = int64_t{4} * band * (w + h);
        const int64_t region = int64_t{w + 2 * band} * (h + 2 * band);
        const int64_t read = static_cast<int64_t>(hal.track.bytes_read);
        EXPECT_LE(std::llabs(read - (ring + pattern_bytes)), int64_t{4} * band * 8)
            << "pair " << n << ": read " << read << ", box " << w << " x " << h;
        EXPECT_LT(read, region) << "pair " << n << ": the whole region read";
    }
    std::printf("%d keyed pairs\n", keyed_pairs);
    EXPECT_GE(keyed_pairs, 10);
}

}  // namespace
