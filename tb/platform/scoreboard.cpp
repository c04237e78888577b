#include "tb/platform/scoreboard.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "model/sensor/truth.h"

namespace platform {

const char* card_verdict_name(card_verdict v) {
    switch (v) {
        case card_verdict::none:
            return "none";
        case card_verdict::frame_ready:
            return "frame_ready";
        case card_verdict::sync_error:
            return "sync_error";
    }
    return "?";
}

namespace {

constexpr simtime::ticks never = INT64_MAX;

double ticks_to_ms(simtime::ticks t) {
    return static_cast<double>(t) / (static_cast<double>(simtime::ticks_per_ns) * 1e6);
}

// First frame of the sensor that started in (from, to), or -1.
int64_t first_frame_between(const std::vector<sensor::frame_truth>& truth, simtime::ticks from,
                            simtime::ticks to) {
    for (size_t i = 0; i < truth.size(); ++i) {
        if (truth[i].start_tick > from && truth[i].start_tick < to) return static_cast<int64_t>(i);
    }
    return -1;
}

// docs/design-brief.md's rule (sensor::pair_in_step), with "show the same scene frame"
// read as "were rendered at the same scene time": each sensor numbers its own
// scene frames, and after an OE restart the two numberings can differ by the
// frames one sensor began and the other did not (docs/platform.md).
bool in_step(const sensor::frame_truth& l, const sensor::frame_truth& r,
             simtime::rational_ticks pclk, const recording_source& source) {
    sensor::frame_truth right = r;
    const double tl = source.scene_time_s(0, l.scene_frame);
    const double tr = source.scene_time_s(1, r.scene_frame);
    if (tl >= 0.0 && tl == tr) right.scene_frame = l.scene_frame;
    return sensor::pair_in_step(l, right, pclk);
}

simtime::ticks first_rise_between(const std::vector<simtime::ticks>& rises, simtime::ticks from,
                                  simtime::ticks to) {
    for (simtime::ticks t : rises)
        if (t > from && t < to) return t;
    return never;
}

// The firmware's output for a pair with the scene's truth at its frame.
platform::frame_record record_of(const platform_top& top, uint64_t scene_frame,
                                 const stereosim_result& out) {
    const scene::scenario& scenario = top.config().scenario;
    platform::frame_record record;
    record.index = static_cast<int>(scene_frame);
    record.time_s = top.source().scene_time_s(1, scene_frame);
    record.out = out;
    scene::replay_object_truth replayed;
    if (top.replay()) {
        // A replay's truth is its CSV's alone: the scenario's rendered ball is
        // not what the sensors saw.
        if (top.replay()->object_truth(static_cast<int>(scene_frame), &replayed)) {
            record.has_truth = true;
            record.truth_has_point = replayed.has_point;
            record.truth = replayed.ball;
        }
    } else if (!scenario.scene.balls.empty() && record.time_s >= 0.0) {
        record.has_truth = true;
        record.truth = scene::ball_truth_at(scenario.scene.rig, scenario.scene.balls[0],
                                            record.time_s, scenario.scene.background.depth_m);
    }
    return record;
}

// Per OE start: timing truth against the card's first verdict.
void check_starts(const platform_top& top, scoreboard_report& r) {
    const island& isl = top.cycle_island();
    const std::vector<sensor::frame_truth>* truth[2] = {&isl.sensor(0).truth(),
                                                        &isl.sensor(1).truth()};
    const simtime::rational_ticks pclk = top.config().profile.pclk_period();
    std::vector<simtime::ticks> oe_rises;
    for (const timeline_event& e : top.events().events())
        if (e.kind == event_kind::oe && e.a == 1) oe_rises.push_back(e.tick);
    r.oe_restarts = oe_rises.empty() ? 0 : static_cast<int>(oe_rises.size()) - 1;
    for (size_t s = 0; s < oe_rises.size(); ++s) {
        start_check c;
        c.oe_rise = oe_rises[s];
        const simtime::ticks next = s + 1 < oe_rises.size() ? oe_rises[s + 1] : never;
        for (int cam = 0; cam < 2; ++cam)
            c.frame[cam] = first_frame_between(*truth[cam], c.oe_rise, next);
        c.truth_in_step = c.frame[0] >= 0 && c.frame[1] >= 0 &&
                          in_step((*truth[0])[static_cast<size_t>(c.frame[0])],
                                  (*truth[1])[static_cast<size_t>(c.frame[1])], pclk, top.source());
        const simtime::ticks ready = first_rise_between(isl.irq_rises(0), c.oe_rise, next);
        const simtime::ticks error = first_rise_between(isl.irq_rises(1), c.oe_rise, next);
        if (ready != never || error != never) {
            c.card = ready < error ? card_verdict::frame_ready : card_verdict::sync_error;
            c.verdict_tick = std::min(ready, error);
        }
        r.starts_agreeing += c.agree();
        r.starts.push_back(c);
    }
}

// Per forwarded pair (FRAME_READY n is pair n), joined by pair number with
// the captures, the rejections and the results; returns the scored records.
std::vector<platform::frame_record> check_pairs(const platform_top& top, scoreboard_report& r) {
    const island& isl = top.cycle_island();
    const std::vector<sensor::frame_truth>* truth[2] = {&isl.sensor(0).truth(),
                                                        &isl.sensor(1).truth()};
    const simtime::rational_ticks pclk = top.config().profile.pclk_period();
    const std::vector<simtime::ticks>& ready = isl.irq_rises(0);
    // The pairs the EDMA moved, the firmware rejected and processed, by the
    // pair number each carries.
    std::set<uint32_t> captured, rejected;
    for (const captured_pair& c : top.captured()) captured.insert(c.pair);
    for (const fw_event& e : top.probe().fw_events()) {
        if (e.event.kind == STEREOSIM_EV_PAIR_REJECTED) rejected.insert(e.event.pair);
    }
    std::multimap<uint32_t, const fw_result*> results_by_pair;
    for (const fw_result& res : top.probe().results()) results_by_pair.emplace(res.pair, &res);
    std::vector<platform::frame_record> records;
    for (size_t n = 0; n < ready.size(); ++n) {
        pair_check p;
        p.pair = static_cast<uint32_t>(n + 1);
        p.ready = ready[n];
        for (int cam = 0; cam < 2; ++cam) p.frame[cam] = top.frame_before(cam, p.ready);
        if (p.frame[0] >= 0 && p.frame[1] >= 0) {
            const sensor::frame_truth& l = (*truth[0])[static_cast<size_t>(p.frame[0])];
            const sensor::frame_truth& rt = (*truth[1])[static_cast<size_t>(p.frame[1])];
            p.truth_in_step = in_step(l, rt, pclk, top.source());
            p.scene_frame = rt.scene_frame;
            p.first_active = std::min(l.first_active_tick, rt.first_active_tick);
            p.last_active = std::max(l.last_active_tick, rt.last_active_tick);
        }
        if (!p.truth_in_step) ++r.forwarded_out_of_step;
        if (r.first_in_step_ready < 0) {
            r.first_in_step_ready = p.ready;
            r.first_in_step_frame = p.frame[0];
        }
        p.captured = captured.count(p.pair) != 0;
        p.rejected = rejected.count(p.pair) != 0;
        const auto results = results_by_pair.equal_range(p.pair);
        for (auto it = results.first; it != results.second; ++it) {
            const fw_result& res = *it->second;
            p.processed = true;
            p.result_tick = res.tick;
            p.used_after_verdict = res.tick > p.ready && p.ready > p.last_active;
            p.latency_ms = ticks_to_ms(res.tick - p.first_active);
            p.record = record_of(top, p.scene_frame, res.out);
            p.errors = platform::score_frame(p.record);
            records.push_back(p.record);
        }
        if (p.processed) {
            r.used_before_verdict += !p.used_after_verdict;
            r.used_out_of_step += !p.truth_in_step;
            if (r.latency_ms_min == 0.0 || p.latency_ms < r.latency_ms_min)
                r.latency_ms_min = p.latency_ms;
            r.latency_ms_max = std::max(r.latency_ms_max, p.latency_ms);
        }
        r.pairs.push_back(p);
    }
    return records;
}

// The firmware's own verdicts and the card's, counted.
void count_verdicts(const platform_top& top, scoreboard_report& r) {
    const island& isl = top.cycle_island();
    r.card_sync_errors = static_cast<int>(isl.irq_rises(1).size());
    for (const fw_event& e : top.probe().fw_events()) {
        if (e.event.kind == STEREOSIM_EV_SYNC_ERROR) ++r.firmware_sync_errors;
        if (e.event.kind == STEREOSIM_EV_IN_STEP && r.firmware_in_step_pair < 0)
            r.firmware_in_step_pair = e.event.pair;
    }
}

// Data path integrity: each captured pair's memory against the sensors' pins.
void check_integrity(const platform_top& top, scoreboard_report& r) {
    for (const captured_pair& c : top.captured()) {
        ++r.integrity_checked;
        bool equal = true;
        for (int cam = 0; cam < 2; ++cam)
            equal &=
                c.sensor_checksum_known[cam] && c.sensor_checksum[cam] == c.memory_checksum[cam];
        r.integrity_equal += equal;
    }
}

// A replay's first frame whose object truth (point, else pixel) differs from
// the frame before's, or -1.
int first_moving_replay_frame(const scene::replay& replay) {
    scene::replay_object_truth before, now;
    for (int k = 1; k < replay.frame_count(); ++k) {
        if (!replay.object_truth(k - 1, &before) || !replay.object_truth(k, &now)) continue;
        const scene::vec3 a = before.ball.centre_m, b = now.ball.centre_m;
        const scene::vec2 p = before.ball.right.ellipse_centre, q = now.ball.right.ellipse_centre;
        if (a.x != b.x || a.y != b.y || a.z != b.z || p.x != q.x || p.y != q.y) return k;
    }
    return -1;
}

// The first scene frame whose ball centre moved (scene truth, or a replay's
// truth CSV), or -1.
int first_moving_scene_frame(const platform_top& top) {
    if (top.replay()) return first_moving_replay_frame(*top.replay());
    const scene::scenario& scenario = top.config().scenario;
    if (scenario.scene.balls.empty()) return -1;
    const scene::ball_desc& ball = scenario.scene.balls[0];
    // A frame the right sensor never rendered (it dropped it) is the left
    // one's; one neither rendered is skipped, not the end.
    const auto time_of = [&top](uint64_t k) {
        const double right = top.source().scene_time_s(1, k);
        return right >= 0.0 ? right : top.source().scene_time_s(0, k);
    };
    const uint64_t last = static_cast<uint64_t>(top.config().frames) + 2;
    for (uint64_t k = 1; k <= last; ++k) {
        const double t0 = time_of(k - 1), t1 = time_of(k);
        if (t0 < 0.0 || t1 < 0.0) continue;
        const scene::vec3 a = scene::ball_truth_at(scenario.scene.rig, ball, t0).centre_m;
        const scene::vec3 b = scene::ball_truth_at(scenario.scene.rig, ball, t1).centre_m;
        if (a.x != b.x || a.y != b.y || a.z != b.z) return static_cast<int>(k);
    }
    return -1;
}

// Tracking and 3D after the first detection: box and depth accuracy.
void score_tracking(scoreboard_report& r) {
    for (const pair_check& p : r.pairs) {
        if (!p.processed) continue;
        if (r.detection_frame < 0) {
            if (p.record.out.detected) r.detection_frame = static_cast<int>(p.scene_frame);
            continue;
        }
        ++r.frames_after_detection;
        if (p.errors.box_scored && p.errors.box_centre_err_px <= 3.0) ++r.box_within_3px;
        if (p.errors.box_scored)
            r.max_box_err_px = std::max(r.max_box_err_px, p.errors.box_centre_err_px);
        const double visible_m = p.errors.visible_z_mm / 1000.0;
        if (p.errors.point_scored && visible_m >= 1.0 && visible_m <= 3.0) {
            ++r.depth_scored_1_3m;
            const double pct = std::fabs(p.errors.depth_err_pct);
            r.depth_within_2pct += pct <= 2.0;
            r.max_depth_err_pct = std::max(r.max_depth_err_pct, pct);
        }
    }
}

}  // namespace

scoreboard_report score(const platform_top& top) {
    scoreboard_report r;
    check_starts(top, r);
    const std::vector<platform::frame_record> records = check_pairs(top, r);
    count_verdicts(top, r);
    check_integrity(top, r);
    r.first_motion_frame = first_moving_scene_frame(top);
    score_tracking(r);
    r.summary = platform::summarize(records, r.first_motion_frame);
    return r;
}

}  // namespace platform
