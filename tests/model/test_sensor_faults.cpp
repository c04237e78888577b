// Each fault hook gives exactly the pin-level outcome written in
// docs/sensor-faults.md: a faulted sensor runs beside an unfaulted reference
// (same profile, seed, scene, OE) and the two pin streams are compared clock
// by clock against the documented rule.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "model/sensor/sensor_core.h"
#include "sensor_test_util.h"

using namespace sensor;
using namespace sensor_test;

namespace {

constexpr uint64_t latency = 7;      // small_profile().startup_latency_pclks
constexpr uint64_t line = 40;        // small_profile().line_pclks
constexpr uint64_t frame = 40 * 30;  // clocks per frame
constexpr uint64_t start(uint64_t k) {
    return latency + k * frame;
}  // S_k with OE high from 0
constexpr uint16_t valid_only = pin_word::valid_bit;
constexpr uint16_t fodd = pin_word::fodd_bit;

struct run_result {
    std::vector<cycle_record> rec;
    std::vector<frame_truth> truth;
    std::vector<frame_request> requests;
};

run_result run_sensor(const std::vector<fault>& faults, uint64_t cycles,
                      const std::function<bool(uint64_t)>& oe = oe_from(0)) {
    const sensor_profile p = small_profile();
    pattern_source source(p.active_cols, p.active_rows);
    sensor_core core(p, scene::camera_id::left, source);
    for (const fault& f : faults) core.add_fault(f);
    run_result r;
    r.rec = run(core, cycles, oe);
    r.truth = core.truth();
    r.requests = source.requests;
    return r;
}

// Number of clocks where out differs from the rule want(n).
template <typename Rule>
uint64_t count_violations(const std::vector<cycle_record>& out, Rule want) {
    uint64_t bad = 0;
    for (uint64_t n = 0; n < out.size(); ++n)
        if (out[n].pins.bits != want(n)) {
            if (bad < 5)
                ADD_FAILURE() << "clock " << n << ": got 0x" << std::hex << out[n].pins.bits
                              << ", want 0x" << want(n);
            ++bad;
        }
    return bad;
}

simtime::ticks rise_of(uint64_t n) {
    return static_cast<simtime::ticks>(n) * 1050;
}

}  // namespace

TEST(SensorFaults, StartSkewDelaysEveryLaterEdgeByExactlyItsClocks) {
    const uint64_t cycles = start(5);
    const auto ref = run_sensor({}, cycles);
    const int k = 3 * 40 + 5;  // 3 lines and 5 pixels
    const auto out = run_sensor({fault::start_skew(fault_trigger::at_frame(1), 3, 5, 40)}, cycles);
    EXPECT_EQ(count_violations(out.rec,
                               [&](uint64_t n) -> uint16_t {
                                   if (n < start(1)) return ref.rec[n].pins.bits;
                                   if (n < start(1) + k) return valid_only;
                                   return ref.rec[n - k].pins.bits;
                               }),
              0u);
    // VSYNC edges exactly 3 line periods + 5 clocks apart, in clocks and ticks.
    const auto vs_ref = rises(ref.rec, pin_word::vsync_bit);
    const auto vs_out = rises(out.rec, pin_word::vsync_bit);
    ASSERT_GE(vs_out.size(), 3u);
    EXPECT_EQ(vs_out[0], vs_ref[0]);
    for (size_t i = 1; i < vs_out.size(); ++i) {
        EXPECT_EQ(vs_out[i] - vs_ref[i], static_cast<uint64_t>(k));
        EXPECT_EQ(out.rec[vs_out[i]].fall - ref.rec[vs_ref[i]].fall, k * 1050);
    }
    EXPECT_EQ(out.truth[1].skew_before_pclks, k);
    EXPECT_TRUE(out.truth[1].faults & fault_bit(fault_kind::start_skew));
    EXPECT_TRUE(pair_in_step(out.truth[0], ref.truth[0], {1050, 1}));
    EXPECT_FALSE(pair_in_step(out.truth[1], ref.truth[1], {1050, 1}));
    EXPECT_FALSE(pair_in_step(out.truth[2], ref.truth[2], {1050, 1}));

    // Before the first frame: a longer start-up (VALID stays low).
    const auto first =
        run_sensor({fault::start_skew(fault_trigger::at_frame(0), 0, 9, 40)}, cycles);
    EXPECT_EQ(count_violations(first.rec,
                               [&](uint64_t n) -> uint16_t {
                                   return n < latency + 9 ? 0 : ref.rec[n - 9].pins.bits;
                               }),
              0u);
    // By time: the first frame starting at or after the tick (frame 2 here).
    const auto timed = run_sensor(
        {fault::start_skew(fault_trigger::at_time(rise_of(start(1) + 1)), 0, 4, 40)}, cycles);
    EXPECT_EQ(timed.truth[1].skew_before_pclks, 0);
    EXPECT_EQ(timed.truth[2].skew_before_pclks, 4);
    EXPECT_EQ(timed.truth[2].start_cycle, start(2) + 4);
}

// A skew's idle clocks cut by an OE stop have moved no frame: the skew acts
// on the first frame after the restart (by frame: the first at or after N).
TEST(SensorFaults, StartSkewCutByAnOeStopActsAfterTheRestart) {
    const uint64_t k = 3 * 40 + 5;
    const uint64_t fall = start(1) + 50, rise = start(1) + 200;
    const auto oe = [&](uint64_t n) { return n < fall || n >= rise; };
    const auto ref = run_sensor({}, start(5), oe);
    const auto out =
        run_sensor({fault::start_skew(fault_trigger::at_frame(1), 3, 5, 40)}, start(5), oe);
    ASSERT_GE(out.truth.size(), 3u);
    ASSERT_GE(ref.truth.size(), 2u);
    // Frame 0 before the stop; frame 1 is the first after the restart.
    EXPECT_EQ(out.truth[1].skew_before_pclks, static_cast<int>(k));
    EXPECT_TRUE(out.truth[1].faults & fault_bit(fault_kind::start_skew));
    uint64_t ref_after_restart = 0;  // the unfaulted sensor's first frame after it
    for (const frame_truth& t : ref.truth)
        if (t.start_cycle >= rise) {
            ref_after_restart = t.start_cycle;
            break;
        }
    EXPECT_EQ(out.truth[1].start_cycle, ref_after_restart + k);
    EXPECT_EQ(out.truth[2].skew_before_pclks, 0);
}

TEST(SensorFaults, DroppedLineLosesExactlyOneHrefPulse) {
    const uint64_t cycles = start(4);
    const auto ref = run_sensor({}, cycles);
    const auto out = run_sensor({fault::dropped_line(fault_trigger::at_frame(1, 10))}, cycles);
    const uint64_t l0 = start(1) + 10 * line;
    EXPECT_EQ(count_violations(out.rec,
                               [&](uint64_t n) -> uint16_t {
                                   const uint16_t r = ref.rec[n].pins.bits;
                                   if (n >= l0 && n < l0 + line)
                                       return r & ~(pin_word::href_bit | pin_word::data_mask);
                                   return r;
                               }),
              0u);
    EXPECT_EQ(out.truth[1].lines_with_href, 15);
    EXPECT_EQ(ref.truth[1].lines_with_href, 16);
    EXPECT_TRUE(out.truth[1].faults & fault_bit(fault_kind::dropped_line));
    EXPECT_FALSE(pair_in_step(out.truth[1], ref.truth[1], {1050, 1}));
    EXPECT_TRUE(pair_in_step(out.truth[2], ref.truth[2], {1050, 1}));

    // A trigger in the vertical blanking (line 25) acts on the next readout
    // line: frame 2, line 4 (first_row_line).
    const auto late = run_sensor({fault::dropped_line(fault_trigger::at_frame(1, 25))}, cycles);
    const uint64_t l2 = start(2) + 4 * line;
    EXPECT_EQ(count_violations(late.rec,
                               [&](uint64_t n) -> uint16_t {
                                   const uint16_t r = ref.rec[n].pins.bits;
                                   if (n >= l2 && n < l2 + line)
                                       return r & ~(pin_word::href_bit | pin_word::data_mask);
                                   return r;
                               }),
              0u);
}

TEST(SensorFaults, DroppedFrameHasNoVsyncNoHrefAndConsumesItsSceneFrame) {
    const uint64_t cycles = start(4);
    const auto ref = run_sensor({}, cycles);
    const auto out = run_sensor({fault::dropped_frame(fault_trigger::at_frame(1))}, cycles);
    EXPECT_EQ(count_violations(out.rec,
                               [&](uint64_t n) -> uint16_t {
                                   // The frame is counted: FODD as in the reference.
                                   if (n >= start(1) && n < start(2))
                                       return valid_only | (ref.rec[n].pins.bits & fodd);
                                   return ref.rec[n].pins.bits;
                               }),
              0u);
    ASSERT_GE(out.truth.size(), 3u);
    EXPECT_TRUE(out.truth[1].dropped);
    EXPECT_EQ(out.truth[2].scene_frame, 2u);
    for (const frame_request& r : out.requests)
        EXPECT_NE(r.scene_frame, 1u) << "frame 1 never rendered";
}

TEST(SensorFaults, ExtraFrameRepeatsTheFrameAndDelaysTheRestByOnePeriod) {
    const uint64_t cycles = start(5);
    const auto ref = run_sensor({}, cycles);
    const auto out = run_sensor({fault::extra_frame(fault_trigger::at_frame(1))}, cycles);
    EXPECT_EQ(count_violations(out.rec,
                               [&](uint64_t n) -> uint16_t {
                                   if (n < start(2)) return ref.rec[n].pins.bits;
                                   if (n < start(3)) return ref.rec[n - frame].pins.bits;  // repeat
                                   // One period late on a periodic timing, showing the
                                   // scene frame of its own time slot: the reference,
                                   // but one new frame fewer since OE rose: FODD inverted.
                                   return ref.rec[n].pins.bits ^ fodd;
                               }),
              0u);
    ASSERT_GE(out.truth.size(), 4u);
    EXPECT_TRUE(out.truth[2].repeated);
    EXPECT_EQ(out.truth[2].scene_frame, 1u);
    EXPECT_EQ(out.truth[3].scene_frame, 3u) << "slot 3: scene frame 2 is never shown";
    EXPECT_EQ(out.truth[3].index, 3u);
    EXPECT_TRUE(pair_in_step(out.truth[3], ref.truth[3], {1050, 1}));
    // The repeat is the held image: no request for it.
    ASSERT_EQ(out.requests.size(), 4u);
    EXPECT_EQ(out.requests[2].scene_frame, 3u);
    EXPECT_EQ(rises(out.rec, pin_word::vsync_bit).size(),
              rises(ref.rec, pin_word::vsync_bit).size())
        << "same count in the window: one more pulse, the last one pushed out";
    // Frames 2 of each start together but show different scene frames.
    EXPECT_EQ(out.truth[2].start_cycle, ref.truth[2].start_cycle);
    EXPECT_FALSE(pair_in_step(out.truth[2], ref.truth[2], {1050, 1}));
}

TEST(SensorFaults, GlitchesInvertTheirPinForExactlyTheirWidth) {
    const uint64_t cycles = start(4);
    const auto ref = run_sensor({}, cycles);
    // VSYNC: 3 clocks from frame 1, line 10, column 5 (active part).
    const uint64_t v0 = start(1) + 10 * line + 5;
    // HREF: 5 clocks from frame 2, line 9, column 38, across the line end.
    const uint64_t h0 = start(2) + 9 * line + 38;
    // VSYNC notch inside the VSYNC pulse, by time: 2 clocks from start(3) + 10.
    const uint64_t n0 = start(3) + 10;
    const auto out = run_sensor({fault::vsync_glitch(fault_trigger::at_frame(1, 10, 5), 3),
                                 fault::href_glitch(fault_trigger::at_frame(2, 9, 38), 5),
                                 fault::vsync_glitch(fault_trigger::at_time(rise_of(n0) - 100), 2)},
                                cycles);
    EXPECT_EQ(count_violations(out.rec,
                               [&](uint64_t n) -> uint16_t {
                                   uint16_t r = ref.rec[n].pins.bits;
                                   if (n >= v0 && n < v0 + 3) r ^= pin_word::vsync_bit;
                                   if (n >= h0 && n < h0 + 5) r ^= pin_word::href_bit;
                                   if (n >= n0 && n < n0 + 2) r ^= pin_word::vsync_bit;
                                   return r;
                               }),
              0u);
    EXPECT_TRUE(out.truth[1].faults & fault_bit(fault_kind::vsync_glitch));
    EXPECT_TRUE(out.truth[2].faults & fault_bit(fault_kind::href_glitch));
    EXPECT_FALSE(pair_in_step(out.truth[2], ref.truth[2], {1050, 1}));
}

// Drift: the same words, edges on the sensor's own oscillator from the onset;
// the truth puts the pair out of step exactly when the closed form says the
// active data has slipped by one pixel clock.
TEST(SensorFaults, DriftMovesOnlyTheEdgesByTheClosedForm) {
    const uint64_t cycles = start(14);
    const auto ref = run_sensor({}, cycles);
    const uint64_t n0 = start(1);
    const auto out = run_sensor({fault::pclk_drift(fault_trigger::at_frame(1), 100)}, cycles);
    EXPECT_EQ(count_violations(out.rec, [&](uint64_t n) { return ref.rec[n].pins.bits; }), 0u);
    const simtime::ticks t0 = rise_of(n0);
    uint64_t edge_errors = 0;
    for (uint64_t n = 0; n < cycles; ++n) {
        simtime::ticks rise = rise_of(n), fall = rise_of(n) + 525;
        if (n >= n0) {
            const int64_t j = static_cast<int64_t>(n - n0);
            rise = t0 + (j * 1050 * 1000100) / 1000000;
            fall = t0 + ((2 * j + 1) * 1050 * 1000100) / 2000000;
        }
        edge_errors += out.rec[n].rise != rise || out.rec[n].fall != fall;
    }
    EXPECT_EQ(edge_errors, 0u);
    int first_out_of_step = -1;
    for (size_t k = 1; k + 1 < out.truth.size(); ++k) {
        const int64_t j = static_cast<int64_t>(out.truth[k].last_active_cycle - n0);
        const simtime::ticks slip = ((2 * j + 1) * 1050 * 1000100) / 2000000 - (2 * j + 1) * 525;
        const bool expect_in_step = slip < 1050;
        EXPECT_EQ(pair_in_step(out.truth[k], ref.truth[k], {1050, 1}), expect_in_step)
            << "frame " << k;
        if (!expect_in_step && first_out_of_step < 0) first_out_of_step = static_cast<int>(k);
    }
    std::printf(
        "+100 ppm from frame 1: pair first out of step at frame %d (1 pclk lost per 10^4 clocks)\n",
        first_out_of_step);
    EXPECT_EQ(first_out_of_step,
              9);  // frame 9's last active pixel is > 10^4 clocks after the onset
}

TEST(SensorFaults, DarkLeakChangesOnlyDarkPixels) {
    const uint64_t cycles = start(4);
    const auto ref = run_sensor({}, cycles);
    const auto out = run_sensor({fault::dark_leak(fault_trigger::at_frame(2), 200)}, cycles);
    const sensor_profile p = small_profile();
    uint64_t dark_seen = 0;
    EXPECT_EQ(count_violations(out.rec,
                               [&](uint64_t n) -> uint16_t {
                                   const uint16_t r = ref.rec[n].pins.bits;
                                   if (n < start(2) || !(r & pin_word::href_bit)) return r;
                                   const uint64_t in_frame = (n - latency) % frame;
                                   const int row =
                                       static_cast<int>(in_frame / line) - p.first_row_line;
                                   const int col = static_cast<int>(in_frame % line) - p.href_start;
                                   const bool dark = row < 1 || row >= 15 || col < 2 || col >= 20;
                                   if (!dark) return r;
                                   ++dark_seen;
                                   return static_cast<uint16_t>((r & ~pin_word::data_mask) | 200);
                               }),
              0u);
    EXPECT_EQ(dark_seen,
              2u * (2 * 22 + 14 * 4));  // 2 frames x (2 dark rows + 14 rows x 4 dark cols)
    EXPECT_TRUE(out.truth[2].faults & fault_bit(fault_kind::dark_leak));
    EXPECT_FALSE(out.truth[1].faults & fault_bit(fault_kind::dark_leak));
}

TEST(SensorFaults, StuckDataBitOnEveryDrivenWord) {
    const uint64_t cycles = start(3);
    const auto ref = run_sensor({}, cycles);
    const uint64_t on = 1500;
    const auto out =
        run_sensor({fault::stuck_data_bit(fault_trigger::at_time(rise_of(on) - 1), 3, true),
                    fault::stuck_data_bit(fault_trigger::at_frame(2), 7, false)},
                   cycles);
    EXPECT_EQ(count_violations(out.rec,
                               [&](uint64_t n) -> uint16_t {
                                   uint16_t r = ref.rec[n].pins.bits;
                                   if (!(r & pin_word::valid_bit)) return r;
                                   if (n >= on) r |= 1u << 3;
                                   if (n >= start(2)) r &= ~(1u << 7);
                                   return r;
                               }),
              0u);
}

TEST(SensorFaults, NeverStartIgnoresOeRises) {
    const uint64_t cycles = start(3);
    const auto idle = run_sensor({fault::never_start()}, cycles);
    EXPECT_EQ(count_violations(idle.rec, [](uint64_t) { return uint16_t{0}; }), 0u);
    EXPECT_TRUE(idle.truth.empty());
    // Armed while running: the sensor runs until OE falls, then never restarts.
    const auto oe = [](uint64_t n) { return n < 1800 || n >= 2000; };
    const auto ref = run_sensor({}, cycles, oe);
    const auto out = run_sensor({fault::never_start(fault_trigger::at_frame(1))}, cycles, oe);
    EXPECT_EQ(count_violations(out.rec,
                               [&](uint64_t n) -> uint16_t {
                                   return n < 1800 ? ref.rec[n].pins.bits : uint16_t{0};
                               }),
              0u);
    const auto ref_vsync = rises(ref.rec, pin_word::vsync_bit);
    EXPECT_NE(std::find(ref_vsync.begin(), ref_vsync.end(), 2000 + latency), ref_vsync.end())
        << "the reference restarts";
}

TEST(SensorFaults, IgnoreOeKeepsRunningThroughRestarts) {
    const uint64_t cycles = start(6);
    const auto oe = [](uint64_t n) { return n < 1800 || (n >= 2000 && n < 5000) || n >= 5300; };
    const auto always = run_sensor({}, cycles, oe_from(0));
    const auto out = run_sensor({fault::ignore_oe()}, cycles, oe);
    EXPECT_EQ(count_violations(out.rec, [&](uint64_t n) { return always.rec[n].pins.bits; }), 0u);
    // From frame 3 on: the first restart (1800..2000) happens, the second does not.
    const auto ref = run_sensor({}, cycles, oe);
    const auto late = run_sensor({fault::ignore_oe(fault_trigger::at_frame(3))}, cycles, oe);
    // The restart reference and the faulted one agree until the second OE fall;
    // after it the faulted sensor goes on as if OE had stayed high.
    const auto restart_only =
        run_sensor({}, cycles, [](uint64_t n) { return n < 1800 || n >= 2000; });
    EXPECT_EQ(count_violations(late.rec, [&](uint64_t n) { return restart_only.rec[n].pins.bits; }),
              0u);
    EXPECT_NE(ref.rec[5100].pins.bits, late.rec[5100].pins.bits);
}

// A fault added during the run with a trigger already passed acts from the
// next clock.
TEST(SensorFaults, FaultAddedMidRunActsFromTheNextClock) {
    const sensor_profile p = small_profile();
    pattern_source s1(p.active_cols, p.active_rows), s2(p.active_cols, p.active_rows);
    sensor_core ref(p, scene::camera_id::left, s1), out(p, scene::camera_id::left, s2);
    for (int i = 0; i < 1500; ++i) ASSERT_EQ(ref.step(true), out.step(true));
    out.add_fault(fault::stuck_data_bit(fault_trigger::at_time(0), 0, true));
    for (int i = 0; i < 1500; ++i) {
        pin_word want = ref.step(true);
        if (want.valid()) want.bits |= 1;
        ASSERT_EQ(out.step(true), want) << i;
    }
}
