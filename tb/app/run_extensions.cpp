#include "tb/app/run_extensions.h"

#include "tb/app/cli/arrangement_option.h"
#include "tb/app/faults/fault_extension.h"
#include "tb/app/output/output_extensions.h"

namespace app {

std::vector<std::unique_ptr<cli::run_extension>> make_run_extensions() {
    std::vector<std::unique_ptr<cli::run_extension>> list;
    list.push_back(faults::make_fault_extension());  // first: its faults shape the config
    list.push_back(output::make_waveform_output());
    list.push_back(output::make_plot_and_trace_output());
    list.push_back(cli::make_arrangement_option());  // last: it sees the pin trace the others attached
    return list;
}

}  // namespace app
