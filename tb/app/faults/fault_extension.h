// Fault injection in `stereosim run` (docs/faults.md), plugged in through the
// run command's extension seam (tb/app/cli/run_outputs.h):
//   --fault SPEC             (repeatable) inject a fault, grammar in docs/faults.md
//   --card-retry-limit N     the card's RETRY_LIMIT (default 8)
//   --hard-error-rearms N    the firmware's re-arms before it gives up (default 1)
// After the run the faults' onsets go on the timeline (event `fault`), and
// report.json gets `faults` and `fault_run` (tb/app/faults/fault_report.h).
#pragma once

#include <memory>

#include "tb/app/cli/run_outputs.h"

namespace faults {

std::unique_ptr<cli::run_extension> make_fault_extension();

}  // namespace faults
