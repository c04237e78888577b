#include "tb/app/sweep/sweep_point.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tb/firmware/builtin.h"
#include "tb/platform/closed_form.h"
#include "tb/platform/firmware_board.h"
#include "tb/platform/host/firmware_host.h"
#include "tb/platform/platform_config.h"

namespace sweep {

namespace {

using json = nlohmann::json;

double round6(double v) {
    return std::round(v * 1e6) / 1e6;
}

// The setup with every key that cannot change the reference firmware's
// charged cycles per pair at its defaults: the host run of one such setup
// serves them all. The clocks stay: the kernels' SDRAM stalls depend on the
// CPU / EMIF ratio. Of a plugin nothing is known: every setting may count.
std::string processing_key(const cli::run_setup& s) {
    cli::run_setup p = s;
    const cli::run_setup defaults;
    p.quantum_ns = defaults.quantum_ns;
    p.hash_pins = defaults.hash_pins;
    if (!s.firmware.empty()) return cli::config_json(p).dump();
    p.cpu_mhz = s.effective_cpu_mhz();
    p.eclk_mhz = s.effective_eclk_mhz();
    p.dsk_version = defaults.dsk_version;
    p.card_setup = defaults.card_setup;
    p.card_strobe = defaults.card_strobe;
    p.card_hold = defaults.card_hold;
    p.sdram_traffic_on_bus = defaults.sdram_traffic_on_bus;
    const auto bus_or_timer = [](const auto& setting) {
        return setting.first == "firmware.mode" || setting.first == "firmware.watchdog_ms" ||
               setting.first == "firmware.card_start_timeout";
    };
    auto& settings = p.firmware_settings;
    settings.erase(std::remove_if(settings.begin(), settings.end(), bus_or_timer), settings.end());
    return cli::config_json(p).dump();
}

// The firmware's host entry over the rendered frames the run processes (no
// sensors, no card, no bus): the largest pair's cycles, as its result
// reports them (capture's included). A run of F periods processes the pairs
// of scene frames 1 .. F - 3 (the first pair is taken in the second period;
// the last two are still in capture and processing when the run ends);
// frame 0 goes first here as the firmware's history. NaN with *error if the
// host run fails.
double host_max_pair_cycles(const platform::platform_config& config,
                            const stereosim_fw_descriptor& firmware, const stereosim_fw_host& entry,
                            std::string* error) {
    // The platform's cost model for this configuration (clocks, compiled-C
    // factor), as the co-simulation prices the kernels.
    const auto host = host::firmware_host::create(
        entry, firmware.stage_count, config.scenario, platform::board_of(config),
        platform::plugin_values(firmware, config), platform::cost_model_of(config), error);
    if (!host) return std::numeric_limits<double>::quiet_NaN();
    uint64_t largest = 0;
    for (int n = 0; n <= std::max(0, config.frames - 3); ++n) {
        stereosim_result r{};
        if (!host->step(n, &r, error)) return std::numeric_limits<double>::quiet_NaN();
        uint64_t cycles = 0;
        for (uint32_t s = 0; s < firmware.stage_count; ++s) cycles += r.stage_cycles[s];
        largest = std::max(largest, cycles);
    }
    return static_cast<double>(largest);
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

// The descriptor and host entry of the setup's firmware (the built-in
// reference's, or the plugin's: loaded once per file); null with *note.
const stereosim_fw_host* closed_form_cache::host_entry(const std::string& path,
                                                       const stereosim_fw_descriptor** firmware,
                                                       std::string* note) {
    if (path.empty()) {
        *firmware = &firmware::builtin();
        return &firmware::builtin_host();
    }
    auto it = m_plugins.find(path);
    if (it == m_plugins.end()) {
        std::string error;
        it = m_plugins.emplace(path, firmware::plugin::load(path, &error)).first;
        if (!it->second) m_load_errors[path] = error;
    }
    if (!it->second) {
        *note = m_load_errors[path];
        return nullptr;
    }
    *firmware = &it->second->descriptor();
    if (it->second->host() == nullptr)
        *note = "the firmware under test has no host entry (" STEREOSIM_FIRMWARE_HOST_ENTRY
                "): no processing estimate";
    return it->second->host();
}

json closed_form_cache::estimate(const cli::run_setup& setup) {
    const platform::platform_config config = cli::platform_config_of(setup);
    const double cpu_mhz = static_cast<double>(config.dsk.cpu_hz) / 1e6;
    double processing_ms = std::numeric_limits<double>::quiet_NaN();
    std::string note;
    const stereosim_fw_descriptor* firmware = nullptr;
    const stereosim_fw_host* entry = host_entry(setup.firmware, &firmware, &note);
    if (!config.replay_manifest.empty()) {
        note = "a replay has no rendered scene: no processing estimate";
    } else if (firmware != nullptr) {
        const std::string key = processing_key(setup);
        auto it = m_cycles.find(key);
        if (it == m_cycles.end()) {
            const double cycles = entry == nullptr
                                      ? std::numeric_limits<double>::quiet_NaN()
                                      : host_max_pair_cycles(config, *firmware, *entry, &note);
            it = m_cycles.emplace(key, std::make_pair(cycles, note)).first;
        }
        processing_ms = it->second.first / cpu_mhz / 1e3;
        note = it->second.second;
    }
    const bool overlapped = firmware == nullptr || platform::asks_overlapped(*firmware, config);
    const platform::budget_estimate b = platform::estimate_budget(
        config, std::isnan(processing_ms) ? 0.0 : processing_ms, overlapped);
    const double period_ms = static_cast<double>(config.period) / (simtime::ticks_per_ns * 1e6);
    json j = {{"capture_ms", round6(b.capture_ms)}, {"traffic_ms", round6(b.traffic_ms)}};
    if (std::isnan(processing_ms)) {
        j["processing_ms"] = j["need_ms"] = j["slack_ms"] = j["verdict"] = json(nullptr);
        if (!note.empty()) j["processing_note"] = note;
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
