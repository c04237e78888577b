// The run extensions of `stereosim run` (tb/app/cli/run_outputs.h), from the
// folders that build on the command: faults, outputs, the arrangement.
#pragma once

#include <memory>
#include <vector>

#include "tb/app/cli/run_outputs.h"

namespace app {

// Every extension, in the order they run.
std::vector<std::unique_ptr<cli::run_extension>> make_run_extensions();

}  // namespace app
