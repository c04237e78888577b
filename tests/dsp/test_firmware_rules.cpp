// Firmware rules (docs/design-brief.md, "Layers"): after init, the controller's frame
// loop allocates nothing; and the cycles it reports per stage are non-zero
// exactly for the stages that ran, equal to what it charged to the HAL.
//
// Heap calls are counted by tests/support/heap_counter.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <set>
#include <utility>
#include <vector>

#include "dsp/controller.h"
#include "dsp/kernel_costs.h"
#include "tests/support/heap_counter.h"
#include "tests/support/host/counting_hal.h"
#include "tests/support/host/scenarios.h"
#include "tests/support/host/stereo_runner.h"

using test_support::heap_counter;

namespace {

using dsp::stage;
using dsp::tracker_state;

constexpr int stage_index(stage s) {
    return static_cast<int>(s);
}

}  // namespace

// The ball leaves the view and comes back, so the frame loop goes through
// every path: history filling, DETECT without and with a detection, TRACK,
// the loss, LOST, DETECT again, TRACK again. Pairs are rendered outside the
// counted region; only process_pair is counted.
TEST(FirmwareRules, ProcessPairAllocatesNothingAfterInit) {
    const scene::scenario scenario = host::exit_return_scenario(4);
    host::stereo_runner runner(scenario, host::controller_config_for(scenario.scene.rig));

    // The counter sees the firmware's own allocations: a second controller's init.
    long init_allocations = 0;
    {
        host::counting_hal hal;
        dsp::controller other;
        heap_counter count;
        other.init(host::controller_config_for(scenario.scene.rig), hal);
        init_allocations = count.allocations();
    }
    EXPECT_GT(init_allocations, 5);

    long allocations = 0, deallocations = 0;
    std::set<tracker_state> states;
    int detections = 0;
    for (int n = 0; n < scenario.frame_count; ++n) {
        runner.render(n);
        runner.hal().begin_frame();
        dsp::frame_output out;
        {
            heap_counter count;
            out =
                runner.firmware().process_pair(runner.raw_left().view(), runner.raw_right().view());
            allocations += count.allocations();
            deallocations += count.deallocations();
        }
        states.insert(out.state);
        if (out.detected) ++detections;
    }
    std::printf(
        "init: %ld allocations; %d pairs: %ld allocations, %ld deallocations, %d detections\n",
        init_allocations, scenario.frame_count, allocations, deallocations, detections);
    RecordProperty("init_allocations", static_cast<int>(init_allocations));
    RecordProperty("frame_loop_allocations", static_cast<int>(allocations));
    EXPECT_EQ(allocations, 0);
    EXPECT_EQ(deallocations, 0);
    EXPECT_EQ(states.size(), 3u) << "the run must visit DETECT, TRACK and LOST";
    EXPECT_GE(detections, 2);
}

// Per frame: a stage has cycles in frame_output exactly when the HAL saw it
// begin, the HAL got the same cycles, the protocol (charges inside their
// stage, begin / end paired) holds, and the set of stages is the one the
// state transition implies (dsp/controller.h).
TEST(FirmwareRules, StageCyclesAreNonZeroExactlyForTheStagesThatRan) {
    const scene::scenario scenario = host::exit_return_scenario(4);
    host::stereo_runner runner(scenario, host::controller_config_for(scenario.scene.rig));
    const dsp::controller_config& config = runner.firmware().config();

    enum kind { filling, detect_nothing, detection, tracked, loss, lost_pair, kinds };
    const char* const kind_names[kinds] = {
        "history filling", "detect, nothing", "detection", "track", "loss", "lost"};
    int seen[kinds] = {};
    tracker_state previous = tracker_state::detect;
    // The left buffer holds the strided history (dsp/stride_history.h) from a
    // DETECT pair with three frames that found nothing until the left image
    // is made again: a DETECT pair then makes it only for a detection, in a
    // second preprocess entry after stage detect.
    bool stride_holds = false;
    int late_left_pairs = 0;
    for (int n = 0; n < scenario.frame_count; ++n) {
        const host::host_record r = runner.step(n);
        const dsp::frame_output& out = r.firmware;
        const host::counting_hal& hal = runner.hal();
        std::set<stage> expected = {stage::preprocess};
        kind k = kinds;
        if (n < 2) {
            k = filling;
        } else if (previous == tracker_state::detect) {
            expected.insert(stage::detect);
            k = out.detected ? detection : detect_nothing;
        } else if (previous == tracker_state::track) {
            expected.insert(stage::track);
            k = out.state == tracker_state::track ? tracked : loss;
        } else {
            k = lost_pair;
        }
        const bool left_at_start = !(previous == tracker_state::detect && stride_holds);
        const bool late_left = !left_at_start && out.has_object;
        late_left_pairs += late_left;
        if (out.has_object) {
            expected.insert(stage::stereo_sad);
            expected.insert(stage::stereo_edge);
        }
        if (out.has_point) expected.insert(stage::xyz);
        ++seen[k];

        for (int i = 0; i < dsp::stage_count; ++i) {
            const stage s = static_cast<stage>(i);
            const bool ran = hal.frame_entries(s) > 0;
            EXPECT_EQ(ran, out.stage_cycles[i] > 0) << "frame " << n << " " << dsp::stage_name(s);
            EXPECT_EQ(ran, expected.count(s) == 1) << "frame " << n << " " << dsp::stage_name(s);
            EXPECT_EQ(hal.frame_cycles(s), out.stage_cycles[i]) << "frame " << n;
            const int entries = s == stage::preprocess && late_left ? 2 : 1;
            EXPECT_LE(hal.frame_entries(s), entries) << "frame " << n << " " << dsp::stage_name(s);
        }
        // The preprocess charge is the cost model's for two VGA frames (raw
        // from SDRAM, gray and brightness in L2: the memory plan), plus the
        // packed Dif(t-1,t) where neither detect nor track makes it (the
        // second pair of the history, and LOST).
        const uint64_t per_image =
            dsp::cost::demosaic_gray_cycles(640, 480, config.frame_memory, config.raw_memory) +
            dsp::cost::brightness_cycles(640, 480, config.frame_memory);
        const bool mask_in_preprocess = n == 1 || previous == tracker_state::lost;
        const uint64_t mask =
            mask_in_preprocess ? dsp::cost::difference_packed_cycles(640, 480, config.frame_memory)
                               : 0;
        const uint64_t images = left_at_start || late_left ? 2 : 1;
        EXPECT_EQ(out.stage_cycles[stage_index(stage::preprocess)], images * per_image + mask)
            << "frame " << n;
        if (left_at_start || late_left) stride_holds = false;
        if (k == detect_nothing && !out.has_object) stride_holds = true;
        EXPECT_EQ(out.stage_cycles[stage_index(stage::capture)], 0u);
        previous = out.state;
    }
    EXPECT_EQ(runner.hal().protocol_errors(), 0u);
    for (int k = 0; k < kinds; ++k) {
        std::printf("%-16s %3d pairs\n", kind_names[k], seen[k]);
        EXPECT_GT(seen[k], 0) << kind_names[k] << " never happened";
    }
    std::printf("%d detections with the left image made late\n", late_left_pairs);
    EXPECT_GT(late_left_pairs, 0);
}

// A pair the firmware cannot use (larger than init's maximum, odd size,
// left and right of different sizes) is refused: nothing runs, nothing is
// charged, the state is kept.
TEST(FirmwareRules, UnusablePairsAreRefusedWithoutRunningAnything) {
    host::counting_hal hal;
    dsp::controller_config config;
    config.max_width = 64;
    config.max_height = 48;
    dsp::controller firmware;
    firmware.init(config, hal);
    std::vector<uint8_t> big(66 * 48, 100), small(64 * 48, 100), odd(63 * 47, 100);
    const dsp::gray_cplane too_wide{big.data(), 66, 48, 66};
    const dsp::gray_cplane fits{small.data(), 64, 48, 64};
    const dsp::gray_cplane odd_size{odd.data(), 63, 47, 63};
    for (const auto& pair : {std::make_pair(too_wide, too_wide), std::make_pair(odd_size, odd_size),
                             std::make_pair(fits, odd_size)}) {
        hal.begin_frame();
        const dsp::frame_output out = firmware.process_pair(pair.first, pair.second);
        EXPECT_FALSE(out.accepted);
        EXPECT_EQ(hal.frame_cycles_all(), 0u);
        for (int i = 0; i < dsp::stage_count; ++i) EXPECT_EQ(out.stage_cycles[i], 0u);
    }
    hal.begin_frame();
    const dsp::frame_output ok = firmware.process_pair(fits, fits);
    EXPECT_TRUE(ok.accepted);
    EXPECT_GT(ok.stage_cycles[stage_index(stage::preprocess)], 0u);
    EXPECT_EQ(hal.protocol_errors(), 0u);
}
