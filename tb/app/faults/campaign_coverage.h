// What a campaign exercised of the fault space (docs/fault-contract.md,
// "Coverage"), from the rows of campaign.json alone so that merged shards
// give the same: per fault kind and sensor, the runs whose onset fell in each
// phase (a line of the frame: vertical_blanking, dark_rows, active_rows; the
// card: oe_restart, first_check; the bus: bus_burst) and under each mode
// (capture overlapped / sequential, DSK v1 / v3), with the combinations no
// run reached listed as holes; and the faults' outcomes as ISO 26262 safety
// classes (contract.h safety_class) with their shares.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace faults {

nlohmann::json fault_space_coverage(const nlohmann::json& rows);
nlohmann::json safety_class_shares(const nlohmann::json& rows);

// The two as text (campaign.txt, after the table).
std::string coverage_text(const nlohmann::json& campaign);

}  // namespace faults
