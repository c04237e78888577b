// The built-in scenarios of `stereosim scenarios` (docs/cli.md) and the scene
// a scenario's parameters make.
//
// A built-in scenario is a name, one line of description and a list of config
// key settings over the defaults (tb/app/cli/config_keys.h), so anything a
// scenario sets can also be set by hand, and a report's config names every
// value the run used.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "model/scene/sequence.h"
#include "tb/app/cli/run_setup.h"

namespace cli {

struct builtin_scenario {
    const char* name;
    const char* description;
    std::vector<std::pair<const char*, const char*>> settings;  // config key, value
};

const std::vector<builtin_scenario>& builtin_scenarios();
// nullptr if there is no such scenario.
const builtin_scenario* find_scenario(const std::string& name);

// The scene of the scenario parameters on `rig`: the procedural background at
// 5 m, one orange textured ball on the chosen path, the lighting change. The
// paths are model/scene/ball_paths.h's, time-scaled by `speed`:
// bounce: scene::thrown_ball_path (scene::default_scenario's throw);
// circle: scene::circling_path (the tests' circling_scenario);
// line: scene::line_path; still: scene::resting_path.
// With the defaults this is exactly scene::default_scenario(3) (tested).
scene::scenario build_scenario(const scenario_params& params, const scene::stereo_rig& rig);

}  // namespace cli
