#include "tb/faults/observe.h"

#include "tb/faults/fault_report.h"

#include <algorithm>
#include <cmath>

#include "model/sensor/truth.h"

namespace faults {

namespace {

constexpr simtime::ticks never = INT64_MAX;

double to_ms(simtime::ticks t) {
    return static_cast<double>(t) / (static_cast<double>(simtime::ticks_per_ns) * 1e6);
}

sensor::fault_kind sensor_kind(const fault_spec& s) {
    switch (s.type) {
        case fault_type::skew:
            return sensor::fault_kind::start_skew;
        case fault_type::drop_line:
            return sensor::fault_kind::dropped_line;
        case fault_type::drop_frame:
            return sensor::fault_kind::dropped_frame;
        case fault_type::extra_frame:
            return sensor::fault_kind::extra_frame;
        case fault_type::drift:
            return sensor::fault_kind::pclk_drift;
        case fault_type::glitch:
            return s.href ? sensor::fault_kind::href_glitch : sensor::fault_kind::vsync_glitch;
        case fault_type::dark_leak:
            return sensor::fault_kind::dark_leak;
        case fault_type::stuck_bit:
            return sensor::fault_kind::stuck_data_bit;
        case fault_type::dead:
            return sensor::fault_kind::never_start;
        default:
            return sensor::fault_kind::ignore_oe;
    }
}

// The tick a fault took effect and the frame it hit, or false if it did not
// act during the run.
bool find_onset(const platform::platform_top& top, const fault_spec& s, simtime::ticks* tick,
                int64_t* frame) {
    const simtime::ticks period = top.config().period;
    const simtime::ticks end = top.end_tick();
    const simtime::ticks trigger = trigger_tick(s, period);
    if (!is_sensor_fault(s.type)) {
        if (trigger >= end) return false;
        *tick = trigger;
        *frame = trigger / period;
        return true;
    }
    const std::vector<sensor::frame_truth>& truth = top.cycle_island().sensor(s.camera).truth();
    const uint32_t bit = sensor::fault_bit(sensor_kind(s));
    for (size_t i = 0; i < truth.size(); ++i) {
        const sensor::frame_truth& t = truth[i];
        if (!(t.faults & bit)) continue;
        if (s.when.kind == trigger_spec::by::frame && t.index < s.when.frame) continue;
        // A pixel fault by time acts from its trigger inside the frame.
        *tick = std::max(t.start_tick, trigger);
        *frame = static_cast<int64_t>(i);
        return *tick < end;
    }
    // A sensor that never (re)starts has no frame to carry the bit: it acts
    // from the first OE rise at or after the trigger.
    if (s.type == fault_type::dead && trigger >= 0) {
        for (const platform::timeline_event& e : top.events().events()) {
            if (e.kind == platform::event_kind::oe && e.a == 1 && e.tick >= trigger) {
                *tick = e.tick;
                *frame = static_cast<int64_t>(truth.size());
                return e.tick < end;
            }
        }
    }
    return false;
}

// The OE start (index into score.starts) a tick belongs to, or -1.
int start_of(const platform::scoreboard_report& score, simtime::ticks t) {
    int found = -1;
    for (size_t i = 0; i < score.starts.size(); ++i)
        if (score.starts[i].oe_rise < t) found = static_cast<int>(i);
    return found;
}

// Whether a SYNC_ERROR at `t` can be the fault's doing: its OE start was in
// step by the truth, or the start's first frame of the faulted sensor carries
// the fault and the fault moves timing (dark-leak and stuck-bit do not: an
// out-of-step start under them is the random start-up latency's), or that
// sensor did not start at all.
bool attributable(const platform::platform_top& top, const platform::scoreboard_report& score,
                  const fault_spec& s, simtime::ticks t) {
    const int i = start_of(score, t);
    if (i < 0) return true;
    const platform::start_check& c = score.starts[static_cast<size_t>(i)];
    if (c.truth_in_step) return true;
    if (s.type == fault_type::dark_leak || s.type == fault_type::stuck_bit) return false;
    const int64_t frame = c.frame[s.camera];
    if (frame < 0) return true;
    const sensor::frame_truth& ft =
        top.cycle_island().sensor(s.camera).truth()[static_cast<size_t>(frame)];
    return (ft.faults & sensor::fault_bit(sensor_kind(s))) != 0;
}

}  // namespace

run_observation observe(platform::platform_top& top, const platform::scoreboard_report& score,
                        const std::vector<fault_spec>& specs) {
    run_observation run;
    const simtime::ticks period = top.config().period;
    const double period_ticks = static_cast<double>(period);
    run.frames = top.config().frames;
    run.period_ms = to_ms(period);
    run.end_ms = to_ms(top.end_tick());
    run.firmware_started = top.firmware_started();
    const platform::island& isl = top.cycle_island();
    const std::vector<simtime::ticks>& sync_errors = isl.irq_rises(1);
    const std::vector<simtime::ticks>& overflows = isl.irq_rises(2);
    static const std::vector<platform::fw_event> no_events;
    const std::vector<platform::fw_event>& events =
        top.firmware_started() ? top.probe().fw_events() : no_events;

    run.pairs_forwarded = static_cast<int>(score.pairs.size());
    for (const platform::pair_check& p : score.pairs) run.pairs_processed += p.processed;
    run.card_sync_errors = static_cast<int>(sync_errors.size());
    run.card_overflows = static_cast<int>(overflows.size());
    run.oe_starts = static_cast<int>(score.starts.size());
    run.unsynced_pairs_used = score.used_out_of_step;
    run.misses = score.forwarded_out_of_step;
    run.used_before_verdict = score.used_before_verdict;
    for (const platform::fw_event& e : events) {
        switch (e.event.kind) {
            case dsp::firmware_event::pair_rejected:
                ++run.pairs_rejected;
                break;
            case dsp::firmware_event::pair_dropped:
                run.pairs_dropped += static_cast<int>(e.event.value);
                break;
            case dsp::firmware_event::sync_error:
                ++run.firmware_sync_errors;
                break;
            case dsp::firmware_event::card_rearmed:
                ++run.rearms;
                break;
            case dsp::firmware_event::hard_error:
                if (!run.hard_error) run.hard_error_ms = to_ms(e.tick);
                run.hard_error = true;
                break;
            default:
                break;
        }
    }

    simtime::ticks first_onset = never;
    for (size_t i = 0; i < specs.size(); ++i) {
        const fault_spec& s = specs[i];
        fault_observation f;
        f.spec = canonical(s);
        f.type = s.type;
        simtime::ticks onset = 0;
        int64_t frame = -1;
        f.in_effect = find_onset(top, s, &onset, &frame);
        if (!f.in_effect) {
            run.faults.push_back(f);
            continue;
        }
        first_onset = std::min(first_onset, onset);
        f.onset_ms = to_ms(onset);
        f.onset_frame = frame;
        top.mark_fault(onset, static_cast<uint8_t>(i), static_cast<uint32_t>(s.type),
                       static_cast<uint32_t>(std::max<int64_t>(frame, 0)));

        // Detection.
        simtime::ticks detect = never;
        if (is_sensor_fault(s.type)) {
            for (simtime::ticks t : sync_errors) {
                if (t < onset) continue;
                if (!attributable(top, score, s, t)) {
                    ++f.masked_checks;
                    continue;
                }
                detect = t;
                f.detected_by = "sync_error";
                break;
            }
        } else if (s.type == fault_type::emif_wait) {
            for (simtime::ticks t : overflows)
                if (t >= onset) {
                    detect = t;
                    f.detected_by = "overflow";
                    break;
                }
        } else {
            for (const platform::fw_event& e : events)
                if (e.event.kind == dsp::firmware_event::pair_dropped && e.tick >= onset) {
                    detect = e.tick;
                    f.detected_by = "pair_dropped";
                    break;
                }
        }
        if (detect != never) {
            f.detected = true;
            f.detect_ms = to_ms(detect);
            f.frames_to_detect = static_cast<int>((detect - onset) / period);
            for (const platform::fw_event& e : events)
                if (e.event.kind == dsp::firmware_event::sync_error && e.tick >= detect) {
                    f.causes = e.event.value & 0xFFu;
                    break;
                }
        }

        // Recovery: the first in-step pair the card forwards after the
        // detection (whether the firmware finishes it before the run ends is
        // pairs_used's business).
        simtime::ticks recover = never;
        for (const platform::pair_check& p : score.pairs) {
            if (detect != never && p.truth_in_step && p.ready > detect) {
                recover = p.ready;
                break;
            }
        }
        if (recover != never) {
            f.recovered = true;
            f.recover_ms = to_ms(recover);
            f.frames_to_recover = static_cast<int>(
                std::floor(static_cast<double>(recover - detect) / period_ticks + 0.5));
        }
        for (const platform::start_check& c : score.starts) {
            if (c.oe_rise > onset) ++f.oe_starts_after;
            if (detect != never && c.oe_rise > detect &&
                c.oe_rise < std::min(recover, top.end_tick()) &&
                c.card != platform::card_verdict::frame_ready)
                ++f.failed_starts;
        }
        for (simtime::ticks t : sync_errors) f.pairs_discarded += t >= onset;
        for (simtime::ticks t : overflows) f.pairs_discarded += t >= onset;
        for (const platform::pair_check& p : score.pairs) {
            if (!p.processed || p.ready <= onset) continue;
            ++f.pairs_used;
            if (p.truth_in_step) continue;
            ++f.unsynced_pairs_used;
            bool repeated = false;
            for (int cam = 0; cam < 2; ++cam) {
                if (p.frame[cam] < 0) continue;
                repeated |= isl.sensor(cam).truth()[static_cast<size_t>(p.frame[cam])].repeated;
            }
            f.stale_pairs_used += repeated;
        }
        for (const platform::fw_event& e : events)
            if (e.event.kind == dsp::firmware_event::pair_dropped && e.tick >= onset)
                f.pairs_dropped += static_cast<int>(e.event.value);
        run.faults.push_back(f);
    }

    // False alarms: a SYNC_ERROR for an in-step start before any fault acted.
    for (simtime::ticks t : sync_errors) {
        if (t >= first_onset) continue;
        ++run.sync_errors_before_onset;
        const int s = start_of(score, t);
        if (s >= 0 && score.starts[static_cast<size_t>(s)].truth_in_step) ++run.false_alarms;
    }
    return run;
}

// Declared in tb/faults/fault_report.h; here so that only this file needs SystemC.
fault_run_result evaluate(platform::platform_top& top, const platform::scoreboard_report& score,
                          const std::vector<fault_spec>& specs) {
    fault_run_result r;
    r.specs = specs;
    r.params = params_for(top.config());
    r.weaken = dsp::firmware_weakening_name(top.config().weaken);
    r.run = observe(top, score, specs);
    if (specs.empty()) r.verdicts.push_back(check_clean(r.run));
    for (size_t i = 0; i < specs.size(); ++i)
        r.verdicts.push_back(check(r.run.faults[i], specs[i], r.params, r.run));
    return r;
}

}  // namespace faults
