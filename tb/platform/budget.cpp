#include "tb/platform/budget.h"

#include <algorithm>
#include <cstdio>

namespace platform {

const char* resource_name(resource r) {
    switch (r) {
        case resource::cpu:
            return "cpu";
        case resource::emif:
            return "emif";
        case resource::fifo:
            return "fifo";
        case resource::pair_buffers:
            return "pair_buffers";
    }
    return "?";
}

std::string overrun::describe() const {
    char text[200];
    if (what == resource::pair_buffers) {
        std::snprintf(
            text, sizeof text,
            "pair_buffers over budget in period %d: pair %u was dropped (ready while stage "
            "%s ran, no pair buffer free)",
            period, pair, stage_name.c_str());
    } else if (what == resource::fifo) {
        std::snprintf(text, sizeof text,
                      "fifo over budget in period %d: a card FIFO overflowed (stage %s)", period,
                      stage_name.c_str());
    } else if (period >= 0 && value_ms >= limit_ms) {
        // Busy the whole period: the work runs on into the next one.
        std::snprintf(text, sizeof text,
                      "%s over budget in period %d (stage %s): busy the whole %.3f ms period, "
                      "its work carried into the next",
                      resource_name(what), period, stage_name.c_str(), limit_ms);
    } else if (period >= 0) {
        std::snprintf(text, sizeof text,
                      "%s over budget in period %d (stage %s): %.3f ms of the %.3f ms budget",
                      resource_name(what), period, stage_name.c_str(), value_ms, limit_ms);
    } else {
        std::snprintf(text, sizeof text, "%s over budget for pair %u (stage %s): %.3f ms > %.3f ms",
                      resource_name(what), pair, stage_name.c_str(), value_ms, limit_ms);
    }
    return text;
}

const overrun* budget_report::first(resource r) const {
    for (const overrun& o : overruns)
        if (o.what == r) return &o;
    return nullptr;
}

namespace {

double ticks_to_ms(simtime::ticks t) {
    return static_cast<double>(t) / (static_cast<double>(simtime::ticks_per_ns) * 1e6);
}

simtime::ticks overlap(simtime::ticks a0, simtime::ticks a1, simtime::ticks b0, simtime::ticks b1) {
    const simtime::ticks lo = std::max(a0, b0), hi = std::min(a1, b1);
    return hi > lo ? hi - lo : 0;
}

// The stage the CPU was in at tick t: the charge covering it, else the last
// one before it.
int stage_at(const std::vector<charge_record>& charges, simtime::ticks t) {
    int s = 0;
    for (const charge_record& c : charges) {
        if (c.begin > t) break;
        s = c.stage;
        if (c.end > t) break;
    }
    return s;
}

int largest(const double* ms) {
    int best = 0;
    for (int i = 1; i < max_stages; ++i)
        if (ms[i] > ms[best]) best = i;
    return best;
}

// A period or a pair saturates a resource when it is busy all of it (to
// a nanosecond of rounding).
constexpr double saturated_slack_ms = 1e-6;

// What every measure of the run reads.
struct run_view {
    const platform_config& config;
    const island& isl;
    const probe_hal& probe;
    simtime::ticks steady_from;  // the first in-step FRAME_READY: judging starts there
    simtime::ticks run_end;
    double eclk_ns;
    double cpu_hz;
    double cycles_ms(uint64_t cycles) const { return 1e3 * static_cast<double>(cycles) / cpu_hz; }
};

period_budget measure_period(const run_view& run, size_t k, const period_sample& sample) {
    period_budget p;
    const simtime::ticks period = run.config.period;
    p.index = static_cast<int>(k);
    p.begin = period * static_cast<simtime::ticks>(k);
    p.end = p.begin + period;
    p.judged = run.steady_from >= 0 && p.begin >= run.steady_from && p.end <= run.run_end;
    simtime::ticks asleep = 0;
    for (const tick_interval& s : run.probe.sleeps())
        asleep += overlap(s.begin, s.end, p.begin, p.end);
    if (run.probe.asleep_since() >= 0)
        asleep += overlap(run.probe.asleep_since(), run.run_end, p.begin, p.end);
    p.cpu_busy_ms = ticks_to_ms(period - asleep);
    p.emif_busy_ms = 1e-6 * run.eclk_ns * static_cast<double>(sample.emif_busy_edges);
    p.cpu_words = sample.cpu_words;
    for (int c = 0; c < 2; ++c) p.fifo_peak_words[c] = sample.fifo_peak_words[c];
    p.overflow = sample.fifo_overflow[0] || sample.fifo_overflow[1];
    for (const charge_record& c : run.probe.charges())
        p.stage_ms[c.stage] += ticks_to_ms(overlap(c.begin, c.end, p.begin, p.end));
    return p;
}

// Drops, by the period their FRAME_READY came in.
void count_drops(const run_view& run, budget_report& b) {
    const std::vector<simtime::ticks>& ready = run.isl.irq_rises(0);
    for (const fw_event& e : run.probe.fw_events()) {
        if (e.event.kind != STEREOSIM_EV_PAIR_DROPPED) continue;
        for (uint32_t n = e.event.pair - e.event.value; n < e.event.pair; ++n) {
            if (n == 0 || n > ready.size()) continue;
            const simtime::ticks t = ready[n - 1];
            const size_t k = static_cast<size_t>(t / run.config.period);
            ++b.drops;
            if (k >= b.periods.size()) continue;
            ++b.periods[k].drops;
            if (b.periods[k].judged) {
                overrun o;
                o.what = resource::pair_buffers;
                o.stage = stage_at(run.probe.charges(), t);
                o.period = static_cast<int>(k);
                o.pair = n;
                b.overruns.push_back(o);
            }
        }
    }
}

// Peaks over every period; overruns of the judged ones (CPU, bus, FIFO).
void judge_periods(budget_report& b) {
    for (period_budget& p : b.periods) {
        for (int c = 0; c < 2; ++c)
            b.fifo_peak_words[c] = std::max(b.fifo_peak_words[c], p.fifo_peak_words[c]);
        b.overflows += p.overflow;
        if (!p.judged) continue;
        ++b.judged_periods;
        b.max_cpu_busy_ms = std::max(b.max_cpu_busy_ms, p.cpu_busy_ms);
        b.max_emif_busy_ms = std::max(b.max_emif_busy_ms, p.emif_busy_ms);
        if (p.cpu_busy_ms >= b.period_ms - saturated_slack_ms) {
            overrun o;
            o.what = resource::cpu;
            o.stage = largest(p.stage_ms);
            o.period = p.index;
            o.value_ms = p.cpu_busy_ms;
            o.limit_ms = b.period_ms;
            b.overruns.push_back(o);
        }
        if (p.emif_busy_ms >= b.period_ms - saturated_slack_ms) {
            overrun o;
            o.what = resource::emif;
            o.period = p.index;
            o.value_ms = p.emif_busy_ms;
            o.limit_ms = b.period_ms;
            b.overruns.push_back(o);
        }
        if (p.overflow) {
            overrun o;
            o.what = resource::fifo;
            o.period = p.index;
            b.overruns.push_back(o);
        }
    }
}

// One forwarded pair: its capture (FRAME_READY to the EDMA chain's last
// burst) and, if processed, its stages. *chain_done: the capture ended in the run.
pair_budget measure_pair(const run_view& run, const pair_check& pc, bool* chain_done) {
    pair_budget pb;
    const std::vector<simtime::ticks>& ready = run.isl.irq_rises(0);
    pb.pair = pc.pair;
    pb.judged = run.steady_from >= 0 && pc.ready >= run.steady_from;
    const simtime::ticks next = pc.pair < ready.size() ? ready[pc.pair] : run.run_end;
    simtime::ticks last = -1;
    for (simtime::ticks t : run.isl.edma_completions())
        if (t > pc.ready && t <= next) last = t;
    *chain_done = last >= 0;
    // The run's last pair: its chain may still be running at the end.
    if (pc.pair >= ready.size()) *chain_done = *chain_done && pc.processed;
    if (*chain_done) pb.capture_ms = ticks_to_ms(last - pc.ready);
    if (pc.processed) {
        pb.processed = true;
        const stereosim_result& out = pc.record.out;
        for (int s = 0; s < max_stages; ++s) pb.stage_ms[s] = run.cycles_ms(out.stage_cycles[s]);
        for (int s = 0; s < max_stages; ++s) pb.processing_ms += pb.stage_ms[s];
        pb.latency_ms = pc.latency_ms;
    }
    return pb;
}

// Sums for the means over the judged captures and the processed pairs.
struct pair_sums {
    int captures = 0;
    double capture_ms = 0.0;
    int processed = 0;
    double stage_ms[max_stages] = {};
};

// A pair's maxima, means and overruns (capture longer than a period,
// processing longer than a period).
void judge_pair(budget_report& b, const pair_budget& pb, bool chain_done, pair_sums& sums) {
    if (pb.processed) {
        ++sums.processed;
        for (int s = 0; s < max_stages; ++s) {
            sums.stage_ms[s] += pb.stage_ms[s];
            b.stage_ms_max[s] = std::max(b.stage_ms_max[s], pb.stage_ms[s]);
        }
        b.max_processing_ms = std::max(b.max_processing_ms, pb.processing_ms);
        b.latency_ms_max = std::max(b.latency_ms_max, pb.latency_ms);
    }
    if (pb.judged && chain_done) {
        ++sums.captures;
        sums.capture_ms += pb.capture_ms;
        b.max_capture_ms = std::max(b.max_capture_ms, pb.capture_ms);
        if (pb.capture_ms > b.period_ms) {
            overrun o;
            o.what = resource::emif;
            o.pair = pb.pair;
            o.value_ms = pb.capture_ms;
            o.limit_ms = b.period_ms;
            b.overruns.push_back(o);
        }
    }
    if (pb.judged && pb.processed && pb.processing_ms > b.period_ms) {
        overrun o;
        o.what = resource::cpu;
        o.stage = largest(pb.stage_ms);
        o.pair = pb.pair;
        o.value_ms = pb.processing_ms;
        o.limit_ms = b.period_ms;
        b.overruns.push_back(o);
    }
}

}  // namespace

budget_report check_budget(const platform_top& top, const scoreboard_report& score) {
    budget_report b;
    const platform_config& config = top.config();
    const simtime::tick_clock& eclk = top.engine().config().eclk;
    const run_view run{config,
                       top.cycle_island(),
                       top.probe(),
                       score.first_in_step_ready,
                       top.end_tick(),
                       static_cast<double>(eclk.period_num()) /
                           static_cast<double>(eclk.period_den()) / simtime::ticks_per_ns,
                       static_cast<double>(config.dsk.cpu_hz)};
    b.period_ms = ticks_to_ms(config.period);
    b.cpu_hz = run.cpu_hz;
    const stereosim_fw_descriptor& firmware = top.firmware_descriptor();
    b.stage_names.assign(firmware.stage_names, firmware.stage_names + firmware.stage_count);

    const std::vector<period_sample>& samples = run.isl.periods();
    for (size_t k = 0; k < samples.size(); ++k)
        b.periods.push_back(measure_period(run, k, samples[k]));
    count_drops(run, b);
    judge_periods(b);

    pair_sums sums;
    for (const pair_check& pc : score.pairs) {
        bool chain_done = false;
        const pair_budget pb = measure_pair(run, pc, &chain_done);
        judge_pair(b, pb, chain_done, sums);
        b.pairs.push_back(pb);
    }
    if (sums.captures > 0) b.mean_capture_ms = sums.capture_ms / sums.captures;
    const uint32_t optional = top.firmware_policy().optional_stages;
    for (uint32_t s = 0; s < firmware.stage_count; ++s) {
        if (sums.processed > 0) b.stage_ms_mean[s] = sums.stage_ms[s] / sums.processed;
        b.stage_cycles_total[s] = run.probe.stage_cycles(static_cast<int>(s));
        if (b.stage_cycles_total[s] == 0 && (optional >> s & 1u) == 0)
            b.stages_not_run.push_back(static_cast<int>(s));
    }
    for (overrun& o : b.overruns) o.stage_name = b.stage_names[static_cast<size_t>(o.stage)];
    b.fits = b.judged_periods > 0 && b.overruns.empty();
    return b;
}

}  // namespace platform
