// The default scenario on the whole platform (issue 5; docs/platform.md):
// VGA, DSK v1, the default rig and 5 cm ball (three still frames, then the
// throw), overlapped mode, seed 3, 12 sync periods. One simulation for the
// whole executable; each test reads one aspect of it. The firmware's own
// SDRAM traffic is on the EMIF bus (the default): with the memory plan of
// dsp/controller.h (the raw pair read once, 4,800 lines) the scenario fits.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "model/c6416/c6416_regs.h"
#include "tests/system/system_run.h"

namespace {

using system_test::system_run;

system_run& run() {
    static system_run r = system_test::simulate([] {
        platform::platform_config config;
        return config;
    }());
    return r;
}

// Sync: the seed's first OE start is out of step, the card sees it and
// restarts OE; the sensors are in step within the first 5 frames; every
// verdict agrees with the sensors' timing truth; a pair is used only after
// the verdict covering its last line; the raw frames land in DSP memory
// exactly as the sensors drove them.
TEST(default_scenario, restart_then_in_step_pairs_used_after_their_verdict_reach_memory_intact) {
    system_run& r = run();
    const platform::scoreboard_report& s = r.score;

    ASSERT_GE(s.starts.size(), 2u);
    EXPECT_GE(s.oe_restarts, 1);
    EXPECT_FALSE(s.starts[0].truth_in_step) << "seed 3: the first start must be out of step";
    EXPECT_EQ(s.starts[0].card, platform::card_verdict::sync_error);
    int with_verdict = 0;
    for (const platform::start_check& c : s.starts) {
        if (c.card == platform::card_verdict::none) continue;
        ++with_verdict;
        EXPECT_TRUE(c.agree()) << "OE start at " << system_test::ticks_to_ms(c.oe_rise) << " ms";
    }
    EXPECT_EQ(s.starts_agreeing, with_verdict);

    // The firmware saw the same: one sync_error report per SYNC_ERROR pulse,
    // and its in_step report names the first pair the card forwarded.
    EXPECT_GE(s.card_sync_errors, 1);
    EXPECT_EQ(s.firmware_sync_errors, s.card_sync_errors);
    EXPECT_EQ(s.firmware_in_step_pair, 1);

    ASSERT_GE(s.first_in_step_frame, 0);
    EXPECT_LE(s.first_in_step_frame, 4) << "in step within the first 5 frames";
    EXPECT_LE(s.first_in_step_ready, 5 * platform::period_24_5_ms);

    EXPECT_EQ(s.forwarded_out_of_step, 0);
    int processed = 0;
    for (const platform::pair_check& p : s.pairs) {
        if (!p.processed) continue;
        ++processed;
        EXPECT_TRUE(p.truth_in_step) << "pair " << p.pair;
        EXPECT_GT(p.ready, p.last_active) << "pair " << p.pair << ": verdict before its last pixel";
        EXPECT_GT(p.result_tick, p.ready) << "pair " << p.pair << ": used before its verdict";
    }
    EXPECT_GE(processed, 8);
    EXPECT_EQ(s.used_before_verdict, 0);
    EXPECT_EQ(s.used_out_of_step, 0);

    ASSERT_GE(r.top->captured().size(), 8u);
    for (const platform::captured_pair& c : r.top->captured()) {
        EXPECT_EQ(c.verdict & 0xFFu, 0u) << "pair " << c.pair << " captured with a cause";
        for (int cam = 0; cam < 2; ++cam) {
            ASSERT_TRUE(c.sensor_checksum_known[cam]) << "pair " << c.pair;
            EXPECT_EQ(c.memory_checksum[cam], c.sensor_checksum[cam])
                << "pair " << c.pair << " cam " << cam;
            EXPECT_EQ(c.differing_pixels[cam], 0u) << "pair " << c.pair << " cam " << cam;
        }
    }
    EXPECT_EQ(s.integrity_equal, s.integrity_checked);
    std::printf(
        "restarts %d, first in-step sensor frame %lld at %.3f ms, %d/%d starts agree, %d pairs "
        "processed, %d/%d captured pairs intact\n",
        s.oe_restarts, static_cast<long long>(s.first_in_step_frame),
        system_test::ticks_to_ms(s.first_in_step_ready), s.starts_agreeing, with_verdict, processed,
        s.integrity_equal, s.integrity_checked);
}

// The firmware's track against the scene: detected within 3 frames of the
// ball's first motion (and not before it); after that the box centre within
// 3 px of the ball's image centre in >= 95 % of the pairs; depth within 2 %
// of the visible-surface depth at 1-3 m.
TEST(default_scenario, ball_detected_within_3_frames_then_tracked_in_3d) {
    const platform::scoreboard_report& s = run().score;
    ASSERT_GE(s.first_motion_frame, 1);
    ASSERT_GE(s.detection_frame, 0) << "never detected";
    EXPECT_GT(s.detection_frame, s.first_motion_frame);
    EXPECT_LE(s.detection_frame - s.first_motion_frame, 3);
    for (const platform::pair_check& p : s.pairs) {
        if (p.processed && static_cast<int>(p.scene_frame) < s.first_motion_frame) {
            EXPECT_FALSE(p.record.out.detected)
                << "detection in still scene frame " << p.scene_frame;
        }
    }
    ASSERT_GE(s.frames_after_detection, 4);
    EXPECT_GE(s.box_within_3px, std::ceil(0.95 * s.frames_after_detection));
    ASSERT_GE(s.depth_scored_1_3m, 4);
    EXPECT_EQ(s.depth_within_2pct, s.depth_scored_1_3m);
    std::printf(
        "motion at scene frame %d, detected at %d; %d/%d boxes within 3 px (max %.2f px); %d/%d "
        "depths within 2 %% (max %.2f %%); RMSE X %.1f Y %.1f Z %.1f mm\n",
        s.first_motion_frame, s.detection_frame, s.box_within_3px, s.frames_after_detection,
        s.max_box_err_px, s.depth_within_2pct, s.depth_scored_1_3m, s.max_depth_err_pct,
        s.summary.rmse_x_mm, s.summary.rmse_y_mm, s.summary.rmse_z_mm);
}

// Timing against the closed forms of docs/budget.md: each pair's capture
// time (FRAME_READY to its last EDMA burst) within 2 % of the figure from
// the EMIF timing; the verdict of each pair after its last active pixel by
// the sensor readout's figure; the overlapped mode within budget, as the
// closed-form estimate (capture + the host harness's processing time) says.
TEST(default_scenario, capture_and_budget_agree_with_the_closed_forms) {
    system_run& r = run();
    const platform::capture_figures cf = system_test::closed_form_capture(*r.top);
    // docs/budget.md: 160 words x 14 ECLK + TA 2 + SDRAM (7 + 80) + TA 2 per line;
    // 300 lines cross a 2 KB SDRAM row (one more row access each; the frames
    // start 64 bytes past a row, after the pair buffer's header).
    EXPECT_EQ(cf.line_eclk, 2331u);
    EXPECT_EQ(cf.header_eclk, 82u);
    EXPECT_EQ(cf.row_crossings, 300u);
    EXPECT_NEAR(cf.total_ms(), 22.556, 0.001);
    // The same chain with the frames at the start of a row: of the 149 row
    // boundaries inside each 300 KB frame, the 29 at a multiple of 5 rows
    // (10 KB = 16 lines) fall between two lines; 120 per frame.
    const platform::capture_figures aligned =
        platform::capture(640, 480, c6416::emifa::dsk_cectl_card_v1, r.top->engine().config(),
                          {0x80000000u, 0x80000000u + 640u * 480u});
    EXPECT_EQ(aligned.row_crossings, 240u);
    EXPECT_EQ(cf.pair_eclk - aligned.pair_eclk, 60u * r.top->engine().config().sdram.access_cycles);

    // The firmware's SDRAM lines (the raw pair, 4,800 x 128 B) share the bus:
    // a capture takes at least the closed form alone (no line inside it, as
    // pair 1) and at most that plus every line of the previous pair inside
    // its card bursts (27 ECLK each); within 2 % of that range.
    const platform::traffic_figures tf = platform::firmware_traffic(
        640, 480, c6416::emifa::dsk_cectl_card_v1, r.top->engine().config());
    EXPECT_EQ(tf.lines, 4800u);
    EXPECT_EQ(tf.line_eclk, 27u);
    int judged = 0;
    for (const platform::pair_budget& p : r.budget.pairs) {
        if (!p.judged || p.capture_ms <= 0.0) continue;
        ++judged;
        EXPECT_GE(p.capture_ms, 0.98 * cf.total_ms()) << "pair " << p.pair;
        EXPECT_LE(p.capture_ms, 1.02 * (cf.total_ms() + tf.ms())) << "pair " << p.pair;
    }
    EXPECT_GE(judged, 6);
    EXPECT_NEAR(r.budget.max_capture_ms, cf.total_ms() + tf.ms(), 0.02 * (cf.total_ms() + tf.ms()));

    // FRAME_READY comes after the frame's last clock: from the last active
    // pixel (driven at its falling edge) to the frame's end is F - last - 1/2
    // pixel clocks (readout figures of the profile); the card samples a clock
    // one pixel clock after it is driven and publishes the verdict within
    // 4 pclk + 12 eclk (docs/card.md).
    const platform::readout_figures rf = platform::readout(r.top->config().profile);
    const double to_frame_end_ms = (rf.frame_pclks - rf.last_active_pclk - 0.5) * rf.pclk_ns * 1e-6;
    const double verdict_bound_ms = (5 * rf.pclk_ns + 12 * cf.eclk_ns) * 1e-6;
    for (const platform::pair_check& p : r.score.pairs) {
        const double gap = system_test::ticks_to_ms(p.ready - p.last_active);
        EXPECT_GE(gap, to_frame_end_ms) << "pair " << p.pair;
        EXPECT_LE(gap, to_frame_end_ms + verdict_bound_ms) << "pair " << p.pair;
        if (&p == &r.score.pairs.front())
            std::printf(
                "last active pixel to FRAME_READY %.6f ms (frame end %.6f + card %.6f ms)\n", gap,
                to_frame_end_ms, gap - to_frame_end_ms);
    }

    const double processing_ms = system_test::host_max_processing_ms(r.top->config(), 12);
    const platform::mode_estimate ovl =
        platform::estimate_overlapped(cf.total_ms(), tf.ms(), processing_ms, r.budget.period_ms);
    const platform::mode_estimate seq =
        platform::estimate_sequential(cf.total_ms(), tf.ms(), processing_ms, r.budget.period_ms);
    EXPECT_TRUE(ovl.fits);
    EXPECT_FALSE(seq.fits);
    EXPECT_EQ(r.budget.fits, ovl.fits);
    EXPECT_TRUE(r.budget.overruns.empty());
    EXPECT_GE(r.budget.judged_periods, 8);
    EXPECT_LT(r.budget.max_cpu_busy_ms, r.budget.period_ms);
    EXPECT_LT(r.budget.max_emif_busy_ms, r.budget.period_ms);
    EXPECT_EQ(r.budget.drops, 0);
    EXPECT_EQ(r.budget.overflows, 0);
    // The platform's own largest pair against the host harness's: the same
    // firmware on nearly the same images (exposure times differ a little).
    EXPECT_NEAR(r.budget.max_processing_ms, processing_ms, 0.1 * processing_ms);
    std::printf(
        "capture closed form %.3f ms, measured mean %.3f max %.3f ms; processing host %.3f "
        "platform %.3f ms; sequential needs %.3f ms, overlapped %.3f ms of %.1f; CPU busy max "
        "%.3f, EMIF busy max %.3f ms; FIFO peak L %u R %u words; latency max %.3f ms\n",
        cf.total_ms(), r.budget.mean_capture_ms, r.budget.max_capture_ms, processing_ms,
        r.budget.max_processing_ms, seq.need_ms, ovl.need_ms, r.budget.period_ms,
        r.budget.max_cpu_busy_ms, r.budget.max_emif_busy_ms, r.budget.fifo_peak_words[0],
        r.budget.fifo_peak_words[1], r.budget.latency_ms_max);
}

// Golden per-stage cycle totals (cost model c64x-op-model-v1) of this run:
// any change to the firmware, the cost model, the scene or the sensors that
// moves the timing results shows here. Update them only for a change that is
// meant to move them, and say so.
TEST(default_scenario, golden_stage_cycles_and_one_timeline) {
    system_run& r = run();
    ASSERT_STREQ(dsp::cost::default_model().id(), "c64x-op-model-v1");
    // Issue 5's memory plan (docs/firmware.md) moved preprocess (raw read
    // once from SDRAM, gray and brightness in L2: 9 x 2,596,950 + one
    // 139,206-cycle packed difference for the history's second frame; was
    // 51,625,350 with the frames in SDRAM), detect (the packed three-frame
    // pass in L2; was 6,484,670) and track (+ the packed difference per
    // tracked pair, the refit in L2; was 2,051,687). The stereo stages, xyz
    // and capture did not move: the same boxes.
    // Issue 17 (objects of any size) moved detect (+ the raw mask's block
    // statistics, cost::motion_blocks_cycles: 3,266,270 before), track (the
    // refit's box from the block groups of both differences instead of
    // projections of their AND: was 2,560,409) and, through the boxes they give, stereo_sad
    // (223,599) and stereo_edge (1,837,562).
    // Issue 35 (the box follows the silhouette, dsp/box_refit.h) moved detect
    // (+ Dif(t-1,t)'s block groups around the detection and a second
    // pattern copy: 3,541,119 before), track (the differences read before
    // the search, over a region grown by the search radius: 2,794,614) and
    // stereo_sad (the boxes it gives, and a 2 px
    // core trim below 16 px: 253,356).
    // The strided detection (dsp/stride_history.h) moved detect: pair 3
    // finds nothing and keeps its frame, one packed-three-frame-sized pass
    // (+182,646: 3,559,731 before); its left image is then made after the
    // detection in pair 4, the same preprocess cycles.
    // The stereo core a seventh of each side, not an eighth (its corners off
    // the background, dsp/controller_stereo.cpp object_core) moved stereo_sad: a
    // smaller core to match (260,877 before).
    // A fast object's box fitted to its last pairs' extents
    // (dsp/extent_window.h: the ball's shaded rim missed by the differences)
    // moved track (the fit's cycles on each axis fitted, cost::
    // window_fit_profile, and the boxes: 2,849,186 before) and, through the
    // boxes, stereo_sad (208,884) and stereo_edge (1,856,560).
    // The motion read from the extent window each tracked pair (cost::
    // window_step_profile, both axes; the 50 mm ball is under 32 px, so the
    // fit is not brought by it) moved track alone: the same boxes
    // (2,887,604 before).
    // The sizes carried with the depth (dsp/size_at_depth.h: at most 4 + 2
    // window extents' software divides charged each tracked pair with a
    // disparity, cost::size_at_depth_profile) moved track alone: the same
    // boxes (2,888,942 before).
    // A fading leading rim read on each axis of a slower object
    // (dsp/extent_window.h, fading_rim_step2: charged as the window's step,
    // cost::window_step_profile) moved track alone: the boxes and depths
    // reported did not move, nor stereo_sad and stereo_edge, which follow
    // the boxes (2,889,736 before).
    // The last detections' boxes kept and their edges' steps compared on
    // each DETECT pair with a detection (dsp/detection_steps.h, cost::
    // detection_steps_profile) moved detect alone: track, stereo_sad and
    // stereo_edge, which follow the boxes, did not move (3,742,377 before).
    // The reach past the box's sides read from the stereo pair on each
    // tracked pair (dsp/stereo_reach.h: its tiles' SAD searches, charged
    // as such) moved stereo_sad alone: the default ball's box was widened
    // on no pair, so stereo_edge and xyz, which follow it, did not move
    // (214,116 before). The same read past its top and bottom
    // (reach_past_ends) moved stereo_sad alone, for the same reason
    // (265,426 before).
    // TRACK's box brought back to a sphere's shape on each tracked pair
    // (dsp/round_box.h, cost::round_box_profile: 308 cycles, two square
    // roots by bits and two divisions) moved track alone, by 5 x 308: the
    // default ball's box was not changed (2,890,276 before).
    // A detection's box that may be a part of its object reads both
    // differences over the whole frame, and its common part is tested for a
    // sphere's shape (dsp/controller_track.cpp, measure_motion and
    // grow_part; is_round charged as round_box_profile, 308 cycles):
    // track alone moved, by 659,247 cycles, 308 of them is_round on one
    // pair; the boxes, and so the other stages and the timeline, did not
    // (2,891,816 before).
    // The stereo reach judged against a sphere's shape on each outlined pair
    // (dsp/controller_stereo.cpp, widen_to_stereo_reach; drawn_out twice,
    // each charged as round_box_profile, 308 cycles) moved stereo_sad
    // alone, by 5 x 2 x 308: no reach of the default ball was refused, so
    // its boxes did not change (309,106 before).
    // A round core for an object of 24-59 px (dsp/object_core.h: the
    // ellipse in the box less a tenth a side, charged as a search of its
    // whole box, larger than the square core's of a seventh) moved
    // stereo_sad alone: the default ball's boxes, and so track, stereo_edge
    // and the timeline, did not change (312,186 before). Its rows, an
    // ellipse's half width each (surface_outline_profile), charged too:
    // 397,155 (368,757 without).
    // The extent window's velocity changing from pair to pair (second
    // differences and their median, two more terms per extent and velocity
    // in window_fit_profile) moved track alone, by 554 cycles: the default
    // ball's boxes did not change (3,551,063 before).
    // The track's depth gated against its line (177 cycles on each of the
    // 6 pairs with a point) moved xyz alone to 2,946, no disparity
    // replaced; the gate was then removed, the measured depth reported
    // (docs/firmware.md, "The measured depth"): xyz back to 1,884.
    // The core's sub-pixel step at half pixels (two more passes over the
    // core, cost::half_pel_profile; docs/firmware.md, "A sub-pixel step at
    // half pixels") moved stereo_sad alone, 397,155 -> 403,431: the boxes,
    // and so track, stereo_edge and the timeline, did not change.
    // The silhouette's box held at the extent's end (cost::extent_end_profile
    // on each followed pair; docs/firmware.md, "A box held at the extent's
    // end") moved track alone, 3,551,617 -> 3,551,727: the default ball's
    // boxes did not change.
    // A size's depth kept while the object goes away (cost::size_depth_profile
    // on each pair with a difference; docs/firmware.md, "A size's depth kept
    // while the object goes away") moved track alone, 3,551,727 -> 3,551,817:
    // the default ball's boxes did not change.
    // A wrong match's depth reported at the line of the track's last three
    // (cost::depth_line_profile on each pair with a disparity, a 64-bit
    // divide; docs/firmware.md, "A depth no motion reaches") moved xyz
    // alone, 1,884 -> 2,622: no disparity of the default ball replaced.
    // That line kept on the triangulated depth instead of a divide of its
    // own (a replaced depth's disparity and point computed again, the only
    // divides it adds) moved xyz alone, 2,622 -> 2,010.
    constexpr uint64_t golden[dsp::stage_count] = {
        6000,      // capture: 10 pairs x 600
        23511756,  // preprocess
        3742479,   // detect
        3551817,   // track
        403431,    // stereo_sad
        1867416,   // stereo_edge
        2010,      // xyz
    };
    for (int s = 0; s < dsp::stage_count; ++s) {
        EXPECT_EQ(r.budget.stage_cycles_total[s], golden[s])
            << dsp::stage_name(static_cast<dsp::stage>(s));
        std::printf("golden %-11s %10llu cycles\n", dsp::stage_name(static_cast<dsp::stage>(s)),
                    static_cast<unsigned long long>(r.budget.stage_cycles_total[s]));
    }

    // Pins and firmware on one timeline, in time order.
    const platform::timeline& t = r.top->events();
    EXPECT_TRUE(t.in_time_order());
    EXPECT_GE(t.count(platform::event_kind::oe), 3u);  // rise, restart fall, rise
    EXPECT_GE(t.count(platform::event_kind::irq), 2 * r.score.pairs.size());
    // Every stage begun ends, but the one running when the run stops.
    EXPECT_LE(t.count(platform::event_kind::stage_begin) - t.count(platform::event_kind::stage_end),
              1u);
    EXPECT_GE(t.count(platform::event_kind::stage_begin), 8u * 2);
    EXPECT_GE(t.count(platform::event_kind::result), 8u);
    EXPECT_GE(t.count(platform::event_kind::sensor_frame), 2u * 10);
    EXPECT_GT(r.top->cycle_island().stats().pin_changes, 1000000u);
    std::printf("timeline %zu events (hash %016llx), pin hash %016llx over %llu changes\n",
                t.events().size(), static_cast<unsigned long long>(t.hash()),
                static_cast<unsigned long long>(r.top->cycle_island().pin_hash()),
                static_cast<unsigned long long>(r.top->cycle_island().stats().pin_changes));
}

}  // namespace
