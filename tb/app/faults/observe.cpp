#include "tb/app/faults/observe.h"

#include "tb/app/faults/fault_report.h"
#include "tb/app/faults/pair_accounting.h"
#include "tb/app/faults/recovery_rule.h"
#include "tb/app/faults/report_protocol.h"
#include "tb/platform/firmware_report.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "dsp/card_regs.h"
#include "model/sensor/truth.h"

namespace faults {

namespace {

constexpr simtime::ticks never = INT64_MAX;
// Every VERDICT field but FRAME is a cause.
constexpr uint32_t verdict_causes_mask =
    dsp::card_regs::verdict_fields_mask & ~dsp::card_regs::verdict_frame_mask;

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

// The line of frame t a dropped-line fault took: the first readout line at
// or after its trigger (the sensor drops no blanking line: a trigger past
// the last readout row takes the next frame's first).
int64_t dropped_line(const sensor::sensor_profile& p, const fault_spec& s,
                     const sensor::frame_truth& t, simtime::ticks trigger) {
    const int64_t first = p.first_row_line, end = first + p.readout_rows();
    if (s.when.kind == trigger_spec::by::frame)
        return t.index == s.when.frame && s.line < end ? std::max<int64_t>(s.line, first) : first;
    const simtime::ticks line_ticks = p.line_pclks * p.mclk_period.num / p.mclk_period.den;
    if (trigger <= t.start_tick || line_ticks <= 0) return first;
    const int64_t line = (trigger - t.start_tick + line_ticks - 1) / line_ticks;
    return std::clamp(line, first, end - 1);
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
    // A dead sensor runs on until the next OE rise, which it ignores: that
    // rise is when it acts, whatever frames carry its bit meanwhile.
    for (size_t i = 0; s.type != fault_type::dead && i < truth.size(); ++i) {
        const sensor::frame_truth& t = truth[i];
        if (!(t.faults & bit)) continue;
        if (s.when.kind == trigger_spec::by::frame && t.index < s.when.frame) continue;
        // Where it first acts on the sensor's pins: a skew's idle clocks come
        // before its frame, a dropped line is the readout line's missing
        // HREF, a pixel fault by time acts from its trigger inside the frame.
        *tick = std::max(t.start_tick, trigger);
        const sensor::sensor_profile& p = top.config().profile;
        const simtime::rational_ticks pclk = p.mclk_period;
        if (s.type == fault_type::skew) *tick -= t.skew_before_pclks * pclk.num / pclk.den;
        if (s.type == fault_type::drop_line)
            *tick = t.start_tick + (dropped_line(p, s, t, trigger) * p.line_pclks + p.href_start) *
                                       pclk.num / pclk.den;
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

// Whether the faulted sensor's first frame after OE start `c` carries the
// fault (the sensors' truth); false if that sensor did not start.
bool first_frame_carries(const platform::platform_top& top, const platform::start_check& c,
                         const fault_spec& s) {
    const int64_t frame = c.frame[s.camera];
    if (frame < 0) return false;
    const sensor::frame_truth& ft =
        top.cycle_island().sensor(s.camera).truth()[static_cast<size_t>(frame)];
    return (ft.faults & sensor::fault_bit(sensor_kind(s))) != 0;
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
    return c.frame[s.camera] < 0 || first_frame_carries(top, c, s);
}

// The pair numbers a pair_dropped report names ([pair - count, pair)),
// clipped to the pairs the card forwarded: a firmware that garbles the
// report must not make the testbench enumerate billions of numbers.
std::vector<uint32_t> dropped_by(const stereosim_event& e, size_t forwarded) {
    std::vector<uint32_t> out;
    const uint64_t end = std::min<uint64_t>(e.pair, forwarded + 1);
    const uint64_t begin = e.value < e.pair ? e.pair - e.value : 1;
    for (uint64_t n = std::max<uint64_t>(begin, 1); n < end; ++n)
        out.push_back(static_cast<uint32_t>(n));
    return out;
}

// Whether a SYNC_ERROR at `t` in start `start` is explained by fault `s`
// (onset `onset`): a persistent fault explains every one after its onset, a
// one-frame timing fault those of the start it hit (until the restart).
bool explains(const platform::platform_top& top, const platform::scoreboard_report& score,
              const fault_spec& s, simtime::ticks onset, simtime::ticks t) {
    if (t < onset || !is_sensor_fault(s.type)) return false;
    switch (s.type) {
        case fault_type::drift:
        case fault_type::dark_leak:
        case fault_type::stuck_bit:
        case fault_type::dead:
        case fault_type::oe_stuck:
            return true;
        default:
            break;
    }
    const int start = start_of(score, t);
    if (start == start_of(score, onset)) return true;
    return start >= 0 && first_frame_carries(top, score.starts[static_cast<size_t>(start)], s);
}

// Card interrupt pulses with no firmware report of `kind` within `window`
// ticks after them, counted up to `until` (the give-up, or a window before
// the end). Pulses that the CPU saw as one latched flag share a report.
int unreported(const std::vector<simtime::ticks>& pulses,
               const std::vector<platform::fw_event>& events, uint32_t kind, simtime::ticks window,
               simtime::ticks until) {
    int missing = 0;
    for (simtime::ticks t : pulses) {
        if (t > until) break;
        bool found = false;
        for (const platform::fw_event& e : events)
            if (e.event.kind == kind && e.tick >= t && e.tick <= t + window) found = true;
        missing += !found;
    }
    return missing;
}

// The slowest CPU of the run: a cpu-slow fault's factor, else 1.
double slow_factor(const std::vector<fault_spec>& specs) {
    double factor = 1.0;
    for (const fault_spec& s : specs)
        if (s.type == fault_type::cpu_slow) factor = std::max(factor, s.factor);
    return factor;
}

// The pair numbers the firmware's pair_dropped reports name.
std::set<uint32_t> reported_dropped(const platform::scoreboard_report& score,
                                    const std::vector<platform::fw_event>& events) {
    std::set<uint32_t> dropped;
    for (const platform::fw_event& e : events)
        if (e.event.kind == STEREOSIM_EV_PAIR_DROPPED)
            for (uint32_t n : dropped_by(e.event, score.pairs.size())) dropped.insert(n);
    return dropped;
}

// Firmware time per pair (pair_captured -> pair_processed): the cheapest
// before `onset`, the dearest taken after it.
void pair_times(const std::vector<platform::fw_event>& events, simtime::ticks onset,
                fault_observation* f) {
    for (const platform::fw_event& done : events) {
        if (done.event.kind != STEREOSIM_EV_PAIR_PROCESSED) continue;
        for (const platform::fw_event& taken : events) {
            if (taken.event.kind != STEREOSIM_EV_PAIR_CAPTURED ||
                taken.event.pair != done.event.pair || taken.tick > done.tick)
                continue;
            const double ms = to_ms(done.tick - taken.tick);
            if (done.tick < onset) {
                f->pair_ms_min = f->pair_ms_min < 0 ? ms : std::min(f->pair_ms_min, ms);
            } else if (taken.tick >= onset) {
                f->slowed_ms_max = std::max(f->slowed_ms_max, ms);
                ++f->slowed_pairs;
            }
        }
    }
}

// The firmware's own report of a detection: the first report of a kind that
// names this fault's effect at or after it.
void find_report(const fault_spec& s, const std::vector<platform::fw_event>& events,
                 simtime::ticks detect, fault_observation* f) {
    for (const platform::fw_event& e : events) {
        if (e.tick < detect) continue;
        const uint32_t k = e.event.kind;
        const uint32_t names_effect = is_sensor_fault(s.type)           ? STEREOSIM_EV_SYNC_ERROR
                                      : s.type == fault_type::emif_wait ? STEREOSIM_EV_OVERFLOW
                                                                        : STEREOSIM_EV_PAIR_DROPPED;
        const bool names_it = k == STEREOSIM_EV_HARD_ERROR || k == names_effect;
        if (!names_it) continue;
        f->reported = true;
        f->reported_by = platform::report_name(k);
        f->report_ms = to_ms(e.tick);
        return;
    }
}

}  // namespace

namespace {

// What one run recorded, in one place for the pieces below.
struct run_sources {
    platform::platform_top& top;
    const platform::scoreboard_report& score;
    const std::vector<simtime::ticks>& sync_errors;  // the card's SYNC_ERROR rises
    const std::vector<simtime::ticks>& overflows;    // OVERFLOW rises
    const std::vector<platform::fw_event>& events;   // the firmware's reports
    simtime::ticks period;
};

void count_run(const run_sources& in, run_observation* run) {
    run->pairs_forwarded = static_cast<int>(in.score.pairs.size());
    for (const platform::pair_check& p : in.score.pairs) run->pairs_processed += p.processed;
    run->card_sync_errors = static_cast<int>(in.sync_errors.size());
    run->card_overflows = static_cast<int>(in.overflows.size());
    run->oe_starts = static_cast<int>(in.score.starts.size());
    run->unsynced_pairs_used = in.score.used_out_of_step;
    run->misses = in.score.forwarded_out_of_step;
    run->used_before_verdict = in.score.used_before_verdict;
    run->boxes_scored = in.score.summary.box_scored_frames;
    run->points_scored = in.score.summary.point_scored_frames;
    run->max_box_err_px = in.score.summary.max_box_centre_err_px;
    run->max_depth_err_pct = in.score.summary.max_abs_depth_err_pct;
    for (const platform::fw_event& e : in.events) {
        switch (e.event.kind) {
            case STEREOSIM_EV_PAIR_REJECTED:
                ++run->pairs_rejected;
                break;
            case STEREOSIM_EV_PAIR_DROPPED:
                run->pairs_dropped +=
                    static_cast<int>(dropped_by(e.event, in.score.pairs.size()).size());
                break;
            case STEREOSIM_EV_SYNC_ERROR:
                ++run->firmware_sync_errors;
                break;
            case STEREOSIM_EV_CARD_REARMED:
                ++run->rearms;
                break;
            case STEREOSIM_EV_HARD_ERROR:
                if (!run->hard_error) run->hard_error_ms = to_ms(e.tick);
                run->hard_error = true;
                break;
            default:
                break;
        }
    }
}

// Detection: the first SYNC_ERROR the fault can explain (sensor faults),
// OVERFLOW (emif-wait) or pair_dropped report (cpu-slow) at or after the
// onset; `never` if none.
simtime::ticks detect_fault(const run_sources& in, const fault_spec& s, simtime::ticks onset,
                            fault_observation* f) {
    if (is_sensor_fault(s.type)) {
        for (simtime::ticks t : in.sync_errors) {
            // A verdict issued before the fault could reach a checked pixel.
            if (t < onset + reaction_window) continue;
            if (!attributable(in.top, in.score, s, t)) {
                ++f->masked_checks;
                continue;
            }
            f->detected_by = "sync_error";
            const int start = start_of(in.score, t);
            f->detect_start_in_step =
                start >= 0 && in.score.starts[static_cast<size_t>(start)].truth_in_step;
            return t;
        }
    } else if (s.type == fault_type::emif_wait) {
        for (simtime::ticks t : in.overflows)
            if (t >= onset) {
                f->detected_by = "overflow";
                return t;
            }
    } else {
        for (const platform::fw_event& e : in.events)
            if (e.event.kind == STEREOSIM_EV_PAIR_DROPPED && e.tick >= onset) {
                f->detected_by = "pair_dropped";
                return e.tick;
            }
    }
    return never;
}

// Recovery: the first in-step pair the card forwards after the detection
// (rule 5 checks that the firmware uses it), and the restarts until then.
void observe_recovery(const run_sources& in, simtime::ticks onset, simtime::ticks detect,
                      fault_observation* f) {
    simtime::ticks recover = never;
    for (const platform::pair_check& p : in.score.pairs) {
        if (detect != never && p.truth_in_step && p.ready > detect) {
            recover = p.ready;
            break;
        }
    }
    if (recover != never) {
        for (const platform::pair_check& p : in.score.pairs)
            if (p.processed && p.ready >= recover) {
                f->resumed_ms = to_ms(p.result_tick);
                break;
            }
        f->recovered = true;
        f->recover_ms = to_ms(recover);
        f->frames_to_recover = static_cast<int>(std::floor(
            static_cast<double>(recover - detect) / static_cast<double>(in.period) + 0.5));
    }
    for (const platform::start_check& c : in.score.starts) {
        if (c.oe_rise > onset) ++f->oe_starts_after;
        if (detect != never && c.oe_rise > detect &&
            c.oe_rise < std::min(recover, in.top.end_tick()) &&
            c.card != platform::card_verdict::frame_ready)
            ++f->failed_starts;
    }
}

// Pairs discarded, used (out of step, stale) and dropped from the onset on.
void observe_pairs(const run_sources& in, simtime::ticks onset, fault_observation* f) {
    for (simtime::ticks t : in.sync_errors) f->pairs_discarded += t >= onset;
    for (simtime::ticks t : in.overflows) f->pairs_discarded += t >= onset;
    const platform::island& isl = in.top.cycle_island();
    for (const platform::pair_check& p : in.score.pairs) {
        if (!p.processed || p.ready <= onset) continue;
        ++f->pairs_used;
        if (p.truth_in_step) continue;
        ++f->unsynced_pairs_used;
        bool repeated = false;
        for (int cam = 0; cam < 2; ++cam) {
            if (p.frame[cam] < 0) continue;
            repeated |= isl.sensor(cam).truth()[static_cast<size_t>(p.frame[cam])].repeated;
        }
        f->stale_pairs_used += repeated;
    }
    for (const platform::fw_event& e : in.events)
        if (e.event.kind == STEREOSIM_EV_PAIR_DROPPED && e.tick >= onset) {
            for (uint32_t n : dropped_by(e.event, in.score.pairs.size()))
                f->dropped_pairs.push_back(n);
            f->pairs_dropped = static_cast<int>(f->dropped_pairs.size());
        }
}

// One fault; `*onset` = its onset tick, `never` if it did not act.
fault_observation observe_fault(const run_sources& in, const fault_spec& s, size_t index,
                                simtime::ticks* onset, simtime::ticks* detect_tick) {
    fault_observation f;
    f.spec = canonical(s);
    f.type = s.type;
    int64_t frame = -1;
    *onset = never;
    f.in_effect = find_onset(in.top, s, onset, &frame);
    if (!f.in_effect) {
        *onset = never;
        return f;
    }
    f.onset_ms = to_ms(*onset);
    f.onset_frame = frame;
    f.frame_id_check = !in.top.firmware_started() || (in.top.probe().card_checks_at(*onset) &
                                                      dsp::card_regs::checks_frame_id_mask);
    in.top.mark_fault(*onset, static_cast<uint8_t>(index), static_cast<uint32_t>(s.type),
                      static_cast<uint32_t>(std::max<int64_t>(frame, 0)));
    const simtime::ticks detect = detect_fault(in, s, *onset, &f);
    *detect_tick = detect;
    if (detect != never) {
        f.detected = true;
        f.detect_ms = to_ms(detect);
        f.frames_to_detect = static_cast<int>((detect - *onset) / in.period);
        for (const platform::fw_event& e : in.events)
            if (e.event.kind == STEREOSIM_EV_SYNC_ERROR && e.tick >= detect) {
                f.causes = e.event.value & verdict_causes_mask;
                break;
            }
        find_report(s, in.events, detect, &f);
    }
    // A dead sensor acts at the OE rise it ignores: its start is that rise's.
    const int onset_start = start_of(in.score, s.type == fault_type::dead ? *onset + 1 : *onset);
    f.onset_start_out_of_step =
        onset_start >= 0 && !in.score.starts[static_cast<size_t>(onset_start)].truth_in_step;
    // A frame whose start met a restart already decided (the card lowered OE
    // on a verdict about an earlier frame) is never checked.
    if (is_sensor_fault(s.type)) {
        for (const platform::timeline_event& e : in.top.events().events()) {
            if (e.kind != platform::event_kind::oe || e.a != 0 || e.tick < *onset) continue;
            f.onset_frame_cut = e.tick <= *onset + reaction_window;
            break;
        }
    }
    f.onset_phases = onset_phases(in.top, s, *onset, f.onset_frame_cut);
    pair_times(in.events, *onset, &f);
    observe_recovery(in, *onset, detect, &f);
    observe_pairs(in, *onset, &f);
    return f;
}

// Rule 8 with several faults: the SYNC_ERROR that detects one may be the
// verdict on another's frame (a skewed R frame checked just as L's dropped
// frame was due), so its causes may name that other fault's sensor.
void note_other_explanations(const run_sources& in, const std::vector<fault_spec>& specs,
                             const std::vector<simtime::ticks>& onsets,
                             const std::vector<simtime::ticks>& detects, run_observation* run) {
    for (size_t i = 0; i < specs.size(); ++i) {
        if (detects[i] == never || run->faults[i].detected_by != "sync_error") continue;
        for (size_t j = 0; j < specs.size(); ++j) {
            if (j == i || onsets[j] == never || !is_sensor_fault(specs[j].type)) continue;
            if (explains(in.top, in.score, specs[j], onsets[j], detects[i]))
                run->faults[i].also_explained_by |= 1u << specs[j].camera;
        }
    }
}

// Rule 10: overflow reports the firmware's configured re-arm (ENABLE 0 -> 1:
// OE low, then high again on the card's pins) did not follow within
// rearm_window_ms. Only reports before the give-up (`stop`) and a window
// before the end are judged. The card restarts OE by itself only after a
// failed sync check, at a frame end; the re-arm is a few register accesses.
int unrearmed_overflows(const run_sources& in, simtime::ticks stop) {
    const auto window = static_cast<simtime::ticks>(rearm_window_ms * 1e6 * simtime::ticks_per_ns);
    int missing = 0;
    for (const platform::fw_event& e : in.events) {
        if (e.event.kind != STEREOSIM_EV_OVERFLOW) continue;
        if (e.tick >= stop || e.tick + window > in.top.end_tick()) continue;
        bool restarted = false;
        for (const platform::start_check& c : in.score.starts)
            restarted |= c.oe_rise > e.tick && c.oe_rise <= e.tick + window;
        missing += !restarted;
    }
    return missing;
}

// The rules over the whole run (docs/fault-contract.md 3, 5, 6, 7, 10).
void observe_run_rules(const run_sources& in, const std::vector<fault_spec>& specs,
                       const std::vector<simtime::ticks>& onsets, run_observation* run) {
    const simtime::ticks first_onset = *std::min_element(onsets.begin(), onsets.end());
    // False alarms, over the whole run: a SYNC_ERROR for a start in step by
    // the truth that no fault in effect explains.
    for (simtime::ticks t : in.sync_errors) {
        run->sync_errors_before_onset += t < first_onset;
        const int s = start_of(in.score, t);
        if (s < 0 || !in.score.starts[static_cast<size_t>(s)].truth_in_step) continue;
        bool explained = false;
        for (size_t i = 0; i < specs.size(); ++i)
            explained |= onsets[i] != never && explains(in.top, in.score, specs[i], onsets[i], t);
        run->false_alarms += !explained;
    }
    // The firmware keeps working and reports what the card flags: a window
    // of (1 + CPU slow-down) periods covers a pair in processing.
    const auto window =
        static_cast<simtime::ticks>((1.0 + slow_factor(specs)) * static_cast<double>(in.period));
    simtime::ticks stop = in.top.end_tick();
    for (const platform::fw_event& e : in.events)
        if (e.event.kind == STEREOSIM_EV_HARD_ERROR) stop = std::min(stop, e.tick);
    const simtime::ticks until = std::min(stop, in.top.end_tick() - window);
    std::vector<forwarded_pair> forwarded;
    for (const platform::pair_check& p : in.score.pairs)
        forwarded.push_back({p.pair, p.ready, p.truth_in_step, p.processed});
    std::vector<simtime::ticks> oe_rises;
    for (const platform::start_check& c : in.score.starts) oe_rises.push_back(c.oe_rise);
    const pair_accounting pairs =
        account_pairs(forwarded, reported_dropped(in.score, in.events), oe_rises, 2 * window, stop);
    run->pairs_in_step = pairs.in_step;
    run->pairs_unaccounted = pairs.unaccounted;
    run->unaccounted_pairs = pairs.unaccounted_pairs;
    if (run->hard_error) {
        simtime::ticks last_good = -1;
        for (simtime::ticks t : in.top.cycle_island().irq_rises(0))
            if (t < stop) last_good = t;
        for (simtime::ticks t : in.sync_errors)
            run->failed_checks_before_give_up += t > last_good && t <= stop;
    }
    run->unreported_sync_errors =
        unreported(in.sync_errors, in.events, STEREOSIM_EV_SYNC_ERROR, window, until);
    run->unreported_overflows =
        unreported(in.overflows, in.events, STEREOSIM_EV_OVERFLOW, window, until);
    const protocol_inputs protocol = gather_protocol_inputs(in.top, in.events, window, until);
    run->unreported_in_step = in_step_unreported(protocol);
    for (const missing_report& m : find_missing_reports(protocol))
        run->missing_reports.push_back(violation_text(m));
    if (in.top.firmware_policy().rearm_on_overflow != 0)
        run->unrearmed_overflows = unrearmed_overflows(in, stop);
    for (const platform::used_pair& u : in.top.used_pairs()) {
        if (!u.checked) continue;
        ++run->identity_checked;
        if (u.matches) continue;
        ++run->identity_mismatches;
        if (run->mismatched_pairs.size() < 8) run->mismatched_pairs.push_back(u.pair);
    }
}

}  // namespace

run_observation observe(platform::platform_top& top, const platform::scoreboard_report& score,
                        const std::vector<fault_spec>& specs) {
    run_observation run;
    const simtime::ticks period = top.config().period;
    run.frames = top.config().frames;
    run.truth_available = !(top.replay() && !top.replay()->has_truth());
    // The mode as the firmware's policy states it.
    const bool created = top.firmware_started() && !top.firmware_init_failed();
    run.mode = !created ? "none" : top.firmware_policy().overlapped ? "overlapped" : "sequential";
    run.dsk_version = top.config().dsk.version;
    run.period_ms = to_ms(period);
    run.end_ms = to_ms(top.end_tick());
    run.firmware_started = top.firmware_started();
    const platform::island& isl = top.cycle_island();
    static const std::vector<platform::fw_event> no_events;
    const run_sources in{top,
                         score,
                         isl.irq_rises(1),
                         isl.irq_rises(2),
                         top.firmware_started() ? top.probe().fw_events() : no_events,
                         period};
    count_run(in, &run);
    std::vector<simtime::ticks> onsets(specs.size(), never), detects(specs.size(), never);
    for (size_t i = 0; i < specs.size(); ++i)
        run.faults.push_back(observe_fault(in, specs[i], i, &onsets[i], &detects[i]));
    note_other_explanations(in, specs, onsets, detects, &run);
    run.recovery = judge_recovery(gather_recovery_inputs(top, specs, onsets));
    onsets.push_back(never);  // a clean run: no onset
    observe_run_rules(in, specs, onsets, &run);
    return run;
}

// Declared in tb/app/faults/fault_report.h; here so that only this file needs SystemC.
fault_run_result evaluate(platform::platform_top& top, const platform::scoreboard_report& score,
                          const std::vector<fault_spec>& specs, bool paper_card) {
    fault_run_result r;
    r.specs = specs;
    r.params = params_for(top.config(), top.firmware_policy(), top.engine().cectl(3));
    r.params.paper_card = paper_card;
    r.run = observe(top, score, specs);
    note_expected_give_ups(specs, r.params, &r.run);
    if (specs.empty()) r.verdicts.push_back(check_clean(r.run));
    for (size_t i = 0; i < specs.size(); ++i)
        r.verdicts.push_back(check(r.run.faults[i], specs[i], r.params, r.run));
    return r;
}

}  // namespace faults
