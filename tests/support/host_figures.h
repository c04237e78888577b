// A report or campaign document without what depends on the host's speed
// (wall times, simulated / wall) or on how a run was started (from a
// snapshot or not: a resumed run may run alone in its group), so that two
// runs of one plan compare equal.
#pragma once

#include <nlohmann/json.hpp>

namespace testsupport {

nlohmann::json without_host_figures(const nlohmann::json& j);

}  // namespace testsupport
