// The stereosim run extensions of tb/app/output (docs/waveforms.md), plugged
// into `stereosim run` through tb/app/cli/run_outputs.h:
//   waveforms  --waves fst|vcd [--waves-from MS --waves-to MS] [--waves-scope
//              LIST]: the card's whole RTL hierarchy and the pin trace of the
//              window into DIR/waves/<scenario>.fst|vcd through Verilator's
//              writers (waves_writer.h), its GTKWave save file and translate
//              filters beside it; --vcd [--vcd-from ...] is --waves vcd;
//   run files  with --out DIR: trajectory.gp + trajectory.png (gnuplot) and
//              timeline.json (Chrome trace events); with --timeline-csv also
//              timeline.csv (every timeline event, one row each).
#pragma once

#include <memory>

#include "tb/app/cli/run_outputs.h"

namespace output {

std::unique_ptr<cli::run_extension> make_waveform_output();
std::unique_ptr<cli::run_extension> make_plot_and_trace_output();

}  // namespace output
