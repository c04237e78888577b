#include "tb/cli/run_outputs.h"

#include "tb/cli/arrangement_option.h"
#include "tb/faults/fault_extension.h"
#include "tb/output/output_extensions.h"

namespace cli {

std::vector<std::unique_ptr<run_extension>> make_run_extensions() {
    std::vector<std::unique_ptr<run_extension>> list;
    // One line per extension, e.g. list.push_back(make_vcd_output());
    list.push_back(faults::make_fault_extension());  // first: its faults shape the config
    list.push_back(output::make_waveform_output());
    list.push_back(output::make_plot_and_trace_output());
    list.push_back(make_arrangement_option());  // last: it sees the pin trace the others attached
    return list;
}

}  // namespace cli
