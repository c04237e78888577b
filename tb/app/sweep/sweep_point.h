// One point of a sweep as sweep.json keeps it (docs/sweep.md): its keys, the
// co-simulation's figures read from the point's report.json, and the closed
// form's budget beside them (tb/platform/closed_form.h: capture and traffic
// from the timing rules, the largest pair's processing from the firmware's host
// entry over the same rendered scene, tb/platform/host).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "tb/app/cli/run_setup.h"
#include "tb/app/sweep/sweep_grid.h"
#include "tb/firmware/plugin.h"

namespace sweep {

// {"index": i, "keys": {KEY: value, ...}} of a grid point.
nlohmann::json point_skeleton(const grid_point& point);

// The co-simulation's figures of a point from its report.json into `point`:
// verdict (within | over), first_overrun, min_slack_ms over the judged
// periods, cpu_busy_ms_max, emif_busy_ms_max, capture_ms {max, mean},
// processing_ms_max, stage_ms_max {stage: ms}. false + *error if the
// report lacks a field.
bool read_point_report(const nlohmann::json& report, nlohmann::json* point, std::string* error);

// The closed form's budget of a setup: {capture_ms, traffic_ms,
// processing_ms, need_ms, slack_ms, verdict}. The processing estimate runs
// the firmware on the host once per distinct scene / image / firmware setup
// (for the reference firmware, clocks, bus timing and mode do not change
// its cycles) and is cached here, through the firmware's host entry
// (include/stereosim/firmware.h). A replay has no rendered scene, a plugin
// may have no host entry: processing_ms and the verdict are null then, with
// processing_note saying why.
class closed_form_cache {
  public:
    nlohmann::json estimate(const cli::run_setup& setup);
    // Host firmware runs done so far (distinct processing setups).
    size_t host_runs() const { return m_cycles.size(); }

  private:
    const stereosim_fw_host* host_entry(const std::string& path,
                                        const stereosim_fw_descriptor** firmware,
                                        std::string* note);

    // processing setup -> the largest pair's cycles (NaN: none) and why none
    std::map<std::string, std::pair<double, std::string>> m_cycles;
    std::map<std::string, std::unique_ptr<firmware::plugin>> m_plugins;  // by path
    std::map<std::string, std::string> m_load_errors;
};

// Sets "closed_form_agrees" on a co-simulated point (its verdict and the
// closed form's); null when either is missing.
void mark_agreement(nlohmann::json* point);

}  // namespace sweep
