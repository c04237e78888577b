#include "tb/app/sweep/sweep_point.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "dsp/kernel_costs.h"
#include "tb/platform/closed_form.h"
#include "tb/platform/host/stereo_runner.h"
#include "tb/platform/platform_config.h"

namespace sweep {

namespace {

using json = nlohmann::json;

double round6(double v) {
    return std::round(v * 1e6) / 1e6;
}

// The setup with every key that cannot change the firmware's charged cycles
// per pair at its defaults: the host run of one such setup serves them all.
// The clocks stay: the kernels' SDRAM stalls depend on the CPU / EMIF ratio.
std::string processing_key(const cli::run_setup& s) {
    cli::run_setup p = s;
    const cli::run_setup defaults;
    p.cpu_mhz = s.effective_cpu_mhz();
    p.eclk_mhz = s.effective_eclk_mhz();
    p.dsk_version = defaults.dsk_version;
    p.card_setup = defaults.card_setup;
    p.card_strobe = defaults.card_strobe;
    p.card_hold = defaults.card_hold;
    p.mode = defaults.mode;
    p.sdram_traffic_on_bus = defaults.sdram_traffic_on_bus;
    p.watchdog_ms = defaults.watchdog_ms;
    p.card_start_timeout = defaults.card_start_timeout;
    p.quantum_ns = defaults.quantum_ns;
    p.hash_pins = defaults.hash_pins;
    return cli::config_json(p).dump();
}

// The firmware on the host over the rendered frames the run processes (no
// sensors, no card, no bus): the largest pair's charged cycles, capture's
// included. A run of F periods processes the pairs of scene frames 1 ..
// F - 3 (the first pair is taken in the second period; the last two are
// still in capture and processing when the run ends); frame 0 goes first
// here as the firmware's history.
double host_max_pair_cycles(const platform::platform_config& config) {
    // The platform's cost model for this configuration (clocks, compiled-C
    // factor), as the co-simulation prices the kernels.
    host::stereo_runner runner(config.scenario, platform::pipeline_config(config),
                               platform::cost_model_of(config));
    uint64_t largest = 0;
    for (int n = 0; n <= std::max(0, config.frames - 3); ++n) {
        runner.step(n);
        largest = std::max(largest, runner.hal().frame_cycles_all());
    }
    return static_cast<double>(largest + config.capture_cycles);
}

}  // namespace

json point_skeleton(const grid_point& point) {
    json keys = json::object();
    for (const cli::key_assignment& a : point.settings) keys[a.key] = a.value;
    return {{"index", point.index}, {"keys", keys}};
}

bool read_point_report(const json& report, json* point, std::string* error) {
    try {
        const json& timing = report.at("summary").at("timing");
        json& p = *point;
        // A run that fits but never ran a stage judged nothing of it: no fit.
        const bool within = report.at("verdict").get<std::string>() == "within_budget";
        const bool judged = report.value("judged", true);
        p["verdict"] = !within ? "over" : judged ? "within" : "not_judged";
        p["not_judged"] = report.value("not_judged", json(nullptr));
        const json& overruns = report.at("overruns");
        p["first_overrun"] = json(nullptr);
        double worst = 0.0;  // the largest overrun: value over its limit
        for (const json& o : overruns)
            worst =
                std::max(worst, o.at("value_ms").get<double>() - o.at("limit_ms").get<double>());
        p["overrun_ms_max"] = overruns.empty() ? json(nullptr) : json(round6(worst));
        if (!overruns.empty()) {
            const json& o = overruns.front();
            p["first_overrun"] = {{"resource", o.at("resource")}, {"stage", o.at("stage")},
                                  {"period", o.at("period")},     {"pair", o.at("pair")},
                                  {"value_ms", o.at("value_ms")}, {"limit_ms", o.at("limit_ms")}};
        }
        double min_slack = std::numeric_limits<double>::infinity();
        for (const json& f : report.at("frames")) {
            const json& b = f.at("budget");
            if (b.at("judged").get<bool>())
                min_slack = std::min(min_slack, b.at("slack_ms").get<double>());
        }
        p["min_slack_ms"] = std::isfinite(min_slack) ? json(round6(min_slack)) : json(nullptr);
        p["judged_periods"] = timing.at("judged_periods");
        p["cpu_busy_ms_max"] = timing.at("cpu_busy_ms_max");
        p["emif_busy_ms_max"] = timing.at("emif_busy_ms_max");
        p["capture_ms"] = timing.at("capture_ms");
        p["processing_ms_max"] = timing.at("processing_ms_max");
        json stages = json::object();
        for (const auto& [stage, figures] : timing.at("stage_ms").items())
            stages[stage] = figures.at("max");
        p["stage_ms_max"] = stages;
        p["fifo_peak_words"] = timing.at("fifo_peak_words");
        p["overflows"] = timing.at("overflows");
        p["drops"] = timing.at("drops");
        return true;
    } catch (const std::exception& e) {
        *error = std::string("report.json: ") + e.what();
        return false;
    }
}

json closed_form_cache::estimate(const cli::run_setup& setup) {
    const platform::platform_config config = cli::platform_config_of(setup);
    const double cpu_mhz = static_cast<double>(config.dsk.cpu_hz) / 1e6;
    double processing_ms = std::numeric_limits<double>::quiet_NaN();
    // The host estimate runs the built-in firmware; a plugin has no host
    // entry (ABI version 1), so its points get no processing estimate.
    const bool plugin = !setup.firmware.empty();
    if (config.replay_manifest.empty() && !plugin) {
        const std::string key = processing_key(setup);
        auto it = m_cycles.find(key);
        if (it == m_cycles.end()) it = m_cycles.emplace(key, host_max_pair_cycles(config)).first;
        processing_ms = it->second / cpu_mhz / 1e3;
    }
    const platform::budget_estimate b =
        platform::estimate_budget(config, std::isnan(processing_ms) ? 0.0 : processing_ms);
    const double period_ms = static_cast<double>(config.period) / (simtime::ticks_per_ns * 1e6);
    json j = {{"capture_ms", round6(b.capture_ms)}, {"traffic_ms", round6(b.traffic_ms)}};
    if (std::isnan(processing_ms)) {
        j["processing_ms"] = j["need_ms"] = j["slack_ms"] = j["verdict"] = json(nullptr);
        if (plugin)
            j["processing_note"] =
                "the firmware under test is a plugin without a host entry: no processing "
                "estimate";
        return j;
    }
    j["processing_ms"] = round6(processing_ms);
    j["need_ms"] = round6(b.verdict.need_ms);
    j["slack_ms"] = round6(period_ms - b.verdict.need_ms);
    j["verdict"] = b.verdict.fits ? "within" : "over";
    return j;
}

void mark_agreement(json* point) {
    json& p = *point;
    const json& cf = p.value("closed_form", json::object());
    const bool both =
        p.value("verdict", json()).is_string() && cf.value("verdict", json()).is_string();
    const bool judged = p.value("verdict", json()) != "not_judged";
    p["closed_form_agrees"] = both && judged ? json(p["verdict"] == cf["verdict"]) : json(nullptr);
}

}  // namespace sweep
