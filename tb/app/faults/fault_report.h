// The faults' part of report.json (docs/faults.md "In report.json"): the
// `faults` array (one object per --fault: spec, kind, when it took effect,
// the observed outcome and the contract's verdict) and `fault_run` (the
// run-wide figures the contract checks, the settings its bounds depend on).
// The campaign reads them back from each child's report.json.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tb/app/faults/contract.h"
#include "tb/app/faults/observation.h"

namespace platform {
class platform_top;
struct scoreboard_report;
}  // namespace platform

namespace faults {

// One run's observation with the contract's verdicts (one per fault, or one
// for a clean run).
struct fault_run_result {
    run_observation run;
    contract_params params;
    std::vector<fault_spec> specs;
    std::vector<verdict> verdicts;
    bool contract_ok() const;
};

// paper_card: judged as the paper's card (contract_params::paper_card).
fault_run_result evaluate(platform::platform_top& top, const platform::scoreboard_report& score,
                          const std::vector<fault_spec>& specs, bool paper_card = false);

// report["faults"] and report["fault_run"].
void add_to_report(nlohmann::json& report, const fault_run_result& r);

// Reads them back (a child's report.json) and re-checks the contract; false
// and *error if the report lacks them.
bool read_from_report(const nlohmann::json& report, fault_run_result* r, std::string* error);

}  // namespace faults
