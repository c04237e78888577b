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
// 5 m, one orange textured ball on the chosen path, the lighting change.
// bounce: scene::default_scenario's throw (from (-0.30, 0, depth) m at
//   (0.14, -2.0, -0.45) m/s, floor 0.35 m below the axis, restitution 0.8),
//   time-scaled by `speed` (velocity x speed, gravity x speed^2);
// circle: host::circling_scenario's circle in the plane Z = depth, radius
//   0.15 depth, 0.41 depth x speed m/s (8 px per frame at any depth, speed 1);
// line: from (-0.25, -0.05, depth) m at (1.0, 0.1, 0) x speed m/s (7 px per
//   frame at 2.6 m);
// still: the ball rests at (-0.30, 0, depth) m.
// With the defaults this is exactly scene::default_scenario(3) (tested).
scene::scenario build_scenario(const scenario_params& params, const scene::stereo_rig& rig);

}  // namespace cli
