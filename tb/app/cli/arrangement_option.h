// `stereosim run --arrangement fast|pins` (docs/arrangements.md): which
// arrangement of sensors, card and EMIF runs. fast (default): the cores
// stepped in one SystemC thread; pins: the literal pin-level reference
// (sc_signals, verilator --sc). Same pins, same report.
#pragma once

#include <memory>

#include "tb/app/cli/run_outputs.h"

namespace cli {

std::unique_ptr<run_extension> make_arrangement_option();

}  // namespace cli
