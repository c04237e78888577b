// `stereosim firmware check [PATH]` (docs/firmware-abi.md "Checking a
// firmware"): is a firmware deterministic, as a campaign needs it to be?
// The default scenario run twice, and fault runs forked from a snapshot
// against the same runs from the start, each pair compared (report.json but
// the host's figures, and frames.csv); the first difference is named. A
// firmware that reads the host's clock, its process id or an uninitialized
// value gives runs that differ, and a campaign's verdicts of it would
// depend on how each run was started.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace cli {

// The first place two documents differ, as a path ("summary.hashes.pins",
// "frames[3].state") with both values, or "" if they are equal.
std::string first_difference(const nlohmann::json& a, const nlohmann::json& b,
                             const std::string& path = "");

// Runs the check with `binary` (this stereosim) on the plugin at `path`
// (empty: the built-in firmware). Prints what it compared; returns 0 if
// every pair agreed, 1 with one line naming the first difference, 2 if the
// plugin cannot load, 3 if a run could not be made.
int check_firmware(const std::string& binary, const std::string& path);

}  // namespace cli
