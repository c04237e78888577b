// A report or campaign document without what depends on the host's speed
// (wall times, simulated / wall) or on how a run was started (from a
// snapshot or not: a resumed run may run alone in its group), so that two
// runs of one plan compare equal (`stereosim firmware check`, the tests).
#pragma once

#include <nlohmann/json.hpp>

namespace cli {

nlohmann::json without_host_figures(const nlohmann::json& document);

}  // namespace cli
